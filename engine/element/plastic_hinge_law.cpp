#include "element/plastic_hinge_law.hpp"

#include "material/material_registry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plastica {

namespace {
// η below this is a fully formed pseudo-spring hinge; the floor keeps its hardening positive.
constexpr double eta_floor = 1e-6;
// An end within this fraction of its capacity is on the capacity surface.
constexpr double on_capacity = 1e-9;
constexpr double no_limit = std::numeric_limits<double>::infinity();
// How far a hinge's state advances is measured against its moment capacity at its axial force, but
// never against less than this share of M_p: near the squash load M_p(N) falls to nothing and
// |M|/M_p(N) would leap at any increment, so that adaptive steps shrank without end (the
// catenary beam with twice the yield stress stopped at 0.143 of 0.3 with increments of 1e-11).
constexpr double advance_capacity_floor = 0.1;
} // namespace

PlasticHingeLaw::PlasticHingeLaw(const SectionSpec& section, double L0, HingeEnds ends_served)
    : EA_(section.E * section.area), EI_(section.E * section.inertia), L0_(L0),
      sections_{FibreSection(section), FibreSection(section)},
      k_elastic_(elastic_basic_stiffness(EA_, EI_, L0_)), f_elastic_(k_elastic_.inverse()),
      moment_scale_(sections_[0].moment_capacity(0.0, 1.0)),
      capacity_at_{ends_served.capacity[0] > 0, ends_served.capacity[1] > 0}, ends_served_(ends_served) {
    if (section.steel) row_hardening_ = std::max(regularising_hardening, hardening_ratio(*section.steel));
    rows_.assign(row_count, YieldRow{});
    for (YieldRow& r : rows_) r.limit = no_limit;
    const FibreSection& s = sections_[0];
    rows_[tension].a = Eigen::Vector3d(1.0 / s.axial_capacity_tension(), 0.0, 0.0);
    rows_[compression].a = Eigen::Vector3d(-1.0 / s.axial_capacity_compression(), 0.0, 0.0);
    for (Row r : {tension, compression}) {
        rows_[r].limit = 1.0;
        rows_[r].hardening = row_hardening_ * rows_[r].a.dot(k_elastic_ * rows_[r].a);
    }
}

void PlasticHingeLaw::set_loading_surfaces() {
    // The pseudo-spring of a partly yielded end: s·m ≤ s·m_c + S·(rotation of the spring), with
    // s the sign of the committed moment; unit row a = s·∂m/∂q / M_p, so H = S / M_p².
    for (int end = 0; end < 2; ++end) {
        YieldRow& row = rows_[spring_i + end];
        const double m = section_moment(q_c_, end);
        if (eta_c_[end] >= 1.0 || m == 0.0) {
            row.limit = no_limit;
            continue;
        }
        const double s = m > 0.0 ? 1.0 : -1.0;
        row.a.setZero();
        row.a[1 + end] = (end == 0 ? -s : s) / moment_scale_;
        row.limit = row.a.dot(q_c_);
        const double eta = std::max(eta_c_[end], eta_floor);
        const double S = 6.0 * EI_ / L0_ * eta / (1.0 - eta);
        // Two equal ends' springs in series where this one stands for both: half as stiff.
        row.hardening = S / ends_served_.spring[end] / (moment_scale_ * moment_scale_);
    }
}

void PlasticHingeLaw::linearise_capacity(double N) {
    for (int r = capacity_i; r <= negative_j; ++r) {
        YieldRow& row = rows_[r];
        const int end = row_end(r);
        if (!capacity_at_[end]) {
            row.limit = no_limit;
            continue;
        }
        const double s = row_sign(r);
        const CapacityCurve& curve = sections_[end].hinge_capacity(s);
        const double n = std::clamp(N, curve.lowest(), curve.highest());
        const CapacityValue v = curve.at(n);
        // s·m − M_p′(N*)·N ≤ M_p(N*) − M_p′(N*)·N*, scaled by 1/M_p(0).
        row.a.setZero();
        row.a[0] = -v.slope / moment_scale_;
        row.a[1 + end] = (end == 0 ? -s : s) / moment_scale_;
        row.limit = (v.moment - v.slope * n) / moment_scale_ + hardened_[r];
        const double hardening = stiffened_ > 0.0 ? std::max(stiffened_, stiffened_own_factor * row_hardening_) : row_hardening_;
        row.hardening = hardening / ends_served_.capacity[end] * row.a.dot(k_elastic_ * row.a);
    }
}

double PlasticHingeLaw::capacity_margin(const Eigen::Vector3d& q, int end) const {
    const double m = section_moment(q, end);
    const double s = m >= 0.0 ? 1.0 : -1.0;
    const double cap = sections_[end].hinge_moment_capacity(q[0], s) +
                       hardened_[(s > 0.0 ? capacity_i : negative_i) + end] * moment_scale_;
    return cap - std::abs(m);
}

bool PlasticHingeLaw::outside_capacity(const Eigen::Vector3d& q) const {
    for (Row r : {tension, compression})
        if (rows_[r].a.dot(q) > 1.0 + hardened_[r]) return true;
    for (int end = 0; end < 2; ++end)
        if (capacity_at_[end] && capacity_margin(q, end) < -1e-12 * moment_scale_) return true;
    return false;
}

Eigen::Matrix3d PlasticHingeLaw::curved_tangent(const ReturnMap& r) const {
    if (curvature_t_ <= 0.0) return r.tangent;
    // The capacity normal turns with N: K̃ = (K⁻¹ + Σγ ∂a/∂q)⁻¹ replaces K.
    Eigen::Matrix3d flexibility = f_elastic_;
    flexibility(0, 0) += curvature_t_;
    return elastoplastic_tangent(flexibility.inverse(), rows_, r.active);
}

void PlasticHingeLaw::set_without_flow(const Eigen::Vector3d& e, const Eigen::Vector3d& q_now,
                                       const Eigen::Matrix3d& k_now, Eigen::Vector3d& q, Eigen::Matrix3d& k) {
    consistent_ = true;
    active_t_.clear();
    gamma_t_.clear();
    flow_t_.setZero();
    q = q_now;
    k = k_now;
    e_t_ = e;
    q_t_ = q;
}

void PlasticHingeLaw::trial_response(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) {
    if (e == e_c_ && !loading_c_.empty() && !unloading_predictor_) {
        // At the committed state the response is one-sided: give the tangent of continued
        // loading (the rows that carried the last step's flow), the predictor of the next step.
        set_without_flow(e, q_c_, elastoplastic_tangent(k_elastic_, rows_, loading_c_), q, k);
        return;
    }
    const Eigen::Vector3d q_trial = q_c_ + k_elastic_ * (e - e_c_);
    const bool springs = eta_c_[0] < 1.0 || eta_c_[1] < 1.0;
    curvature_t_ = 0.0;
    if (!springs && active_c_.empty() && !(frozen_ && !active_t_.empty()) && !outside_capacity(q_trial)) {
        // Elastic: no yielded end, inside the capacity surface.
        set_without_flow(e, q_trial, k_elastic_, q, k);
        return;
    }
    // The squash loads bound N only in an element without capacity rows: the capacity curve
    // itself meets M = 0 at them, so a third row through that vertex would be a multiple of the
    // other two there, its multipliers split by the regularising hardening alone (a whole
    // member at the squash load then swaps between splits from one iteration to the next).
    const bool axial_rows = !capacity_at_[0] && !capacity_at_[1];
    for (Row r : {tension, compression}) rows_[r].limit = axial_rows ? 1.0 + hardened_[r] : no_limit;
    // Linearise the capacity at the trial state, return, and repeat at the returned N.
    // The returned N is a function G of the N the surface is linearised at; the state on the
    // curved surface is its fixed point. Plain repetition N ← G(N) has the factor
    // −(γ·|M_p″|/M_p(0))·(EA/L) per pass, which a hinge flowing far in one step takes to 1 (N
    // then swings from pass to pass and the tangent no longer fits the state), so the fixed
    // point is found by the secant method on G(N) − N, kept inside the bracket the passes
    // have found (bisected where the secant leaves it or the active rows change, as they do
    // where the surface's side switches with N).
    double N = q_trial[0];
    double previous_N = 0.0, previous_gap = 0.0;
    double below = -std::numeric_limits<double>::infinity(); // G(N) > N there
    double above = std::numeric_limits<double>::infinity();  // G(N) < N there
    RowSet working = frozen_ ? active_t_ : active_c_;
    ReturnMap r;
    const double N_scale = sections_[0].axial_capacity_tension();
    for (int pass = 0; pass < 30; ++pass) {
        linearise_capacity(N);
        r = return_map(k_elastic_, q_trial, rows_, working, frozen_);
        if (!r.ok) break;
        const bool on_curve = std::any_of(r.active.begin(), r.active.end(),
                                          [](int row) { return capacity_row(row); });
        const double gap = r.q[0] - N;
        if (!on_curve || std::abs(gap) <= 1e-12 * N_scale) break;
        (gap > 0.0 ? below : above) = N;
        double next = r.q[0];
        const bool same_rows = pass > 0 && r.active == working;
        if (same_rows && N != previous_N) {
            const double derivative = (gap - previous_gap) / (N - previous_N);
            if (std::abs(derivative) > 1e-12) next = N - gap / derivative;
        }
        if (std::isfinite(below) && std::isfinite(above) && (!same_rows || next <= std::min(below, above) ||
                                                             next >= std::max(below, above)))
            next = 0.5 * (below + above);
        previous_N = N;
        previous_gap = gap;
        N = next;
        working = r.active;
    }
    if (!r.ok) {
        // No solution found: make the increment fail rather than accept a wrong state.
        q.setConstant(std::numeric_limits<double>::quiet_NaN());
        k = k_elastic_;
        return;
    }
    for (std::size_t i = 0; i < r.active.size(); ++i) {
        const int row = r.active[i];
        if (!capacity_row(row)) continue;
        const CapacityCurve& curve = sections_[row_end(row)].hinge_capacity(row_sign(row));
        curvature_t_ += std::max(r.multipliers[i], 0.0) * -curve.at(r.q[0]).curvature / moment_scale_;
    }
    consistent_ = r.consistent;
    active_t_ = r.active;
    gamma_t_ = r.multipliers;
    flow_t_ = r.flow;
    q = r.q;
    k = curved_tangent(r);
    e_t_ = e;
    q_t_ = q;
}

void PlasticHingeLaw::commit() {
    for (int end = 0; end < 2; ++end) {
        FibreSection& section = sections_[end];
        HingeReport& report = committed_end_[end];
        const double N = q_t_[0];
        const double m = section_moment(q_t_, end);
        // The capacity on the side the end bends to; unbent, the lower of the two sides.
        const double cap = m != 0.0 ? section.hinge_moment_capacity(N, m > 0.0 ? 1.0 : -1.0)
                                    : std::min(section.hinge_moment_capacity(N, 1.0), section.hinge_moment_capacity(N, -1.0));
        report.capacity = cap;
        // The true ratio: an end above its capacity must show above 1.
        report.utilisation = cap > 0.0 ? std::abs(m) / cap : 1.0;
        const bool flowing = std::any_of(active_t_.begin(), active_t_.end(), [&](int r) {
            return (capacity_row(r) && row_end(r) == end) || r == tension || r == compression;
        });
        // A plastic end stays plastic until its moment falls (no flicker between plastic and
        // yielding while it rides the surface without flowing in one step).
        const bool held = capacity_at_[end] && report.state == HingeState::plastic &&
                          std::abs(m) >= std::abs(section_moment(q_c_, end)) * (1.0 - 1e-12);
        const bool at_capacity =
            flowing || held || (capacity_at_[end] && capacity_margin(q_t_, end) <= on_capacity * moment_scale_);
        ScmResult scm;
        if (!at_capacity) scm = section.solve_for_forces(N, m);
        if (!at_capacity && scm.outcome == ScmOutcome::converged) {
            section.commit();
            report.ei_ratio = std::clamp(scm.ei_tangent / section.elastic_ei(), 0.0, 1.0);
            report.ea_ratio = std::clamp(scm.ea_tangent / section.elastic_ea(), 0.0, 1.0);
            report.state = report.ei_ratio < 1.0 - 1e-12 ? HingeState::yielding : HingeState::elastic;
            // An end whose spring the other end at the node stands for has none of its own.
            eta_c_[end] = ends_served_.spring[end] > 0 ? report.ei_ratio : 1.0;
        } else if (!at_capacity && scm.outcome == ScmOutcome::no_convergence) {
            // The section solve failed: keep the previous stiffness and say so.
            section.revert();
            ++report.section_failures;
        } else {
            // On the capacity surface (or between the fibre polygon and its rounding): the
            // capacity rows govern; no pseudo-spring. The fibres remember the state just below
            // capacity, so that an end that unloads and reloads is elastic up to the moment it
            // carried (left where they were when that state is out of the section's reach).
            section.revert();
            const double sign = m >= 0.0 ? 1.0 : -1.0;
            if (section.solve_for_forces(N, sign * (1.0 - 1e-3) * cap).outcome == ScmOutcome::converged) section.commit();
            else section.revert();
            report.ei_ratio = 0.0;
            report.ea_ratio = 0.0;
            report.state = at_capacity ? HingeState::plastic : HingeState::yielding;
            eta_c_[end] = 1.0;
        }
        report.failed_fibres = section.failed_fibres();
        if (report.failed_fibres > 0) report.state = HingeState::failed;
    }
    // The rows that flowed: capacity rows keep the limit their hardening reached (the next step
    // starts on the surface instead of being pulled back onto it), and all of them give the
    // next predictor's tangent.
    loading_c_.clear();
    for (std::size_t i = 0; i < active_t_.size() && i < gamma_t_.size(); ++i) {
        const int r = active_t_[i];
        if (gamma_t_[i] <= 0.0) continue;
        if (r >= capacity_i) hardened_[r] += rows_[r].hardening * gamma_t_[i];
        loading_c_.push_back(r);
    }
    e_c_ = e_t_;
    q_c_ = q_t_;
    unloading_predictor_ = false;
    // Only capacity rows carry over as a warm start; the loading surfaces move with the state.
    active_c_.clear();
    for (int r : active_t_)
        if (r >= capacity_i) active_c_.push_back(r);
    active_t_ = active_c_;
    gamma_t_.assign(active_t_.size(), 0.0);
    flow_t_.setZero();
    set_loading_surfaces();
    loading_c_.erase(std::remove_if(loading_c_.begin(), loading_c_.end(),
                                    [&](int r) { return !std::isfinite(rows_[r].limit); }),
                     loading_c_.end());
}

void PlasticHingeLaw::serve_hinge_ends(const HingeEnds& ends) {
    if (ends == ends_served_) return;
    for (int end = 0; end < 2; ++end) {
        capacity_at_[end] = ends.capacity[end] > 0;
        // An end that takes over its joint's spring starts from its section's committed
        // stiffness; at or beyond its capacity the capacity rows govern and it has none (a
        // spring row beside the capacity row of the same moment would make the two parallel).
        const bool at_capacity = capacity_at_[end] && capacity_margin(q_c_, end) <= on_capacity * moment_scale_;
        if (ends.spring[end] > 0 && ends_served_.spring[end] == 0) eta_c_[end] = at_capacity ? 1.0 : committed_end_[end].ei_ratio;
        if (ends.spring[end] == 0) eta_c_[end] = 1.0;
    }
    const auto dropped = [&](int r) { return capacity_row(r) && !capacity_at_[row_end(r)]; };
    active_c_.erase(std::remove_if(active_c_.begin(), active_c_.end(), dropped), active_c_.end());
    loading_c_.erase(std::remove_if(loading_c_.begin(), loading_c_.end(), dropped), loading_c_.end());
    // An end that takes over a joint at its capacity takes over the flow as well: its capacity
    // row on the side it bends to starts active and gives the next predictor, as the row of the
    // end it relieves did.
    for (int end = 0; end < 2; ++end) {
        if (ends.capacity[end] == 0 || ends_served_.capacity[end] > 0) continue;
        if (capacity_margin(q_c_, end) > on_capacity * moment_scale_) continue;
        const int row = (section_moment(q_c_, end) >= 0.0 ? capacity_i : negative_i) + end;
        if (std::find(active_c_.begin(), active_c_.end(), row) == active_c_.end()) active_c_.push_back(row);
        if (std::find(loading_c_.begin(), loading_c_.end(), row) == loading_c_.end()) loading_c_.push_back(row);
    }
    ends_served_ = ends;
    linearise_capacity(q_c_[0]); // the predictor's rows, at the committed axial force
    active_t_ = active_c_;
    gamma_t_.assign(active_t_.size(), 0.0);
    set_loading_surfaces();
    loading_c_.erase(std::remove_if(loading_c_.begin(), loading_c_.end(),
                                    [&](int r) { return !std::isfinite(rows_[r].limit); }),
                     loading_c_.end());
}

double PlasticHingeLaw::trial_yield_advance() const {
    // |M|/M_p(N) of an end in a state, against the capacity on the side it bends to.
    auto utilisation = [&](const Eigen::Vector3d& q, int end, double& capacity) {
        const double m = section_moment(q, end);
        capacity = std::max(sections_[end].hinge_moment_capacity(q[0], m >= 0.0 ? 1.0 : -1.0), advance_capacity_floor * moment_scale_);
        return capacity > 0.0 ? std::min(std::abs(m) / capacity, 1.0) : 0.0;
    };
    double advance = 0.0;
    for (int end = 0; end < 2; ++end) {
        double cap_t = 0.0, cap_c = 0.0;
        const double u_t = utilisation(q_t_, end, cap_t), u_c = utilisation(q_c_, end, cap_c);
        if (!(cap_t > 0.0) || !(cap_c > 0.0)) continue;
        const double side = section_moment(q_t_, end) >= 0.0 ? 1.0 : -1.0;
        const double u_y = std::clamp(sections_[end].first_fibre_yield_moment(q_t_[0], side) / cap_t, 0.0, 1.0);
        advance = std::max(advance, u_t - std::max(u_c, u_y));
    }
    return advance;
}

void PlasticHingeLaw::revert() {
    e_t_ = e_c_;
    q_t_ = q_c_;
    flow_t_.setZero();
    active_t_ = active_c_;
    gamma_t_.assign(active_t_.size(), 0.0);
    consistent_ = true;
    for (FibreSection& s : sections_) s.revert();
}

Eigen::Vector3d PlasticHingeLaw::plastic_deformation() const {
    // What the elastic beam cannot account for: e − k_el⁻¹ q.
    return e_c_ - f_elastic_ * q_c_;
}

} // namespace plastica
