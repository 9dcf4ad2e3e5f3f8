// A steel ring (R = 100, wall h = R/(R/h), b = 1, 50 elements, fibre sections) crushed between a
// fixed lower plate and an upper one moving down by the load factor, for the crushing tests, and
// the roughness of a crush curve.
#pragma once

#include "analysis_helpers.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace plastica::testing {

// `analysis`: the [analysis] keys before the control point; `law`: the material's law lines
// (hardening 1e-4·E unless given); `penalty`: both plates' stiffness (0: 1e4·EI/R³).
inline std::string crushed_ring(double r_over_h, const std::string& analysis,
                                const std::string& law = "law = \"kinematic_hardening\"\nhardening_ratio = 1e-4\n", double penalty = 0.0) {
    const double R = 100.0, h = R / r_over_h, E = 210000.0, EI = E * h * h * h / 12.0;
    const double k = penalty > 0.0 ? penalty : 1e4 * EI / (R * R * R);
    return "[scene]\nname = \"crush\"\n[[material]]\nname = \"steel\"\nE = 210000.0\nfy = 355.0\n" + law +
           "[[section]]\nname = \"ring\"\nmaterial = \"steel\"\nshape = \"rectangle\"\nb = 1.0\nh = " + std::to_string(h) +
           "\nplasticity = \"distributed\"\n[[arc]]\nname = \"ring\"\ncenter = [0.0, 100.0]\nradius = 100.0\nstart_angle = -90.0\n"
           "end_angle = 90.0\nelements = 50\nsection = \"ring\"\n"
           "[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"rz\"]\n[[support]]\nat = [0.0, 200.0]\nfix = [\"ux\", \"rz\"]\n"
           "[[foundation]]\nkind = \"unilateral\"\non = \"ring\"\nky = " + std::to_string(k) +
           "\nhalve_at = [[0.0, 0.0]]\n"
           "[[foundation]]\nkind = \"unilateral\"\non = \"ring\"\nky = " + std::to_string(k) +
           "\nhalve_at = [[0.0, 200.0]]\nbase_point = [0.0, 200.0]\nbase_normal = [0.0, -1.0]\nbase_motion = [0.0, -1.0]\n"
           "[analysis]\n" + analysis + "control_at = [0.0, 200.0]\ncontrol_dof = \"uy\"\ncontrol_sign = -1.0\nmax_steps = 4000\n"
           "[report]\nload_scale = 2.0\n";
}

// The largest deviation of the load from the mean of its 9 neighbours on a grid of the plate's
// travel 0.5 apart (the curve interpolated linearly between steps), relative to the load, from
// a travel of `from` on.
inline double crush_roughness(const Run& r, double from) {
    std::vector<double> travel, load;
    for (const StepResult& s : r.steps) {
        travel.push_back(s.load_factor);
        load.push_back(s.load);
    }
    std::vector<double> grid;
    for (double x = from; x <= travel.back(); x += 0.5) {
        const std::size_t i = static_cast<std::size_t>(std::lower_bound(travel.begin(), travel.end(), x) - travel.begin());
        const double t = (x - travel[i - 1]) / (travel[i] - travel[i - 1]);
        grid.push_back(load[i - 1] + t * (load[i] - load[i - 1]));
    }
    double worst = 0.0;
    for (std::size_t i = 4; i + 4 < grid.size(); ++i) {
        double mean = 0.0;
        for (std::size_t k = i - 4; k <= i + 4; ++k) mean += grid[k] / 9.0;
        worst = std::max(worst, std::abs(grid[i] - mean) / grid[i]);
    }
    return worst;
}

} // namespace plastica::testing
