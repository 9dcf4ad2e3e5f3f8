// Incremental-iterative path following of R(u, λ) = F_held + λ·F − f_int(u) = 0 (prescribed
// displacements scale with λ too), λ the factor of the load pattern the stage drives. One Newton corrector serves three constraints on the
// increment: load control (Δλ fixed), displacement control of one DOF (Batoz & Dhatt), and
// Crisfield's cylindrical arc length ‖Δu‖ = Δl with the root nearest the previous direction.
// Increments adapt to the iteration count; a failed increment is reverted and halved.
#pragma once

#include "analysis/path_extrapolation.hpp"
#include "analysis/step_controller.hpp"
#include "analysis/step_result.hpp"
#include "analysis/structural_system.hpp"
#include "model/model.hpp"
#include "solver/linear_solver.hpp"
#include "solver/newton_solver.hpp"

#include <atomic>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace plastica {

// Takes each converged step (and the unloaded state as step 0). One that throws ends the run
// with RunStatus::output_failed; it must leave its output as it was before that step.
using StepObserver = std::function<void(const StepResult&)>;

struct RunControl {
    const std::atomic<bool>* interrupt = nullptr; // set from a signal handler to stop cleanly
    // Unilateral springs keep their active set after this many iterations of one increment,
    // then the set is re-checked at convergence (remedy for chattering).
    int freeze_active_after = 12;
    // Hinge states (loading or unloading ends, active capacity sides) are decided by the
    // predictor and first correction, then kept until equilibrium, re-checked there and
    // re-decided if the state contradicts them (no cycling of a kink inside Newton).
    int freeze_hinges_after = 1000;
    // Fibre branches of distributed plasticity (elastic or yielding) are kept from this
    // iteration on, re-checked at equilibrium and re-decided where contradicted: without it
    // fibres flip between yielding and unloading from one iteration to the next.
    int freeze_fibres_after = 3;
    // Each step's result lists the sections along members with distributed plasticity (their
    // yielded share, curvature, moment): a series draws them, a curve does not need them, and
    // scanning every fibre for them costs 5 % of a plastic-zone run.
    bool report_sections = true;
};

// Per-iteration record for solver diagnostics (quadratic convergence checks).
struct IterationTrace {
    int step = 0;
    int iteration = 0;
    double residual = 0.0; // relative
};

class PathFollowing {
public:
    explicit PathFollowing(const Model& model);

    // Runs to the target or a stop; a model larger than the memory the process may have stops
    // with out_of_memory, its converged steps published.
    RunSummary run(const std::vector<StepObserver>& observers, const RunControl& control = {});
    // Empty when the unloaded structure is stable; otherwise names the DOF that is free
    // (a mechanism before loading, e.g. a missing support).
    std::string initial_mechanism();

    const StructuralSystem& system() const { return system_; }
    const std::vector<IterationTrace>& trace() const { return trace_; }

private:
    RunSummary run_steps(const std::vector<StepObserver>& observers, const RunControl& control, RunSummary& summary);
    // extrapolate: start from the path's quadratic extrapolation when there is one.
    NewtonResult attempt_increment(double h, const RunControl& control, bool extrapolate);
    // One increment under the given scheme instead of the stage's (an arc-length step's landing).
    NewtonResult attempt_increment(double h, const RunControl& control, bool extrapolate, Scheme scheme);
    // Where the current state lies along the path: the controlled displacement, the load
    // factor or the arc length, by the scheme.
    double path_parameter() const;
    // Whether the next increment starts from the path's extrapolation.
    bool extrapolating() const;
    // Back to the state before the attempt (the elements' trial states too).
    void roll_back(const Eigen::VectorXd& u_saved, double lambda_saved);
    // Stiffness in the load direction, against the initial, below which a tangent shows a limit:
    // a hinges' plateau, or members whose sections are at capacity (plastic_sites.hpp).
    static constexpr double hinge_plateau_stiffness = 1e-4;
    static constexpr double plastic_zone_stiffness = 1e-2;
    bool tangent_shows_limit(double below = hinge_plateau_stiffness);
    // The residual, relative to the load, that the rounding of the displacements alone leaves
    // at the current state (StructuralSystem::round_off_floor).
    RoundOffFloor round_off_floor() const;
    // Empty, or what passed through what in the last converged step.
    std::string check_penetration() const;
    // Where the last evaluation left a base that the last converged step touched, and that
    // frees a rigid motion: the contact lost and the motion, in words; else empty.
    std::string contact_mechanism() const;
    // The same where the failed iterate does not show it, a small step along the load's
    // response from the converged state (the system is left there: revert after).
    std::string probe_contact_mechanism(const Eigen::VectorXd& u_converged, double lambda_converged);
    void remember_contact(); // after a commit
    // Where the unloaded tangent is singular although the supports hold every rigid motion: the
    // mechanism the member-end releases leave, in words, if holding them makes it stable; else empty.
    std::string release_mechanism() const;
    // f·K⁻¹f of the driven load direction at the last evaluation (0 where K is singular): the
    // reference of Bergan's current stiffness parameter in tangent_shows_limit().
    double load_flexibility();
    std::vector<bool> committed_contact_; // per foundation spring: touching at the last converged step
    double control_value(const Eigen::VectorXd& u) const; // of the current stage's controlled DOF
    // A stage that drives another pattern: the one driven so far keeps its factor, λ takes up
    // the new pattern's, and loads, pressures, prescribed displacements and bases follow.
    void drive_pattern(int pattern);
    // The converged state as a step's result, in storage kept from step to step (the
    // observers copy what they keep). with_sections: RunControl::report_sections of the run.
    const StepResult& make_result(int step, int iterations, Acceptance rule, bool with_sections);
    // Whether the current stage's target is reached (within round-off of its increment).
    bool target_reached() const;
    // How far the current state lies past the stage's target, toward it positive (in load
    // factor or controlled displacement); −∞ without a target.
    double past_target() const;
    // Round-off of the increment that led to the target: nearer than this counts as on it.
    double target_slack() const { return 1e-9 * std::abs(analysis_.initial_increment); }
    // Makes stages[k] of the model the current stage; returns its first increment, signed
    // toward its target.
    double begin_stage(std::size_t k);

    Model model_;
    AnalysisSpec analysis_;   // the current stage: [analysis], then each [[stage]] over it
    std::size_t stage_ = 0;   // 0: [analysis]; k: the model's stages[k − 1]
    double direction_ = 1.0;  // the sign of travel toward the current stage's target
    StructuralSystem system_;
    LinearSolver solver_;
    Eigen::VectorXd u_;     // full displacement vector
    Eigen::VectorXd ubar_;  // reference prescribed displacements of the driven pattern, full
    Eigen::VectorXd ubar_held_; // prescribed displacements the held patterns keep, full
    PatternFactors factors_;
    Eigen::VectorXd previous_increment_; // free DOFs, last converged Δu
    double lambda_ = 0.0;
    double peak_lambda_ = 0.0; // largest |λ| converged so far: the residual's reference
    int failures_in_step_ = 0; // attempts of the coming step that failed
    // An arc-length corrector's line missed the arc in this step (it was cut for that), and
    // the count of steps in a row before it that were cut for that.
    bool missed_arc_in_step_ = false;
    int steps_missing_arc_ = 0;
    StepController steps_;     // the next increment's size
    double arc_length_ = 0.0;
    double last_residual_ = 0.0;
    int step_ = 0;
    int control_equation_ = -1;
    double initial_flexibility_ = 0.0; // f·K₀⁻¹f of the unloaded structure
    std::string limit_evidence_;
    std::vector<IterationTrace> trace_;
    PathExtrapolation path_; // the last converged states, for the predictor
    StepResult result_;      // the step being published (make_result)
};

} // namespace plastica
