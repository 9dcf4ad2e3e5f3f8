#include "analysis/structure_problem.hpp"

namespace plastica {

StructureProblem::StructureProblem(StructuralSystem& system, Eigen::VectorXd& u, double& lambda,
                                   const Eigen::VectorXd& ubar, const Eigen::VectorXd& ubar_held,
                                   int contact_freeze, int hinge_freeze, int fibre_freeze)
    : system_(system), u_(u), lambda_(lambda), ubar_(ubar), ubar_held_(ubar_held), u_free_(system.gather(u)),
      contact_freeze_(contact_freeze), hinge_freeze_(hinge_freeze), fibre_freeze_(fibre_freeze) {
    for (int dof = 0; dof < ubar.size(); ++dof)
        if ((ubar[dof] != 0.0 || ubar_held[dof] != 0.0) && system.equation(dof) < 0) prescribed_.push_back(dof);
}

bool StructureProblem::evaluate(int iteration, bool release) {
    const bool contact_frozen = iteration >= contact_freeze_ && !release;
    const bool hinges_frozen = iteration >= hinge_freeze_ && !release;
    const bool fibres_frozen = iteration >= fibre_freeze_ && !release;
    // The force scale from the last evaluation's load (none before the first).
    system_.set_contact_undecided_force(load_direction_.size() > 0 ? contact_band_ * force_scale(reference_level_) : 0.0);
    if (!system_.evaluate(u_, ubar_, lambda_, contact_frozen, hinges_frozen, fibres_frozen)) return false;
    if (iteration == 0 && predicted_axial_forces_) system_.take_axial_forces_in_tangent(*predicted_axial_forces_);
    if (load_.size() == 0 || system_.load_follows_deformation()) {
        system_.gather(system_.load(), load_);
        system_.gather(system_.held_load(), held_);
        held_scale_ = held_.norm();
    }
    system_.gather(system_.internal_force(), internal_);
    load_direction_ = load_ - system_.coupling();
    residual_ = lambda_ * load_ - internal_;
    if (held_scale_ > 0.0) residual_ += held_;
    return true;
}

bool StructureProblem::settled() const {
    return system_.contact_settled() && system_.hinge_states_consistent();
}

void StructureProblem::move(const Eigen::VectorXd& dx, double dlambda) {
    u_free_ += dx;
    lambda_ += dlambda;
    system_.scatter(u_free_, u_);
    for (int dof : prescribed_) u_[dof] = ubar_held_[dof] + lambda_ * ubar_[dof];
}

double StructureProblem::force_scale(double level) const {
    // Loads held from earlier stages count with the driven ones: their part of the residual is
    // measured against them, not against a driven load that may be far smaller.
    const double held = held_scale_;
    if (!system_.driven_by_platens()) return held + NewtonProblem::force_scale(level);
    return held + system_.platen_force().norm();
}

} // namespace plastica
