#include "element/plastic_hinge_law.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

namespace {
// η below this is a fully formed hinge; the floor keeps the series flexibility finite.
constexpr double eta_floor = 1e-12;
// An end within this fraction of its capacity is on the capacity curve.
constexpr double on_capacity = 1e-9;
} // namespace

PlasticHingeLaw::PlasticHingeLaw(const SectionSpec& section, double L0)
    : EA_(section.E * section.area), EI_(section.E * section.inertia), L0_(L0),
      sections_{FibreSection(section), FibreSection(section)} {}

Eigen::Matrix3d PlasticHingeLaw::stiffness(const std::array<double, 2>& eta,
                                           double axial_ratio) const {
    // Flexibility of the elastic beam plus the two hinge flexibilities (1 − η)/η · L/(6EI).
    const double unit = L0_ / (6.0 * EI_);
    Eigen::Matrix2d F;
    F << 2.0 * unit, -unit, -unit, 2.0 * unit;
    for (int end = 0; end < 2; ++end) {
        const double h = std::max(eta[end], eta_floor);
        F(end, end) += (1.0 - h) / h * unit;
    }
    Eigen::Matrix3d k = Eigen::Matrix3d::Zero();
    k(0, 0) = axial_ratio * EA_ / L0_;
    k.bottomRightCorner<2, 2>() = F.inverse();
    return k;
}

double PlasticHingeLaw::capacity(int end, double N, double m) const {
    return sections_[end].moment_capacity(N, m >= 0.0 ? 1.0 : -1.0);
}

void PlasticHingeLaw::trial(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) {
    const Eigen::Vector3d de = e - e_committed_;
    // Loading or unloading per end, judged by the elastic trial increment of its moment.
    const Eigen::Vector3d dq_elastic = elastic_basic_stiffness(EA_, EI_, L0_) * de;
    std::array<double, 2> eta{};
    for (int end = 0; end < 2; ++end) {
        const double m = section_moment(q_committed_, end);
        const double dm = section_moment(dq_elastic, end);
        const bool unloading = m * dm < 0.0;
        eta[end] = unloading ? 1.0 : committed_end_[end].ei_ratio;
    }
    // The axial term stays elastic. A section yielding in bending has EA_T → 0; applied to
    // the whole member that would leave its interior free along the axis (a spurious
    // mechanism). The N–M interaction acts through the capacity M_p(N) instead.
    const double axial_ratio = 1.0;

    std::array<bool, 2> at_capacity{false, false};
    k = stiffness(eta, axial_ratio);
    q = q_committed_ + k * de;
    // An end that crosses the capacity curve becomes a free hinge for the rest of the
    // increment; recomputing with its η = 0 lets the other end carry the redistribution.
    for (int pass = 0; pass < 2; ++pass) {
        bool changed = false;
        for (int end = 0; end < 2; ++end) {
            const double m = section_moment(q, end);
            if (!at_capacity[end] && std::abs(m) > capacity(end, q[0], m)) {
                at_capacity[end] = true;
                eta[end] = 0.0;
                changed = true;
            }
        }
        if (!changed) break;
        k = stiffness(eta, axial_ratio);
        q = q_committed_ + k * de;
    }
    // Return every end at capacity exactly onto the curve M = ±M_p(N).
    for (int end = 0; end < 2; ++end) {
        const double m = section_moment(q, end);
        const double cap = capacity(end, q[0], m);
        if (at_capacity[end] || std::abs(m) > cap) {
            const double projected = std::copysign(cap, m);
            if (end == 0) q[1] = -projected; else q[2] = projected;
        }
    }
    e_trial_ = e;
    q_trial_ = q;
}

void PlasticHingeLaw::commit() {
    for (int end = 0; end < 2; ++end) {
        FibreSection& section = sections_[end];
        HingeReport& report = committed_end_[end];
        const double N = q_trial_[0];
        const double m = section_moment(q_trial_, end);
        const double cap = capacity(end, N, m);
        report.utilisation = cap > 0.0 ? std::min(1.0, std::abs(m) / cap) : 1.0;
        ScmResult scm;
        if (report.utilisation < 1.0 - on_capacity)
            scm = section.solve_for_forces(N, m);
        if (scm.outcome == ScmOutcome::converged) {
            section.commit();
            report.ei_ratio = std::clamp(scm.ei_tangent / section.elastic_ei(), 0.0, 1.0);
            report.ea_ratio = std::clamp(scm.ea_tangent / section.elastic_ea(), 0.0, 1.0);
            report.state = report.ei_ratio < 1.0 - 1e-12 ? HingeState::yielding : HingeState::elastic;
        } else {
            // On the capacity curve the section has no unique deformation: a free hinge.
            section.revert();
            report.utilisation = 1.0;
            report.ei_ratio = 0.0;
            report.state = HingeState::plastic;
        }
        report.failed_fibres = section.failed_fibres();
        if (report.failed_fibres > 0) report.state = HingeState::failed;
    }
    e_committed_ = e_trial_;
    q_committed_ = q_trial_;
}

void PlasticHingeLaw::revert() {
    e_trial_ = e_committed_;
    q_trial_ = q_committed_;
    for (FibreSection& s : sections_) s.revert();
}

Eigen::Vector3d PlasticHingeLaw::plastic_deformation() const {
    // What the elastic beam cannot account for: e − k_el⁻¹ q.
    return e_committed_ - elastic_basic_stiffness(EA_, EI_, L0_).inverse() * q_committed_;
}

} // namespace plastica
