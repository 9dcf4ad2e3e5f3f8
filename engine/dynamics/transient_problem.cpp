#include "dynamics/transient_problem.hpp"

namespace plastica {

TransientProblem::TransientProblem(StructuralSystem& system, const MassMatrix& mass, Eigen::VectorXd& u,
                                   const DynamicState& start, const NewmarkCoefficients& c, const RayleighDamping& damping,
                                   double load_factor, const std::array<double, 2>& ground, int contact_freeze,
                                   int hinge_freeze, int fibre_freeze)
    : system_(system), mass_(mass), u_(u), start_(start), c_(c), damping_(damping), lambda_(load_factor), ground_(ground),
      contact_freeze_(contact_freeze), hinge_freeze_(hinge_freeze), fibre_freeze_(fibre_freeze),
      zero_ubar_(Eigen::VectorXd::Zero(u.size())), no_load_(Eigen::VectorXd::Zero(system.free_count())) {
    state_.x = system.gather(u);
}

bool TransientProblem::evaluate(int iteration, bool release) {
    if (!system_.evaluate(u_, zero_ubar_, lambda_, iteration >= contact_freeze_ && !release,
                          iteration >= hinge_freeze_ && !release, iteration >= fibre_freeze_ && !release))
        return false;
    effective_ready_ = false;
    DynamicState& s = state_;
    const Eigen::VectorXd dx = s.x - start_.x;
    s.a = c_.acceleration_per_displacement() * dx - start_.v / (c_.beta * c_.dt) - (0.5 / c_.beta - 1.0) * start_.a;
    s.v = start_.v + c_.dt * ((1.0 - c_.gamma) * start_.a + c_.gamma * s.a);
    s.internal = system_.gather(system_.internal_force());
    s.members = system_.gather(system_.member_internal_force());
    s.ground = Eigen::VectorXd::Zero(s.x.size());
    for (int d = 0; d < 2; ++d)
        if (ground_[static_cast<std::size_t>(d)] != 0.0) s.ground -= ground_[static_cast<std::size_t>(d)] * mass_.influence(u_, d);
    s.external = system_.gather(system_.external_force(lambda_)) + s.ground;
    mass_matrix_ = mass_.assemble(u_);
    s.damping = Eigen::VectorXd::Zero(s.x.size());
    if (damping_.alpha_m != 0.0) s.damping += damping_.alpha_m * (mass_matrix_ * s.v);
    if (damping_.beta_k != 0.0)
        s.damping += damping_.beta_k * (damping_.fixed_stiffness ? *damping_.fixed_stiffness * s.v : system_.tangent() * s.v);
    const Eigen::VectorXd inertia = mass_matrix_ * s.a;
    const double a = c_.alpha;
    residual_ = (1.0 + a) * (s.external - s.internal - s.damping) - a * (start_.external - start_.internal - start_.damping) - inertia;
    // A body flying free has no force at all to measure its residual's round-off against: the
    // force that would stop its momentum in a step, times 1e-9, stands in (it loosens nothing
    // where forces act).
    scale_ = std::max({s.external.norm(), s.internal.norm(), inertia.norm(), 1e-9 * (mass_matrix_ * s.v).norm() / c_.dt});
    return true;
}

const SparseMatrix& TransientProblem::tangent() const {
    if (effective_ready_) return effective_;
    // ∂/∂u of M a₁ + (1+α)(f + C v₁): v₁ and a₁ move with u₁ by γ/(βΔt) and 1/(βΔt²).
    const double a = c_.alpha, dv = c_.velocity_per_displacement();
    const double on_k = (1.0 + a) * (1.0 + (damping_.fixed_stiffness ? 0.0 : dv * damping_.beta_k));
    const double on_m = c_.acceleration_per_displacement() + (1.0 + a) * dv * damping_.alpha_m;
    effective_ = on_k * system_.tangent() + on_m * mass_matrix_;
    if (damping_.fixed_stiffness && damping_.beta_k != 0.0) effective_ += ((1.0 + a) * dv * damping_.beta_k) * *damping_.fixed_stiffness;
    effective_ready_ = true;
    return effective_;
}

void TransientProblem::move(const Eigen::VectorXd& dx, double) {
    state_.x += dx;
    system_.scatter(state_.x, u_);
}

} // namespace plastica
