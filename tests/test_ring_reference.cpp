// The three shipped ring scenes against their stored reference values (tests/reference/
// ring_curves.csv), and plastic hinges that do not flicker: an end leaves the capacity surface
// only when its moment falls.
#include "analysis_helpers.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <sstream>

using namespace plastica;
using namespace plastica::testing;

namespace {

std::string source(const std::string& relative) { return std::string(PLASTICA_SOURCE_DIR) + "/" + relative; }


double load_at(const std::vector<StepResult>& steps, double d) {
    for (std::size_t k = 1; k < steps.size(); ++k) {
        const double a = steps[k - 1].control_displacement, b = steps[k].control_displacement;
        if (a <= d && d <= b && b > a) return steps[k - 1].load + (d - a) / (b - a) * (steps[k].load - steps[k - 1].load);
    }
    return NAN;
}

// Reference curves of a CSV file with columns scene,displacement,load ('#' comments).
std::map<std::string, std::vector<std::pair<double, double>>> stored_curves(const std::string& relative) {
    std::ifstream in(source(relative));
    std::map<std::string, std::vector<std::pair<double, double>>> reference;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#' || line.rfind("scene,", 0) == 0) continue;
        std::stringstream row(line);
        std::string scene, d, p;
        std::getline(row, scene, ',');
        std::getline(row, d, ',');
        std::getline(row, p, ',');
        reference[scene].push_back({std::stod(d), std::stod(p)});
    }
    return reference;
}

} // namespace

TEST_CASE("The shipped rings stay within 0.1 % of their stored curves", "[ring][reference]") {
    const auto reference = stored_curves("tests/reference/ring_curves.csv");
    REQUIRE(reference.size() == 3);
    for (const auto& [scene, points] : reference) {
        const Run r = run_scene_file("models/" + scene + ".toml");
        REQUIRE(r.summary.status == RunStatus::completed);
        for (const auto& [d, p] : points) {
            CAPTURE(scene, d);
            // The elastic scenes are unchanged to round-off; the inelastic ring's hinges at
            // capacity follow the smooth N–M curve with axial flow (0.045 % at δ = 100).
            CHECK(load_at(r.steps, d) == Approx(p).epsilon(scene == "ring_inelastic" ? 1e-3 : 1e-9));
        }
    }
}

TEST_CASE("The distributed-plasticity ring: its stored curve, and within 0.5 % of the converged one", "[ring][reference][distributed]") {
    const auto reference = stored_curves("tests/reference/ring_distributed.csv");
    REQUIRE(reference.count("ring_distributed"));
    REQUIRE(reference.count("ring_distributed_converged"));
    const Run r = run_scene_file("models/ring_distributed.toml");
    REQUIRE(r.summary.status == RunStatus::completed);
    // Pinned: Newton accepts residuals of 1e-5 of the load, so builds that round differently
    // may move the accepted states by about that much, not more.
    for (const auto& [d, p] : reference.at("ring_distributed")) {
        CAPTURE(d);
        CHECK(load_at(r.steps, d) == Approx(p).epsilon(1e-4));
    }
    // The discretisation error of the shipped scene (50 elements of 4 segments) against the
    // converged curve: second order before yield (0.09 % at δ = 5 … 40), first order in the
    // element length once plastic zones spread (0.25 % at δ = 100, 0.34 % at δ = 90): within
    // 0.5 % everywhere. The plain element (one segment, 3 points) was 1.3 % high at δ = 100.
    for (const auto& [d, p] : reference.at("ring_distributed_converged")) {
        CAPTURE(d);
        CHECK(std::abs(load_at(r.steps, d) / p - 1.0) <= 5e-3);
    }
}

TEST_CASE("Hinge states do not flicker: an end leaves the capacity only when its moment falls", "[ring][plasticity]") {
    for (const char* scene : {"models/ring_inelastic.toml", "models/gallery/portal_frame.toml"}) {
        const Run r = run_scene_file(scene);
        REQUIRE(r.summary.status == RunStatus::completed);
        int reversals = 0, unloadings = 0;
        for (std::size_t k = 1; k < r.steps.size(); ++k)
            for (std::size_t e = 0; e < r.steps[k].elements.size(); ++e)
                for (int end = 0; end < 2; ++end) {
                    const HingeReport& before = r.steps[k - 1].elements[e].hinge[end];
                    const HingeReport& now = r.steps[k].elements[e].hinge[end];
                    if (before.state != HingeState::plastic || now.state == HingeState::plastic) continue;
                    const BeamForces& fb = r.steps[k - 1].elements[e].forces;
                    const BeamForces& fn = r.steps[k].elements[e].forces;
                    const double mb = std::abs(end == 0 ? fb.moment_i : fb.moment_j);
                    const double mn = std::abs(end == 0 ? fn.moment_i : fn.moment_j);
                    if (mn < mb) ++unloadings; // left the surface by unloading: allowed
                    else ++reversals;
                }
        CAPTURE(scene, unloadings);
        CHECK(reversals == 0);
    }
}

TEST_CASE("The elastic ring's steps converge in two corrections from the extrapolated start", "[ring][newton]") {
    // The extrapolated start leaves a residual of about 50 times the load in the membrane; with the
    // path's axial forces in the first tangent the first correction lands at round-off, and the
    // second only confirms it (179 of 200 steps; the others are the steps where nodes meet the
    // base). With the start's own axial forces in that tangent, 54 of 200 steps did.
    const Run r = run_scene_file("models/ring_elastic.toml");
    REQUIRE(r.summary.status == RunStatus::completed);
    int in_two = 0;
    for (const StepResult& s : r.steps) in_two += s.step > 0 && s.iterations <= 2;
    CHECK(in_two >= 170);
}
