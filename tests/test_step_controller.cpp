// The increment rules of analysis/step_controller.hpp on their own: landing on a target,
// halving after a failure, retaking a step that carried a hinge too far, adapting toward the
// desired iteration count, and recovering after cuts with fixed increments.
#include "analysis/step_controller.hpp"

#include <catch2/catch.hpp>

using namespace plastica;

namespace {
NewtonResult converged_in(int iterations, double contraction = 0.5) {
    NewtonResult r;
    r.iterations = iterations;
    r.contraction = contraction;
    return r;
}
} // namespace

TEST_CASE("An increment lands on the target instead of passing it", "[step_controller]") {
    CHECK(StepController::landing(0.5, 2.0) == 0.5);
    CHECK(StepController::landing(0.5, 0.2) == 0.2);
    CHECK(StepController::landing(-0.5, -0.1) == -0.1); // a stage going back
    CHECK(StepController::landing(0.5, -0.1) == -0.1);  // already past it: back onto it
}

TEST_CASE("Adaptive increments follow the iteration count within half and double", "[step_controller]") {
    AnalysisSpec a;
    a.desired_iterations = 5;
    StepController c;
    // √(5/20) = 0.5; √(5/5) = 1; √(5/1) is capped at 2.
    CHECK(c.after_success(a, 0.1, 0.1, converged_in(20), 0.0) == Approx(0.05));
    CHECK(c.after_success(a, 0.1, 0.1, converged_in(5), 0.0) == Approx(0.1));
    CHECK(c.after_success(a, 0.1, 0.1, converged_in(1), 0.0) == Approx(0.2));
    CHECK(c.after_success(a, 0.1, 0.1, converged_in(80), 0.0) == Approx(0.05));
    // Iterations spent re-deciding settled states do not count.
    NewtonResult settling = converged_in(20);
    settling.iterations_before_settling = 5;
    CHECK(c.after_success(a, 0.1, 0.1, settling, 0.0) == Approx(0.1));
    // A last iteration that still contracted tenfold was inside Newton's basin: no shrinking.
    CHECK(c.after_success(a, 0.1, 0.1, converged_in(20, 0.05), 0.0) == Approx(0.1));
    // A hinge carried 0.1 into its yielding range: at most 0.05/0.1 of the increment.
    CHECK(c.after_success(a, 0.1, 0.1, converged_in(1), 0.1) == Approx(0.05));
    // The sign follows the increment; the cap holds.
    CHECK(c.after_success(a, -0.1, -0.1, converged_in(5), 0.0) == Approx(-0.1));
    a.max_increment = 0.15;
    CHECK(c.after_success(a, 0.1, 0.1, converged_in(1), 0.0) == Approx(0.15));
    // A landing step shorter than the increment does not shrink the next one.
    a.max_increment = 0.0;
    CHECK(c.after_success(a, 0.1, 0.02, converged_in(5), 0.0) == Approx(0.1));
}

TEST_CASE("Fixed increments are halved on failure and recover after three steps", "[step_controller]") {
    AnalysisSpec a;
    a.adaptive = false;
    a.initial_increment = 0.4;
    StepController c;
    double h = c.after_failure(0.4);
    CHECK(h == Approx(0.2));
    CHECK(c.after_success(a, h, h, converged_in(3), 0.0) == Approx(0.2));
    CHECK(c.after_success(a, h, h, converged_in(3), 0.0) == Approx(0.2));
    h = c.after_success(a, h, h, converged_in(3), 0.0); // the third step at 0.2: back up
    CHECK(h == Approx(0.4));
    CHECK(c.after_success(a, h, h, converged_in(3), 0.0) == Approx(0.4)); // never past the given one
    // After a recovery the count starts again: two cuts need three steps at each level.
    h = c.after_failure(c.after_failure(0.4));
    CHECK(h == Approx(0.1));
    for (int k = 0; k < 2; ++k) CHECK(c.after_success(a, h, h, converged_in(3), 0.0) == Approx(0.1));
    h = c.after_success(a, h, h, converged_in(3), 0.0);
    CHECK(h == Approx(0.2));
    for (int k = 0; k < 2; ++k) CHECK(c.after_success(a, h, h, converged_in(3), 0.0) == Approx(0.2));
    CHECK(c.after_success(a, h, h, converged_in(3), 0.0) == Approx(0.4));
}

TEST_CASE("A step that carried a hinge too far is taken again smaller unless the advance is a jump", "[step_controller]") {
    StepController c;
    // 0.1 into the yielding range: again at 0.9·0.05/0.1 = 0.45 of the increment.
    CHECK(c.refined(0.1, 0.1, 1e-8) == Approx(0.045));
    // Taken again smaller it carried the section as far (0.095 ≥ 0.9·0.1): a jump, kept.
    CHECK(c.refined(0.045, 0.095, 1e-8) == 0.0);
    // Far past the range: no less than a quarter.
    CHECK(c.refined(0.1, 10.0, 1e-8) == Approx(0.025));
    // Within the range, or an increment already at the smallest: kept.
    CHECK(c.refined(0.1, 0.04, 1e-8) == 0.0);
    CHECK(c.refined(1e-8, 0.2, 1e-8) == 0.0);
}
