#include "element/distributed_plasticity_law.hpp"

namespace plastica {

DistributedPlasticityLaw::DistributedPlasticityLaw(const SectionSpec& section, double L0, int integration_points,
                                                   double regularisation)
    : L0_(L0),
      k_regular_(regularisation * elastic_basic_stiffness(section.E * section.area, section.E * section.inertia, L0)) {
    const FibreSection prototype(section);
    for (const QuadraturePoint& p : gauss_legendre(integration_points))
        points_.push_back({p, prototype, (6.0 * p.xi - 4.0) / L0, (6.0 * p.xi - 2.0) / L0, {}, {}});
}

void DistributedPlasticityLaw::trial_response(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) {
    q = k_regular_ * e;
    k = k_regular_;
    consistent_ = true;
    const double eps0 = e[0] / L0_;
    for (IntegrationPoint& p : points_) {
        const double kappa = p.curvature_per_theta_i * e[1] + p.curvature_per_theta_j * e[2];
        p.trial = frozen_ ? p.section.set_trial_deformation_on_branches(eps0, kappa)
                          : p.section.set_trial_deformation(eps0, kappa);
        if (frozen_ && consistent_) consistent_ = p.section.branches_consistent();
        // Bᵀ s and Bᵀ k_s B with B = [1/L0 0 0; 0 b_i b_j], weighted by w·L0.
        const double wL = p.at.weight * L0_;
        const Eigen::Vector3d axial(1.0 / L0_, 0.0, 0.0);
        const Eigen::Vector3d bending(0.0, p.curvature_per_theta_i, p.curvature_per_theta_j);
        const Eigen::Matrix2d& ks = p.trial.tangent;
        q += wL * (p.trial.N * axial + p.trial.M * bending);
        const Eigen::Vector3d dN = ks(0, 0) * axial + ks(0, 1) * bending; // ∂N/∂e
        const Eigen::Vector3d dM = ks(1, 0) * axial + ks(1, 1) * bending; // ∂M/∂e
        k.noalias() += wL * (axial * dN.transpose() + bending * dM.transpose());
    }
}

void DistributedPlasticityLaw::commit() {
    for (IntegrationPoint& p : points_) {
        p.section.commit();
        p.committed = p.trial;
    }
}

void DistributedPlasticityLaw::revert() {
    for (IntegrationPoint& p : points_) {
        p.section.revert();
        p.trial = p.committed;
    }
}

std::vector<SectionReport> DistributedPlasticityLaw::sections() const {
    std::vector<SectionReport> out;
    out.reserve(points_.size());
    for (const IntegrationPoint& p : points_)
        out.push_back({p.at.xi, p.section.yielded_area_share(), p.section.committed_curvature(),
                       p.committed.M, p.committed.N});
    return out;
}

} // namespace plastica
