// Load patterns held while another is driven (engine/load/pattern_factors.hpp): gravity first,
// held at its factor, then a lateral load pushed; checked against closed forms of second-order
// elasticity, against path independence where the structure is elastic, and by equilibrium.
#include "analysis_helpers.hpp"

#include <catch2/catch.hpp>

using namespace plastica;
using namespace plastica::testing;

namespace {

const double pi = std::acos(-1.0);

// A cantilever along x, clamped at x = 0, EI = 1, L = 1, with an axial force held and a small
// transverse load driven after it.
std::string column_under_axial_load(double P, double H, int elements) {
    return cantilever(1.0, elements, 1.0e6, 1.0, 1.0e-6,
                      "[[load]]\nat = [1.0, 0.0]\nfx = " + num(-P) + "\npattern = \"axial\"\n"
                      "[[load]]\nat = [1.0, 0.0]\nfy = " + num(H) + "\npattern = \"lateral\"\n",
                      "pattern = \"axial\"\nscheme = \"load_control\"\nincrement = 0.25\ntarget_load_factor = 1.0\n"
                      "[[stage]]\npattern = \"lateral\"\nscheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 1.0\n"
                      "control_at = [1.0, 0.0]\ncontrol_dof = \"uy\"\n");
}

// A fixed-base portal 6 m wide and 4 m high (elastic HEB 200-like members), gravity on the
// column tops and a lateral load at the left one, in patterns or in one.
std::string portal(const std::string& loads, const std::string& analysis, const std::string& section_extra = "") {
    return "[scene]\nname = \"portal\"\n"
           "[[material]]\nname = \"S355\"\nE = 2.1e8\n" + section_extra +
           "[[section]]\nname = \"col\"\nmaterial = \"S355\"\nshape = \"i\"\ndepth = 0.2\nflange_width = 0.2\n"
           "flange_thickness = 0.015\nweb_thickness = 0.009\n"
           "[[line]]\nstart = [0.0, 0.0]\nend = [0.0, 4.0]\nelements = 8\nsection = \"col\"\n"
           "[[line]]\nstart = [0.0, 4.0]\nend = [6.0, 4.0]\nelements = 8\nsection = \"col\"\n"
           "[[line]]\nstart = [6.0, 4.0]\nend = [6.0, 0.0]\nelements = 8\nsection = \"col\"\n"
           "[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n"
           "[[support]]\nat = [6.0, 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n" + loads + "[analysis]\n" + analysis;
}

const std::string gravity_then_lateral =
    "[[load]]\nat = [0.0, 4.0]\nfy = -1500.0\npattern = \"gravity\"\n"
    "[[load]]\nat = [6.0, 4.0]\nfy = -1500.0\npattern = \"gravity\"\n"
    "[[load]]\nat = [0.0, 4.0]\nfx = 100.0\npattern = \"lateral\"\n";

double total_reaction(const StepResult& s, int dof) {
    double sum = 0.0;
    for (std::size_t k = dof; k < s.reaction.size(); k += 3) sum += s.reaction[k];
    return sum;
}

} // namespace

TEST_CASE("An axial load held while a lateral load is driven amplifies the deflection as the beam-column's closed form", "[patterns]") {
    // Cantilever, EI = L = 1, axial compression P = 0.5·P_cr held, then a lateral tip load H:
    // δ = H/(P·k)·(tan kL − kL), k = √(P/EI) (Timoshenko & Gere, Theory of Elastic Stability,
    // 1961, §1.11). H = 1e-5·P keeps δ/L near 1e-5, where the third-order terms are 1e-10.
    const double P = 0.5 * pi * pi / 4.0, H = 1e-5 * P, k = std::sqrt(P);
    const double exact = H / (P * k) * (std::tan(k) - k);
    double previous_error = 1.0;
    for (int elements : {4, 8, 16}) {
        CAPTURE(elements);
        const Run run = run_scene(column_under_axial_load(P, H, elements));
        REQUIRE(run.summary.status == RunStatus::completed);
        const StepResult& last = run.steps.back();
        CHECK(last.stage == 2);
        REQUIRE(last.pattern_factors.size() == run.model.patterns.size());
        CHECK(last.pattern_factors[1] == Approx(1.0).epsilon(1e-12)); // the axial pattern, held
        CHECK(last.pattern_factors[2] == Approx(1.0).epsilon(1e-12)); // the lateral one, driven to its target
        const double error = std::abs(last.control_displacement / exact - 1.0);
        CAPTURE(last.control_displacement, exact, error);
        // Cubic elements with their geometric stiffness: the amplification converges as 1/n²
        // (measured 1.25e-2, 3.19e-3, 8.0e-4 for 4, 8, 16 elements: 0.20/n²).
        CHECK(error < 0.22 / (elements * elements));
        CHECK(error < previous_error);
        previous_error = error;
        // While the axial load was being applied, nothing moved sideways.
        for (const StepResult& s : run.steps)
            if (s.stage == 1) CHECK(std::abs(s.control_displacement) < 1e-12);
    }
}

TEST_CASE("An elastic frame reaches the same state by gravity then a lateral load as by both at once", "[patterns]") {
    // Conservative loads on an elastic structure: the end state does not depend on the path.
    const Run staged = run_scene(portal(gravity_then_lateral,
                                        "pattern = \"gravity\"\nscheme = \"load_control\"\nincrement = 0.2\ntarget_load_factor = 1.0\n"
                                        "[[stage]]\npattern = \"lateral\"\nscheme = \"load_control\"\nincrement = 0.25\n"
                                        "target_load_factor = 1.0\ncontrol_at = [0.0, 4.0]\ncontrol_dof = \"ux\"\n"));
    const Run together = run_scene(portal("[[load]]\nat = [0.0, 4.0]\nfx = 100.0\nfy = -1500.0\n"
                                          "[[load]]\nat = [6.0, 4.0]\nfy = -1500.0\n",
                                          "scheme = \"load_control\"\nincrement = 0.1\ntarget_load_factor = 1.0\n"
                                          "control_at = [0.0, 4.0]\ncontrol_dof = \"ux\"\n"));
    REQUIRE(staged.summary.status == RunStatus::completed);
    REQUIRE(together.summary.status == RunStatus::completed);
    const std::vector<double>& a = staged.steps.back().displacement;
    const std::vector<double>& b = together.steps.back().displacement;
    double largest = 0.0, difference = 0.0;
    for (std::size_t k = 0; k < a.size(); ++k)
        largest = std::max(largest, std::abs(b[k])), difference = std::max(difference, std::abs(a[k] - b[k]));
    CAPTURE(largest, difference);
    // Both solved to a residual of 1e-6 of the load: the displacements agree to about that.
    CHECK(difference < 1e-6 * largest);
    // The curve reports the lateral pattern: its load at its factor, the sway of its control point.
    CHECK(staged.steps.back().load == Approx(100.0).epsilon(1e-12));
    CHECK(staged.steps.back().control_displacement == Approx(together.steps.back().control_displacement).epsilon(1e-6));
}

TEST_CASE("Gravity held on a yielding frame while the sway is pushed past the peak stays in equilibrium", "[patterns][plasticity]") {
    const Run run = run_scene(portal(gravity_then_lateral,
                                     "pattern = \"gravity\"\nscheme = \"load_control\"\nincrement = 0.25\ntarget_load_factor = 1.0\n"
                                     "[[stage]]\npattern = \"lateral\"\nscheme = \"displacement_control\"\nincrement = 0.004\n"
                                     "adaptive = true\ntarget_displacement = 0.25\ncontrol_at = [0.0, 4.0]\ncontrol_dof = \"ux\"\n",
                                     "fy = 3.55e5\n"));
    REQUIRE(run.summary.status == RunStatus::completed);
    int pushed = 0;
    double peak = 0.0;
    for (const StepResult& s : run.steps) {
        if (s.stage != 2) continue;
        ++pushed;
        CAPTURE(s.step);
        // The vertical reactions carry the held gravity, the horizontal ones the driven load.
        CHECK(total_reaction(s, 1) == Approx(3000.0).epsilon(1e-5));
        CHECK(-total_reaction(s, 0) == Approx(100.0 * s.load_factor).margin(1e-5 * 3000.0));
        CHECK(s.pattern_factors[1] == 1.0);
        peak = std::max(peak, s.load);
    }
    CHECK(pushed > 10);
    // Past the peak: the yielding frame with P–Δ sheds load (the columns' tops at capacity).
    CHECK(run.steps.back().load < peak);
    CHECK(run.steps.back().plastic_hinge_count >= 2);
}

TEST_CASE("A support settlement held in its pattern stays put while a load is added", "[patterns]") {
    // A beam clamped at both ends, L = 4, EI = 1e4: the right support settles by s = 0.004 (pattern
    // "settlement", held), then a midspan load P down is driven. Linear theory: the right
    // support's upward force is P/2 − 12·EI·s/L³, its moment 6·EI·s/L² − P·L/8 (counter-
    // clockwise); the right end slides freely along the beam, so no chord tension stiffens it.
    const double EI = 1.0e4, L = 4.0, s = 0.004, P = 10.0;
    const std::string scene =
        "[scene]\nname = \"settlement\"\n[[material]]\nname = \"m\"\nE = 1.0e8\n"
        "[[section]]\nname = \"s\"\nmaterial = \"m\"\nA = 1.0\nI = 1.0e-4\n"
        "[[line]]\nstart = [0.0, 0.0]\nend = [4.0, 0.0]\nelements = 8\nsection = \"s\"\n"
        "[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n"
        "[[support]]\nat = [4.0, 0.0]\nfix = [\"rz\"]\n"
        "[[prescribed]]\nat = [4.0, 0.0]\ndof = \"uy\"\nvalue = -0.004\npattern = \"settlement\"\n"
        "[[load]]\nat = [2.0, 0.0]\nfy = -10.0\n"
        "[analysis]\npattern = \"settlement\"\nscheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 1.0\n"
        "control_at = [2.0, 0.0]\n"
        "[[stage]]\nscheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 1.0\n";
    const Run run = run_scene(scene);
    REQUIRE(run.summary.status == RunStatus::completed);
    const StepResult& last = run.steps.back();
    CHECK(run.node_dof(last, 4.0, 0.0, 1) == -s);
    const double reaction = last.reaction[3 * 8 + 1], moment = last.reaction[3 * 8 + 2];
    // Second-order terms are of the order of the rotations, 1e-3.
    CHECK(reaction == Approx(P / 2 - 12 * EI * s / (L * L * L)).epsilon(2e-3));
    CHECK(moment == Approx(6 * EI * s / (L * L) - P * L / 8).epsilon(2e-3));
}

TEST_CASE("A platen's travel held in its pattern keeps the ring pressed while another load is driven", "[patterns][contact]") {
    // A ring (R = 1) on a rigid floor, pressed by a platen that moves down by 0.2 (pattern "press",
    // driven to 1, then held); then a small sideways load at the ring's right side.
    const std::string scene =
        "[scene]\nname = \"pressed_ring\"\n[[material]]\nname = \"m\"\nE = 1.0e4\n"
        "[[section]]\nname = \"s\"\nmaterial = \"m\"\nA = 0.1\nI = 1.0e-3\n"
        "[[arc]]\nname = \"ring\"\ncenter = [0.0, 1.0]\nradius = 1.0\nstart_angle = -90.0\nend_angle = 270.0\nelements = 48\nsection = \"s\"\n"
        "[[foundation]]\nkind = \"unilateral\"\non = \"ring\"\nky = 1.0e5\nbase_point = [0.0, 0.0]\n"
        "[[foundation]]\nkind = \"unilateral\"\non = \"ring\"\nky = 1.0e5\nbase_point = [0.0, 2.0]\nbase_normal = [0.0, -1.0]\n"
        "base_motion = [0.0, -0.2]\npattern = \"press\"\n"
        "[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"rz\"]\n"
        "[[load]]\nat = [1.0, 1.0]\nfx = 0.01\npattern = \"side\"\n"
        "[analysis]\npattern = \"press\"\nscheme = \"load_control\"\nincrement = 0.1\ntarget_load_factor = 1.0\n"
        "control_at = [0.0, 2.0]\n"
        "[[stage]]\npattern = \"side\"\nscheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 1.0\n"
        "control_at = [1.0, 1.0]\ncontrol_dof = \"ux\"\n";
    const Run run = run_scene(scene);
    REQUIRE(run.summary.status == RunStatus::completed);
    const StepResult* pressed = nullptr;
    for (const StepResult& s : run.steps)
        if (s.stage == 1) pressed = &s;
    REQUIRE(pressed);
    const StepResult& last = run.steps.back();
    // The top stays under the held platen (were the platen back at its start, the ring would
    // spring back by 0.2); the side load moves it by a small fraction of that.
    const double top_pressed = run.node_dof(*pressed, 0.0, 2.0, 1), top_last = run.node_dof(last, 0.0, 2.0, 1);
    CAPTURE(top_pressed, top_last);
    CHECK(top_pressed < -0.19);
    CHECK(std::abs(top_last - top_pressed) < 0.01 * 0.2);
    CHECK(last.control_displacement > 0.0);
}

TEST_CASE("Pattern mistakes are located errors", "[patterns][scene]") {
    const std::string loads = "[[load]]\nat = [0.0, 4.0]\nfy = -100.0\npattern = \"gravity\"\n"
                              "[[load]]\nat = [0.0, 4.0]\nfx = 10.0\npattern = \"lateral\"\n";
    const auto error_of = [](const std::string& text) { return scene_error_of(text, "p.toml"); };
    // A pattern no stage drives would never act.
    CHECK_THAT(error_of(portal(loads, "pattern = \"gravity\"\nscheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 1.0\n")),
               Catch::Contains("load pattern 'lateral' is driven by neither [analysis] nor a [[stage]]"));
    // [analysis] drives "main" unless it says: here "main" holds nothing.
    CHECK_THAT(error_of(portal(loads, "scheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 1.0\n")),
               Catch::Contains("'analysis.pattern': no load, pressure, prescribed displacement or moving base belongs to pattern 'main' (the default)"));
    // A stage's controlled DOF needs its point.
    CHECK_THAT(error_of(portal(loads, "pattern = \"gravity\"\nscheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 1.0\n"
                                      "[[stage]]\npattern = \"lateral\"\nincrement = 0.5\ntarget_load_factor = 1.0\ncontrol_dof = \"ux\"\n")),
               Catch::Contains("'stage[1].control_dof': name the controlled point as well"));
    CHECK_THAT(error_of(portal("[[load]]\nat = [0.0, 4.0]\nfy = -100.0\npattern = \"grav ity\"\n",
                               "scheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 1.0\n")),
               Catch::Contains("'load[1].pattern': expected 1 to 32 letters"));
}
