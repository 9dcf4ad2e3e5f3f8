// Path following's transient stages: the same run, its steps published the same way, but each
// step advances in time (dynamics/time_stepper.hpp) instead of along a path constraint.
#include "analysis/path_following.hpp"

#include "analysis/mechanisms.hpp"
#include "dynamics/excitation.hpp"

#include <cmath>
#include <sstream>

namespace plastica {

namespace {
// Halvings of a time step before the run stops: 1/1024 of the scene's step.
constexpr int max_time_cuts = 10;
} // namespace

ModalResult PathFollowing::modes(int count) {
    system_.evaluate(u_, ubar_, lambda_, true, true, true);
    return structure_modes(system_, model_, u_, count);
}

BucklingResult PathFollowing::buckling(int count) {
    system_.evaluate(u_, ubar_, lambda_, true, true, true);
    return linear_buckling(system_, ubar_, lambda_, count);
}

void PathFollowing::set_factors_at(double t) {
    // From t = 0 (a scene that starts in motion) every pattern acts at factor 1 unless a series
    // drives it; after static stages each keeps the factor it was left at.
    if (model_.analysis.scheme == Scheme::transient && t == 0.0) {
        for (double& f : factors_.held) f = 1.0;
        lambda_ = 1.0;
    }
    for (const TimeSeriesSpec& s : model_.dynamics.series) {
        const double value = series_value(s, t);
        if (s.pattern == factors_.driven) lambda_ = value;
        else factors_.held[static_cast<std::size_t>(s.pattern)] = value;
    }
    system_.set_pattern_factors(factors_);
}

double PathFollowing::advance_in_time(double dt, const RunControl& control, RunSummary& summary, NewtonResult& outcome) {
    const AnalysisSpec& a = stages_.current();
    NewtonSettings settings;
    settings.max_iterations = a.max_iterations;
    settings.residual_tolerance = a.residual_tolerance;
    settings.tolerance_follows_floor = a.residual_tolerance_follows_floor;
    settings.displacement_tolerance = a.displacement_tolerance;
    settings.backtrack_at_kinks = !system_.all_members_elastic();
    const FreezeAfter freeze{control.freeze_active_after, control.freeze_hinges_after, control.freeze_fibres_after};
    const Eigen::VectorXd u_saved = u_;
    const double lambda_saved = lambda_;
    const std::vector<double> held_saved = factors_.held;
    for (int cut = 0; cut <= max_time_cuts; ++cut, dt *= 0.5) {
        set_factors_at(stepper_->time() + dt);
        const int step = step_ + 1;
        const IterationHook hook = [&](int iteration, double relative) {
            trace_.push_back({step, iteration, relative});
            last_residual_ = relative;
            if (control.interrupt && control.interrupt->load()) throw RunInterrupted{};
        };
        outcome = stepper_->step(dt, u_, lambda_, settings, freeze, solver_, hook);
        if (outcome.converged()) return dt;
        summary.iterations += outcome.iterations;
        ++summary.cut_steps;
        u_ = u_saved;
        lambda_ = lambda_saved;
        factors_.held = held_saved;
        system_.set_pattern_factors(factors_);
        system_.revert();
    }
    return 0.0;
}

std::optional<StopReason> PathFollowing::run_transient_stage(const std::function<bool(const StepResult&)>& publish,
                                                             const RunControl& control, RunSummary& summary, bool begun) {
    const TransientSpec spec = stages_.current().transient;
    if (!begun) stepper_->begin_stage(spec, u_, lambda_);
    const double end = stepper_->time() + spec.duration;
    double dt = spec.time_step;
    while (stepper_->time() < end - 1e-9 * spec.time_step) {
        if (control.interrupt && control.interrupt->load()) return StopReason{RunStatus::interrupted, "interrupted"};
        const double wanted = std::min(dt, end - stepper_->time());
        NewtonResult outcome;
        const double taken = advance_in_time(wanted, control, summary, outcome);
        if (taken == 0.0) {
            system_.evaluate(u_, ubar_, lambda_, false); // the system at the last converged state
            std::ostringstream why;
            why << "no convergence at t = " << stepper_->time() << " with the time step cut " << max_time_cuts
                << " times to " << wanted / std::pow(2.0, max_time_cuts) << " (" << to_string(outcome.failure) << ")";
            if (!system_.non_finite_where().empty() && outcome.failure == NewtonFailure::non_finite)
                why << ": " << system_.non_finite_where();
            return StopReason{RunStatus::no_convergence, why.str()};
        }
        summary.iterations += outcome.iterations;
        if (outcome.rule == Acceptance::residual) ++summary.accepted_by_residual;
        if (outcome.rule == Acceptance::stagnation) ++summary.accepted_by_stagnation;
        system_.commit();
        stepper_->commit(taken);
        committed_contact_ = touching_bases(system_);
        ++step_;
        // After a cut, the step grows back to the scene's.
        dt = taken < wanted ? taken : std::min(2.0 * dt, spec.time_step);
        if (taken == wanted && wanted < spec.time_step && wanted == dt) dt = std::min(2.0 * dt, spec.time_step);
        const std::string crossing = check_penetration();
        make_result(step_, outcome.iterations, outcome.rule, control.report_sections);
        stepper_->fill(u_, result_);
        if (result_.energy.error > summary.largest_energy_error) {
            summary.largest_energy_error = result_.energy.error;
            summary.largest_energy_error_step = step_;
        }
        if (result_.negative_pivots > 0 && summary.negative_pivot_steps++ == 0) summary.first_negative_pivot_step = step_;
        if (!publish(result_)) return StopReason{RunStatus::output_failed, summary.reason};
        if (!crossing.empty()) return StopReason{RunStatus::penetration, crossing};
    }
    return std::nullopt;
}

} // namespace plastica
