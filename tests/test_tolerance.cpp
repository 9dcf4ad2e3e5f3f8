// The default residual tolerance follows the model's round-off floor: every mesh of the elastic
// ring and penalties up to 1e12 complete with the defaults, converging to the same curve; an
// explicit tolerance is honoured as given (engine/solver/newton_solver.hpp).
#include "analysis_helpers.hpp"

#include <catch2/catch.hpp>

using namespace plastica;
using namespace plastica::testing;

namespace {

// models/ring_elastic.toml without its residual_tolerance: the defaults.
std::string ring_with_defaults(int elements, const std::string& ky, const std::string& tolerance = "") {
    std::string text = scene_file_text("models/ring_elastic.toml");
    const auto line = text.find("residual_tolerance");
    REQUIRE(line != std::string::npos);
    text.erase(line, text.find('\n', line) - line + 1);
    auto replace = [&](const std::string& from, const std::string& to) {
        const auto at = text.find(from);
        REQUIRE(at != std::string::npos);
        text.replace(at, from.size(), to);
    };
    replace("elements = 50", "elements = " + std::to_string(elements));
    replace("ky = 1200.0", "ky = " + ky);
    if (!tolerance.empty()) replace("[analysis]\n", "[analysis]\nresidual_tolerance = " + tolerance + "\n");
    return text;
}

} // namespace

TEST_CASE("The elastic ring completes on 10 to 400 elements and penalties to 1e12 with the default tolerance", "[tolerance][ring][contact]") {
    // With a fixed 1e-6 the 200- and 400-element rings stopped in steps 1 and 2 and a penalty of
    // 1.2e12 at δ = 58: their round-off floors (eps·|K|·|u| over the load) lie at 2e-4 to 1e-2.
    std::vector<double> at_100;
    for (int n : {10, 50, 200, 400}) {
        const Run r = run_scene(ring_with_defaults(n, "1200.0"));
        INFO(n << " elements: " << r.summary.reason);
        REQUIRE(r.summary.status == RunStatus::completed);
        CHECK(r.steps.back().control_displacement == Approx(100.0));
        at_100.push_back(r.steps.back().load);
        // Equilibrium within the tolerance used: the base carries the half-model load.
        for (const StepResult& s : r.steps) CHECK(s.base_reaction == Approx(s.load_factor).epsilon(1e-3).margin(1e-12));
    }
    // The curve converges with the mesh as with a tight tolerance (docs/studies.md: 200 elements
    // 0.008 % from 400 at δ = 100): 0.4811, 0.47294, 0.47276, 0.47273.
    INFO("P(100) on 10, 50, 200, 400 elements: " << Catch::Detail::stringify(at_100));
    CHECK(std::abs(at_100[3] - at_100[2]) < 0.25 * std::abs(at_100[2] - at_100[1]));
    CHECK(std::abs(at_100[2] - at_100[1]) < 0.05 * std::abs(at_100[1] - at_100[0]));
    CHECK(at_100[3] == Approx(at_100[2]).epsilon(1.5e-4));

    // Penalties 1.2e8, 1.2e10, 1.2e12: the same curve (the penetration is below 1e-6 of δ).
    std::vector<double> stiff;
    for (const char* ky : {"1.2e8", "1.2e10", "1.2e12"}) {
        const Run r = run_scene(ring_with_defaults(50, ky));
        INFO("ky = " << ky << ": " << r.summary.reason);
        REQUIRE(r.summary.status == RunStatus::completed);
        stiff.push_back(r.steps.back().load);
    }
    CHECK(stiff[1] == Approx(stiff[0]).epsilon(1e-6));
    CHECK(stiff[2] == Approx(stiff[0]).epsilon(1e-6));
}

TEST_CASE("An explicit residual tolerance is honoured, and a floor above it stops the run with the reason", "[tolerance][ring]") {
    const Run r = run_scene(ring_with_defaults(400, "1200.0", "1e-6"));
    CHECK(r.summary.status == RunStatus::no_convergence);
    CHECK_THAT(r.summary.reason, Catch::Contains("round-off alone leaves about"));
    CHECK(r.summary.largest_residual_tolerance <= 1e-6);
}
