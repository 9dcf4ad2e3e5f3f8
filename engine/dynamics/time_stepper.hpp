// Advances a transient stage in time: Newmark or HHT steps (transient_problem.hpp) from the
// committed state, which it keeps (velocity, acceleration, time), with Rayleigh damping, the
// ground's acceleration and the energy accounts. Path following (analysis/path_following.hpp)
// owns the run and its steps; a transient stage advances through this instead of a path
// constraint.
#pragma once

#include "analysis/step_result.hpp"
#include "analysis/structural_system.hpp"
#include "dynamics/mass_matrix.hpp"
#include "dynamics/transient_problem.hpp"
#include "solver/linear_solver.hpp"
#include "solver/newton_solver.hpp"

#include <array>
#include <memory>

namespace plastica {

// Iteration counts from which Newton keeps contact sets, hinge states and fibre branches.
struct FreezeAfter {
    int contact = 12, hinges = 1000, fibres = 3;
};

class TimeStepper {
public:
    TimeStepper(const Model& model, StructuralSystem& system);

    // The unloaded structure's tangent, for damping proportional to the initial stiffness.
    void note_initial_tangent();
    // A transient stage begins from u at the current time: at rest (or with the scene's initial
    // velocities, at the first), its acceleration in equilibrium with the loads at λ. The
    // damping's coefficients are found here (from the modes of this state, for a ratio).
    void begin_stage(const TransientSpec& spec, const Eigen::VectorXd& u, double load_factor);
    // One step of dt; u is moved, and on failure is the caller's to restore.
    NewtonResult step(double dt, Eigen::VectorXd& u, double load_factor, const NewtonSettings& settings,
                      const FreezeAfter& freeze, LinearSolver& solver, const IterationHook& hook);
    // The converged step becomes the committed state (after the system's commit).
    void commit(double dt);
    // Time, velocity, acceleration and energies of the committed state.
    void fill(const Eigen::VectorXd& u, StepResult& out);

    double time() const { return time_; }
    double alpha_m() const { return damping_.alpha_m; }
    double beta_k() const { return damping_.beta_k; }
    // The ground's acceleration in x and y at time t.
    std::array<double, 2> ground_at(double t) const;

private:
    double strain_energy() const;
    double kinetic_energy(const Eigen::VectorXd& u) const;
    void set_damping(const TransientSpec& spec, const Eigen::VectorXd& u);

    const Model& model_;
    StructuralSystem& system_;
    MassMatrix mass_;
    TransientSpec spec_;
    RayleighDamping damping_;
    SparseMatrix initial_tangent_, committed_tangent_;
    bool damping_set_ = false;
    bool started_ = false;
    double time_ = 0.0;
    double stage_start_ = 0.0;
    DynamicState state_;                       // committed
    std::unique_ptr<TransientProblem> trial_;  // the last step's problem, for commit()
    // The energy accounts since the first transient stage began.
    double kinetic_start_ = 0.0, strain_start_ = 0.0;
    double external_ = 0.0, ground_ = 0.0, members_ = 0.0, contact_ = 0.0, damped_ = 0.0;
    double reference_scale_ = 0.0; // the largest force scale of the committed steps
    double energy_scale_ = 0.0; // the largest energy term reported so far
};

} // namespace plastica
