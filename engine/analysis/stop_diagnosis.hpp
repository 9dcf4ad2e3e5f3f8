// Why a run stops where an increment cannot be found at any size: a non-finite state, a
// mechanism (contact lost), a limit load, or no convergence, with what the user can do about
// it (the round-off floor of a stiff model and where it comes from). The facts are gathered by
// path_limits.cpp; the words are chosen here.
#pragma once

#include "analysis/step_result.hpp"
#include "analysis/structural_system.hpp"
#include "solver/newton_solver.hpp"

#include <string>

namespace plastica {

struct FailedStep {
    int step = 0;             // the step that failed (1 for the first)
    double load_factor = 0.0; // at the last converged step
    NewtonFailure failure = NewtonFailure::none;
    std::string non_finite_where; // the element, for a non-finite state
    std::string mechanism;        // the rigid motion that contact lost left free, in words
    bool limit = false;           // the tangent shows a limit point (load control of forces)
    std::string limit_evidence;   // how it shows it
    std::string plastic_sites;    // where hinges are at capacity (a plastic mechanism)
    bool hopeless = false;        // the round-off floor is far above the tolerance: no cut can help
    double increment = 0.0;       // the increment it was cut to
    double residual = 0.0;        // relative, where Newton ended
    double tolerance = 0.0;       // the residual tolerance
    double correction_ratio = 0.0; // the last correction over the increment, where Newton ended
    double displacement_tolerance = 0.0;
    bool settled = true;          // the active sets agreed with the state where Newton ended
    bool tolerance_follows_floor = false;
    RoundOffFloor floor;          // at the failed state
    // Displacement control with the members' surfaces pressed together at the last converged
    // state: the controlled point may be unable to move on (a flattened ring's walls met).
    bool controlled_through_contact = false;
};

struct StopReason {
    RunStatus status = RunStatus::no_convergence;
    std::string reason;
};

StopReason diagnose_failed_step(const FailedStep& f);

} // namespace plastica
