// Newton's method for one increment of a path-following analysis, R(x, λ) = λ f − r(x) = 0,
// bordered by a constraint on the increment that fixes the load change at every iteration
// (load control, displacement control, arc length: analysis/increment_constraints.hpp).
// The problem supplies the residual, the tangent and an iteration hook (active sets of
// contact and hinges: frozen after some iterations, then checked at convergence); Newton
// decides acceptance and says which rule accepted the state.
#pragma once

#include "solver/block_assembler.hpp"
#include "solver/linear_solver.hpp"

#include <Eigen/Dense>
#include <functional>

namespace plastica {

class NewtonProblem {
public:
    virtual ~NewtonProblem() = default;
    // Evaluates the residual at the current state at the given iteration of the increment (the
    // tangent there may wait until asked for). State-dependent parts (contact, hinges) may keep
    // their previous choice after some iterations; `release` asks them to decide afresh. False
    // when a value is not finite.
    virtual bool evaluate(int iteration, bool release) = 0;
    virtual const Eigen::VectorXd& residual() const = 0;       // λ f − r(x), free DOFs
    virtual const Eigen::VectorXd& load_direction() const = 0; // ∂R/∂λ
    virtual const SparseMatrix& tangent() const = 0;           // ∂r/∂x
    virtual bool tangent_finite() const { return true; } // of the tangent at the evaluated state
    // Active sets unchanged by the last evaluation and consistent with the state.
    virtual bool settled() const { return true; }
    virtual void move(const Eigen::VectorXd& dx, double dlambda) = 0;
    virtual double load_factor() const = 0;
    virtual double state_norm() const = 0; // ‖x‖, for the round-off floor of a correction
    // The relative residual that the rounding of the state alone leaves (0: not known).
    virtual double round_off_floor() const { return 0.0; }
    // The same floor as a force (the norm of eps·|K|·|u|), to be measured against force_scale.
    virtual double round_off_force() const { return 0.0; }
    // The force the residual is measured against, given the load level: the reference load at
    // that level, unless the problem knows a truer scale (the force a platen presses with).
    virtual double force_scale(double level) const { return level * load_direction().norm(); }
};

// Fixes the load change of each iteration; NaN when no state satisfies the constraint.
class IncrementConstraint {
public:
    virtual ~IncrementConstraint() = default;
    // Iteration 0 is the predictor; `increment` is Δx of the step so far.
    virtual double load_change(int iteration, const Eigen::VectorXd& increment,
                               const Eigen::VectorXd& du_residual, const Eigen::VectorXd& du_load) = 0;
};

enum class Acceptance { none, residual, stagnation };
// turned_back: set by path following, for an arc-length increment that went back down the path.
enum class NewtonFailure { none, diverged, singular, non_finite, no_constraint_root, iteration_limit, unsettled, turned_back };

const char* to_string(Acceptance rule);
const char* to_string(NewtonFailure failure);

struct NewtonSettings {
    int max_iterations = 30;
    double residual_tolerance = 1e-6;     // ‖R‖ relative to the reference load
    // Raise the tolerance to the evaluated state's round-off floor where that lies above it.
    bool tolerance_follows_floor = false;
    // ‖δx‖ relative to ‖Δx‖ of the increment; path following passes the scene's
    // ([analysis] displacement_tolerance, AnalysisSpec::default_displacement_tolerance).
    double displacement_tolerance = 1e-8;
    double reference_level = 0.0;         // |λ| the residual is measured against (0: this increment's)
    // Stagnation at round-off is accepted only within this multiple of the tolerance.
    double stagnation_factor = 10.0;
    // Give up at once when the first correction does not lower the residual (above the
    // stagnation band): for a start from a guess, which another start can replace.
    bool fail_fast = false;
    // Give up after this many corrections without a new lowest residual.
    int stall_iterations = 10;
    // Accept an evaluated state in equilibrium whose own correction is within a hundredth of
    // the displacement tolerance, in the state and in the load factor, without taking that
    // correction: it saves the evaluation after it and moves the path by less than 1e-10 of an
    // increment. For smooth laws (elastic members); see path_increment.cpp.
    bool accept_before_correction = false;
    // Take back half of a correction that multiplied a residual within the stagnation band
    // thirtyfold (it crossed a kink of a piecewise-linear law), up to four times an increment.
    bool backtrack_at_kinks = false;
};

struct NewtonResult {
    Acceptance rule = Acceptance::none;
    NewtonFailure failure = NewtonFailure::none;
    int iterations = 0;
    double residual = 0.0; // relative, at the last evaluation
    double tolerance = 0.0; // the residual tolerance at the last evaluation (above the given one where it follows the floor)
    // Where it ended: the last correction over the increment (the displacement criterion), and
    // whether the active sets (contact, hinges, fibres) agreed with the state. A step that fails
    // with its residual within the tolerance failed on one of these.
    double correction_ratio = 0.0;
    bool settled = true;
    Eigen::VectorXd increment; // Δx of the increment
    double load_change = 0.0;  // Δλ
    int negative_pivots_seen = 0; // most negative pivots of any tangent factorised
    double contraction = 1.0;     // last residual over the one before, at acceptance
    // Iterations until equilibrium was first reached with active sets the state contradicted;
    // those after it went to re-deciding them (contact, hinges, fibres), which takes the same
    // few iterations at any increment size. 0: no set was re-decided.
    int iterations_before_settling = 0;
    bool converged() const { return rule != Acceptance::none; }
};

using IterationHook = std::function<void(int iteration, double relative_residual)>;

// A first estimate of the increment (extrapolated from the path). With one, Newton starts
// there and every iteration is a corrector: the constraint is asked as from iteration 1 on.
struct IncrementGuess {
    Eigen::VectorXd dx;
    double dlambda = 0.0;
};

NewtonResult solve_increment(NewtonProblem& problem, IncrementConstraint& constraint,
                             const NewtonSettings& settings, LinearSolver& solver,
                             const IterationHook& hook = {}, const IncrementGuess* guess = nullptr);

} // namespace plastica
