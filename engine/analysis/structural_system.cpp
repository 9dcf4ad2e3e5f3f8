#include "analysis/structural_system.hpp"

#include "element/distributed_plasticity_law.hpp"
#include "element/force_based_plasticity_law.hpp"
#include "element/plastic_hinge_law.hpp"
#include "element/released_ends_law.hpp"
#include "element/segmented_plasticity_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plastica {

namespace {

std::vector<int> number_equations(const Model& model, int& free_count) {
    const int n = model.dof_count();
    std::vector<bool> constrained(n, false);
    for (const Support& s : model.supports)
        for (int d = 0; d < dofs_per_node; ++d)
            if (s.fixed[d]) constrained[dofs_per_node * s.node + d] = true;
    for (const PrescribedDisplacement& p : model.prescribed)
        constrained[dofs_per_node * p.node + p.dof] = true;
    // A rotation that only released member ends meet has no stiffness: held at zero.
    const std::vector<bool> unattached = model.rotation_unattached();
    for (std::size_t node = 0; node < unattached.size(); ++node)
        if (unattached[node]) constrained[dofs_per_node * node + 2] = true;
    std::vector<int> eq(n, -1);
    free_count = 0;
    for (int i = 0; i < n; ++i)
        if (!constrained[i]) eq[i] = free_count++;
    return eq;
}

std::vector<std::vector<int>> assembly_blocks(const Model& model, const std::vector<int>& eq) {
    std::vector<std::vector<int>> blocks;
    for (const ElementSpec& e : model.elements) {
        std::vector<int> b;
        for (int node : {e.node_i, e.node_j})
            for (int d = 0; d < dofs_per_node; ++d) b.push_back(eq[dofs_per_node * node + d]);
        blocks.push_back(std::move(b));
    }
    for (const FoundationSpring& s : model.springs) {
        std::vector<int> b;
        for (int d = 0; d < dofs_per_node; ++d) b.push_back(eq[dofs_per_node * s.node + d]);
        blocks.push_back(std::move(b));
    }
    return blocks;
}

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

std::vector<Eigen::VectorXd> nodal_loads(const Model& model) {
    std::vector<Eigen::VectorXd> force(model.patterns.size(), Eigen::VectorXd::Zero(model.dof_count()));
    for (const NodalLoad& l : model.loads)
        for (int d = 0; d < dofs_per_node; ++d) force[static_cast<std::size_t>(l.pattern)][dofs_per_node * l.node + d] += l.value[d];
    return force;
}

} // namespace

StructuralSystem::StructuralSystem(const Model& model)
    : element_specs_(model.elements), nodes_(model.nodes), foundation_(model), self_contact_(model),
      pressure_(model),
      joint_hinges_(model), pattern_loads_(nodal_loads(model)),
      equation_(number_equations(model, free_count_)),
      assembler_(free_count_, assembly_blocks(model, equation_)) {
    if (!self_contact_.empty()) blocks_ = assembly_blocks(model, equation_);
    member_blocks_ = blocks_.size();
    for (const FoundationSpring& s : model.springs)
        on_moving_base_.push_back(s.unilateral && !s.anchored && model.bases.at(static_cast<std::size_t>(s.base)).moves());
    for (std::size_t p = 0; p < model.patterns.size(); ++p) platens_only_.push_back(model.driven_by_platens(static_cast<int>(p)));
    PatternFactors first(model.patterns.size());
    first.driven = model.analysis.pattern;
    set_pattern_factors(first);
    const std::vector<HingeEnds>& ends_served = joint_hinges_.ends_served();
    elements_.reserve(model.elements.size());
    for (std::size_t i = 0; i < model.elements.size(); ++i) {
        const ElementSpec& e = model.elements[i];
        const Node& a = model.nodes[e.node_i];
        const Node& b = model.nodes[e.node_j];
        const SectionSpec& section = model.sections[e.section];
        distributed_.push_back(section.plasticity == Plasticity::distributed);
        elastic_ea_.push_back(section.plasticity == Plasticity::none ? section.E * section.area : 0.0);
        elements_.emplace_back(a, b, make_law(e, section, std::hypot(b.x - a.x, b.y - a.y), ends_served[i]));
        std::vector<int> held;
        for (int local = 0; local < 6; ++local)
            if (equation_[dofs_per_node * (local < 3 ? e.node_i : e.node_j) + local % 3] < 0) held.push_back(local);
        held_dofs_.push_back(std::move(held));
    }
    dof_of_equation_.assign(static_cast<std::size_t>(free_count_), 0);
    for (int i = 0; i < dof_count(); ++i)
        if (equation_[i] >= 0) dof_of_equation_[static_cast<std::size_t>(equation_[i])] = i;
    internal_ = Eigen::VectorXd::Zero(dof_count());
    coupling_ = Eigen::VectorXd::Zero(free_count_);
}

void StructuralSystem::set_pattern_factors(const PatternFactors& factors) {
    fixed_load_ = pattern_loads_[static_cast<std::size_t>(factors.driven)];
    held_fixed_load_ = Eigen::VectorXd::Zero(fixed_load_.size());
    for (std::size_t p = 0; p < pattern_loads_.size(); ++p)
        if (factors.constant(static_cast<int>(p)) != 0.0) held_fixed_load_ += factors.constant(static_cast<int>(p)) * pattern_loads_[p];
    load_ = fixed_load_;
    held_load_ = held_fixed_load_;
    pressure_.set_pattern_factors(factors);
    foundation_.set_pattern_factors(factors);
    driven_by_platens_ = platens_only_[static_cast<std::size_t>(factors.driven)];
}

bool StructuralSystem::evaluate(const Eigen::VectorXd& u, const Eigen::VectorXd& ubar, double load_factor,
                                bool freeze_active, bool freeze_hinges, bool freeze_fibres) {
    internal_.setZero();
    coupling_.setZero();
    tangent_assembled_ = false;
    tangent_takes_axial_forces_ = false;
    evaluated_load_factor_ = load_factor;
    Vector6 d, f;
    Matrix6 k;
    int dofs[6];
    for (std::size_t e = 0; e < elements_.size(); ++e) {
        const ElementSpec& spec = element_specs_[e];
        for (int a = 0; a < 3; ++a) {
            dofs[a] = dofs_per_node * spec.node_i + a;
            dofs[3 + a] = dofs_per_node * spec.node_j + a;
        }
        for (int a = 0; a < 6; ++a) d[a] = u[dofs[a]];
        elements_[e].freeze_states(distributed_[e] ? freeze_fibres : freeze_hinges);
        elements_[e].compute(d, f, nullptr);
        if (!f.allFinite()) {
            name_non_finite(e);
            return false;
        }
        for (int a = 0; a < 6; ++a) internal_[dofs[a]] += f[a];
        // Prescribed displacements act on the free DOFs through the element's tangent.
        const std::vector<int>& held = held_dofs_[e];
        if (std::none_of(held.begin(), held.end(), [&](int b) { return ubar[dofs[b]] != 0.0; })) continue;
        if (!element_tangent(e, k)) return false;
        for (int a = 0; a < 6; ++a) {
            const int row = equation_[dofs[a]];
            if (row < 0) continue;
            for (int b : held)
                if (ubar[dofs[b]] != 0.0) coupling_[row] += k(a, b) * ubar[dofs[b]];
        }
    }
    if (!pressure_.empty()) {
        load_ = fixed_load_;
        pressure_.add_forces(u, load_);
        held_load_ = held_fixed_load_;
        pressure_.add_held_forces(u, held_load_);
    }
    foundation_.evaluate(u, load_factor, freeze_active);
    for (std::size_t s = 0; s < foundation_.size(); ++s) {
        const int base = dofs_per_node * foundation_.spring(s).node;
        const Eigen::Vector3d fs = foundation_.internal_force(s);
        internal_.segment<3>(base) += fs;
        // A platen moving with λ acts on the free DOFs as prescribed displacements do.
        const Eigen::Vector3d rate = foundation_.load_rate(s);
        for (int d = 0; d < dofs_per_node; ++d)
            if (rate[d] != 0.0 && equation_[base + d] >= 0) coupling_[equation_[base + d]] += rate[d];
    }
    if (!self_contact_.empty()) {
        self_contact_.evaluate(u, freeze_active, undecided_force_);
        for (const SurfaceContact& c : self_contact_.contacts()) {
            const std::array<int, 3> nodes = c.node_list();
            for (int k = 0; k < c.nodes(); ++k) internal_.segment<2>(dofs_per_node * nodes[k]) += c.force.segment<2>(2 * k);
        }
        if (add_surface_blocks()) assembler_ = BlockAssembler(free_count_, blocks_);
    }
    return true;
}

bool StructuralSystem::add_surface_blocks() {
    bool added = false;
    for (const SurfaceContact& c : self_contact_.contacts()) {
        const std::array<int, 3> nodes = c.node_list();
        if (surface_block_.count(nodes)) continue;
        std::vector<int> block;
        for (int k = 0; k < c.nodes(); ++k)
            for (int d = 0; d < dofs_per_node; ++d) block.push_back(equation_[dofs_per_node * nodes[k] + d]);
        surface_block_[nodes] = blocks_.size();
        blocks_.push_back(std::move(block));
        added = true;
    }
    return added;
}

void StructuralSystem::keep_touching_surface_blocks() {
    if (surface_block_.size() == self_contact_.contacts().size()) return; // every registered pair touches
    blocks_.resize(member_blocks_);
    surface_block_.clear();
    add_surface_blocks();
    assembler_ = BlockAssembler(free_count_, blocks_);
    tangent_assembled_ = false;
}

bool StructuralSystem::contact_settled() const {
    return !foundation_.active_set_changed() && foundation_.active_set_consistent() &&
           !self_contact_.active_set_changed() && self_contact_.active_set_consistent();
}

void StructuralSystem::name_non_finite(std::size_t e) const {
    const ElementSpec& spec = element_specs_[e];
    non_finite_where_ = "element " + std::to_string(e + 1) + " (nodes " + std::to_string(spec.node_i + 1) + "–" +
                        std::to_string(spec.node_j + 1) + ")";
}

void StructuralSystem::take_axial_forces_in_tangent(const Eigen::VectorXd& forces) {
    tangent_axial_forces_ = forces;
    tangent_takes_axial_forces_ = true;
    tangent_assembled_ = false;
}

Eigen::VectorXd StructuralSystem::axial_forces() const {
    Eigen::VectorXd forces(elements_.size());
    for (std::size_t e = 0; e < elements_.size(); ++e) forces[static_cast<Eigen::Index>(e)] = elements_[e].forces().axial;
    return forces;
}

void StructuralSystem::element_stiffness(std::size_t e, Matrix6& k) const {
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
    if (!pressure_.empty() && pressure_.loads(e)) k += pressure_.stiffness(e, evaluated_load_factor_);
}

bool StructuralSystem::element_tangent(std::size_t e, Matrix6& k) const {
    element_stiffness(e, k);
    if (k.allFinite()) return true;
    name_non_finite(e);
    return false;
}

void StructuralSystem::assemble_tangent() const {
    assembler_.set_zero();
    Matrix6 k;
    for (std::size_t e = 0; e < elements_.size(); ++e) {
        element_stiffness(e, k);
        assembler_.add(e, k);
    }
    for (std::size_t s = 0; s < foundation_.size(); ++s) assembler_.add(elements_.size() + s, foundation_.tangent(s));
    Eigen::Matrix<double, 9, 9> surface;
    for (const SurfaceContact& c : self_contact_.contacts()) {
        // The pair's translations into its nodes' three DOFs (no moment: the normal passes
        // through both centre lines).
        surface.setZero();
        for (int a = 0; a < c.nodes(); ++a)
            for (int b = 0; b < c.nodes(); ++b) surface.block<2, 2>(3 * a, 3 * b) = c.tangent.block<2, 2>(2 * a, 2 * b);
        const std::size_t block = surface_block_.at(c.node_list());
        if (c.nodes() == 2) assembler_.add(block, surface.topLeftCorner<6, 6>());
        else assembler_.add(block, surface);
    }
    tangent_assembled_ = true;
    // Finite entries have a finite sum unless it overflows (no structure is that stiff): one sum
    // instead of a test of every element's entries. Only if it is not finite are the elements
    // tested one by one, to name the one at fault.
    const SparseMatrix& K = assembler_.matrix();
    const Eigen::Map<const Eigen::ArrayXd> values(K.valuePtr(), K.nonZeros());
    tangent_finite_ = true;
    if (std::isfinite(values.sum())) return;
    for (std::size_t e = 0; e < elements_.size() && tangent_finite_; ++e) tangent_finite_ = element_tangent(e, k);
}

const SparseMatrix& StructuralSystem::tangent() const {
    if (!tangent_assembled_) assemble_tangent();
    return assembler_.matrix();
}

bool StructuralSystem::tangent_finite() const {
    if (!tangent_assembled_) assemble_tangent();
    return tangent_finite_;
}

bool StructuralSystem::all_members_elastic() const {
    return std::all_of(elastic_ea_.begin(), elastic_ea_.end(), [](double ea) { return ea > 0.0; });
}

bool StructuralSystem::hinge_states_consistent() const {
    for (const CorotationalBeam& e : elements_)
        if (!e.law().states_consistent()) return false;
    return true;
}

double StructuralSystem::trial_yield_advance() const {
    double advance = 0.0;
    for (const CorotationalBeam& e : elements_) advance = std::max(advance, e.trial_yield_advance());
    return advance;
}

double StructuralSystem::round_off_force(const Eigen::VectorXd& u_full) const {
    // A displacement is known to about eps·|u|, so the residual of K·u cannot be brought below
    // about eps·|K|·|u| (absolute values throughout). K is stored as its lower triangle.
    const SparseMatrix& K = tangent();
    const Eigen::VectorXd u = gather(u_full).cwiseAbs();
    Eigen::VectorXd floor = Eigen::VectorXd::Zero(u.size());
    for (int col = 0; col < K.outerSize(); ++col)
        for (SparseMatrix::InnerIterator it(K, col); it; ++it) {
            const double k = std::abs(it.value());
            floor[it.row()] += k * u[col];
            if (it.row() != col) floor[col] += k * u[it.row()];
        }
    return std::numeric_limits<double>::epsilon() * floor.norm();
}

RoundOffFloor StructuralSystem::round_off_floor(const Eigen::VectorXd& u_full, double load_factor) const {
    // Relative to the load, round_off_force is this state's floor.
    const double force = round_off_force(u_full);
    // The springs' share: their stiffness times the rounding of their node's displacement.
    Eigen::VectorXd springs = Eigen::VectorXd::Zero(u_full.size());
    for (std::size_t s = 0; s < foundation_.size(); ++s) {
        const FoundationSpring& spring = foundation_.spring(s);
        const std::size_t at = static_cast<std::size_t>(dofs_per_node) * static_cast<std::size_t>(spring.node);
        const double k[3] = {spring.kx, spring.ky, spring.krot};
        for (std::size_t d = 0; d < 3; ++d) springs[at + d] += k[d] * std::abs(u_full[at + d]);
    }
    const double load = gather(external_force(load_factor)).norm();
    if (!(load > 0.0)) return {0.0, 0.0, force};
    return {force / load, std::numeric_limits<double>::epsilon() * springs.norm() / load, force};
}

Eigen::VectorXd StructuralSystem::gather(const Eigen::VectorXd& full) const {
    Eigen::VectorXd free;
    gather(full, free);
    return free;
}

void StructuralSystem::gather(const Eigen::VectorXd& full, Eigen::VectorXd& free) const {
    free.resize(free_count_);
    for (int k = 0; k < free_count_; ++k) free[k] = full[dof_of_equation_[static_cast<std::size_t>(k)]];
}

void StructuralSystem::scatter(const Eigen::VectorXd& free, Eigen::VectorXd& full) const {
    for (int k = 0; k < free_count_; ++k) full[dof_of_equation_[static_cast<std::size_t>(k)]] = free[k];
}

void StructuralSystem::predict_unloading() {
    for (CorotationalBeam& e : elements_) e.predict_unloading();
}

void StructuralSystem::commit() {
    for (CorotationalBeam& e : elements_) e.commit();
    if (!self_contact_.empty()) keep_touching_surface_blocks();
    joint_hinges_.reassign(elements_);
}

void StructuralSystem::revert() {
    // The tangent stays that of the last evaluation, as the elements' trial states go back.
    if (!tangent_assembled_) assemble_tangent();
    for (CorotationalBeam& e : elements_) e.revert();
}

void StructuralSystem::report(const Eigen::VectorXd& u, const Eigen::VectorXd& external,
                              StepResult& out, bool with_sections) const {
    out.displacement.assign(u.data(), u.data() + u.size());
    out.reaction.assign(u.size(), 0.0);
    out.applied_load.assign(external.data(), external.data() + external.size());
    for (int i = 0; i < dof_count(); ++i)
        if (equation_[i] < 0) out.reaction[i] = internal_[i] - external[i];
    // Spring forces are not support reactions: take them out of the supported DOFs.
    for (std::size_t s = 0; s < foundation_.size(); ++s) {
        const int base = dofs_per_node * foundation_.spring(s).node;
        for (int d = 0; d < dofs_per_node; ++d)
            if (equation_[base + d] < 0) out.reaction[base + d] -= foundation_.internal_force(s)[d];
    }

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

    out.springs.resize(foundation_.size());
    out.contact_count = 0;
    out.base_reaction = 0.0;
    std::vector<bool> in_contact(nodes_.size(), false);
    for (std::size_t s = 0; s < foundation_.size(); ++s) {
        const SpringState& st = foundation_.states()[s];
        SpringResult& r = out.springs[s];
        r.node = st.node;
        r.unilateral = st.unilateral;
        r.active = st.unilateral ? st.active : true;
        r.gap = st.gap;
        r.force = {st.force[0], st.force[1], st.force[2]};
        if (st.unilateral && st.active) {
            ++out.contact_count;
            out.base_reaction += st.force.head<2>().norm();
            in_contact[st.node] = true;
        }
    }
    out.surface_contacts.clear();
    for (const SurfaceContact& c : self_contact_.contacts())
        out.surface_contacts.push_back({c.node, c.segment, c.xi, c.gap, {-c.force[0], -c.force[1]}});
    out.contact_length = 0.0;
    for (const ElementSpec& e : element_specs_) {
        if (!in_contact[e.node_i] || !in_contact[e.node_j]) continue;
        const double dx = nodes_[e.node_j].x + u[3 * e.node_j] - nodes_[e.node_i].x - u[3 * e.node_i];
        const double dy = nodes_[e.node_j].y + u[3 * e.node_j + 1] - nodes_[e.node_i].y - u[3 * e.node_i + 1];
        out.contact_length += std::hypot(dx, dy);
    }
}

Eigen::VectorXd StructuralSystem::platen_force() const {
    Eigen::VectorXd force = Eigen::VectorXd::Zero(free_count_);
    for (std::size_t s = 0; s < foundation_.size(); ++s) {
        if (!on_moving_base_[s]) continue;
        const int base = dofs_per_node * foundation_.spring(s).node;
        for (int d = 0; d < dofs_per_node; ++d)
            if (equation_[base + d] >= 0) force[equation_[base + d]] += foundation_.states()[s].force[d];
    }
    return force;
}

} // namespace plastica
