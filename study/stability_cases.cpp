#include "stability_cases.hpp"

#include "robustness_cases.hpp"

#include "analysis/path_following.hpp"
#include "scene_reader.hpp"
#include "verification/cantilever_elastica.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace plastica {

namespace {

std::string num(double v) {
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", v);
    std::string s(b);
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
}

std::string sci(double v) {
    char b[16];
    std::snprintf(b, sizeof b, "%.0e", v);
    return b;
}

// A cantilever of length 1 and EI = 1 along x, clamped at the origin.
std::string cantilever(int elements, double area, const std::string& load, const std::string& analysis) {
    return "[scene]\nname = \"cantilever\"\n[[material]]\nname = \"m\"\nE = 1.0\n[[section]]\nname = \"s\"\n"
           "material = \"m\"\nA = " + num(area) + "\nI = 1.0\n[[line]]\nstart = [0.0, 0.0]\nend = [1.0, 0.0]\n"
           "elements = " + std::to_string(elements) + "\nsection = \"s\"\n[[support]]\nat = [0.0, 0.0]\n"
           "fix = [\"ux\", \"uy\", \"rz\"]\n[[load]]\nat = [1.0, 0.0]\n" + load + "[analysis]\n" + analysis;
}

std::string tip_load(int elements, double area, double alpha, const std::string& increments) {
    return cantilever(elements, area, "fy = " + num(-alpha) + "\n",
                      "scheme = \"load_control\"\n" + increments + "target_load_factor = 1.0\n"
                      "control_at = [1.0, 0.0]\ncontrol_dof = \"uy\"\ncontrol_sign = -1.0\n");
}

// The exact elastica's tip deflection at PL²/EI = alpha, within a relative tolerance.
auto deflection_near(double alpha, double tolerance) {
    return [=](const std::vector<StepResult>& steps, const RunSummary&) -> std::string {
        const double exact = cantilever_tip_load(alpha).deflection;
        const double got = steps.back().control_displacement;
        if (std::abs(got - exact) <= tolerance * exact) return "";
        return "tip deflection " + num(got) + ", exact " + num(exact);
    };
}

std::string ring_on_unilateral_base(double ky) {
    return R"([scene]
name = "ring"
[[material]]
name = "m"
E = 1.0e9
[[section]]
name = "s"
material = "m"
A = 0.1
I = 1.0e-6
[[arc]]
name = "ring"
center = [0.0, 100.0]
radius = 100.0
start_angle = -90.0
end_angle = 90.0
elements = 50
section = "s"
[[support]]
at = [0.0, 0.0]
fix = ["ux", "rz"]
[[support]]
at = [0.0, 200.0]
fix = ["ux", "rz"]
[[load]]
at = [0.0, 200.0]
fy = -1.0
[[foundation]]
kind = "unilateral"
on = "ring"
ky = )" + num(ky) + R"(
halve_at = [[0.0, 0.0]]
base_point = [0.0, 0.0]
base_normal = [0.0, 1.0]
[analysis]
scheme = "displacement_control"
increment = 0.5
adaptive = true
min_increment = 1e-6
control_at = [0.0, 200.0]
control_dof = "uy"
control_sign = -1.0
target_displacement = 100.0
max_steps = 400
# The ring's round-off floor (EA·R²/EI = 1e9) is near 2e-6 of the load.
residual_tolerance = 1e-5
[report]
load_scale = 2.0
)";
}

// A pinned circular arch of span 200 and rise 8 (f/r = 8, r the radius of gyration) under a central load:
// it snaps through, traced by arc length to an apex deflection of 2.5 rises.
std::string shallow_arch() {
    const double a = 100.0, f = 8.0, R = (a * a + f * f) / (2 * f);
    const double half = std::asin(a / R) * 180.0 / M_PI;
    return "[scene]\nname = \"arch\"\n[[material]]\nname = \"m\"\nE = 1.0e6\n[[section]]\nname = \"s\"\n"
           "material = \"m\"\nA = 1.0\nI = 1.0\n[[arc]]\ncenter = [0.0, " + num(f - R) + "]\nradius = " + num(R) +
           "\nstart_angle = " + num(90.0 - half) + "\nend_angle = " + num(90.0 + half) + "\nelements = 40\nsection = \"s\"\n"
           "[[support]]\nat = [" + num(a) + ", 0.0]\nfix = [\"ux\", \"uy\"]\n[[support]]\nat = [" + num(-a) +
           ", 0.0]\nfix = [\"ux\", \"uy\"]\n[[load]]\nat = [0.0, " + num(f) + "]\nfy = -1.0\n[analysis]\n"
           "scheme = \"arc_length\"\nincrement = 2.0\nmax_increment = 5.0\ncontrol_at = [0.0, " + num(f) +
           "]\ncontrol_dof = \"uy\"\ncontrol_sign = -1.0\ntarget_displacement = 20.0\nmax_steps = 2000\n";
}

std::string plastic_header() {
    return "[scene]\nname = \"plastic\"\n[[material]]\nname = \"steel\"\nE = 2.0e8\nfy = 250.0\n[[section]]\n"
           "name = \"s\"\nmaterial = \"steel\"\nshape = \"rectangle\"\nb = 10.0\nh = 20.0\nfibres = 10\n";
}

} // namespace

std::vector<StabilityCase> stability_cases() {
    using Check = decltype(StabilityCase::check);
    std::vector<StabilityCase> cases;
    const auto completed = RunStatus::completed;
    // Unilateral penalty from far softer than the ring (EI/R³ = 1e-3) to 1e12: the base reaction
    // must equal the applied load at the end.
    // At 1e12 the penalty is 1e15 times the ring's bending scale EI/R³. A contact node's force
    // is ky times its gap, and its displacement (about 1) is known to eps, so the force is
    // known to about ky·eps = 2e-4, some 1e-3 of the load: no solver in double precision can
    // meet the tolerance of 1e-5 once the contact spreads. What a correct solver does, and what
    // this case expects: stop with "no convergence", name that round-off floor and the penalty
    // as its cause, and keep every converged step in equilibrium (not wander, not produce NaN,
    // not accept steps out of balance).
    for (double ky : {1e0, 1e4, 1e8, 1e10, 1e12})
        cases.push_back({"ring on a unilateral base", "ky = " + sci(ky), ring_on_unilateral_base(ky),
                         ky < 1e11 ? completed : RunStatus::no_convergence,
                         [ky](const std::vector<StepResult>& s, const RunSummary& summary) -> std::string {
                             const StepResult& r = s.back();
                             if (ky > 1e11 && summary.reason.find("round-off alone leaves") == std::string::npos)
                                 return "the reason does not name the round-off floor: " + summary.reason;
                             if (ky > 1e11 && summary.reason.find("foundation's penalty stiffness") == std::string::npos)
                                 return "the reason does not name the penalty as the floor's cause: " + summary.reason;
                             // The half model carries half the reported load; equilibrium holds to the
                             // residual the step was accepted with.
                             const double tolerance = std::max(1e-6, 2.0 * r.residual);
                             if (std::abs(r.base_reaction - 0.5 * r.load) <= tolerance * r.load) return "";
                             return "base reaction " + num(r.base_reaction) + " against " + num(0.5 * r.load);
                         }});
    // Slenderness: EA/EI from 1e2 to 1e10 (the axial stiffness dwarfs the bending one).
    for (double ratio : {1e2, 1e6, 1e10})
        cases.push_back({"cantilever, tip load PL²/EI = 10", "EA/EI = " + sci(ratio),
                         tip_load(20, ratio, 10.0, "increment = 0.02\n"), completed,
                         ratio >= 1e6 ? Check(deflection_near(10.0, 2e-3)) : Check()});
    // Rotations past 2π: an end moment 4πEI/L rolls the cantilever twice round.
    cases.push_back({"cantilever rolled by an end moment", "4π EI/L (two turns)",
                     cantilever(20, 1e6, "moment = " + num(4 * M_PI) + "\n",
                                "scheme = \"load_control\"\nincrement = 0.02\ntarget_load_factor = 1.0\n"
                                "control_at = [1.0, 0.0]\ncontrol_dof = \"rz\"\nallow_crossing = true\n"),
                     completed, [](const std::vector<StepResult>& s, const RunSummary&) -> std::string {
                         const double rz = s.back().control_displacement;
                         return std::abs(rz - 4 * M_PI) <= 1e-6 ? "" : "tip rotation " + num(rz) + ", expected 4π";
                     }});
    // Load control past the collapse of a propped cantilever (6 Mp/L = 750): a clean stop.
    cases.push_back({"propped cantilever, load control past collapse", "target 1.5 × 6Mp/L",
                     plastic_header() + "[[line]]\nstart = [0.0, 0.0]\nend = [2000.0, 0.0]\nelements = 8\nsection = \"s\"\n"
                     "[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n[[support]]\nat = [2000.0, 0.0]\nfix = [\"uy\"]\n"
                     "[[load]]\nat = [1000.0, 0.0]\nfy = -750.0\n[analysis]\nscheme = \"load_control\"\nincrement = 0.05\n"
                     "target_load_factor = 1.5\ncontrol_at = [1000.0, 0.0]\ncontrol_dof = \"uy\"\ncontrol_sign = -1.0\n",
                     RunStatus::limit_load, [](const std::vector<StepResult>& s, const RunSummary&) -> std::string {
                         double peak = 0.0;
                         for (const StepResult& r : s) peak = std::max(peak, r.load_factor);
                         return peak > 0.97 && peak <= 1.01 ? "" : "peak load " + num(750 * peak) + ", expected 750";
                     }});
    // Snap-through of a shallow arch (rise 4 % of the span) by arc length: past the limit point
    // the tangent has a negative pivot, and the path comes back to positive stiffness.
    cases.push_back({"shallow arch snap-through, arc length", "rise/span = 0.04", shallow_arch(), completed,
                     [](const std::vector<StepResult>& s, const RunSummary&) -> std::string {
                         // The first limit point, then the load must drop far below it.
                         std::size_t k = 1;
                         while (k < s.size() && s[k].load >= s[k - 1].load) ++k;
                         if (k == s.size()) return "no limit point";
                         const double limit = s[k - 1].load;
                         double lowest = limit;
                         bool negative = false;
                         for (std::size_t i = k; i < s.size(); ++i) lowest = std::min(lowest, s[i].load), negative |= s[i].negative_pivots > 0;
                         if (!negative) return "no negative pivot past the limit point";
                         return lowest < 0.5 * limit ? "" : "the load did not fall after the limit point";
                     }});
    // Tiny loads: 1e-12 of the reference; linear theory PL³/3EI to 1e-6.
    cases.push_back({"cantilever, tiny tip load", "PL²/EI = 1e-12", tip_load(20, 1e6, 1e-12, "increment = 0.25\n"), completed,
                     [](const std::vector<StepResult>& s, const RunSummary&) -> std::string {
                         const double v = s.back().control_displacement, exact = 1e-12 / 3.0;
                         return std::abs(v - exact) <= 1e-6 * exact ? "" : "tip deflection " + num(v) + ", linear " + num(exact);
                     }});
    // A single huge increment (PL²/EI = 10 at once): the step is cut and the path recovered.
    cases.push_back({"cantilever, one huge increment", "ΔPL²/EI = 10 in one step",
                     tip_load(20, 1e6, 10.0, "increment = 1.0\nmax_iterations = 5\n"), completed,
                     [](const std::vector<StepResult>& s, const RunSummary& r) -> std::string {
                         if (r.cut_steps == 0) return "the step was never cut";
                         return deflection_near(10.0, 2e-3)(s, r);
                     }});
    // The smallest and a large mesh (2000 elements: EA/L = 2e9 puts the residual's round-off
    // floor near 1e-5 of the load, so the scene asks for that tolerance).
    cases.push_back({"cantilever, tip load PL²/EI = 10", "1 element", tip_load(1, 1e6, 10.0, "increment = 0.02\n"), completed, nullptr});
    cases.push_back({"cantilever, tip load PL²/EI = 10", "2000 elements", tip_load(2000, 1e6, 10.0, "increment = 0.1\nresidual_tolerance = 1e-5\n"), completed,
                     deflection_near(10.0, 1e-3)});
    for (StabilityCase& c : robustness_cases()) cases.push_back(std::move(c));
    return cases;
}

StabilityRow run_stability_case(const StabilityCase& c) {
    StabilityRow row;
    row.name = c.name;
    row.parameter = c.parameter;
    const Model model = read_scene_text(c.scene, "stability: " + c.name);
    PathFollowing analysis(model);
    std::vector<StepResult> steps;
    bool finite = true;
    const RunSummary summary = analysis.run({[&](const StepResult& r) {
        for (double u : r.displacement) finite = finite && std::isfinite(u);
        row.max_residual = std::max(row.max_residual, r.residual);
        row.max_negative_pivots = std::max(row.max_negative_pivots, r.negative_pivots);
        row.peak_load = std::max(row.peak_load, r.load);
        steps.push_back(r);
    }});
    row.outcome = to_string(summary.status);
    row.reason = summary.reason;
    row.steps = summary.steps;
    row.iterations = summary.iterations;
    row.cut_steps = summary.cut_steps;
    row.seconds = summary.seconds;
    if (!finite) row.problem = "a converged step holds NaN or Inf";
    else if (summary.status != c.expected) row.problem = std::string("expected ") + to_string(c.expected);
    else if (steps.empty()) row.problem = "no converged step";
    else if (c.check) row.problem = c.check(steps, summary);
    row.passed = row.problem.empty();
    return row;
}

} // namespace plastica
