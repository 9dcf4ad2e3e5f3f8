#include "solver/newton_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace plastica {

namespace {
// Corrections larger than this times the step so far (the first correction, or the start from
// a guess) end the attempt as diverged.
constexpr double max_correction_growth = 100.0;
// A residual within this multiple of the state's round-off floor (an estimate of its order) is round-off.
constexpr double round_off_margin = 10.0;
// A correction this share of the displacement tolerance need not be taken (accept_before_correction).
constexpr double unapplied_correction_share = 1e-2;
// A correction that multiplied a residual within the stagnation band this many times over crossed
// a kink of a piecewise-linear law; it is halved, at most this many times in an increment. By
// measurement (docs/stability.md): 100 left the catenary beam with half its yield stress stopped,
// 10 moved the whole ring's path more than 30 and stopped the 80-element beam with twice it.
constexpr double kink_growth = 30.0;
constexpr int max_backtracks = 4;
} // namespace

const char* to_string(Acceptance rule) {
    switch (rule) {
    case Acceptance::none: return "none";
    case Acceptance::residual: return "residual";
    case Acceptance::stagnation: return "stagnation";
    }
    return "unknown";
}

const char* to_string(NewtonFailure failure) {
    switch (failure) {
    case NewtonFailure::none: return "none";
    case NewtonFailure::diverged: return "diverged";
    case NewtonFailure::singular: return "singular tangent";
    case NewtonFailure::non_finite: return "non-finite state";
    case NewtonFailure::no_constraint_root: return "no point on the constraint";
    case NewtonFailure::iteration_limit: return "iteration limit";
    case NewtonFailure::unsettled: return "active set did not settle";
    case NewtonFailure::turned_back: return "turned back along the path";
    }
    return "unknown";
}

NewtonResult solve_increment(NewtonProblem& problem, IncrementConstraint& constraint,
                             const NewtonSettings& settings, LinearSolver& solver,
                             const IterationHook& hook, const IncrementGuess* guess) {
    NewtonResult result;
    if (guess) {
        problem.move(guess->dx, guess->dlambda);
        result.increment = guess->dx;
        result.load_change = guess->dlambda;
    }
    const int first_constraint_iteration = guess ? 1 : 0;
    double last_correction = 0.0;
    double first_correction = 0.0;
    double damping = 1.0;
    std::vector<double> history; // residual norms of the iterations so far
    double lowest = std::numeric_limits<double>::infinity(); // of the corrections' residuals
    int last_lowest = 1;
    bool release = false; // re-decide frozen active sets at the next evaluation
    bool in_equilibrium = false; // the evaluated state is within the tolerance, active sets settled
    double correction_floor = 0.0; // round-off of the whole state, for a correction
    // A correction within `share` of the displacement tolerance of the increment, or of the
    // round-off floor of the whole state.
    const auto within = [&](double correction, double share) {
        return correction <= share * settings.displacement_tolerance * result.increment.norm() ||
               correction <= share * correction_floor;
    };
    Eigen::VectorXd du_r, du_f, du; // corrections for the residual, per unit load, and in all
    Eigen::VectorXd last_move;      // the correction last taken, and its load-factor change
    double last_load_move = 0.0;
    double last_good_relative = std::numeric_limits<double>::infinity(); // before the correction last taken
    int backtracks = 0;
    if (!problem.evaluate(0, false)) {
        result.failure = NewtonFailure::non_finite;
        return result;
    }
    for (int it = 0; it <= settings.max_iterations; ++it) {
        result.iterations = it;
        const Eigen::VectorXd& residual = problem.residual();
        const Eigen::VectorXd& load = problem.load_direction();
        if (result.increment.size() != residual.size()) result.increment = Eigen::VectorXd::Zero(residual.size());
        // Residual relative to the reference load: the largest converged load level so far
        // (meaningful where λ passes zero after a limit point, and not inflated by a wild
        // iterate); in the first increment, the load level being applied.
        const double level = settings.reference_level > 0.0
                                 ? settings.reference_level
                                 : std::max(std::abs(problem.load_factor()), std::abs(result.load_change));
        const double relative = residual.norm() / std::max(problem.force_scale(level), 1e-300);
        if (!std::isfinite(relative)) {
            result.failure = NewtonFailure::non_finite;
            return result;
        }
        // The state's round-off floor, when the tolerance follows it: no residual can be brought
        // below it, however small the increment.
        const double tolerance =
            settings.tolerance_follows_floor
                ? std::max(settings.residual_tolerance, problem.round_off_force() / std::max(problem.force_scale(level), 1e-300))
                : settings.residual_tolerance;
        result.tolerance = tolerance;
        const double previous_relative = it > 0 ? result.residual : relative;
        result.residual = relative;
        if (it > 1) result.contraction = relative / std::max(previous_relative, 1e-300);
        if (hook) hook(it, relative);
        // Near convergence the tangent of a hinge at its squash load holds only the regularising
        // hardening: a correction for a residual just above the tolerance can cross the kink where
        // the hinge unloads and throw the state far off. Half of that correction is taken back
        // (a backtracking line search), so that the state stays on the side Newton's model holds.
        const bool near_tolerance = last_good_relative <= settings.stagnation_factor * tolerance;
        if (settings.backtrack_at_kinks && it >= 2 && backtracks < max_backtracks && near_tolerance &&
            relative > kink_growth * last_good_relative) {
            ++backtracks;
            last_move *= 0.5;
            last_load_move *= 0.5;
            problem.move(-last_move, -last_load_move);
            result.increment -= last_move;
            result.load_change -= last_load_move;
            result.residual = last_good_relative;
            if (!problem.evaluate(it, release)) {
                result.failure = NewtonFailure::non_finite;
                return result;
            }
            continue;
        }
        last_good_relative = relative;
        if (it > 0) {
            // The correction relative to the increment, with a floor at round-off of the whole
            // state (a tiny last increment that lands on a target would otherwise never pass).
            // The correction is small relative to the increment, or below 1e-9 of the whole
            // state: a piecewise-linear law (a hinge turning round) can make Newton swap
            // between two states that far apart without ever settling, and a tiny last
            // increment that lands on a target has no other scale.
            correction_floor = 1e-9 * problem.state_norm();
            const bool small_correction = within(last_correction, 1.0);
            const bool settled = problem.settled();
            result.correction_ratio = last_correction / std::max(result.increment.norm(), 1e-300);
            result.settled = settled;
            in_equilibrium = settled && relative <= tolerance;
            // Equilibrium with frozen active sets that the state contradicts: let them be
            // re-decided once, then freeze again (an active-set iteration).
            release = !settled && relative <= tolerance * settings.stagnation_factor;
            if (release && result.iterations_before_settling == 0) result.iterations_before_settling = it;
            // Below the tolerance and no longer falling: round-off, which a nearly singular tangent
            // (near a bifurcation, a membrane far stiffer than its bending) turns into corrections
            // as large as a tiny increment, so they would never pass the correction test.
            const bool floor_reached = it > 1 && relative <= tolerance && relative > 0.5 * previous_relative;
            if (floor_reached && settled && !small_correction) {
                result.rule = Acceptance::stagnation;
                return result;
            }
            if (small_correction && settled) {
                if (relative <= tolerance) {
                    result.rule = Acceptance::residual;
                    return result;
                }
                // Round-off stagnation: the state no longer moves, the residual no longer falls,
                // and it is within a few times the tolerance (a stiff membrane's floor).
                if (last_correction <= correction_floor && relative > 0.5 * previous_relative &&
                    relative <= settings.stagnation_factor * tolerance) {
                    result.rule = Acceptance::stagnation;
                    return result;
                }
            }
            if (settings.fail_fast && it == 1 && relative > previous_relative &&
                relative > settings.stagnation_factor * tolerance) {
                result.failure = NewtonFailure::diverged;
                return result;
            }
            // Ten corrections without a new lowest residual since the first: Newton is
            // wandering, not converging: a cut increment costs less than the remaining ones.
            if (it > 1) lowest = std::min(lowest, relative);
            if (it > 1 && relative <= lowest) last_lowest = it;
            if (it - std::max(last_lowest, 1) >= settings.stall_iterations) {
                // Wandering within the stagnation band and within a few times the state's
                // round-off floor, active sets settled: the iterates swap across a kink of a
                // piecewise-linear law at that floor (a stiff membrane's), where no increment,
                // however small, does better. Accepted as stagnation, as a floor reached directly
                // is. Above the floor, wandering is Newton's failure, and the increment is cut.
                if (settled && relative <= settings.stagnation_factor * tolerance &&
                    relative <= round_off_margin * problem.round_off_floor()) {
                    result.rule = Acceptance::stagnation;
                    return result;
                }
                result.failure = NewtonFailure::diverged;
                return result;
            }
            if (relative > 1e8) {
                result.failure = NewtonFailure::diverged;
                return result;
            }
        }
        if (it == settings.max_iterations) break;

        if (!problem.tangent_finite()) {
            result.failure = NewtonFailure::non_finite;
            return result;
        }
        if (!solver.factorize(problem.tangent())) {
            result.failure = NewtonFailure::singular;
            return result;
        }
        result.negative_pivots_seen = std::max(result.negative_pivots_seen, solver.negative_pivots());
        solver.solve(residual, load, du_r, du_f);
        const double dl = constraint.load_change(it + first_constraint_iteration, result.increment, du_r, du_f);
        if (!std::isfinite(dl)) {
            result.failure = NewtonFailure::no_constraint_root;
            return result;
        }
        du = du_r + dl * du_f;
        double step_dl = dl;
        if (!du.allFinite()) {
            result.failure = NewtonFailure::non_finite;
            return result;
        }
        // A state in equilibrium whose own correction is far inside the tolerance is accepted
        // as it stands: the correction and the evaluation after it would move it by less than
        // 1e-10 of the increment and of the load level.
        if (settings.accept_before_correction && in_equilibrium) {
            const double tiny = unapplied_correction_share * settings.displacement_tolerance;
            if (std::abs(dl) <= tiny * std::abs(problem.load_factor()) && within(du.norm(), unapplied_correction_share)) {
                result.iterations = it + 1;
                result.rule = Acceptance::residual;
                return result;
            }
        }
        const double before = residual.norm();
        // A cycle (the residual repeating that of two or three iterations ago) means Newton
        // jumps across a kink of a piecewise-linear law back and forth: shorten the step
        // (halved again at each repetition) so that it lands between the two sides.
        history.push_back(before);
        const std::size_t h = history.size();
        for (std::size_t back = 2; back <= 3 && h > back; ++back)
            if (std::abs(history[h - 1 - back] - before) <= 1e-3 * before) {
                damping = std::max(damping * 0.5, 1.0 / 64.0);
                break;
            }
        if (damping < 1.0 && it > 0) {
            du *= damping;
            step_dl *= damping;
        }
        // A correction a hundred times the step so far has found a mechanism the iterate
        // created (a section flipped across its yield surface, a spurious hinge): following it
        // lands on another equilibrium branch far away. A smaller increment costs less.
        const double correction = du.norm();
        if (it == 0) first_correction = correction;
        if (it >= 1 && correction > max_correction_growth * std::max(first_correction, result.increment.norm())) {
            result.failure = NewtonFailure::diverged;
            return result;
        }
        problem.move(du, step_dl);
        last_move = du;
        last_load_move = step_dl;
        if (!problem.evaluate(it + 1, release)) {
            result.failure = NewtonFailure::non_finite;
            return result;
        }
        result.increment += du;
        result.load_change += step_dl;
        last_correction = correction;
    }
    result.failure = problem.settled() ? NewtonFailure::iteration_limit : NewtonFailure::unsettled;
    return result;
}

} // namespace plastica
