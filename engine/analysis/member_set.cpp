#include "analysis/member_set.hpp"

#include "element/distributed_plasticity_law.hpp"
#include "element/force_based_plasticity_law.hpp"
#include "element/plastic_hinge_law.hpp"
#include "element/released_ends_law.hpp"
#include "element/segmented_plasticity_law.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

namespace {

std::unique_ptr<BasicLaw> make_member_law(const SectionSpec& s, double L0, HingeEnds ends_served) {
    switch (s.plasticity) {
    case Plasticity::hinges: return std::make_unique<PlasticHingeLaw>(s, L0, ends_served);
    case Plasticity::distributed:
        if (s.formulation == Formulation::force) return std::make_unique<ForceBasedPlasticityLaw>(s, L0, s.integration_points);
        if (s.segments > 1 && s.axial_strain_per_segment)
            return std::make_unique<AxialStrainPerSegment>(s, L0, s.segments, s.integration_points, s.segment_grading);
        if (s.segments > 1) return std::make_unique<SharedAxialStrain>(s, L0, s.segments, s.integration_points, s.segment_grading);
        return std::make_unique<DistributedPlasticityLaw>(s, L0, s.integration_points);
    case Plasticity::none: break;
    }
    return std::make_unique<ElasticLaw>(s.E * s.area, s.E * s.inertia, L0);
}

// The member's law, its released ends condensed out.
std::unique_ptr<BasicLaw> make_law(const ElementSpec& e, const SectionSpec& s, double L0, HingeEnds ends_served) {
    std::unique_ptr<BasicLaw> law = make_member_law(s, L0, ends_served);
    if (!e.released[0] && !e.released[1]) return law;
    return std::make_unique<ReleasedEndsLaw>(std::move(law), e.released);
}

} // namespace

MemberSet::MemberSet(const Model& model, const std::vector<int>& equation, const FollowerPressure& pressure)
    : specs_(model.elements), equation_(equation), pressure_(pressure), joint_hinges_(model) {
    const std::vector<HingeEnds>& ends_served = joint_hinges_.ends_served();
    elements_.reserve(model.elements.size());
    for (std::size_t i = 0; i < model.elements.size(); ++i) {
        const ElementSpec& e = model.elements[i];
        const Node& a = model.nodes[e.node_i];
        const Node& b = model.nodes[e.node_j];
        const SectionSpec& section = model.sections[e.section];
        distributed_.push_back(section.plasticity == Plasticity::distributed);
        elastic_ea_.push_back(section.plasticity == Plasticity::none ? section.E * section.area : 0.0);
        elements_.emplace_back(a, b, make_law(e, section, std::hypot(b.x - a.x, b.y - a.y), ends_served[i]),
                               model.analysis.geometry == Geometry::first_order);
        std::vector<int> held;
        for (int local = 0; local < 6; ++local)
            if (equation_[dofs_per_node * (local < 3 ? e.node_i : e.node_j) + local % 3] < 0) held.push_back(local);
        held_dofs_.push_back(std::move(held));
    }
}

bool MemberSet::evaluate(const EvaluationPoint& at, Eigen::VectorXd& internal, Eigen::VectorXd& coupling) {
    tangent_takes_axial_forces_ = false;
    evaluated_load_factor_ = at.load_factor;
    Vector6 d, f;
    Matrix6 k;
    int dofs[6];
    for (std::size_t e = 0; e < elements_.size(); ++e) {
        const ElementSpec& spec = specs_[e];
        for (int a = 0; a < 3; ++a) {
            dofs[a] = dofs_per_node * spec.node_i + a;
            dofs[3 + a] = dofs_per_node * spec.node_j + a;
        }
        for (int a = 0; a < 6; ++a) d[a] = at.u[dofs[a]];
        elements_[e].freeze_states(distributed_[e] ? at.freeze_fibres : at.freeze_hinges);
        elements_[e].compute(d, f, nullptr);
        if (!f.allFinite()) {
            name_non_finite(e);
            return false;
        }
        for (int a = 0; a < 6; ++a) internal[dofs[a]] += f[a];
        // Prescribed displacements act on the free DOFs through the element's tangent.
        const std::vector<int>& held = held_dofs_[e];
        if (std::none_of(held.begin(), held.end(), [&](int b) { return at.ubar[dofs[b]] != 0.0; })) continue;
        if (!element_tangent(e, k)) return false;
        for (int a = 0; a < 6; ++a) {
            const int row = equation_[dofs[a]];
            if (row < 0) continue;
            for (int b : held)
                if (at.ubar[dofs[b]] != 0.0) coupling[row] += k(a, b) * at.ubar[dofs[b]];
        }
    }
    return true;
}

void MemberSet::append_blocks(std::vector<std::vector<int>>& blocks) const {
    for (const ElementSpec& e : specs_) {
        std::vector<int> b;
        for (int node : {e.node_i, e.node_j})
            for (int d = 0; d < dofs_per_node; ++d) b.push_back(equation_[dofs_per_node * node + d]);
        blocks.push_back(std::move(b));
    }
}

void MemberSet::assemble(BlockAssembler& assembler, std::size_t first) const {
    Matrix6 k;
    for (std::size_t e = 0; e < elements_.size(); ++e) {
        element_stiffness(e, k);
        assembler.add(first + e, k);
    }
}

bool MemberSet::find_non_finite_tangent() const {
    Matrix6 k;
    for (std::size_t e = 0; e < elements_.size(); ++e)
        if (!element_tangent(e, k)) return true;
    return false;
}

void MemberSet::name_non_finite(std::size_t e) const {
    const ElementSpec& spec = specs_[e];
    non_finite_where_ = "element " + std::to_string(e + 1) + " (nodes " + std::to_string(spec.node_i + 1) + "–" +
                        std::to_string(spec.node_j + 1) + ")";
}

void MemberSet::take_axial_forces_in_tangent(const Eigen::VectorXd& forces) {
    tangent_axial_forces_ = forces;
    tangent_takes_axial_forces_ = true;
}

Eigen::VectorXd MemberSet::axial_forces() const {
    Eigen::VectorXd forces(elements_.size());
    for (std::size_t e = 0; e < elements_.size(); ++e) forces[static_cast<Eigen::Index>(e)] = elements_[e].forces().axial;
    return forces;
}

std::array<int, 6> MemberSet::dofs(std::size_t e) const {
    const ElementSpec& spec = specs_[e];
    std::array<int, 6> out{};
    for (int a = 0; a < 3; ++a) {
        out[static_cast<std::size_t>(a)] = dofs_per_node * spec.node_i + a;
        out[static_cast<std::size_t>(3 + a)] = dofs_per_node * spec.node_j + a;
    }
    return out;
}

Eigen::VectorXd MemberSet::axial_force_rates(const Eigen::VectorXd& rate) const {
    Eigen::VectorXd out(static_cast<Eigen::Index>(elements_.size()));
    Vector6 d;
    for (std::size_t e = 0; e < elements_.size(); ++e) {
        const std::array<int, 6> at = dofs(e);
        for (int a = 0; a < 6; ++a) d[a] = rate[at[static_cast<std::size_t>(a)]];
        out[static_cast<Eigen::Index>(e)] = elements_[e].axial_force_rate(d);
    }
    return out;
}

SparseMatrix MemberSet::geometric_stiffness(const Eigen::VectorXd& axial_forces, int free_count, bool cubic) const {
    std::vector<Eigen::Triplet<double>> entries;
    Matrix6 k;
    for (std::size_t e = 0; e < elements_.size(); ++e) {
        elements_[e].geometric_stiffness(axial_forces[static_cast<Eigen::Index>(e)], k, cubic);
        // Follower pressure's load stiffness grows with its factor: its rate per unit factor.
        if (!pressure_.empty() && pressure_.loads(e)) k += pressure_.stiffness(e, 1.0) - pressure_.stiffness(e, 0.0);
        const std::array<int, 6> at = dofs(e);
        for (int a = 0; a < 6; ++a) {
            const int row = equation_[at[static_cast<std::size_t>(a)]];
            if (row < 0) continue;
            for (int b = 0; b < 6; ++b) {
                const int col = equation_[at[static_cast<std::size_t>(b)]];
                if (col >= 0 && k(a, b) != 0.0) entries.emplace_back(row, col, k(a, b));
            }
        }
    }
    SparseMatrix G(free_count, free_count);
    G.setFromTriplets(entries.begin(), entries.end());
    return G;
}

void MemberSet::element_stiffness(std::size_t e, Matrix6& k) const {
    // A start whose stretch is that close to the path's lies on it but for the stiff membrane's
    // own error (the ring's: about 1e-7); one further off (a cantilever rolled by 0.25 rad a
    // step: about 1e-3) is better served by the Jacobian at the start itself. Measured over the
    // elastic stability cases, limits of 1e-7 … 1e-3 took 4 641, 4 812, 4 490, 4 262 (1e-4),
    // 4 279 and 4 377 iterations; the start's own axial forces 4 630.
    constexpr double path_stretch_band = 1e-4;
    const double path_force = tangent_takes_axial_forces_ ? tangent_axial_forces_[static_cast<Eigen::Index>(e)] : 0.0;
    if (elastic_ea_[e] > 0.0 && tangent_takes_axial_forces_ &&
        std::abs(elements_[e].trial_axial_force() - path_force) <= path_stretch_band * elastic_ea_[e])
        elements_[e].tangent(k, path_force);
    else
        elements_[e].tangent(k);
    if (pressure_.follows_deformation() && pressure_.loads(e)) k += pressure_.stiffness(e, evaluated_load_factor_);
}

bool MemberSet::element_tangent(std::size_t e, Matrix6& k) const {
    element_stiffness(e, k);
    if (k.allFinite()) return true;
    name_non_finite(e);
    return false;
}

bool MemberSet::all_elastic() const {
    return std::all_of(elastic_ea_.begin(), elastic_ea_.end(), [](double ea) { return ea > 0.0; });
}

bool MemberSet::hinge_states_consistent() const {
    for (const CorotationalBeam& e : elements_)
        if (!e.law().states_consistent()) return false;
    return true;
}

double MemberSet::trial_yield_advance() const {
    double advance = 0.0;
    for (const CorotationalBeam& e : elements_) advance = std::max(advance, e.trial_yield_advance());
    return advance;
}

void MemberSet::stiffen_capacity(double ratio) {
    for (CorotationalBeam& e : elements_) e.stiffen_capacity(ratio);
}

void MemberSet::predict_unloading() {
    for (CorotationalBeam& e : elements_) e.predict_unloading();
}

void MemberSet::commit() {
    for (CorotationalBeam& e : elements_) e.commit();
    joint_hinges_.reassign(elements_);
}

void MemberSet::revert() {
    for (CorotationalBeam& e : elements_) e.revert();
}

void MemberSet::report(const Eigen::VectorXd&, bool with_sections, StepResult& out) const {
    out.elements.resize(elements_.size());
    out.hinge_count = out.plastic_hinge_count = 0;
    for (std::size_t e = 0; e < elements_.size(); ++e) {
        ElementResult& r = out.elements[e];
        r.forces = elements_[e].forces();
        r.hinged = elements_[e].law().has_hinges();
        if (with_sections) r.sections = elements_[e].law().sections();
        else r.sections.clear(); // out may hold an earlier step
        for (int end = 0; end < 2; ++end) r.hinge[end] = {};
        for (int end = 0; end < 2 && r.hinged; ++end) {
            r.hinge[end] = elements_[e].law().hinge(end);
            if (r.hinge[end].state != HingeState::elastic) ++out.hinge_count;
            if (r.hinge[end].state == HingeState::plastic || r.hinge[end].state == HingeState::failed)
                ++out.plastic_hinge_count;
        }
    }
}

} // namespace plastica
