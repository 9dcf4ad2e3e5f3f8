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
        // Bᵀ s and Bᵀ k_s B with B = [1/L0 0 0; 0 b_i b_j], weighted by w·L0: the axial row
        // of B meets ε0 alone, the bending row the end rotations alone (entry by entry).
        const double wL = p.at.weight * L0_;
        const double a = 1.0 / L0_, bi = p.curvature_per_theta_i, bj = p.curvature_per_theta_j;
        const Eigen::Matrix2d& ks = p.trial.tangent;
        q[0] += wL * (p.trial.N * a);
        q[1] += wL * (p.trial.M * bi);
        q[2] += wL * (p.trial.M * bj);
        const double dN[3] = {ks(0, 0) * a, ks(0, 1) * bi, ks(0, 1) * bj}; // ∂N/∂e
        const double dM[3] = {ks(1, 0) * a, ks(1, 1) * bi, ks(1, 1) * bj}; // ∂M/∂e
        for (int j = 0; j < 3; ++j) {
            k(0, j) += wL * (a * dN[j]);
            k(1, j) += wL * (bi * dM[j]);
            k(2, j) += wL * (bj * dM[j]);
        }
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
