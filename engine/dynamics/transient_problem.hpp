// One time step of Newmark's or HHT's method as a Newton problem on the free DOFs (Hilber,
// Hughes & Taylor, "Improved numerical dissipation for time integration algorithms in
// structural dynamics", Earthquake Eng. Struct. Dyn. 5, 1977):
//   M a₁ + (1+α)(f(u₁) + C v₁ − F₁) − α(f(u₀) + C v₀ − F₀) = 0,
//   a₁ = (u₁ − u₀)/(βΔt²) − v₀/(βΔt) − (1/(2β) − 1) a₀,  v₁ = v₀ + Δt((1−γ) a₀ + γ a₁),
// with γ = 1/2 − α, β = (1 − α)²/4 (α = 0: the average acceleration). F holds the loads at
// their patterns' factors and −M r a_g of a moving ground (u is relative to the ground).
#pragma once

#include "analysis/structural_system.hpp"
#include "dynamics/mass_matrix.hpp"
#include "solver/newton_solver.hpp"

#include <array>

namespace plastica {

struct NewmarkCoefficients {
    double alpha = 0.0, gamma = 0.5, beta = 0.25, dt = 0.0;
    NewmarkCoefficients(double hht_alpha, double time_step)
        : alpha(hht_alpha), gamma(0.5 - hht_alpha), beta(0.25 * (1.0 - hht_alpha) * (1.0 - hht_alpha)), dt(time_step) {}
    double acceleration_per_displacement() const { return 1.0 / (beta * dt * dt); }
    double velocity_per_displacement() const { return gamma / (beta * dt); }
};

// Rayleigh damping C = α_M M + β_K K; K is the tangent at each iteration, or a fixed matrix
// (the initial or the committed tangent).
struct RayleighDamping {
    double alpha_m = 0.0, beta_k = 0.0;
    const SparseMatrix* fixed_stiffness = nullptr; // null: the tangent at each iteration
};

// The committed state a step leaves from (free DOFs).
struct DynamicState {
    Eigen::VectorXd x, v, a;
    Eigen::VectorXd internal, damping, external; // f(u), C v, F
    Eigen::VectorXd members, ground;             // the members' part of f, the ground's of F
};

class TransientProblem final : public NewtonProblem {
public:
    // u: the full displacement vector, moved in place; load_factor: the driven pattern's λ at
    // the step's end (the system holds the other factors); ground: a_g in x and y there.
    TransientProblem(StructuralSystem& system, const MassMatrix& mass, Eigen::VectorXd& u, const DynamicState& start,
                     const NewmarkCoefficients& c, const RayleighDamping& damping, double load_factor,
                     const std::array<double, 2>& ground, int contact_freeze, int hinge_freeze, int fibre_freeze);

    bool evaluate(int iteration, bool release) override;
    const Eigen::VectorXd& residual() const override { return residual_; }
    const Eigen::VectorXd& load_direction() const override { return no_load_; }
    const SparseMatrix& tangent() const override;
    bool tangent_finite() const override { return system_.tangent_finite(); }
    bool settled() const override { return system_.contact_settled() && system_.hinge_states_consistent(); }
    void move(const Eigen::VectorXd& dx, double dlambda) override;
    double load_factor() const override { return lambda_; }
    double state_norm() const override { return state_.x.norm(); }
    double round_off_force() const override { return system_.round_off_force(u_); }
    // The residual is measured against the largest of the forces that balance: the loads, the
    // internal forces and the inertia (and the step's start's scale, so that a vibration dying
    // out is not chased to round-off).
    double force_scale(double) const override { return std::max(scale_, reference_scale_); }
    void set_reference_scale(double scale) { reference_scale_ = scale; }
    double own_scale() const { return scale_; } // of the last evaluation alone

    // The evaluated end-of-step state.
    const DynamicState& state() const { return state_; }

private:
    StructuralSystem& system_;
    const MassMatrix& mass_;
    Eigen::VectorXd& u_;
    const DynamicState& start_;
    NewmarkCoefficients c_;
    RayleighDamping damping_;
    double lambda_;
    std::array<double, 2> ground_;
    int contact_freeze_, hinge_freeze_, fibre_freeze_;
    Eigen::VectorXd zero_ubar_, no_load_;
    DynamicState state_;
    SparseMatrix mass_matrix_;
    mutable SparseMatrix effective_;
    mutable bool effective_ready_ = false;
    Eigen::VectorXd residual_;
    double scale_ = 0.0, reference_scale_ = 0.0;
};

} // namespace plastica
