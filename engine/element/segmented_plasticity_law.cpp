#include "element/segmented_plasticity_law.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

namespace {
constexpr int max_element_iterations = 40;
// The inner nodes are in equilibrium when their forces are this small against the element's.
constexpr double inner_tolerance = 1e-10;

// How segment s of n sees the basic deformations [u_l, θ_i, θ_j] in its nodes' (u, w, θ):
// the axial motion is shared in proportion, θ_i and θ_j act at the element's ends.
Eigen::Matrix<double, 6, 3> basic_map(std::size_t s, std::size_t n) {
    Eigen::Matrix<double, 6, 3> G = Eigen::Matrix<double, 6, 3>::Zero();
    G(0, 0) = static_cast<double>(s) / static_cast<double>(n);
    G(3, 0) = static_cast<double>(s + 1) / static_cast<double>(n);
    if (s == 0) G(2, 1) = 1.0;
    if (s + 1 == n) G(5, 2) = 1.0;
    return G;
}
} // namespace

SegmentedPlasticityLaw::SegmentedPlasticityLaw(const SectionSpec& section, double L0, int segments,
                                               int integration_points)
    : L0_(L0), segment_length_(L0 / segments), EA_(section.E * section.area), EI_(section.E * section.inertia) {
    const std::size_t n = static_cast<std::size_t>(segments);
    segments_.reserve(n);
    for (std::size_t s = 0; s < n; ++s) segments_.emplace_back(section, segment_length_, integration_points);
    segment_forces_.resize(n);
    segment_tangents_.resize(n);
    pivot_inverse_.resize(n - 1);
    multiplier_.resize(n - 1);
    upper_.resize(n - 1);
    inner_t_ = inner_c_ = std::vector<Inner>(n - 1, Inner::Zero());
    // The elastic condensation, the warm start of the first trial: evaluated at rest.
    evaluate(Eigen::Vector3d::Zero(), inner_t_);
    std::vector<Inner> forces;
    Eigen::Vector3d q;
    Eigen::Matrix3d k;
    condense(forces, q, k);
    condensation_c_ = condensation_t_;
    for (DistributedPlasticityLaw& s : segments_) s.revert();
}

void SegmentedPlasticityLaw::evaluate(const Eigen::Vector3d& e, const std::vector<Inner>& inner) {
    const std::size_t n = segments_.size();
    const double l = segment_length_;
    // Segment deformations [u_b − u_a, θ_a − β, θ_b − β], β = (w_b − w_a)/l, from its nodes'
    // (u, w, θ) at a and b.
    Eigen::Matrix<double, 3, 6> T = Eigen::Matrix<double, 3, 6>::Zero();
    T(0, 0) = -1.0;
    T(0, 3) = 1.0;
    T(1, 1) = T(2, 1) = 1.0 / l;
    T(1, 4) = T(2, 4) = -1.0 / l;
    T(1, 2) = 1.0;
    T(2, 5) = 1.0;
    for (std::size_t s = 0; s < n; ++s) {
        Vector6 d = basic_map(s, n) * e;
        if (s > 0) d.segment<2>(1) = inner[s - 1];
        if (s + 1 < n) d.segment<2>(4) = inner[s];
        Eigen::Vector3d q;
        Eigen::Matrix3d k;
        segments_[s].trial(T * d, q, k);
        segment_forces_[s].noalias() = T.transpose() * q;
        segment_tangents_[s].noalias() = T.transpose() * k * T;
    }
}

template <class Block>
void SegmentedPlasticityLaw::solve_inner(std::vector<Block>& b) const {
    const std::size_t m = b.size();
    for (std::size_t i = 1; i < m; ++i) b[i] -= multiplier_[i] * b[i - 1];
    b[m - 1] = (pivot_inverse_[m - 1] * b[m - 1]).eval();
    for (std::size_t i = m - 1; i-- > 0;) b[i] = (pivot_inverse_[i] * (b[i] - upper_[i] * b[i + 1])).eval();
}

void SegmentedPlasticityLaw::condense(std::vector<Inner>& inner_forces, Eigen::Vector3d& q, Eigen::Matrix3d& k) {
    const std::size_t n = segments_.size(), m = n - 1;
    const std::vector<Vector6>& f = segment_forces_;
    const std::vector<Matrix6>& S = segment_tangents_;
    // Basic forces and K_ee, and each segment's stiffness against the basic deformations.
    q.setZero();
    k.setZero();
    std::vector<Eigen::Matrix<double, 6, 3>> SG(n);
    for (std::size_t s = 0; s < n; ++s) {
        const Eigen::Matrix<double, 6, 3> G = basic_map(s, n);
        q.noalias() += G.transpose() * f[s];
        SG[s].noalias() = S[s] * G;
        k.noalias() += G.transpose() * SG[s];
    }
    // Inner node i (element node i + 1) is the far node of segment i and the near one of
    // segment i + 1: its (w, θ) are local DOFs 4, 5 of the first and 1, 2 of the second.
    inner_forces.resize(m);
    std::vector<Coupling> coupling(m);
    for (std::size_t i = 0; i < m; ++i) {
        inner_forces[i] = f[i].segment<2>(4) + f[i + 1].segment<2>(1);
        coupling[i] = SG[i].block<2, 3>(4, 0) + SG[i + 1].block<2, 3>(1, 0);
    }
    // Block LDLᵀ of the chain: pivot_i = D_i − C_{i−1}ᵀ pivot_{i−1}⁻¹ C_{i−1}.
    for (std::size_t i = 0; i < m; ++i) {
        Eigen::Matrix2d pivot = S[i].block<2, 2>(4, 4) + S[i + 1].block<2, 2>(1, 1);
        if (i > 0) {
            multiplier_[i] = upper_[i - 1].transpose() * pivot_inverse_[i - 1];
            pivot -= multiplier_[i] * upper_[i - 1];
        }
        pivot_inverse_[i] = pivot.inverse();
        if (i + 1 < m) upper_[i] = S[i + 1].block<2, 2>(1, 4);
    }
    std::vector<Coupling> solved = coupling;
    solve_inner(solved);
    condensation_t_.resize(m);
    for (std::size_t i = 0; i < m; ++i) {
        condensation_t_[i] = -solved[i];
        k.noalias() -= coupling[i].transpose() * solved[i];
    }
}

double SegmentedPlasticityLaw::inner_residual(const std::vector<Inner>& r) const {
    // Moments against the segment length, so that the norm adds forces.
    double sum = 0.0;
    for (const Inner& v : r) sum += v[0] * v[0] + (v[1] / segment_length_) * (v[1] / segment_length_);
    return std::sqrt(sum);
}

void SegmentedPlasticityLaw::trial(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) {
    // Start from the last trial state moved along its condensed tangent: exact while every
    // section stays on its branch, so an elastic element needs one evaluation.
    std::vector<Inner> inner = inner_t_;
    for (std::size_t i = 0; i < inner.size(); ++i) inner[i] += condensation_t_[i] * (e - e_t_);
    std::vector<Inner> r;
    evaluate(e, inner);
    condense(r, q, k);
    double residual = inner_residual(r);
    // Against the end forces, and against the elastic forces of the deformation, which set
    // the round-off of every force here.
    const double scale = std::abs(q[0]) + (std::abs(q[1]) + std::abs(q[2])) / segment_length_ +
                         EA_ * std::abs(e[0]) / L0_ + EI_ * (std::abs(e[1]) + std::abs(e[2])) / (L0_ * segment_length_);
    inner_converged_ = residual <= inner_tolerance * scale;
    // Newton on the inner nodes with a backtracking line search: the fibres' piecewise-linear
    // law can make a full step jump across a kink, and a shortened one lands between.
    for (int it = 0; it < max_element_iterations && !inner_converged_; ++it) {
        std::vector<Inner> step = r;
        solve_inner(step);
        const std::vector<Inner> start = inner;
        double length = 1.0;
        for (int cut = 0;; ++cut) {
            for (std::size_t i = 0; i < inner.size(); ++i) inner[i] = start[i] - length * step[i];
            evaluate(e, inner);
            condense(r, q, k);
            const double next = inner_residual(r);
            if (next < residual || cut == 8 || !std::isfinite(next)) {
                residual = next;
                break;
            }
            length *= 0.5;
        }
        if (!std::isfinite(residual)) break;
        inner_converged_ = residual <= inner_tolerance * scale;
    }
    // A state whose inner nodes are not in equilibrium is not accepted (states_consistent).
    e_t_ = e;
    inner_t_ = inner;
}

void SegmentedPlasticityLaw::commit() {
    for (DistributedPlasticityLaw& s : segments_) s.commit();
    e_c_ = e_t_;
    inner_c_ = inner_t_;
    condensation_c_ = condensation_t_;
}

void SegmentedPlasticityLaw::revert() {
    for (DistributedPlasticityLaw& s : segments_) s.revert();
    e_t_ = e_c_;
    inner_t_ = inner_c_;
    condensation_t_ = condensation_c_;
    inner_converged_ = true;
}

std::vector<SectionReport> SegmentedPlasticityLaw::sections() const {
    std::vector<SectionReport> out;
    const double n = static_cast<double>(segments_.size());
    for (std::size_t s = 0; s < segments_.size(); ++s)
        for (SectionReport r : segments_[s].sections()) {
            r.xi = (static_cast<double>(s) + r.xi) / n;
            out.push_back(r);
        }
    return out;
}

} // namespace plastica
