#include "element/distributed_plasticity_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plastica {

namespace {
// The axial strains settle in a few element iterations (one for sections in elastic bending);
// a section at its squash load has only the regularising stiffness, and takes the most.
constexpr int max_axial_iterations = 50;
} // namespace

DistributedPlasticityLaw::DistributedPlasticityLaw(const SectionSpec& section, double L0, int integration_points,
                                                   double regularisation, Axial axial)
    : axial_(axial), L0_(L0),
      k_regular_(regularisation * elastic_basic_stiffness(section.E * section.area, section.E * section.inertia, L0)),
      // Each section's parallel axial stiffness: at 1e-9, a section whose every fibre has yielded
      // made the member's axial tangent a billionth of its stiffness, while its N(ε) steps up as
      // fibres cross over, and Newton cycled (a propped cantilever on 32 elements stopped at its
      // mechanism); at 1e-6 it changes the collapse load by 2e-6.
      regular_ea_(axial == Axial::equilibrated ? std::max(regularisation, 1e-6) * section.E * section.area : 0.0),
      // The yield strain (1e-3 for an elastic section).
      strain_scale_(section.steel ? section.steel->fy / section.steel->E : 1e-3),
      force_scale_(section.E * section.area * strain_scale_),
      stiffening_(elastic_basic_stiffness(section.E * section.area, section.E * section.inertia, L0)) {
    if (axial == Axial::equilibrated) k_regular_(0, 0) = 0.0;
    const FibreSection prototype(section);
    for (const QuadraturePoint& p : gauss_legendre(integration_points))
        points_.push_back({p, prototype, (6.0 * p.xi - 4.0) / L0, (6.0 * p.xi - 2.0) / L0, {}, {}, 0.0, 0.0, 0.0});
}

void DistributedPlasticityLaw::evaluate_sections(const Eigen::Vector3d& e) {
    consistent_ = true;
    for (IntegrationPoint& p : points_) {
        p.curvature = p.curvature_per_theta_i * e[1] + p.curvature_per_theta_j * e[2];
        evaluate_section(p);
    }
}

void DistributedPlasticityLaw::evaluate_section(IntegrationPoint& p) {
    p.trial = frozen_ ? p.section.set_trial_deformation_on_branches(p.strain, p.curvature)
                      : p.section.set_trial_deformation(p.strain, p.curvature);
    if (frozen_ && consistent_) consistent_ = p.section.branches_consistent();
    if (regular_ea_ == 0.0) return;
    p.trial.N += regular_ea_ * p.strain;
    p.trial.tangent(0, 0) += regular_ea_;
}

namespace {
// One step of a safeguarded Newton iteration on a rising function: the Newton point, or the
// middle of the bracket [low, high] where the Newton point leaves it.
double safeguarded_step(double x, double step, double low, double high) {
    const double next = x + step;
    if (next > low && next < high) return next;
    if (std::isfinite(low) && std::isfinite(high)) return 0.5 * (low + high);
    return next;
}
} // namespace

void DistributedPlasticityLaw::section_strain_for(IntegrationPoint& p, double N) {
    double low = -std::numeric_limits<double>::infinity(), high = std::numeric_limits<double>::infinity();
    for (int it = 0; it < 200; ++it) {
        evaluate_section(p);
        const double miss = N - p.trial.N;
        if (std::abs(miss) <= 1e-14 * force_scale_) return;
        (miss > 0.0 ? low : high) = p.strain;
        const double next = safeguarded_step(p.strain, miss / p.trial.tangent(0, 0), low, high);
        if (std::abs(next - p.strain) <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(p.strain), strain_scale_)) return;
        p.strain = next;
    }
}

bool DistributedPlasticityLaw::settle_axial_safeguarded(double chord_strain) {
    // N_k(ε) rises with ε at a fixed curvature (bilinear fibres and a parallel stiffness), so
    // each section's strain for a given N, and the mean of those strains against N, are found
    // within brackets: where every fibre of a section has yielded, its N(ε) is a staircase of
    // fibres crossing over, and plain Newton steps between the stairs cycle.
    double N = 0.0;
    for (const IntegrationPoint& p : points_) N += p.at.weight * p.trial.N;
    double low = -std::numeric_limits<double>::infinity(), high = std::numeric_limits<double>::infinity();
    for (int it = 0; it < 200; ++it) {
        double mean = 0.0, flexibility = 0.0, scale = strain_scale_;
        for (IntegrationPoint& p : points_) {
            section_strain_for(p, N);
            mean += p.at.weight * p.strain;
            flexibility += p.at.weight / p.trial.tangent(0, 0);
            scale = std::max(scale, std::abs(p.strain));
        }
        const double miss = chord_strain - mean;
        if (std::abs(miss) <= 8 * std::numeric_limits<double>::epsilon() * scale) return true;
        (miss > 0.0 ? low : high) = N;
        const double next = safeguarded_step(N, miss / flexibility, low, high);
        if (std::abs(next - N) <= 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(N), 1e-3 * force_scale_)) return true;
        N = next;
    }
    return false;
}

void DistributedPlasticityLaw::uniform_strain_response(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) {
    q = k_regular_ * e;
    k = k_regular_;
    const double a = 1.0 / L0_;
    for (IntegrationPoint& p : points_) p.strain = e[0] / L0_;
    evaluate_sections(e);
    for (const IntegrationPoint& p : points_) {
        // Bᵀ s and Bᵀ k_s B with B = [1/L0 0 0; 0 b_i b_j], weighted by w·L0: the axial row
        // of B meets ε0 alone, the bending row the end rotations alone (entry by entry).
        const double wL = p.at.weight * L0_;
        const double bi = p.curvature_per_theta_i, bj = p.curvature_per_theta_j;
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

void DistributedPlasticityLaw::trial_response(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) {
    if (axial_ == Axial::uniform_strain) uniform_strain_response(e, q, k);
    else equilibrated_response(e, q, k);
    stiffening_.add(e, q, k);
}

void DistributedPlasticityLaw::equilibrated_response(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) {
    // Element iterations on the sections' axial strains: each step moves every section to the
    // common N that, at the sections' axial stiffnesses, makes the strains add up to the chord's.
    // They start from the last strains shifted to add up to it (exact for elastic sections), and
    // go on to round-off: a strain left off by δ leaves a force error EA·δ in the element.
    const double chord_strain = e[0] / L0_;
    double mean = 0.0;
    for (const IntegrationPoint& p : points_) mean += p.at.weight * p.strain;
    for (IntegrationPoint& p : points_) p.strain += chord_strain - mean;
    double previous = std::numeric_limits<double>::infinity(), largest = 0.0;
    for (int it = 0; it < max_axial_iterations; ++it) {
        evaluate_sections(e);
        double flexibility = 0.0, mean_strain = 0.0, weighted = 0.0, scale = strain_scale_;
        for (const IntegrationPoint& p : points_) {
            const double ea = p.trial.tangent(0, 0);
            flexibility += p.at.weight / ea;
            mean_strain += p.at.weight * p.strain;
            weighted += p.at.weight * p.trial.N / ea;
            scale = std::max(scale, std::abs(p.strain));
        }
        const double N = (chord_strain - mean_strain + weighted) / flexibility;
        largest = 0.0;
        for (const IntegrationPoint& p : points_) largest = std::max(largest, std::abs((N - p.trial.N) / p.trial.tangent(0, 0)));
        // At round-off, or no longer getting smaller (round-off of the sections' sums): the
        // sections stand where they were evaluated.
        if (largest <= 4 * std::numeric_limits<double>::epsilon() * scale || (largest >= previous && largest <= 1e-9 * scale)) break;
        previous = largest;
        for (IntegrationPoint& p : points_) p.strain += (N - p.trial.N) / p.trial.tangent(0, 0);
    }
    bool settled = largest <= 1e-8 * strain_scale_;
    if (!settled) settled = settle_axial_safeguarded(chord_strain);
    // Newton may not accept a state whose sections disagree on N by more than round-off allows.
    consistent_ = consistent_ && settled;

    // Forces and the condensed tangent (the header's formulas).
    double flexibility = 0.0, n = 0.0, dn_i = 0.0, dn_j = 0.0;
    for (const IntegrationPoint& p : points_) {
        const double ea = p.trial.tangent(0, 0);
        flexibility += p.at.weight / ea;
        n += p.at.weight * p.trial.N;
        dn_i += p.at.weight * p.trial.tangent(0, 1) / ea * p.curvature_per_theta_i;
        dn_j += p.at.weight * p.trial.tangent(0, 1) / ea * p.curvature_per_theta_j;
    }
    const double dn[3] = {1.0 / (flexibility * L0_), dn_i / flexibility, dn_j / flexibility}; // ∂N/∂e
    q = k_regular_ * e;
    k = k_regular_;
    q[0] += n;
    for (int j = 0; j < 3; ++j) k(0, j) += dn[j];
    for (const IntegrationPoint& p : points_) {
        const Eigen::Matrix2d& ks = p.trial.tangent;
        const double wL = p.at.weight * L0_, bi = p.curvature_per_theta_i, bj = p.curvature_per_theta_j;
        const double carried = ks(1, 0) / ks(0, 0);        // ∂M/∂N through the section's strain
        const double bending = ks(1, 1) - carried * ks(0, 1); // ∂M/∂κ at constant N
        q[1] += wL * (p.trial.M * bi);
        q[2] += wL * (p.trial.M * bj);
        const double dM[3] = {carried * dn[0], carried * dn[1] + bending * bi, carried * dn[2] + bending * bj};
        for (int j = 0; j < 3; ++j) {
            k(1, j) += wL * (bi * dM[j]);
            k(2, j) += wL * (bj * dM[j]);
        }
    }
}

void DistributedPlasticityLaw::commit() {
    for (IntegrationPoint& p : points_) {
        p.section.commit();
        p.committed = p.trial;
        p.committed_strain = p.strain;
    }
    stiffening_.commit();
}

void DistributedPlasticityLaw::revert() {
    for (IntegrationPoint& p : points_) {
        p.section.revert();
        p.trial = p.committed;
        p.strain = p.committed_strain;
    }
    stiffening_.revert();
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
