#include "analysis/surface_contact_component.hpp"

namespace plastica {

SurfaceContactComponent::SurfaceContactComponent(const Model& model, const std::vector<int>& equation)
    : contact_(model), equation_(equation) {}

bool SurfaceContactComponent::evaluate(const EvaluationPoint& at, Eigen::VectorXd& internal, Eigen::VectorXd&) {
    blocks_changed_ = false;
    if (contact_.empty()) return true;
    contact_.evaluate(at.u, at.freeze_active, undecided_force_);
    for (const SurfaceContact& c : contact_.contacts()) {
        const std::array<int, 3> nodes = c.node_list();
        for (int k = 0; k < c.nodes(); ++k) internal.segment<2>(dofs_per_node * nodes[k]) += c.force.segment<2>(2 * k);
    }
    blocks_changed_ = add_blocks();
    return true;
}

bool SurfaceContactComponent::add_blocks() {
    bool added = false;
    for (const SurfaceContact& c : contact_.contacts()) {
        const std::array<int, 3> nodes = c.node_list();
        if (block_of_.count(nodes)) continue;
        std::vector<int> block;
        for (int k = 0; k < c.nodes(); ++k)
            for (int d = 0; d < dofs_per_node; ++d) block.push_back(equation_[dofs_per_node * nodes[k] + d]);
        block_of_[nodes] = blocks_.size();
        blocks_.push_back(std::move(block));
        added = true;
    }
    return added;
}

void SurfaceContactComponent::append_blocks(std::vector<std::vector<int>>& blocks) const {
    blocks.insert(blocks.end(), blocks_.begin(), blocks_.end());
}

void SurfaceContactComponent::assemble(BlockAssembler& assembler, std::size_t first) const {
    Eigen::Matrix<double, 9, 9> surface;
    for (const SurfaceContact& c : contact_.contacts()) {
        // The pair's translations into its nodes' three DOFs (no moment: the normal passes
        // through both centre lines).
        surface.setZero();
        for (int a = 0; a < c.nodes(); ++a)
            for (int b = 0; b < c.nodes(); ++b) surface.block<2, 2>(3 * a, 3 * b) = c.tangent.block<2, 2>(2 * a, 2 * b);
        const std::size_t block = first + block_of_.at(c.node_list());
        if (c.nodes() == 2) assembler.add(block, surface.topLeftCorner<6, 6>());
        else assembler.add(block, surface);
    }
}

void SurfaceContactComponent::commit() {
    blocks_changed_ = false;
    if (contact_.empty() || block_of_.size() == contact_.contacts().size()) return; // every registered pair touches
    blocks_.clear();
    block_of_.clear();
    add_blocks();
    blocks_changed_ = true;
}

void SurfaceContactComponent::report(const Eigen::VectorXd&, bool, StepResult& out) const {
    out.surface_contacts.clear();
    for (const SurfaceContact& c : contact_.contacts())
        out.surface_contacts.push_back({c.node, c.segment, c.xi, c.gap, {-c.force[0], -c.force[1]}});
}

} // namespace plastica
