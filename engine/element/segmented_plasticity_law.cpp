#include "element/segmented_plasticity_law.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

namespace {
constexpr int max_condensation_iterations = 40;
// The inner nodes are in equilibrium when their forces are this small against the element's.
constexpr double inner_tolerance = 1e-10;
// The segments' parallel elastic stiffness (the plain law's is 1e-9): an inner node between
// fully plastic sections is held by it alone, and at 1e-9 the condensation lost nine digits, so
// that the condensed tangent no longer matched the forces (the ten times thicker ring stopped
// at δ = 39 where its top yields through). It changes the ring's P(100) by 1.3e-5.
constexpr double segment_regularisation = 1e-6;

} // namespace

template <int InnerDofs>
SegmentedPlasticityLaw<InnerDofs>::SegmentedPlasticityLaw(const SectionSpec& section, double L0, int segments,
                                                          int integration_points, double grading)
    : L0_(L0), segment_length_(L0 / segments), EA_(section.E * section.area), EI_(section.E * section.inertia),
      stiffening_(elastic_basic_stiffness(EA_, EI_, L0)) {
    const std::size_t n = static_cast<std::size_t>(segments), m = n - 1;
    // Lengths grow by `grading` from either end toward the middle.
    std::vector<double> length(n);
    double total = 0.0;
    for (std::size_t s = 0; s < n; ++s) total += length[s] = std::pow(grading, static_cast<double>(std::min(s, n - 1 - s)));
    segments_.reserve(n);
    bounds_.assign(1, 0.0);
    near_.resize(n);
    far_.resize(n);
    // The chord's stretch is shared in proportion to length, and an inner node's axial motion
    // (with the axial strain per segment) moves it between segments; θ_i and θ_j act on the
    // first and the last segment; an inner node's (w, θ) on the segments either side of it.
    basic_map_.assign(n, Eigen::Matrix3d::Zero());
    for (std::size_t s = 0; s < n; ++s) {
        const double l = length[s] * L0 / total;
        segments_.emplace_back(section, l, integration_points, segment_regularisation, DistributedPlasticityLaw::Axial::uniform_strain);
        bounds_.push_back(bounds_.back() + l);
        basic_map_[s](0, 0) = l / L0;
        if constexpr (InnerDofs == 2) {
            near_[s] << 0.0, 0.0, 1.0 / l, 1.0, 1.0 / l, 0.0;
            far_[s] << 0.0, 0.0, -1.0 / l, 0.0, -1.0 / l, 1.0;
        } else {
            near_[s] << -1.0, 0.0, 0.0, 0.0, 1.0 / l, 1.0, 0.0, 1.0 / l, 0.0;
            far_[s] << 1.0, 0.0, 0.0, 0.0, -1.0 / l, 0.0, 0.0, -1.0 / l, 1.0;
        }
    }
    basic_map_[0](1, 1) = 1.0;
    basic_map_[n - 1](2, 2) = 1.0;
    segment_forces_.resize(n);
    segment_tangents_.resize(n);
    pivot_inverse_.resize(m);
    multiplier_.resize(m);
    upper_.resize(m);
    coupling_.resize(m);
    solved_.resize(m);
    residual_.resize(m);
    inner_t_ = inner_c_ = std::vector<Inner>(m, Inner::Zero());
    // The elastic condensation, the warm start of the first trial: evaluated at rest.
    evaluate(Eigen::Vector3d::Zero(), inner_t_);
    Eigen::Vector3d q;
    Eigen::Matrix3d k;
    condense(residual_, q, k);
    condensation_c_ = condensation_t_;
    for (DistributedPlasticityLaw& s : segments_) s.revert();
}

template <int InnerDofs>
void SegmentedPlasticityLaw<InnerDofs>::evaluate(const Eigen::Vector3d& e, const std::vector<Inner>& inner) {
    const std::size_t n = segments_.size();
    for (std::size_t s = 0; s < n; ++s) {
        Eigen::Vector3d d = basic_map_[s] * e;
        if (s > 0) d.noalias() += near_[s] * inner[s - 1];
        if (s + 1 < n) d.noalias() += far_[s] * inner[s];
        segments_[s].trial(d, segment_forces_[s], segment_tangents_[s]);
    }
}

template <int InnerDofs>
template <class Column>
void SegmentedPlasticityLaw<InnerDofs>::solve_inner(std::vector<Column>& b) const {
    const std::size_t m = b.size();
    for (std::size_t i = 1; i < m; ++i) b[i] -= multiplier_[i] * b[i - 1];
    b[m - 1] = (pivot_inverse_[m - 1] * b[m - 1]).eval();
    for (std::size_t i = m - 1; i-- > 0;) b[i] = (pivot_inverse_[i] * (b[i] - upper_[i] * b[i + 1])).eval();
}

template <int InnerDofs>
void SegmentedPlasticityLaw<InnerDofs>::condense(std::vector<Inner>& inner_forces, Eigen::Vector3d& q, Eigen::Matrix3d& k) {
    // With one strain per element the maps are sparse, and the products are written out entry by
    // entry (dense 3 × 3 products were a fifth of a plastic-zone run): basic_map_ is
    // diag(l/L0, b_i, b_j), and an inner node's (w, θ) acts on the end rotations alone,
    // near·(w, θ) = (0, w/l + θ, w/l) and far·(w, θ) = (0, −w/l, −w/l + θ), 1/l = near_(1, 0).
    const std::size_t n = segments_.size(), m = n - 1;
    const std::vector<Eigen::Vector3d>& f = segment_forces_;
    const std::vector<Eigen::Matrix3d>& S = segment_tangents_;
    // Basic forces and K_ee = Σ Bᵀ S B.
    q.setZero();
    k.setZero();
    for (std::size_t s = 0; s < n; ++s) {
        const Eigen::Vector3d b = basic_map_[s].diagonal();
        q += b.cwiseProduct(f[s]);
        k += b.asDiagonal() * S[s] * b.asDiagonal();
    }
    // Inner node i (element node i + 1) is the far node of segment i (a) and the near one of
    // segment i + 1 (b). Block LDLᵀ of the chain: pivot_i = D_i − C_{i−1}ᵀ pivot_{i−1}⁻¹ C_{i−1}.
    inner_forces.resize(m);
    const auto eliminate = [&](std::size_t i, Block& pivot) {
        if (i > 0) {
            multiplier_[i].noalias() = upper_[i - 1].transpose() * pivot_inverse_[i - 1];
            pivot.noalias() -= multiplier_[i] * upper_[i - 1];
        }
        pivot_inverse_[i] = pivot.inverse();
    };
    if constexpr (InnerDofs == 2) {
        for (std::size_t i = 0; i < m; ++i) {
            const Eigen::Vector3d &fa = f[i], &fb = f[i + 1];
            const Eigen::Matrix3d &Sa = S[i], &Sb = S[i + 1];
            const double ga = near_[i](1, 0), gb = near_[i + 1](1, 0);
            const Eigen::Vector3d ba = basic_map_[i].diagonal(), bb = basic_map_[i + 1].diagonal();
            inner_forces[i] << -ga * (fa[1] + fa[2]) + gb * (fb[1] + fb[2]), fa[2] + fb[1];
            for (int j = 0; j < 3; ++j) {
                coupling_[i](0, j) = -ga * (Sa(1, j) + Sa(2, j)) * ba[j] + gb * (Sb(1, j) + Sb(2, j)) * bb[j];
                coupling_[i](1, j) = Sa(2, j) * ba[j] + Sb(1, j) * bb[j];
            }
            const double sum_a = Sa(1, 1) + Sa(1, 2) + Sa(2, 1) + Sa(2, 2), sum_b = Sb(1, 1) + Sb(1, 2) + Sb(2, 1) + Sb(2, 2);
            Block pivot;
            pivot << ga * ga * sum_a + gb * gb * sum_b, -ga * (Sa(1, 2) + Sa(2, 2)) + gb * (Sb(1, 1) + Sb(2, 1)),
                -ga * (Sa(2, 1) + Sa(2, 2)) + gb * (Sb(1, 1) + Sb(1, 2)), Sa(2, 2) + Sb(1, 1);
            // near(b)ᵀ S_b far(b): the coupling of this node to the next through segment b.
            if (i + 1 < m)
                upper_[i] << -gb * gb * sum_b, gb * (Sb(1, 2) + Sb(2, 2)), -gb * (Sb(1, 1) + Sb(1, 2)), Sb(1, 2);
            eliminate(i, pivot);
        }
    } else {
        // With the axial freedom the maps are dense enough for plain products.
        for (std::size_t i = 0; i < m; ++i) {
            const InnerMap &Fa = far_[i], &Nb = near_[i + 1];
            const Block FaS = Fa.transpose() * S[i], NbS = Nb.transpose() * S[i + 1];
            inner_forces[i].noalias() = Fa.transpose() * f[i] + Nb.transpose() * f[i + 1];
            coupling_[i].noalias() = FaS * basic_map_[i].diagonal().asDiagonal();
            coupling_[i].noalias() += NbS * basic_map_[i + 1].diagonal().asDiagonal();
            Block pivot = FaS * Fa;
            pivot.noalias() += NbS * Nb;
            if (i + 1 < m) upper_[i].noalias() = NbS * far_[i + 1];
            eliminate(i, pivot);
        }
    }
    solved_ = coupling_;
    solve_inner(solved_);
    condensation_t_.resize(m);
    for (std::size_t i = 0; i < m; ++i) {
        condensation_t_[i] = -solved_[i];
        k.noalias() -= coupling_[i].transpose() * solved_[i];
    }
}

template <int InnerDofs>
double SegmentedPlasticityLaw<InnerDofs>::inner_residual(const std::vector<Inner>& r) const {
    // Moments against the segment length, so that the norm adds forces.
    double sum = 0.0;
    for (const Inner& v : r) {
        if constexpr (InnerDofs == 3) sum += v[0] * v[0];
        sum += v[InnerDofs - 2] * v[InnerDofs - 2] + (v[InnerDofs - 1] / segment_length_) * (v[InnerDofs - 1] / segment_length_);
    }
    return std::sqrt(sum);
}

template <int InnerDofs>
void SegmentedPlasticityLaw<InnerDofs>::trial_response(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) {
    // Start from the last trial state moved along its condensed tangent: exact while every
    // section stays on its branch, so an elastic element needs one evaluation.
    std::vector<Inner>& inner = inner_t_;
    for (std::size_t i = 0; i < inner.size(); ++i) inner[i].noalias() += condensation_t_[i] * (e - e_t_);
    e_t_ = e;
    evaluate(e, inner);
    condense(residual_, q, k);
    double residual = inner_residual(residual_);
    // Against the end forces, and against the elastic forces of the deformation, which set
    // the round-off of every force here.
    const double scale = std::abs(q[0]) + (std::abs(q[1]) + std::abs(q[2])) / segment_length_ +
                         EA_ * std::abs(e[0]) / L0_ + EI_ * (std::abs(e[1]) + std::abs(e[2])) / (L0_ * segment_length_);
    inner_converged_ = residual <= inner_tolerance * scale;
    // Newton on the inner nodes with a backtracking line search: the fibres' piecewise-linear
    // law can make a full step jump across a kink, and a shortened one lands between.
    // A state whose inner nodes are not in equilibrium is not accepted (states_consistent).
    for (int it = 0; it < max_condensation_iterations && !inner_converged_; ++it) {
        step_ = residual_;
        solve_inner(step_);
        line_start_ = inner;
        double length = 1.0;
        for (int cut = 0;; ++cut) {
            for (std::size_t i = 0; i < inner.size(); ++i) inner[i] = line_start_[i] - length * step_[i];
            evaluate(e, inner);
            condense(residual_, q, k);
            const double next = inner_residual(residual_);
            if (next < residual || cut == 40 || !std::isfinite(next)) {
                residual = next;
                break;
            }
            length *= 0.5;
        }
        if (!std::isfinite(residual)) break;
        inner_converged_ = residual <= inner_tolerance * scale;
    }
    stiffening_.add(e, q, k);
}

template <int InnerDofs>
void SegmentedPlasticityLaw<InnerDofs>::commit() {
    for (DistributedPlasticityLaw& s : segments_) s.commit();
    e_c_ = e_t_;
    inner_c_ = inner_t_;
    condensation_c_ = condensation_t_;
    stiffening_.commit();
}

template <int InnerDofs>
void SegmentedPlasticityLaw<InnerDofs>::revert() {
    for (DistributedPlasticityLaw& s : segments_) s.revert();
    e_t_ = e_c_;
    inner_t_ = inner_c_;
    condensation_t_ = condensation_c_;
    inner_converged_ = true;
    stiffening_.revert();
}

template <int InnerDofs>
std::vector<SectionReport> SegmentedPlasticityLaw<InnerDofs>::sections() const {
    std::vector<SectionReport> out;
    for (std::size_t s = 0; s < segments_.size(); ++s)
        for (SectionReport r : segments_[s].sections()) {
            r.xi = (bounds_[s] + r.xi * (bounds_[s + 1] - bounds_[s])) / L0_;
            out.push_back(r);
        }
    return out;
}

template class SegmentedPlasticityLaw<2>;
template class SegmentedPlasticityLaw<3>;

} // namespace plastica
