// Path-following solver properties: quadratic convergence of Newton near the solution, and
// stops with the last converged state kept.
#include "analysis_helpers.hpp"

#include <catch2/catch.hpp>

using namespace plastica;
using namespace plastica::testing;

TEST_CASE("Newton converges quadratically near a solution", "[solver]") {
    // One load step to PL²/EI = 1 on a 10-element elastica: several iterations to watch.
    const Run r = run_scene(cantilever(1.0, 10, 1.0, 1e2, 1.0, "[[load]]\nat = [1.0, 0.0]\nfy = -1.0\n",
                                       "scheme = \"load_control\"\nincrement = 1.0\ntarget_load_factor = 1.0\n"
                                       "residual_tolerance = 1e-10\ndisplacement_tolerance = 1e-12\nmax_iterations = 40\n"));
    REQUIRE(r.summary.status == RunStatus::completed);
    std::vector<double> res;
    for (const IterationTrace& t : r.trace) res.push_back(t.residual);
    INFO("residuals: " << Catch::Detail::stringify(res));
    // In the tail (residual between 1e-2 and 1e-5, next one above the round-off floor; EA·L²/EI = 100
    // keeps the constant of the quadratic rate modest) each iteration squares the residual, up to a modest constant.
    int quadratic_pairs = 0;
    for (std::size_t k = 2; k < res.size(); ++k) {
        if (res[k - 1] < 1e-2 && res[k - 1] > 1e-5 && res[k] > 1e-9) {
            CHECK(res[k] < 10.0 * res[k - 1] * res[k - 1]);
            ++quadratic_pairs;
        }
    }
    CHECK(quadratic_pairs >= 1);
}

TEST_CASE("A load beyond a softening mechanism stops with 'limit load reached' and keeps the converged steps", "[solver][plasticity]") {
    // A clamped column, axial load P and lateral load 0.1 P: the base hinge forms near
    // 0.1·P·L = Mp, then P-Δ makes the sway mechanism soften, so load control cannot go on.
    // fy/E = 1.25e-6 keeps the first-order collapse load 10 Mp/L = 2500 a close upper bound.
    const std::string scene = R"(
[scene]
name = "collapse"
[[material]]
name = "steel"
E = 2.0e8
fy = 250.0
[[section]]
name = "s"
material = "steel"
shape = "rectangle"
b = 10.0
h = 20.0
fibres = 10
[[line]]
start = [0.0, 0.0]
end = [0.0, 1000.0]
elements = 8
section = "s"
[[support]]
at = [0.0, 0.0]
fix = ["ux", "uy", "rz"]
[[load]]
at = [0.0, 1000.0]
fy = -1000.0
fx = 100.0
[analysis]
scheme = "load_control"
increment = 0.1
target_load_factor = 4.0
)";
    const Run r = run_scene(scene);
    CHECK(r.summary.status == RunStatus::limit_load);
    CHECK_THAT(r.summary.reason, Catch::Contains("limit load reached"));
    REQUIRE(r.steps.size() > 1);
    for (const StepResult& s : r.steps) CHECK(std::isfinite(s.load));
    const double collapse = 2.5; // λ at 0.1·P·L = Mp
    CHECK(r.steps.back().load_factor <= collapse);
    CHECK(r.steps.back().load_factor >= 0.97 * collapse);
}
