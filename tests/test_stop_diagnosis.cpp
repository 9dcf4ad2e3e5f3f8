// The words a stopped run ends with (analysis/stop_diagnosis.hpp), from the facts alone: each
// cause named before the ones it would otherwise be taken for.
#include "analysis/stop_diagnosis.hpp"

#include <catch2/catch.hpp>

using namespace plastica;

namespace {
FailedStep diverged() {
    FailedStep f;
    f.step = 12;
    f.load_factor = 0.75;
    f.failure = NewtonFailure::diverged;
    f.increment = 1e-6;
    f.residual = 3e-3;
    f.tolerance = 1e-6;
    return f;
}
} // namespace

TEST_CASE("A stop names a non-finite state, then a mechanism, then a limit load", "[stop_diagnosis]") {
    FailedStep f = diverged();
    f.failure = NewtonFailure::non_finite;
    f.non_finite_where = "element 7 (nodes 7–8)";
    f.mechanism = "contact with the base was lost at 1 node ([0, 401])";
    f.limit = true;
    f.limit_evidence = "2 negative pivot(s)";
    const struct {
        RunStatus status;
        const char* reason;
    } expected[] = {
        {RunStatus::non_finite, "non-finite state in step 12 at element 7 (nodes 7–8)"},
        {RunStatus::no_convergence,
         "the structure became a mechanism in step 12 at load factor 0.75: contact with the base was lost at 1 node ([0, 401])"},
        {RunStatus::limit_load, "limit load reached at load factor 0.75 (2 negative pivot(s))"},
    };
    // Each cause in turn, the ones before it taken away.
    for (const auto& e : expected) {
        const StopReason s = diagnose_failed_step(f);
        CHECK(s.status == e.status);
        CHECK(s.reason == e.reason);
        if (f.failure == NewtonFailure::non_finite) f.failure = NewtonFailure::diverged;
        else f.mechanism.clear();
    }
}

TEST_CASE("A limit load of plastic hinges names where they are at capacity", "[stop_diagnosis]") {
    FailedStep f = diverged();
    f.limit = true;
    f.limit_evidence = "1 negative pivot(s)";
    f.plastic_sites = "[0, 4000], [4000, 4000], [8000, 4000]";
    CHECK(diagnose_failed_step(f).reason == "limit load reached at load factor 0.75 (1 negative pivot(s)): a plastic "
                                             "mechanism, hinges at capacity at [0, 4000], [4000, 4000], [8000, 4000]");
}

TEST_CASE("No convergence says how far the increment was cut and what round-off allows", "[stop_diagnosis]") {
    FailedStep f = diverged();
    CHECK(diagnose_failed_step(f).reason ==
          "no convergence in step 12 at load factor 0.75 (diverged with the increment cut to 1e-06; the residual "
          "ended at 0.003 of the load, residual_tolerance 1e-06)");
    // A floor far above the tolerance: no cut can help, and the springs are to blame.
    f.hopeless = true;
    f.floor = {5e-4, 4e-4, 1.0};
    const std::string springs = diagnose_failed_step(f).reason;
    CHECK_THAT(springs, Catch::Contains("(diverged, no smaller increment can help;") &&
                            Catch::Contains("round-off alone leaves about 0.0005 of the load out of balance") &&
                            Catch::Contains("the foundation's penalty stiffness: lower it"));
    // The elements' own stiffness.
    f.floor = {5e-4, 1e-5, 1.0};
    CHECK_THAT(diagnose_failed_step(f).reason, Catch::Contains("use fewer or longer elements"));
    // A tolerance that follows the floor is never below it: no advice.
    f.tolerance_follows_floor = true;
    CHECK_THAT(diagnose_failed_step(f).reason, !Catch::Contains("round-off"));
    // A floor far below the tolerance is not the cause.
    f.tolerance_follows_floor = false;
    f.floor = {1e-9, 0.0, 1.0};
    CHECK_THAT(diagnose_failed_step(f).reason, !Catch::Contains("round-off"));
}

TEST_CASE("A step that fails with its residual within the tolerance names the criterion that failed", "[stop_diagnosis]") {
    // The words agree with the verdict: a residual below residual_tolerance is never quoted as
    // the reason (a crushed pipe stopped "with the residual at 3.5e-09, tolerance 1e-06").
    FailedStep f = diverged();
    f.residual = 3.5e-9;
    f.correction_ratio = 0.02;
    f.displacement_tolerance = 1e-8;
    f.floor = {5e-4, 1e-5, 1.0}; // no round-off advice for a residual that was met
    CHECK(diagnose_failed_step(f).reason ==
          "no convergence in step 12 at load factor 0.75 (diverged with the increment cut to 1e-06; the residual "
          "ended at 3.5e-09 of the load, within residual_tolerance 1e-06, but the corrections stayed at 0.02 of the "
          "increment, above displacement_tolerance 1e-08)");
    f.settled = false;
    CHECK(diagnose_failed_step(f).reason ==
          "no convergence in step 12 at load factor 0.75 (diverged with the increment cut to 1e-06; the residual "
          "ended at 3.5e-09 of the load, within residual_tolerance 1e-06, but contact, hinges or fibres kept changing "
          "state between iterations)");
}
