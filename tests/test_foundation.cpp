// Foundation springs and unilateral contact against closed forms (Hetényi, "Beams on Elastic
// Foundation", 1946; Timoshenko, "Strength of Materials II", 1956) and the
// ring scenes: Hetényi's beam on a Winkler foundation, the tensionless foundation, the
// pinched ring at small load, penalty convergence, equilibrium of contact forces, symmetry.
#include "analysis_helpers.hpp"
#include "crushed_ring.hpp"

#include <catch2/catch.hpp>

using namespace plastica;
using namespace plastica::testing;

namespace {

// Free-free beam of length βL centred on x = 0, EI = 1, k = 4 per unit length (β = 1),
// springs k·s at the nodes (half at the ends through the tributary length), load P at x = 0.
Run winkler_beam(double length, int elements, const std::string& kind, double P) {
    const std::string base = kind == "unilateral" ? "base_point = [0.0, 0.0]\nbase_normal = [0.0, 1.0]\n" : "";
    return run_scene("[scene]\nname = \"winkler\"\n[[material]]\nname = \"m\"\nE = 1.0\n[[section]]\nname = \"s\"\n"
                     "material = \"m\"\nA = 1e6\nI = 1.0\n[[line]]\nname = \"beam\"\nstart = [" + num(-length / 2) +
                     ", 0.0]\nend = [" + num(length / 2) + ", 0.0]\nelements = " + std::to_string(elements) +
                     "\nsection = \"s\"\n[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\"]\n"
                     "[[foundation]]\nkind = \"" + kind + "\"\non = \"beam\"\nky = 4.0\nper_length = true\n" + base +
                     "[[load]]\nat = [0.0, 0.0]\nfy = " + num(-P) + "\n"
                     "[analysis]\nscheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 1.0\n"
                     "residual_tolerance = 1e-8\n");
}

double centre_moment(const Run& r) {
    const StepResult& s = r.steps.back();
    for (std::size_t e = 0; e < r.model.elements.size(); ++e)
        if (std::abs(r.model.nodes[r.model.elements[e].node_j].x) < 1e-12) return s.elements[e].forces.moment_j;
    return 0.0;
}

Run ring(const std::string& foundation, double increment, double target, const std::string& extra = "") {
    std::string scene = R"(
[scene]
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
[report]
load_scale = 2.0
)";
    return run_scene(scene + foundation + "[analysis]\nscheme = \"displacement_control\"\nincrement = " + num(increment) +
                     "\nadaptive = false\ncontrol_at = [0.0, 200.0]\ncontrol_sign = -1.0\ntarget_displacement = " +
                     num(target) + "\nmax_steps = 5000\n" + extra);
}

std::string unilateral(double ky) {
    return "[[foundation]]\nkind = \"unilateral\"\non = \"ring\"\nky = " + num(ky) +
           "\nhalve_at = [[0.0, 0.0]]\nbase_point = [0.0, 0.0]\nbase_normal = [0.0, 1.0]\n";
}

} // namespace

TEST_CASE("A beam on a Winkler foundation matches Hetényi's closed form as the springs refine", "[foundation]") {
    // βL = 4: w_c = 0.134994 P β/k·(k=4 → per unit P), M_c = 0.263462 P/β (Hetényi 1946).
    const double P = 1e-4;
    double previous = 1.0;
    for (int n : {20, 40, 80}) {
        const Run r = winkler_beam(4.0, n, "bilateral", P);
        REQUIRE(r.summary.status == RunStatus::completed);
        const double w = -r.node_dof(r.steps.back(), 0.0, 0.0, 1) / P;
        const double M = centre_moment(r) / P;
        const double error = std::max(std::abs(w - 0.134994) / 0.134994, std::abs(std::abs(M) - 0.263462) / 0.263462);
        INFO(n << " elements: w_c = " << w << ", M_c = " << M << ", error " << error);
        // Lumping k·s at nodes errs by O(s²); s = 0.05 gives about 0.1 %.
        CHECK(error < previous);
        previous = error;
    }
    CHECK(previous < 2e-3);
}

TEST_CASE("A tensionless foundation lifts off beyond a = π/2β and deflects 1.0903 × the bilateral value", "[foundation][contact]") {
    // βL = 10, s = 0.1: w0 = coth(π/2)·Pβ/2k = 0.136291·P, contact |x| ≤ π/2β (Tsai & Westmann, "Beam on tensionless foundation", J. Eng. Mech. Div. 93, 1967).
    // Both ways to model it: springs against a rigid base line through the beam's axis, and a
    // tensionless bed anchored at each node's initial position.
    const std::string kind = GENERATE(as<std::string>{}, "unilateral", "tensionless");
    INFO(kind);
    const double P = 1e-4;
    const Run r = winkler_beam(10.0, 100, kind, P);
    REQUIRE(r.summary.status == RunStatus::completed);
    const StepResult& s = r.steps.back();
    const double w0 = -r.node_dof(s, 0.0, 0.0, 1) / P;
    CHECK(w0 == Approx(0.136291).epsilon(2e-3));
    // Contact zone: the contiguous active nodes span π/β within two spring spacings.
    CHECK(std::abs(s.contact_length - M_PI) <= 2 * 0.1);
    for (const SpringResult& sp : s.springs) {
        const double x = r.model.nodes[sp.node].x;
        if (std::abs(x) < M_PI / 2 - 0.1) CHECK(sp.active);
        if (std::abs(x) > M_PI / 2 + 0.1) CHECK_FALSE(sp.active);
    }
    // The lifted ends carry no force and the response is linear in P once the zone is fixed.
    const Run r2 = winkler_beam(10.0, 100, kind, 3 * P);
    CHECK(-r2.node_dof(r2.steps.back(), 0.0, 0.0, 1) / (3 * P) == Approx(w0).epsilon(1e-6));
    CHECK(r2.steps.back().contact_count == s.contact_count);
}

TEST_CASE("The ring at small load matches linear ring theory plus the base spring", "[foundation][ring]") {
    // Castigliano for a ring pinched by two opposite loads P: δ = (π/4 − 2/π) P R³/EI
    // = 0.148778 P R³/EI. The base spring (1200 under the full ring) adds P/1200 in series.
    const Run r = ring(unilateral(1200.0), 0.005, 0.05);
    REQUIRE(r.summary.status == RunStatus::completed);
    const double flexibility = (M_PI / 4.0 - 2.0 / M_PI) * 1e6 / 1e3 + 1.0 / 1200.0;
    const StepResult& first = r.steps[1];
    // δ/R = 5e-5: geometric nonlinearity is below 1e-4; 50 chords of the half ring err by
    // O((π/50)²/12) ≈ 3e-4 on the bending flexibility.
    CHECK(first.load / first.control_displacement == Approx(1.0 / flexibility).epsilon(1e-3));
}

TEST_CASE("The ring converges as the penalty stiffness grows and stays stable up to 1e12", "[foundation][ring][contact]") {
    std::vector<double> loads;
    for (double ky : {1e2, 1e4, 1e6, 1e8, 1e12}) {
        const Run r = ring(unilateral(ky), 1.0, 40.0);
        INFO("ky = " << ky << ": " << r.summary.reason << ", iterations " << r.summary.iterations);
        // Completion means every step converged; contact changes may cut an increment.
        REQUIRE(r.summary.status == RunStatus::completed);
        loads.push_back(r.steps.back().load);
        for (const StepResult& s : r.steps) {
            // Vertical equilibrium of the half ring: the base carries the half-model load λ.
            CHECK(s.base_reaction == Approx(s.load_factor).epsilon(1e-6).margin(1e-12));
        }
    }
    INFO("P at δ = 40 for ky = 1e2, 1e4, 1e6, 1e8, 1e12: " << Catch::Detail::stringify(loads));
    // The penetration error falls like 1/ky: successive differences shrink.
    CHECK(std::abs(loads[2] - loads[1]) < std::abs(loads[1] - loads[0]));
    CHECK(std::abs(loads[3] - loads[2]) < std::abs(loads[2] - loads[1]) + 1e-9);
    CHECK(loads[4] == Approx(loads[3]).epsilon(1e-4));
}

TEST_CASE("A full ring without symmetry conditions gives the same curve as the half ring", "[foundation][ring]") {
    const Run half = ring(unilateral(1200.0), 1.0, 40.0);
    const Run full = run_scene(R"(
[scene]
name = "full_ring"
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
end_angle = 270.0
elements = 100
section = "s"
# Frictionless springs hold nothing horizontally: ux at the top and the bottom removes the
# rigid translation and rotation without constraining a symmetric deformation.
[[support]]
at = [0.0, 200.0]
fix = ["ux"]
[[support]]
at = [0.0, 0.0]
fix = ["ux"]
[[foundation]]
kind = "unilateral"
on = "ring"
ky = 1200.0
base_point = [0.0, 0.0]
[[load]]
at = [0.0, 200.0]
fy = -1.0
[analysis]
scheme = "displacement_control"
increment = 1.0
adaptive = false
control_at = [0.0, 200.0]
control_sign = -1.0
target_displacement = 40.0
)");
    REQUIRE(half.summary.status == RunStatus::completed);
    REQUIRE(full.summary.status == RunStatus::completed);
    REQUIRE(full.steps.size() == half.steps.size());
    for (std::size_t k = 1; k < half.steps.size(); k += 5) {
        CAPTURE(half.steps[k].control_displacement);
        CHECK(full.steps[k].load == Approx(half.steps[k].load).epsilon(1e-6));
    }
}

TEST_CASE("A tensionless bed follows the members' normals: a pipe in soil bears where it pushes outward", "[foundation][contact]") {
    // A straight beam from left to right: its left normal is +y, the default direction.
    const std::string beam = "[scene]\nname = \"bed\"\n[[material]]\nname = \"m\"\nE = 1.0\n[[section]]\nname = \"s\"\n"
                             "material = \"m\"\nA = 1e6\nI = 1.0\n[[line]]\nname = \"beam\"\nstart = [-5.0, 0.0]\nend = [5.0, 0.0]\n"
                             "elements = 20\nsection = \"s\"\n[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\"]\n"
                             "[[foundation]]\nkind = \"tensionless\"\non = \"beam\"\nky = 4.0\nper_length = true\n";
    const std::string loaded = "[[load]]\nat = [0.0, 0.0]\nfy = -1e-4\n[analysis]\nscheme = \"load_control\"\n"
                               "increment = 1.0\ntarget_load_factor = 1.0\nresidual_tolerance = 1e-8\n";
    const Run fixed = run_scene(beam + loaded);
    const Run normal = run_scene(beam + "direction = \"left_normal\"\n" + loaded);
    REQUIRE(fixed.summary.status == RunStatus::completed);
    REQUIRE(normal.summary.status == RunStatus::completed);
    CHECK(fixed.steps.back().displacement == normal.steps.back().displacement);

    // A ring of radius 1 in soil all round (the left normal of a counter-clockwise ring points to
    // its centre: the soil pushes inward), pressed down at its top: the crown moves in, away from
    // its soil, the invert and the springings move out into theirs. The bed carries the load.
    const Run pipe = run_scene(
        "[scene]\nname = \"pipe\"\n[[material]]\nname = \"m\"\nE = 1.0\n[[section]]\nname = \"s\"\nmaterial = \"m\"\n"
        "A = 1e4\nI = 1.0\n[[arc]]\nname = \"pipe\"\ncenter = [0.0, 0.0]\nradius = 1.0\nstart_angle = -90.0\nend_angle = 270.0\n"
        "elements = 48\nsection = \"s\"\n[[support]]\nat = [0.0, 1.0]\nfix = [\"ux\"]\n[[foundation]]\nkind = \"tensionless\"\n"
        "on = \"pipe\"\nky = 10.0\nper_length = true\ndirection = \"left_normal\"\n[[load]]\nat = [0.0, 1.0]\nfy = -1e-3\n"
        "[analysis]\nscheme = \"load_control\"\nincrement = 1.0\ntarget_load_factor = 1.0\nresidual_tolerance = 1e-9\n");
    REQUIRE(pipe.summary.status == RunStatus::completed);
    const StepResult& s = pipe.steps.back();
    double carried = 0.0;
    bool crown_free = false, invert_bears = false, sides_bear = false;
    for (const SpringResult& sp : s.springs) {
        carried += sp.force[1];
        const Node& n = pipe.model.nodes[sp.node];
        if (std::abs(n.x) < 1e-9 && n.y > 0.99) crown_free = !sp.active;
        if (std::abs(n.x) < 1e-9 && n.y < -0.99) invert_bears = sp.active;
        if (std::abs(n.y) < 1e-9) sides_bear = sp.active;
    }
    CHECK(carried == Approx(1e-3).epsilon(1e-6));
    CHECK(crown_free);
    CHECK(invert_bears);
    CHECK(sides_bear);
}

TEST_CASE("A ring between two plates, the upper one moving, is the headline ring while each plate touches one node", "[foundation][ring][contact]") {
    // The moving plate's penalty spring at the top node carries what the headline ring's point
    // load carries, so P against the top displacement is the same curve until the contact
    // spreads over the upper plate (near δ = 50 of 100).
    const Run headline = run_scene_file("models/ring_elastic.toml");
    const Run plates = run_scene_file("models/gallery/ring_between_plates.toml");
    REQUIRE(headline.summary.status == RunStatus::completed);
    REQUIRE(plates.summary.status == RunStatus::completed);
    auto load_at = [](const Run& r, double d) {
        return value_at(r.steps, d, [](const StepResult& s) { return s.control_displacement; }, [](const StepResult& s) { return s.load; });
    };
    for (double d : {1.0, 5.0, 10.0, 20.0, 30.0, 40.0}) {
        CAPTURE(d);
        CHECK(load_at(plates, d) == Approx(load_at(headline, d)).epsilon(1e-6));
    }
    // Balance at every step: the fixed plate carries what the moving one presses with (the
    // reported load is twice the half model's plate force; base_reaction sums both plates).
    for (const StepResult& r : plates.steps) CHECK(r.base_reaction == Approx(r.load).margin(1e-9).epsilon(1e-6));
    // Newton measures the residual against the platen's own force, so every step meets the
    // scene's tolerance, 1e-5 (against λ × the penalty stiffness none could: they passed by
    // stagnation, up to ten times the tolerance).
    for (std::size_t k = 1; k < plates.steps.size(); ++k) {
        CHECK(plates.steps[k].accepted_by != Acceptance::none);
        CHECK(plates.steps[k].residual <= 1e-5);
    }
    // The plate travel is the load factor; by its end the contact has spread to a second node on each plate.
    CHECK(plates.steps.back().load_factor == Approx(120.0));
    CHECK(plates.steps.back().contact_count >= 4); // two nodes on each plate
}

TEST_CASE("A contact whose force would stay within the undecided band keeps its state, beyond it the gap decides", "[foundation][contact]") {
    Model model;
    model.nodes.push_back({0.0, 0.0});
    model.bases.push_back(BaseLine{});
    FoundationSpring spring;
    spring.ky = 1e6;
    spring.unilateral = true;
    model.springs.push_back(spring);
    Foundation foundation(model);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(3);
    u[1] = -1e-6; // pressed in: closed
    foundation.evaluate(u, 0.0, false);
    REQUIRE(foundation.states()[0].active);
    // Lifted by 1e-8: a force of 0.01 if it stayed closed. Strictly the gap decides: it opens.
    u[1] = 1e-8;
    foundation.evaluate(u, 0.0, false);
    CHECK_FALSE(foundation.states()[0].active);
    CHECK(foundation.active_set_changed());
    // Closed again, then lifted by the same 1e-8 with a band of 0.02: it stays closed, and that
    // is consistent (open or closed, the residual differs by less than the band).
    u[1] = -1e-6;
    foundation.evaluate(u, 0.0, false);
    foundation.set_undecided_force(0.02);
    u[1] = 1e-8;
    foundation.evaluate(u, 0.0, false);
    CHECK(foundation.states()[0].active);
    CHECK_FALSE(foundation.active_set_changed());
    CHECK(foundation.active_set_consistent());
    // Lifted by 1e-7 (a force of 0.1): beyond the band, it opens.
    u[1] = 1e-7;
    foundation.evaluate(u, 0.0, false);
    CHECK_FALSE(foundation.states()[0].active);
    // Frozen closed at that gap: inconsistent.
    u[1] = -1e-6;
    foundation.evaluate(u, 0.0, false);
    u[1] = 1e-7;
    foundation.evaluate(u, 0.0, true);
    CHECK(foundation.states()[0].active);
    CHECK_FALSE(foundation.active_set_consistent());
}

TEST_CASE("A platen's travel is no load: negative pivots along it are counted, not a limit that stops the run", "[foundation][contact][plasticity]") {
    // A steel ring (R/h = 10, fibre sections) crushed by a platen under load control of its
    // travel, penalty 1.75e9. In 10 layers its tangent turns indefinite from travel 10.6 on; that
    // stopped the run as "limit load reached at 12.77" although the user prescribes the travel.
    std::string crush = crushed_ring(10.0, "scheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 16.0\n", "", 1.75e9);
    crush.insert(crush.find("plasticity = \"distributed\""), "fibres = 10\n");
    const Run r = run_scene(crush);
    INFO(r.summary.reason);
    CHECK(r.summary.status == RunStatus::completed);
    CHECK(r.summary.negative_pivot_steps > 10);
    CHECK(r.summary.first_negative_pivot_step > 0);
    int indefinite = 0;
    for (const StepResult& s : r.steps) indefinite += s.negative_pivots > 0;
    CHECK(indefinite == r.summary.negative_pivot_steps);
}
