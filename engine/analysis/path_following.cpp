// The run's step loop (run_steps): each step advanced along the path or in time, published, and
// the stages begun in turn. Its parts by responsibility: increments (path_increment.cpp), failed
// steps and limits (path_limits.cpp), the state it publishes (path_state.cpp), transient stages
// (transient_stage.cpp).
#include "analysis/path_following.hpp"

#include "analysis/mechanisms.hpp"
#include "analysis/penetration_check.hpp"
#include "analysis/plastic_sites.hpp"
#include "analysis/stop_diagnosis.hpp"
#include "analysis/structure_problem.hpp"
#include "dynamics/modal_analysis.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <new>
#include <sstream>

namespace plastica {

PathFollowing::PathFollowing(const Model& model)
    : model_(model), stages_(model), constraint_(make_path_constraint(model.analysis.scheme)), system_(model),
      factors_(model.patterns.size()) {
    const int n = model.dof_count();
    u_ = Eigen::VectorXd::Zero(n);
    ubar_ = Eigen::VectorXd::Zero(n);
    ubar_held_ = Eigen::VectorXd::Zero(n);
    factors_.driven = model.analysis.pattern;
    for (const PrescribedDisplacement& p : model.prescribed)
        if (p.pattern == factors_.driven) ubar_[dofs_per_node * p.node + p.dof] = p.value;
    const DofRef& c = model.analysis.control;
    control_equation_ = system_.equation(dofs_per_node * c.node + c.dof);
    if (model.transient()) stepper_ = std::make_unique<TimeStepper>(model_, system_);
}

std::string PathFollowing::initial_mechanism() {
    // A structure in motion from the start is held by its inertia: a free body may fly.
    if (model_.analysis.scheme == Scheme::transient) return {};
    return unloaded_mechanism(model_, system_, solver_, u_, ubar_, lambda_);
}

void PathFollowing::roll_back(const Eigen::VectorXd& u_saved, double lambda_saved) {
    u_ = u_saved;
    lambda_ = lambda_saved;
    system_.revert();
}

RoundOffFloor PathFollowing::round_off_floor() const {
    return system_.round_off_floor(u_, lambda_);
}

RunSummary PathFollowing::run(const std::vector<StepObserver>& observers, const RunControl& control) {
    RunSummary summary;
    try {
        return run_steps(observers, control, summary);
    } catch (const ModalError& e) {
        // Damping by modal ratios needs the modes where the first transient stage starts.
        summary.status = RunStatus::no_convergence;
        summary.reason = std::string("the damping's modes: ") + e.what();
        summary.steps = step_;
        return summary;
    } catch (const RunInterrupted&) {
        u_ = u_published_;
        lambda_ = lambda_published_;
        system_.revert();
        summary.status = RunStatus::interrupted;
        summary.reason = "interrupted";
        summary.steps = step_;
        if (stepper_) summary.time = stepper_->time();
        return summary;
    } catch (const std::bad_alloc&) {
        summary.status = RunStatus::out_of_memory;
        std::ostringstream why;
        why << "out of memory in step " << step_ + 1 << ": the model's " << system_.free_count()
            << " unknowns need more memory than this process may have";
        summary.reason = why.str();
        summary.steps = step_;
        return summary;
    }
}

RunSummary PathFollowing::run_steps(const std::vector<StepObserver>& observers, const RunControl& control,
                                    RunSummary& summary) {
    const auto start = std::chrono::steady_clock::now();
    // An observer that cannot take a step (its disk is full) ends the run: the step is not
    // counted, and the run's outputs end with the step before it.
    auto publish = [&](const StepResult& r) {
        try {
            for (const StepObserver& o : observers) o(r);
            return true;
        } catch (const std::exception& e) {
            summary.status = RunStatus::output_failed;
            summary.reason = "the results of step " + std::to_string(r.step) + " could not be written: " + e.what();
            return false;
        }
    };
    auto finish = [&](int steps) {
        summary.steps = steps;
        if (summary.status == RunStatus::step_limit) summary.reason += unstable_ending(summary);
        if (stepper_) {
            summary.time = stepper_->time();
            summary.rayleigh_alpha_m = stepper_->alpha_m();
            summary.rayleigh_beta_k = stepper_->beta_k();
        }
        summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return summary;
    };
    auto stop = [&](const StopReason& why) {
        summary.status = why.status;
        summary.reason = why.reason;
    };

    // Step 0: the unloaded state (springs evaluated so the contact set is known).
    if (stepper_) {
        system_.evaluate(u_, ubar_, lambda_, false);
        stepper_->note_initial_tangent();
        if (model_.analysis.scheme == Scheme::transient) set_factors_at(0.0);
    }
    system_.evaluate(u_, ubar_, lambda_, false);
    system_.commit();
    committed_contact_ = touching_bases(system_);
    initial_flexibility_ = load_flexibility();
    // A scene in motion from the start: step 0 is its state at t = 0, velocities and energies too.
    const bool starts_in_time = stepper_ && model_.analysis.scheme == Scheme::transient;
    if (starts_in_time) stepper_->begin_stage(model_.analysis.transient, u_, lambda_);
    make_result(0, 0, Acceptance::none, control.report_sections);
    if (starts_in_time) stepper_->fill(u_, result_);
    if (!publish(result_)) return finish(0);
    path_.add(path_parameter(), system_.gather(u_), lambda_, system_.axial_forces());
    watch_stage();

    // The current stage's settings (the sequence updates them in place at each new stage).
    const AnalysisSpec& stage = stages_.current();
    double h = stage.initial_increment;
    failures_in_step_ = 0;
    summary.status = RunStatus::step_limit;
    summary.reason = "step limit reached";
    while (step_ < stage.max_steps) {
        if (control.interrupt && control.interrupt->load()) {
            stop({RunStatus::interrupted, "interrupted"});
            break;
        }
        if (stage.scheme == Scheme::transient) {
            const bool begun = starts_in_time && stages_.number() == 1;
            if (const std::optional<StopReason> stopped = run_transient_stage(publish, control, summary, begun)) {
                if (stopped->status == RunStatus::output_failed) return finish(step_ - 1);
                stop(*stopped);
                break;
            }
            if (stages_.has_next()) {
                h = begin_next_stage();
                continue;
            }
            std::ostringstream reason;
            reason << "duration reached (t = " << stepper_->time() << ")";
            if (stages_.number() > 1) reason << " (" << stages_.number() << " stages)";
            stop({RunStatus::completed, reason.str()});
            break;
        }
        const double step_h = constraint_->landing(h, position(), stage);
        const Eigen::VectorXd u_saved = u_;
        const double lambda_saved = lambda_;
        const NewtonResult outcome = attempt_step(step_h, control, u_saved, lambda_saved, summary);
        summary.iterations += outcome.iterations;
        if (outcome.rule == Acceptance::residual) ++summary.accepted_by_residual;
        if (outcome.rule == Acceptance::stagnation) ++summary.accepted_by_stagnation;
        if (!outcome.converged()) {
            const std::optional<StopReason> failed = after_failure(outcome, step_h, u_saved, lambda_saved, h);
            ++summary.cut_steps;
            if (!failed) continue;
            stop(*failed);
            break;
        }
        // Adaptive increments also bound the error of the hinges' explicit pseudo-springs (η from
        // the start of the step): a step that carries a section further than max_yield_advance
        // into its yielding range is taken again, smaller in proportion (StepController::refined).
        const double advance = stage.adaptive ? system_.trial_yield_advance() : 0.0;
        if (const double smaller = steps_.refined(step_h, advance, stage.min_increment); smaller != 0.0) {
            roll_back(u_saved, lambda_saved);
            ++summary.refined_steps;
            h = smaller;
            continue;
        }
        // Critical points of elastic structures are passed one at a time, each located
        // (path_critical.cpp); a yielding structure's step that turns many pivots at once leapt
        // past its limit (a column's long first arc onto its squashed straight state): cut too.
        const bool tracks_critical_points = model_.tracks_critical_points();
        if (tracks_critical_points ? cut_for_pivots(step_h) : leapt_past_limit(step_h)) {
            roll_back(u_saved, lambda_saved);
            ++summary.cut_steps;
            h = 0.5 * step_h;
            continue;
        }
        // Under load control a yielding step that turned a pivot negative ended past its limit
        // load: cut to the least increment, then the limit (path_limits.cpp).
        if (!tracks_critical_points && ended_past_limit_load()) {
            roll_back(u_saved, lambda_saved);
            ++summary.cut_steps;
            h = 0.5 * step_h;
            if (std::abs(h) >= stage.min_increment) continue;
            stop(limit_beyond(step_h));
            break;
        }
        // A bifurcation jumped onto a stable branch shows no pivot: the step is cut until it stays
        // on its path, or, cut no more, is published as passing it onto the branch it took.
        const bool jumped = tracks_critical_points && outcome.iterations >= branch_check_iterations && left_the_path(u_saved, lambda_saved);
        if (jumped && branch_cuts_in_step_ < most_branch_cuts && std::abs(0.5 * step_h) >= stage.min_increment) {
            roll_back(u_saved, lambda_saved);
            ++branch_cuts_in_step_;
            ++summary.cut_steps;
            h = 0.5 * step_h;
            continue;
        }
        std::optional<CriticalPoint> critical;
        if (jumped && tracks_critical_points) critical = CriticalPoint{CriticalKind::bifurcation, step_ + 1, lambda_saved, 0.0, 0.0, {}, true};
        if (tracks_critical_points && solver_.negative_pivots() > committed_pivots_) {
            std::optional<double> land_at;
            critical = locate_critical_point(u_saved, lambda_saved, land_at);
            if (land_at) { // taken again shorter, to end at it
                roll_back(u_saved, lambda_saved);
                ++landings_;
                if (critical->kind == CriticalKind::bifurcation && constraint_->scheme() != Scheme::arc_length)
                    // Short of it by half the band: at the bifurcation itself the tangent is
                    // singular, and round-off along the mode would turn the path onto the branch.
                    landing_load_factor_ = critical->load_factor - (critical->load_factor > lambda_saved ? 0.5 : -0.5) *
                                                                        landing_band * std::abs(critical->load_factor);
                else
                    h = *land_at * step_h;
                continue;
            }
            landings_ = 0;
        }
        pivot_cuts_in_step_ = 0;
        branch_cuts_in_step_ = 0;
        NewtonResult taken = outcome;
        if (critical && critical->kind == CriticalKind::bifurcation && stage.bifurcation == BifurcationRule::switch_branch &&
            !branch_switched_ && !critical->mode.empty()) {
            // One try: a branch that cannot be reached leaves the path on the fundamental one.
            branch_switched_ = true;
            const Eigen::VectorXd u_past = u_;
            const double lambda_past = lambda_;
            roll_back(u_saved, lambda_saved);
            taken = switch_branch(*critical, u_saved, lambda_saved, u_past, lambda_past, control, summary);
            if (!taken.converged()) {
                roll_back(u_saved, lambda_saved);
                h = step_h;
                continue;
            }
            critical->followed = true;
            path_.clear(); // the fundamental path's points extrapolate nothing on the branch
        }
        commit_step(taken, summary);
        const std::string crossing = check_penetration();
        StepResult& result = make_result(step_, taken.iterations, taken.rule, control.report_sections);
        result.critical = critical;
        if (critical) summary.critical_points.push_back(*critical);
        committed_pivots_ = result.negative_pivots;
        committed_lambda_ = lambda_;
        if (result.negative_pivots > 0) {
            if (summary.negative_pivot_steps++ == 0) summary.first_negative_pivot_step = step_;
        }
        watch_.note(step_, lambda_);
        result.past_first_limit = watch_.past_first_limit();
        if (!publish(result)) return finish(step_ - 1);
        if (!crossing.empty()) {
            stop({RunStatus::penetration, crossing});
            break;
        }

        h = steps_.after_success(stage, h, step_h, outcome, advance);
        if (stages_.target_reached(lambda_, u_)) {
            if (stages_.has_next()) {
                h = begin_next_stage();
                continue;
            }
            std::string reason = stage.target_load_factor ? "target load factor reached" : "target displacement reached";
            if (stages_.number() > 1) reason += " (" + std::to_string(stages_.number()) + " stages)";
            reason += unstable_ending(summary);
            stop({RunStatus::completed, reason});
            break;
        }
        if (const std::optional<StopReason> limit = limit_on_plateau(step_h)) {
            stop(*limit);
            break;
        }
    }
    return finish(step_);
}

} // namespace plastica
