// The structure as a Newton problem: equilibrium F_held + λ·F − f_int(u) = 0 on the free DOFs,
// with prescribed displacements ū_held + λ·ū (their coupling K_fp·ū joins the load direction).
// F and ū are the driven pattern's; F_held and ū_held the held patterns' (PatternFactors).
#pragma once

#include "analysis/structural_system.hpp"
#include "solver/newton_solver.hpp"

namespace plastica {

class StructureProblem final : public NewtonProblem {
public:
    // u (full DOF vector) and lambda are the state, moved in place; ubar is the reference
    // prescribed displacement (full), ubar_held the held one; the reference loads are the
    // system's (they may follow u).
    // Contact sets are frozen from iteration `contact_freeze`, hinge states from `hinge_freeze`,
    // fibre branches of distributed plasticity from `fibre_freeze`.
    StructureProblem(StructuralSystem& system, Eigen::VectorXd& u, double& lambda,
                     const Eigen::VectorXd& ubar, const Eigen::VectorXd& ubar_held,
                     int contact_freeze, int hinge_freeze, int fibre_freeze);

    // The first tangent (at an extrapolated start) takes these axial forces, one per member, in
    // its geometric stiffness (path_extrapolation.hpp); they must outlive the increment.
    void predict_axial_forces(const Eigen::VectorXd& forces) { predicted_axial_forces_ = &forces; }
    bool evaluate(int iteration, bool release) override;
    const Eigen::VectorXd& residual() const override { return residual_; }
    const Eigen::VectorXd& load_direction() const override { return load_direction_; }
    const SparseMatrix& tangent() const override { return system_.tangent(); }
    bool tangent_finite() const override { return system_.tangent_finite(); }
    bool settled() const override;
    void move(const Eigen::VectorXd& dx, double dlambda) override;
    double load_factor() const override { return lambda_; }
    double state_norm() const override { return u_free_.norm(); }
    double round_off_floor() const override { return system_.round_off_floor(u_, lambda_).total; }
    double round_off_force() const override { return system_.round_off_force(u_); }
    // Driven by platens alone, the residual is measured against the force they press with
    // (λ times their penalty stiffness would be the force on a rigid structure, far above it);
    // loads held from earlier stages add their size.
    double force_scale(double level) const override;
    // A contact whose spring force would stay below this fraction of the residual tolerance (at
    // the reference load level) is left as it is, open or closed: either way the residual can
    // meet the tolerance.
    void set_contact_band(double residual_tolerance, double reference_level) {
        contact_band_ = residual_tolerance;
        reference_level_ = reference_level;
    }

private:
    StructuralSystem& system_;
    Eigen::VectorXd& u_;
    double& lambda_;
    const Eigen::VectorXd& ubar_;
    const Eigen::VectorXd& ubar_held_;
    Eigen::VectorXd u_free_;
    Eigen::VectorXd load_, held_, internal_; // the free DOFs' reference load, held load and internal force
    double held_scale_ = 0.0;                // ‖held‖
    Eigen::VectorXd residual_;
    Eigen::VectorXd load_direction_;
    std::vector<int> prescribed_; // full DOF indices with ū ≠ 0
    int contact_freeze_, hinge_freeze_, fibre_freeze_;
    double contact_band_ = 0.0, reference_level_ = 0.0;
    const Eigen::VectorXd* predicted_axial_forces_ = nullptr;
};

} // namespace plastica
