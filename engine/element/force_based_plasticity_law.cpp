#include "element/force_based_plasticity_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plastica {

namespace {
constexpr int max_element_iterations = 40;
// The element iterations have settled when the work of their last correction, Δq·(e − e(q)),
// is this small against the member's work scale N_y·ε_y·L0 + M_y·κ_y·L0 (about 1e-11 of the
// forces and deformations), or when it no longer falls below a tenth of the previous one while
// under the looser bound (1e-8 of them): round-off of deformations far into the plastic range
// (a crushed ring's sections at 100 times their yield curvature) keeps the work near 1e-21.
constexpr double work_tolerance = 1e-22;
constexpr double round_off_work = 1e-16;
// The increment is taken in up to this many parts from the committed state where one part
// does not settle.
constexpr int most_parts = 64;
// The parallel elastic stiffness of each section, as a share of its own (see the header).
constexpr double regular_bending = 1e-9;
constexpr double regular_axial = 1e-4;
} // namespace

ForceBasedPlasticityLaw::ForceBasedPlasticityLaw(const SectionSpec& section, double L0, int integration_points)
    : L0_(L0), regular_(regular_axial * section.E * section.area, regular_bending * section.E * section.inertia),
      stiffening_(elastic_basic_stiffness(section.E * section.area, section.E * section.inertia, L0)) {
    const double yield_strain = section.steel ? section.steel->fy / section.steel->E : 1e-3;
    const double yield_curvature = 2.0 * yield_strain / section.surface_depth();
    work_scale_ = (section.E * section.area * yield_strain * yield_strain + section.E * section.inertia * yield_curvature * yield_curvature) * L0;
    const FibreSection prototype(section);
    for (const QuadraturePoint& at : gauss_lobatto(integration_points)) points_.push_back({at, prototype, {}, {}, {}, {}, {}, {}, {}});
}

void ForceBasedPlasticityLaw::evaluate(IntegrationPoint& p) {
    const double eps0 = p.deformation[0], curvature = p.deformation[1];
    p.trial = frozen_ ? p.section.set_trial_deformation_on_branches(eps0, curvature)
                      : p.section.set_trial_deformation(eps0, curvature);
    if (frozen_ && consistent_) consistent_ = p.section.branches_consistent();
    p.trial.N += regular_[0] * eps0;
    p.trial.M += regular_[1] * curvature;
    p.trial.tangent(0, 0) += regular_[0];
    p.trial.tangent(1, 1) += regular_[1];
    p.flexibility = p.trial.tangent.inverse();
}

bool ForceBasedPlasticityLaw::iterate(const Eigen::Vector3d& e) {
    // Newton with a backtracking line search on the correction's work: on a section whose fibres
    // sit at a kink, full steps can jump between branches for ever.
    double accepted_work = std::numeric_limits<double>::infinity(), scale = 1.0;
    Eigen::Vector3d start_q = q_t_, step_q = Eigen::Vector3d::Zero();
    for (int it = 0; it < max_element_iterations; ++it) {
        // Sections left at their deformations by the last settled trial need no new evaluation.
        const bool evaluate_sections = it > 0 || !sections_current_;
        sections_current_ = true;
        if (evaluate_sections) consistent_ = true;
        Eigen::Vector3d residual = e;
        flexibility_.setZero();
        for (IntegrationPoint& p : points_) {
            if (evaluate_sections) evaluate(p);
            const double wL = p.at.weight * L0_, a = p.at.xi - 1.0, b = p.at.xi;
            const Eigen::Vector2d unbalance = section_forces(p.at.xi, q_t_) - Eigen::Vector2d(p.trial.N, p.trial.M);
            residual -= wL * end_share(p.at.xi, p.deformation + p.flexibility * unbalance);
            // bᵀ f b, entry by entry.
            const Eigen::Matrix2d& f = p.flexibility;
            flexibility_(0, 0) += wL * f(0, 0);
            flexibility_(0, 1) += wL * f(0, 1) * a;
            flexibility_(0, 2) += wL * f(0, 1) * b;
            flexibility_(1, 1) += wL * f(1, 1) * a * a;
            flexibility_(1, 2) += wL * f(1, 1) * a * b;
            flexibility_(2, 2) += wL * f(1, 1) * b * b;
        }
        flexibility_(1, 0) = flexibility_(0, 1);
        flexibility_(2, 0) = flexibility_(0, 2);
        flexibility_(2, 1) = flexibility_(1, 2);
        const Eigen::Vector3d dq = flexibility_.ldlt().solve(residual);
        if (!dq.allFinite()) {
            sections_current_ = false;
            return false;
        }
        const double work = std::abs(dq.dot(residual)) / work_scale_;
        if (work <= work_tolerance || (work <= round_off_work && work > 0.1 * accepted_work)) return true;
        sections_current_ = false; // the deformations move on
        if (work > accepted_work && scale > 1.0 / 64) {
            // Back along the last step, halved.
            scale *= 0.5;
            q_t_ = start_q + scale * step_q;
            for (IntegrationPoint& p : points_) p.deformation = p.step_start + scale * p.step;
            continue;
        }
        accepted_work = work;
        scale = 1.0;
        start_q = q_t_;
        step_q = dq;
        q_t_ += dq;
        for (IntegrationPoint& p : points_) {
            const Eigen::Vector2d unbalance = section_forces(p.at.xi, q_t_) - Eigen::Vector2d(p.trial.N, p.trial.M);
            p.step_start = p.deformation;
            p.step = p.flexibility * unbalance;
            p.deformation += p.step;
        }
    }
    sections_current_ = false;
    return false;
}

void ForceBasedPlasticityLaw::trial_response(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) {
    // From the last trial where it settled (a warm start along the tangent), else from the
    // committed state; then from the committed state in parts.
    auto restart = [&] {
        sections_current_ = false;
        q_t_ = q_c_;
        for (IntegrationPoint& p : points_) p.deformation = p.committed_deformation;
    };
    if (!settled_) restart();
    settled_ = iterate(e);
    if (!settled_) {
        Eigen::Vector3d e_c = Eigen::Vector3d::Zero();
        for (int parts = 2; parts <= most_parts && !settled_; parts *= 2) {
            restart();
            // The committed deformations' end deformations, where the parts start.
            e_c.setZero();
            for (const IntegrationPoint& p : points_) e_c += p.at.weight * L0_ * end_share(p.at.xi, p.deformation);
            settled_ = true;
            for (int part = 1; part <= parts && settled_; ++part) settled_ = iterate(e_c + (e - e_c) * (double(part) / parts));
        }
    }
    q = q_t_;
    k = flexibility_.inverse();
    if (!q.allFinite() || !k.allFinite()) {
        // Newton will not accept this state (settled_ is false); it needs finite numbers.
        settled_ = false;
        restart();
        q = q_c_;
        k = Eigen::Matrix3d::Identity() * (regular_[1] / L0_);
    }
    stiffening_.add(e, q, k);
}

void ForceBasedPlasticityLaw::commit() {
    for (IntegrationPoint& p : points_) {
        p.section.commit();
        p.committed = p.trial;
        p.committed_deformation = p.deformation;
    }
    q_c_ = q_t_;
    settled_ = true;
    stiffening_.commit();
}

void ForceBasedPlasticityLaw::revert() {
    for (IntegrationPoint& p : points_) {
        p.section.revert();
        p.trial = p.committed;
        p.deformation = p.committed_deformation;
    }
    q_t_ = q_c_;
    settled_ = true;
    sections_current_ = false;
    stiffening_.revert();
}

std::vector<SectionReport> ForceBasedPlasticityLaw::sections() const {
    std::vector<SectionReport> out;
    out.reserve(points_.size());
    for (const IntegrationPoint& p : points_)
        out.push_back({p.at.xi, p.section.yielded_area_share(), p.committed_deformation[1], p.committed.M, p.committed.N});
    return out;
}

} // namespace plastica
