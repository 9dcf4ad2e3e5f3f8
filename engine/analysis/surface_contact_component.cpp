#include "analysis/surface_contact_component.hpp"

#include <algorithm>

namespace plastica {

namespace {

// A pair's distinct nodes, in order of their first slot, and each slot's place among them (a
// point along a member that touches its neighbour's end names that node twice).
struct PairNodes {
    std::vector<int> nodes;
    std::array<int, 4> place{};
};

PairNodes pair_nodes(const SurfaceContact& c) {
    PairNodes out;
    const std::array<int, 4> slots = c.node_list();
    for (int k = 0; k < c.nodes(); ++k) {
        const auto at = std::find(out.nodes.begin(), out.nodes.end(), slots[k]);
        out.place[k] = static_cast<int>(at - out.nodes.begin());
        if (at == out.nodes.end()) out.nodes.push_back(slots[k]);
    }
    return out;
}

} // namespace

SurfaceContactComponent::SurfaceContactComponent(const Model& model, const std::vector<int>& equation)
    : contact_(model), equation_(equation) {}

bool SurfaceContactComponent::evaluate(const EvaluationPoint& at, Eigen::VectorXd& internal, Eigen::VectorXd&) {
    blocks_changed_ = false;
    if (contact_.empty()) return true;
    contact_.evaluate(at.u, at.freeze_active, undecided_force_);
    for (const SurfaceContact& c : contact_.contacts()) {
        const std::array<int, 4> nodes = c.node_list();
        for (int k = 0; k < c.nodes(); ++k) internal.segment<2>(dofs_per_node * nodes[k]) += c.force.segment<2>(2 * k);
    }
    blocks_changed_ = add_blocks();
    return true;
}

bool SurfaceContactComponent::add_blocks() {
    bool added = false;
    for (const SurfaceContact& c : contact_.contacts()) {
        const std::vector<int> nodes = pair_nodes(c).nodes;
        if (block_of_.count(nodes)) continue;
        std::vector<int> block;
        for (int node : nodes)
            for (int d = 0; d < dofs_per_node; ++d) block.push_back(equation_[dofs_per_node * node + d]);
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
    Eigen::MatrixXd surface;
    for (const SurfaceContact& c : contact_.contacts()) {
        // The pair's translations into its nodes' three DOFs (no moment: the normal passes
        // through both centre lines).
        const PairNodes pair = pair_nodes(c);
        const int n = static_cast<int>(pair.nodes.size());
        surface.setZero(3 * n, 3 * n);
        for (int a = 0; a < c.nodes(); ++a)
            for (int b = 0; b < c.nodes(); ++b)
                surface.block<2, 2>(3 * pair.place[a], 3 * pair.place[b]) += c.tangent.block<2, 2>(2 * a, 2 * b);
        assembler.add(first + block_of_.at(pair.nodes), surface);
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
        out.surface_contacts.push_back({c.node, c.segment, c.xi, c.gap, {-c.point_force()[0], -c.point_force()[1]}, c.point, c.eta});
}

} // namespace plastica
