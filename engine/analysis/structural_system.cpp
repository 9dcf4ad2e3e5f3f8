#include "analysis/structural_system.hpp"

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

std::vector<Eigen::VectorXd> nodal_loads(const Model& model) {
    std::vector<Eigen::VectorXd> force(model.patterns.size(), Eigen::VectorXd::Zero(model.dof_count()));
    for (const NodalLoad& l : model.loads)
        for (int d = 0; d < dofs_per_node; ++d) force[static_cast<std::size_t>(l.pattern)][dofs_per_node * l.node + d] += l.value[d];
    return force;
}

} // namespace

StructuralSystem::StructuralSystem(const Model& model)
    : equation_(number_equations(model, free_count_)), pressure_(model), pattern_loads_(nodal_loads(model)),
      assembler_(0, {}) {
    members_ = add<MemberSet>(model, equation_, pressure_);
    foundation_ = add<FoundationComponent>(model, equation_);
    surfaces_ = add<SurfaceContactComponent>(model, equation_);
    build_assembler();
    for (std::size_t p = 0; p < model.patterns.size(); ++p) platens_only_.push_back(model.driven_by_platens(static_cast<int>(p)));
    PatternFactors first(model.patterns.size());
    first.driven = model.analysis.pattern;
    set_pattern_factors(first);
    dof_of_equation_.assign(static_cast<std::size_t>(free_count_), 0);
    for (int i = 0; i < dof_count(); ++i)
        if (equation_[i] >= 0) dof_of_equation_[static_cast<std::size_t>(equation_[i])] = i;
    internal_ = Eigen::VectorXd::Zero(dof_count());
    coupling_ = Eigen::VectorXd::Zero(free_count_);
}

void StructuralSystem::build_assembler() {
    std::vector<std::vector<int>> blocks;
    first_block_.clear();
    for (const auto& c : components_) {
        first_block_.push_back(blocks.size());
        c->append_blocks(blocks);
    }
    assembler_ = BlockAssembler(free_count_, blocks);
}

void StructuralSystem::set_pattern_factors(const PatternFactors& factors) {
    fixed_load_ = pattern_loads_[static_cast<std::size_t>(factors.driven)];
    held_fixed_load_ = Eigen::VectorXd::Zero(fixed_load_.size());
    for (std::size_t p = 0; p < pattern_loads_.size(); ++p)
        if (factors.constant(static_cast<int>(p)) != 0.0) held_fixed_load_ += factors.constant(static_cast<int>(p)) * pattern_loads_[p];
    load_ = fixed_load_;
    held_load_ = held_fixed_load_;
    pressure_.set_pattern_factors(factors);
    foundation_->foundation().set_pattern_factors(factors);
    driven_by_platens_ = platens_only_[static_cast<std::size_t>(factors.driven)];
}

bool StructuralSystem::evaluate(const Eigen::VectorXd& u, const Eigen::VectorXd& ubar, double load_factor,
                                bool freeze_active, bool freeze_hinges, bool freeze_fibres) {
    internal_.setZero();
    coupling_.setZero();
    tangent_assembled_ = false;
    const EvaluationPoint at{u, ubar, load_factor, freeze_active, freeze_hinges, freeze_fibres};
    bool blocks_changed = false;
    for (const auto& c : components_) {
        if (!c->evaluate(at, internal_, coupling_)) return false;
        blocks_changed = blocks_changed || c->blocks_changed();
        if (keep_member_forces_ && c.get() == members_) member_internal_ = internal_;
    }
    if (blocks_changed) build_assembler();
    if (!pressure_.empty()) {
        load_ = fixed_load_;
        pressure_.add_forces(u, load_);
        held_load_ = held_fixed_load_;
        pressure_.add_held_forces(u, held_load_);
    }
    return true;
}

bool StructuralSystem::contact_settled() const {
    return std::all_of(components_.begin(), components_.end(), [](const auto& c) { return c->settled(); });
}

void StructuralSystem::take_axial_forces_in_tangent(const Eigen::VectorXd& forces) {
    members_->take_axial_forces_in_tangent(forces);
    tangent_assembled_ = false;
}

Eigen::VectorXd StructuralSystem::axial_forces() const {
    return members_->axial_forces();
}

void StructuralSystem::assemble_tangent() const {
    assembler_.set_zero();
    for (std::size_t k = 0; k < components_.size(); ++k) components_[k]->assemble(assembler_, first_block_[k]);
    tangent_assembled_ = true;
    // Finite entries have a finite sum unless it overflows (no structure is that stiff): one sum
    // instead of a test of every element's entries. Only if it is not finite are the members
    // tested one by one, to name the one at fault.
    const SparseMatrix& K = assembler_.matrix();
    const Eigen::Map<const Eigen::ArrayXd> values(K.valuePtr(), K.nonZeros());
    tangent_finite_ = true;
    if (std::isfinite(values.sum())) return;
    tangent_finite_ = !members_->find_non_finite_tangent();
}

const SparseMatrix& StructuralSystem::tangent() const {
    if (!tangent_assembled_) assemble_tangent();
    return assembler_.matrix();
}

bool StructuralSystem::tangent_finite() const {
    if (!tangent_assembled_) assemble_tangent();
    return tangent_finite_;
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
    const Foundation& foundation = foundation_->foundation();
    for (std::size_t s = 0; s < foundation.size(); ++s) {
        const FoundationSpring& spring = foundation.spring(s);
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

void StructuralSystem::commit() {
    bool blocks_changed = false;
    for (const auto& c : components_) {
        c->commit();
        blocks_changed = blocks_changed || c->blocks_changed();
    }
    if (!blocks_changed) return;
    build_assembler();
    tangent_assembled_ = false;
}

void StructuralSystem::revert() {
    // The tangent stays that of the last evaluation, as the components' trial states go back.
    if (!tangent_assembled_) assemble_tangent();
    for (const auto& c : components_) c->revert();
}

void StructuralSystem::report(const Eigen::VectorXd& u, const Eigen::VectorXd& external,
                              StepResult& out, bool with_sections) const {
    out.displacement.assign(u.data(), u.data() + u.size());
    out.reaction.assign(u.size(), 0.0);
    out.applied_load.assign(external.data(), external.data() + external.size());
    for (int i = 0; i < dof_count(); ++i)
        if (equation_[i] < 0) out.reaction[i] = internal_[i] - external[i];
    for (const auto& c : components_) c->report(u, with_sections, out);
}

} // namespace plastica
