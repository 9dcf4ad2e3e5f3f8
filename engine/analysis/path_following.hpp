// Incremental-iterative path following of R(u, λ) = F_held + λ·F − f_int(u) = 0 (prescribed
// displacements scale with λ too), λ the factor of the load pattern the stage drives. One Newton corrector serves three constraints on the
// increment: load control (Δλ fixed), displacement control of one DOF (Batoz & Dhatt), and
// Crisfield's cylindrical arc length ‖Δu‖ = Δl with the root nearest the previous direction.
// Increments adapt to the iteration count; a failed increment is reverted and halved.
#pragma once

#include "analysis/path_constraint.hpp"
#include "analysis/linear_buckling.hpp"
#include "analysis/path_extrapolation.hpp"
#include "analysis/path_watch.hpp"
#include "analysis/stage_sequence.hpp"
#include "analysis/step_controller.hpp"
#include "analysis/step_result.hpp"
#include "analysis/stop_diagnosis.hpp"
#include "analysis/structural_system.hpp"
#include "dynamics/structure_modes.hpp"
#include "dynamics/time_stepper.hpp"
#include "model/model.hpp"
#include "solver/linear_solver.hpp"
#include "solver/newton_solver.hpp"
#include "solver/tangent_spectrum.hpp"

#include <atomic>
#include <functional>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
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

// Thrown between Newton iterations once RunControl::interrupt is set: the run goes back to its
// last published state and stops as interrupted (a long step does not delay a signal).
struct RunInterrupted {};

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
    // The natural modes at the committed state (after run(), where it stopped), with hinges,
    // fibres and contacts in their states (dynamics/structure_modes.hpp).
    ModalResult modes(int count);
    // Linear buckling of the current stage's loads about the committed state
    // (analysis/linear_buckling.hpp).
    BucklingResult buckling(int count);
    const std::vector<IterationTrace>& trace() const { return trace_; }

private:
    RunSummary run_steps(const std::vector<StepObserver>& observers, const RunControl& control, RunSummary& summary);
    // One step of size h from the state saved: the extrapolated start, else the tangent's, and
    // a step past the target taken again to land on it. Discarded attempts' iterations are
    // counted in the summary; the returned attempt's are the caller's to count.
    NewtonResult attempt_step(double h, const RunControl& control, const Eigen::VectorXd& u_saved,
                              double lambda_saved, RunSummary& summary);
    // One increment under the given constraint (the stage's, or the one that lands on its
    // target); extrapolate: start from the path's quadratic extrapolation when there is one.
    // Starts from the path extrapolated to `extrapolate_to` (a value of the run's path parameter;
    // default: h further) when asked and the path allows it.
    // branch: an increment started at this guess (free DOFs) and held on the sphere of its
    // length about the start, the root nearest it (a switch to a buckled branch), with branch_load
    // the guess's load factor change.
    NewtonResult attempt_increment(double h, const RunControl& control, bool extrapolate, const PathConstraint& constraint,
                                   std::optional<double> extrapolate_to = std::nullopt,
                                   const Eigen::VectorXd* branch = nullptr, double branch_load = 0.0);
    // After a failed attempt of size step_h: back to the saved state, h the increment to try
    // next; the stop, where no smaller increment is left to try or none can help.
    std::optional<StopReason> after_failure(const NewtonResult& outcome, double step_h, const Eigen::VectorXd& u_saved,
                                            double lambda_saved, double& h);
    // The converged attempt becomes the next step.
    void commit_step(const NewtonResult& outcome, RunSummary& summary);
    // Under load control of forces, a step cut to a thousandth of the stage's increment whose
    // tangent shows no stiffness in the load direction: the limit load.
    std::optional<StopReason> limit_on_plateau(double step_h);
    // The limit load at the current state, where a load step of step_h beyond it, cut to the
    // least increment, still turned the tangent's pivot negative.
    StopReason limit_beyond(double step_h);
    bool ended_past_limit_load() const;
    // The driven pattern's load on the free DOFs, less the coupling of its prescribed
    // displacements: the right-hand side of the path's tangent, K⁻¹f.
    Eigen::VectorXd load_direction() const;
    // The next stage drives its pattern under its constraint; returns its first increment.
    double begin_next_stage();
    // The path watch starts on the current stage (analysis/path_watch.hpp).
    void watch_stage();
    PathWatch watch_;
    // A transient stage, from its start to its duration (analysis/transient_stage.cpp): each
    // step is published; a step that fails is cut and retaken. Returns the stop if it ends the
    // run early; publish is run_steps' own. begun: the stepper has begun it (at step 0).
    std::optional<StopReason> run_transient_stage(const std::function<bool(const StepResult&)>& publish,
                                                  const RunControl& control, RunSummary& summary, bool begun);
    // The patterns' factors at time t: those with a [[time_series]] follow it.
    void set_factors_at(double t);
    // One transient step of dt, cut in halves (up to ten times) until it converges; the time
    // step it took, or 0 where none converged.
    double advance_in_time(double dt, const RunControl& control, RunSummary& summary, NewtonResult& outcome);
    // Critical points (analysis/path_critical.cpp). A converged step that turns more than one
    // pivot negative is cut (at most ten times) so that they are met one at a time.
    bool cut_for_pivots(double step_h);
    // A yielding structure's step that turned more than one pivot negative (hinges and fibres
    // turn them one or two at a time as they yield): cut likewise, down to the least increment.
    bool leapt_past_limit(double step_h);
    // A converged step that left the path it started on (a bifurcation jumped onto its stable
    // buckled branch, which no pivot shows): its increment turns more than 45° from the path's
    // tangent at its start (cosine below branch_alignment). Checked on steps that took
    // branch_check_iterations or more, as a jump does: a step along the path takes one or two.
    bool left_the_path(const Eigen::VectorXd& u_saved, double lambda_saved);
    static constexpr double branch_alignment = 0.7071;
    static constexpr int branch_check_iterations = 5;
    static constexpr int most_branch_cuts = 12;
    LinearSolver check_solver_; // the start's tangent, beside the step's own factorisation
    int branch_cuts_in_step_ = 0;
    // The tangent at another state (u, λ), the system left as it was.
    SparseMatrix tangent_at(const Eigen::VectorXd& u, double lambda);
    // The critical point a converged step passed (one more negative pivot than the state it
    // started from, saved in u_saved, λ_saved): located about that state, and classified.
    // land_at: where a coarse step should have ended to land on it, as a share of the step
    // (the step is then taken again that long, up to four times a critical point).
    CriticalPoint locate_critical_point(const Eigen::VectorXd& u_saved, double lambda_saved, std::optional<double>& land_at);
    int landings_ = 0; // steps taken again shorter to land on the critical point ahead
    static constexpr double landing_band = 1e-3;
    // A bifurcation ahead on a rising load: the next step is taken under load control to it.
    std::optional<double> landing_load_factor_;
    // [analysis] bifurcation = "switch": from the state the step started at (saved), a step
    // to the buckled branch through the located bifurcation, started along its mode on the side
    // where the load rises. The step's outcome, converged or not (then the path goes on along
    // the fundamental one).
    NewtonResult switch_branch(const CriticalPoint& at, const Eigen::VectorXd& u_saved, double lambda_saved,
                               const Eigen::VectorXd& u_past, double lambda_past, const RunControl& control,
                               RunSummary& summary);
    bool branch_switched_ = false; // once per run
    // "; past a bifurcation at λ = … (unstable)" where the run ends beyond one it did not follow.
    std::string unstable_ending(RunSummary& summary) const;
    int committed_pivots_ = 0; // the negative pivots of the last published step's tangent
    double committed_lambda_ = 0.0; // the load factor of the last published step
    int pivot_cuts_in_step_ = 0;
    std::unique_ptr<TimeStepper> stepper_; // for a scene with a transient stage
    // Where the current state lies: its load factor, controlled displacement and arc length,
    // and its place along the path in the current constraint's parameter.
    PathPosition position() const;
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
    // f·K⁻¹f of the driven load direction at the last evaluation (0 where K is singular): the
    // reference of Bergan's current stiffness parameter in tangent_shows_limit().
    double load_flexibility();
    std::vector<bool> committed_contact_; // per foundation spring: touching at the last converged step
    // A stage that drives another pattern: the one driven so far keeps its factor, λ takes up
    // the new pattern's, and loads, pressures, prescribed displacements and bases follow.
    void drive_pattern(int pattern);
    // The converged state as a step's result, in storage kept from step to step (the
    // observers copy what they keep). with_sections: RunControl::report_sections of the run.
    StepResult& make_result(int step, int iterations, Acceptance rule, bool with_sections);

    Model model_;
    StageSequence stages_;
    std::unique_ptr<PathConstraint> constraint_; // the current stage's scheme
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
    // The coming step is taken with the hinges' capacity rows or the fibre members stiffened (after_failure).
    bool stiffened_step_ = false;
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
    Eigen::VectorXd u_published_; // the state of the last published step, where an interrupt returns
    double lambda_published_ = 0.0;
};

} // namespace plastica
