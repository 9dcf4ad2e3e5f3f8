// Path following's increments: one step from the saved state, by the extrapolated start or the
// tangent's, under the stage's constraint or the one that lands on its target.
#include "analysis/path_following.hpp"

#include "analysis/increment_constraints.hpp"
#include "analysis/mechanisms.hpp"
#include "analysis/penetration_check.hpp"
#include "analysis/plastic_sites.hpp"
#include "analysis/stop_diagnosis.hpp"
#include "analysis/structure_problem.hpp"

#include <cmath>
#include <sstream>

namespace plastica {

NewtonResult PathFollowing::attempt_increment(double h, const RunControl& control, bool extrapolate,
                                              const PathConstraint& constraint, std::optional<double> extrapolate_to,
                                              const Eigen::VectorXd* branch, double branch_load) {
    const AnalysisSpec& a = stages_.current();
    StructureProblem problem(system_, u_, lambda_, ubar_, ubar_held_, control.freeze_active_after,
                             control.freeze_hinges_after, control.freeze_fibres_after);
    problem.set_contact_band(a.residual_tolerance, peak_lambda_);
    NewtonSettings settings;
    settings.max_iterations = a.max_iterations;
    settings.residual_tolerance = a.residual_tolerance;
    settings.tolerance_follows_floor = a.residual_tolerance_follows_floor;
    settings.displacement_tolerance = a.displacement_tolerance;
    settings.reference_level = peak_lambda_;
    // Hinged and fibre members are left out: with them, four variants that complete (the arch
    // with fibre sections, the catenary beam in 40 elements, the arch in three times the
    // elements, the whole ring with I × 3 and adaptive increments) crept into their step limits
    // or stopped, and the inelastic ring saved 1 % of its work. Along an arc the accepted state
    // would lie off the arc by the correction not taken, which moves the adaptive arc's steps
    // (Lee's frame: 95 steps against 104).
    settings.accept_before_correction = system_.all_members_elastic() && constraint.scheme() != Scheme::arc_length;
    // Where hinges or fibres make the laws piecewise linear; an elastic structure's residual that
    // grows near convergence (a follower pressure's) is Newton's to reduce, not a kink.
    settings.backtrack_at_kinks = !system_.all_members_elastic();
    const int step = step_ + 1;
    const IterationHook hook = [&](int iteration, double relative) {
        trace_.push_back({step, iteration, relative});
        last_residual_ = relative;
        if (control.interrupt && control.interrupt->load()) throw RunInterrupted{};
    };
    IncrementGuess guess;
    const IncrementGuess* start = nullptr;
    PathPoint ahead;
    if (extrapolate && constraint.starts_from_extrapolation() && path_.ready()) {
        ahead = path_.at(extrapolate_to.value_or(path_parameter() + h));
        guess.dx = ahead.displacement - system_.gather(u_);
        guess.dlambda = constraint.extrapolated_load_change(h, ahead.load_factor - lambda_);
        start = &guess;
        problem.predict_axial_forces(ahead.axial_forces);
        settings.fail_fast = true; // the tangent's predictor is the fallback
    }
    // After three cuts of this step a root-less arc-length corrector takes the line's point
    // nearest the arc instead of cutting on (before, a cut is what settles most such
    // corrections). So does every step after three in a row that were cut for it: approaching a
    // corner of the path, each step misses at its first try and lands at half of it, the next
    // regrows and misses again, and the increments shrink geometrically: their sum never
    // reaches the corner.
    CorrectorContext context;
    context.control_equation = control_equation_;
    context.control_sign = a.control.sign;
    context.previous = &previous_increment_;
    context.nearest_when_no_root = failures_in_step_ >= 3 || steps_missing_arc_ >= 3;
    std::unique_ptr<IncrementConstraint> corrector;
    if (branch) {
        guess.dx = *branch;
        guess.dlambda = branch_load;
        start = &guess;
        corrector = std::make_unique<ArcLength>(branch->norm(), *branch);
    } else {
        corrector = constraint.corrector(h, context);
    }
    NewtonResult result = solve_increment(problem, *corrector, settings, solver_, hook, start);
    // Refused, the increment counts as a failure and the step is cut. Where λ moves plates or
    // prescribed displacements alone it is the travel the user drives: an arc-length step that
    // takes it back met the arc where the structure springs back (its fibres unloading), not
    // further along the path; attempt_step then takes the step under load control of the
    // travel. A flattened pipe's plate otherwise returned from 170 of its 195 and the ring
    // unloaded to nothing.
    const bool travel_back = constraint.scheme() == Scheme::arc_length && !model_.has_forces(factors_.driven) &&
                             !stages_.turned_back() && result.load_change * stages_.direction() < 0.0;
    // A state with an element crushed through its length or stretched past any beam's reach is
    // no equilibrium of the structure: the step is cut (load control then finds the limit load).
    const bool beyond_reach = !branch && result.converged() && !a.allow_crossing && !element_beyond_reach(model_, u_).empty();
    if (!branch && result.converged() &&
        (beyond_reach || (path_.traced_a_step() && (travel_back || constraint.turned_back(result.increment, previous_increment_))))) {
        result.rule = Acceptance::none;
        result.failure = NewtonFailure::turned_back;
    }
    if (result.converged()) previous_increment_ = result.increment;
    return result;
}

NewtonResult PathFollowing::attempt_step(double h, const RunControl& control, const Eigen::VectorXd& u_saved,
                                         double lambda_saved, RunSummary& summary) {
    // Landing on a bifurcation located ahead (path_critical.cpp): the load rises to it.
    if (landing_load_factor_) {
        const double to = *landing_load_factor_;
        landing_load_factor_.reset();
        NewtonResult landed = attempt_increment(to - lambda_saved, control, false, *make_path_constraint(Scheme::load_control));
        if (landed.converged()) return landed;
        summary.iterations += landed.iterations;
        roll_back(u_saved, lambda_saved);
    }
    NewtonResult outcome = attempt_increment(h, control, true, *constraint_);
    if (!outcome.converged() && extrapolating()) {
        // The extrapolation may overshoot a kink of the path (a hinge or contact that appears
        // in this step): try the tangent's predictor before cutting the step.
        summary.iterations += outcome.iterations;
        roll_back(u_saved, lambda_saved);
        outcome = attempt_increment(h, control, false, *constraint_);
    }
    // Where the load factor moves plates or prescribed displacements alone it measures no load,
    // and the path rarely folds in it: an arc-length step that finds no point on its arc is
    // taken under load control of the travel the path extrapolates to that arc length. Fibres
    // yielding and unloading as λ swings within the corrector's iterations make it cycle
    // (a crushed ring's walls); with λ held, the same step converges.
    if (!outcome.converged() && constraint_->scheme() == Scheme::arc_length && !model_.has_forces(factors_.driven) &&
        path_.traced_a_step() && !stages_.turned_back()) {
        const double travel = path_.at(path_parameter() + h).load_factor - lambda_saved;
        if (travel != 0.0) {
            summary.iterations += outcome.iterations;
            roll_back(u_saved, lambda_saved);
            outcome = attempt_increment(travel, control, true, *make_path_constraint(Scheme::load_control), path_parameter() + h);
        }
    }
    // A step past the stage's target that the scheme could not shorten beforehand is taken
    // again from where it started, under the control that lands on the target exactly (a step
    // that fails to land is cut).
    if (outcome.converged() && constraint_->retakes_past_target() &&
        stages_.past_target(lambda_, u_) > stages_.target_slack()) {
        summary.iterations += outcome.iterations;
        roll_back(u_saved, lambda_saved);
        const double remaining = stages_.remaining(lambda_, u_);
        outcome = attempt_increment(remaining, control, false, *make_path_constraint(stages_.landing_scheme()));
    }
    return outcome;
}

} // namespace plastica
