// A steel ring (R = 100, wall h = R/(R/h), b = 1, 50 elements, fibre sections) crushed between a
// fixed lower plate and an upper one moving down by the load factor, for the crushing tests.
#pragma once

#include <string>

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

} // namespace plastica::testing
