#include "analysis/foundation_component.hpp"

#include <cmath>

namespace plastica {

FoundationComponent::FoundationComponent(const Model& model, const std::vector<int>& equation)
    : foundation_(model), equation_(equation), elements_(model.elements), nodes_(model.nodes) {
    for (const FoundationSpring& s : model.springs)
        on_moving_base_.push_back(s.unilateral && !s.anchored && model.bases.at(static_cast<std::size_t>(s.base)).moves());
}

bool FoundationComponent::evaluate(const EvaluationPoint& at, Eigen::VectorXd& internal, Eigen::VectorXd& coupling) {
    foundation_.evaluate(at.u, at.load_factor, at.freeze_active);
    for (std::size_t s = 0; s < foundation_.size(); ++s) {
        const int base = dofs_per_node * foundation_.spring(s).node;
        const Eigen::Vector3d fs = foundation_.internal_force(s);
        internal.segment<3>(base) += fs;
        // A platen moving with λ acts on the free DOFs as prescribed displacements do.
        const Eigen::Vector3d rate = foundation_.load_rate(s);
        for (int d = 0; d < dofs_per_node; ++d)
            if (rate[d] != 0.0 && equation_[base + d] >= 0) coupling[equation_[base + d]] += rate[d];
    }
    return true;
}

void FoundationComponent::append_blocks(std::vector<std::vector<int>>& blocks) const {
    for (std::size_t s = 0; s < foundation_.size(); ++s) {
        std::vector<int> b;
        for (int d = 0; d < dofs_per_node; ++d) b.push_back(equation_[dofs_per_node * foundation_.spring(s).node + d]);
        blocks.push_back(std::move(b));
    }
    for (std::size_t e = 0; e < foundation_.edge_count(); ++e) {
        std::vector<int> b;
        for (int spring : foundation_.edge(e).spring)
            for (int d = 0; d < dofs_per_node; ++d) b.push_back(equation_[dofs_per_node * foundation_.spring(spring).node + d]);
        blocks.push_back(std::move(b));
    }
}

void FoundationComponent::assemble(BlockAssembler& assembler, std::size_t first) const {
    for (std::size_t s = 0; s < foundation_.size(); ++s) assembler.add(first + s, foundation_.tangent(s));
    for (std::size_t e = 0; e < foundation_.edge_count(); ++e) assembler.add(first + foundation_.size() + e, foundation_.edge_tangent(e));
}

Eigen::VectorXd FoundationComponent::platen_force(int size) const {
    Eigen::VectorXd force = Eigen::VectorXd::Zero(size);
    for (std::size_t s = 0; s < foundation_.size(); ++s) {
        if (!on_moving_base_[s]) continue;
        const int base = dofs_per_node * foundation_.spring(s).node;
        for (int d = 0; d < dofs_per_node; ++d)
            if (equation_[base + d] >= 0) force[equation_[base + d]] += foundation_.states()[s].force[d];
    }
    return force;
}

void FoundationComponent::report(const Eigen::VectorXd& u, bool, StepResult& out) const {
    // Spring forces are not support reactions: take them out of the supported DOFs.
    for (std::size_t s = 0; s < foundation_.size(); ++s) {
        const int base = dofs_per_node * foundation_.spring(s).node;
        for (int d = 0; d < dofs_per_node; ++d)
            if (equation_[base + d] < 0) out.reaction[base + d] -= foundation_.internal_force(s)[d];
    }
    out.springs.resize(foundation_.size());
    out.contact_count = 0;
    out.base_reaction = 0.0;
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
        }
    }
    // The length of the members in contact: whose both ends touch a node-wise base, and the
    // overlapping share of those that bear along their length.
    auto current_length = [&](int i, int j) {
        const double dx = nodes_[j].x + u[3 * j] - nodes_[i].x - u[3 * i];
        const double dy = nodes_[j].y + u[3 * j + 1] - nodes_[i].y - u[3 * i + 1];
        return std::hypot(dx, dy);
    };
    out.contact_length = 0.0;
    for (std::size_t e = 0; e < foundation_.edge_count(); ++e) {
        const std::array<int, 2>& s = foundation_.edge(e).spring;
        out.contact_length += foundation_.edge_fraction(e) * current_length(foundation_.spring(s[0]).node, foundation_.spring(s[1]).node);
    }
    std::vector<bool> in_contact(nodes_.size(), false);
    for (std::size_t s = 0; s < foundation_.size(); ++s) {
        const SpringState& st = foundation_.states()[s];
        if (st.unilateral && st.active && !foundation_.spring(s).along_members) in_contact[st.node] = true;
    }
    for (const ElementSpec& e : elements_)
        if (in_contact[e.node_i] && in_contact[e.node_j]) out.contact_length += current_length(e.node_i, e.node_j);
}

} // namespace plastica
