// A followed path is the structure's, or the run stops and says why: the peak is the first
// limit point, never a higher load met on another branch, and an arc that turns back stops.
#include "analysis/path_watch.hpp"
#include "analysis_helpers.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace plastica;
using plastica::testing::Run;
using plastica::testing::run_scene;

namespace {

// A pinned 12 m HEB 300 column in S355 with refined hinges on 12 elements, bowed L/1000 in its
// first mode, pressed at its top and reported at mid-height along x.
std::string hinged_column(const std::string& analysis) {
    return R"(
[scene]
name = "column"
[units]
length = "m"
force = "kN"
[[material]]
name = "S355"
E = 2.1e8
fy = 3.55e5
[[section]]
name = "HEB300"
material = "S355"
profile = "HEB 300"
plasticity = "hinges"
[[line]]
start = [0.0, 0.0]
end = [0.0, 12.0]
elements = 12
section = "HEB300"
[[support]]
at = [0.0, 0.0]
fix = ["ux", "uy"]
[[support]]
at = [0.0, 12.0]
fix = ["ux"]
[[load]]
at = [0.0, 12.0]
fy = -1.0
[[imperfection]]
mode = 1
amplitude = 0.012
[analysis]
control_at = [0.0, 6.0]
control_dof = "ux"
max_steps = 2000
)" + analysis;
}

// The largest load before the path passed its first limit point.
double peak_of(const Run& p) {
    double peak = 0.0;
    for (const StepResult& r : p.steps)
        if (!r.past_first_limit) peak = std::max(peak, r.load);
    return peak;
}

} // namespace

TEST_CASE("An arc-length column reports its first limit point as its peak, not the higher load it meets folded") {
    // Displacement control in steps of 2 mm resolves the peak to 1e-4 (its curvature over one
    // step): the reference.
    const Run reference = run_scene(hinged_column("scheme = \"displacement_control\"\nincrement = 0.002\ntarget_displacement = 0.3\n"));
    REQUIRE(reference.summary.status == RunStatus::completed);
    const double capacity = peak_of(reference);
    for (const double increment : {0.05, 0.2, 0.5}) {
        CAPTURE(increment);
        const Run arc = run_scene(hinged_column("scheme = \"arc_length\"\nincrement = " + std::to_string(increment) +
                                              "\ntarget_displacement = 8.0\n"));
        // The steps near the peak are the arc's own (0.2 m of the column's motion for the middle
        // one): within 1 % of the peak's load.
        CHECK(peak_of(arc) == Approx(capacity).epsilon(0.01));
        // Folded as far as its halves allow (5.9 m at mid-height), the column folds on below its
        // base pin and its load rises far above the capacity: those steps are marked.
        bool above = false;
        for (const StepResult& r : arc.steps) {
            if (r.load > 1.05 * capacity) CHECK(r.past_first_limit);
            above = above || r.load > 1.05 * capacity;
        }
        if (increment == 0.2) CHECK(above);
    }
}

TEST_CASE("The path watch finds the first limit point, not a sawtooth, and keeps it past a higher load") {
    SECTION("a sawtooth of 3 % is no limit point") {
        PathWatch w;
        w.begin_stage(true, 1.0, 0.0);
        for (int k = 1; k <= 20; ++k) w.note(k, k % 2 ? 1.0 * k : 0.97 * k);
        CHECK(!w.past_first_limit());
    }
    SECTION("a snap-through's limit stays the first one when the load later rises higher") {
        PathWatch w;
        w.begin_stage(true, 1.0, 0.0);
        const double lambda[] = {0.5, 1.0, 1.8, 1.75, 1.0, -0.5, 0.2, 1.0, 2.5, 4.0};
        for (int k = 0; k < 10; ++k) w.note(k + 1, lambda[k]);
        CHECK(w.past_first_limit());
        CHECK(w.limit_step() == 3);
        CHECK(w.limit_load_factor() == 1.8);
    }
    SECTION("a stage that unloads by design is not watched; one loaded the other way is") {
        PathWatch w;
        w.begin_stage(false, 1.0, 2.0);
        for (int k = 1; k <= 5; ++k) w.note(k, 2.0 - 0.4 * k);
        CHECK(!w.past_first_limit());
        w.begin_stage(true, -1.0, 0.0);
        w.note(6, -1.0);
        w.note(7, -2.0);
        w.note(8, -1.5);
        CHECK(w.past_first_limit());
        CHECK(w.limit_load_factor() == -2.0);
    }
}

namespace {

// A pinned 10 m column of E = 2.1e11, I = 1e-4, A = 0.01 (slender: EA/P_E = 1000) on n elements,
// loaded by its Euler load π²EI/L² times λ, straight or bowed in its first mode.
std::string euler_column(int elements, double increment, const std::string& extra = "") {
    return R"(
[scene]
name = "column"
[[material]]
name = "m"
E = 2.1e11
[[section]]
name = "s"
material = "m"
A = 0.01
I = 1.0e-4
[[line]]
start = [0.0, 0.0]
end = [0.0, 10.0]
elements = )" + std::to_string(elements) + R"(
section = "s"
[[support]]
at = [0.0, 0.0]
fix = ["ux", "uy"]
[[support]]
at = [0.0, 10.0]
fix = ["ux"]
[[load]]
at = [0.0, 10.0]
fy = -2072616.9242287652
[analysis]
scheme = "load_control"
increment = )" + std::to_string(increment) + "\ntarget_load_factor = 1.3\ncontrol_at = [0.0, 10.0]\ncontrol_dof = \"uy\"\n" + extra;
}

} // namespace

TEST_CASE("A perfect column's bifurcation is located under any load step, once, and published as one step") {
    // The members carry their axial force's geometric stiffness on their chords, so the discrete
    // column bifurcates above Euler's load, by 1.39, 0.42 and 0.18 % on 8, 16 and 32 elements
    // (as measured; the path's own bifurcation, whatever the step, is what is checked to 1e-4).
    const std::vector<std::pair<int, double>> meshes = {{8, 1.0139}, {16, 1.0042}, {32, 1.0018}};
    for (const auto& [elements, bifurcation] : meshes)
        for (const double increment : {0.02, 0.05, 0.1, 0.15, 0.2}) {
            CAPTURE(elements, increment);
            const Run run = run_scene(euler_column(elements, increment));
            REQUIRE(run.summary.critical_points.size() == 1);
            const CriticalPoint& c = run.summary.critical_points.front();
            CHECK(c.kind == CriticalKind::bifurcation);
            CHECK(c.load_factor == Approx(bifurcation).epsilon(1e-4));
            CHECK(c.load_factor == Approx(1.0).epsilon(0.015));
            // No load factor is published twice (a landing taken again on the spot).
            for (std::size_t k = 1; k < run.steps.size(); ++k) CHECK(run.steps[k].load_factor != run.steps[k - 1].load_factor);
        }
}

TEST_CASE("A bowed column under load control follows its stable buckled path, not a branch a step lands on") {
    // Bowed by L/10 000 and loaded past its buckling load in steps of 0.05 or 0.2: a step across
    // λ = 1 converged onto the complementary branch (the bow reversed, nearly straight, unstable)
    // and the run ended there at 1.3 P_E. Steps that leave the path's tangent by more than 45°
    // are cut instead. At P = 1.3 P_E the elastica shortens by 0.4474 L (K(k) = 1.7910,
    // k = 0.64736); the discrete column's 0.42 % higher buckling load takes about 1 % off that.
    for (const double increment : {0.05, 0.2}) {
        CAPTURE(increment);
        const Run run = run_scene(euler_column(16, increment, "[[imperfection]]\nmode = 1\namplitude = 0.001\n"));
        REQUIRE(run.summary.status == RunStatus::completed);
        const StepResult& last = run.steps.back();
        CHECK(last.load_factor == Approx(1.3));
        CHECK(last.negative_pivots == 0);
        CHECK(std::abs(last.control_displacement) == Approx(0.4474 * 10.0).epsilon(0.02));
        CHECK(run.summary.critical_points.empty());
    }
}

namespace {
// The HEB 300 column of hinged_column with another formulation, length and bow.
std::string column_variant(const std::string& plasticity, double length, double bow, const std::string& analysis) {
    std::string text = hinged_column(analysis);
    const auto swap = [&](const std::string& from, const std::string& to) { text.replace(text.find(from), from.size(), to); };
    swap("plasticity = \"hinges\"", plasticity);
    swap("end = [0.0, 12.0]", "end = [0.0, " + std::to_string(length) + "]");
    swap("[[support]]\nat = [0.0, 12.0]", "[[support]]\nat = [0.0, " + std::to_string(length) + "]");
    swap("[[load]]\nat = [0.0, 12.0]", "[[load]]\nat = [0.0, " + std::to_string(length) + "]");
    swap("amplitude = 0.012", "amplitude = " + std::to_string(bow));
    swap("control_at = [0.0, 6.0]", "control_at = [0.0, " + std::to_string(length / 2.0) + "]");
    return text;
}
} // namespace

TEST_CASE("Yielding columns reach their displacement-controlled capacity under arc length and load control") {
    // Force-based fibre members under arc length: the first arc (L/60 of motion) leapt to the
    // squashed straight column, eleven pivots at once, and climbed to 5 470 kN, 1.8 × the capacity.
    // Displacement-based ones under load control in steps of 250 kN: a step past the capacity
    // landed on the column crushed through its own length and inverted, "completed" at 20 000 kN.
    struct Case {
        const char* plasticity;
        double length, bow;
        std::string scheme;
    };
    const std::string distributed = "plasticity = \"distributed\"\nformulation = ";
    const std::vector<Case> cases = {
        {"force", 12.0, 0.012, "scheme = \"arc_length\"\nincrement = 0.2\ntarget_displacement = 0.3\n"},
        {"force", 18.0, 0.018, "scheme = \"arc_length\"\nincrement = 0.3\ntarget_displacement = 0.45\n"},
        {"displacement", 3.0, 0.0006, "scheme = \"load_control\"\nincrement = 250.0\ntarget_load_factor = 20000.0\n"},
        // A load step past the buckling load onto the straight column, two pivots negative, at 5 266 kN.
        {"displacement", 18.0, 0.0036, "scheme = \"load_control\"\nincrement = 250.0\ntarget_load_factor = 20000.0\n"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.plasticity, c.length, c.scheme);
        const std::string formulation = distributed + "\"" + c.plasticity + "\"";
        const double target = c.length / 40.0;
        const Run reference = run_scene(column_variant(formulation, c.length, c.bow,
                                                       "scheme = \"displacement_control\"\nincrement = " + std::to_string(c.length / 6000.0) +
                                                           "\ntarget_displacement = " + std::to_string(target) + "\n"));
        REQUIRE(reference.summary.status == RunStatus::completed);
        const Run run = run_scene(column_variant(formulation, c.length, c.bow, c.scheme));
        CHECK(run.summary.status != RunStatus::non_finite);
        // Each step of the path's own size lands within 1 % of the peak it resolves.
        CHECK(peak_of(run) == Approx(peak_of(reference)).epsilon(0.01));
        for (const StepResult& r : run.steps) CHECK(r.load <= 1.01 * peak_of(reference));
    }
}
