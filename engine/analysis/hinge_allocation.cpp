#include "analysis/hinge_allocation.hpp"

#include "section/fibre_section.hpp"

#include <algorithm>
#include <limits>

namespace plastica {

namespace {

// Nodes whose rotation is held or loaded by something other than the elements.
std::vector<bool> rotation_taken(const Model& model) {
    std::vector<bool> taken(model.nodes.size(), false);
    for (const Support& s : model.supports)
        if (s.fixed[2]) taken[s.node] = true;
    for (const PrescribedDisplacement& p : model.prescribed)
        if (p.dof == 2) taken[p.node] = true;
    for (const FoundationSpring& s : model.springs)
        if (s.krot != 0.0) taken[s.node] = true;
    for (const NodalLoad& l : model.loads)
        if (l.value[2] != 0.0) taken[l.node] = true;
    return taken;
}

// Plastic moment at N = 0 of each hinge section, the weaker bending direction.
std::vector<double> section_capacities(const Model& model) {
    std::vector<double> capacity(model.sections.size(), std::numeric_limits<double>::infinity());
    for (std::size_t s = 0; s < model.sections.size(); ++s) {
        if (model.sections[s].plasticity != Plasticity::hinges) continue;
        const FibreSection section(model.sections[s]);
        capacity[s] = std::min(section.moment_capacity(0.0, 1.0), section.moment_capacity(0.0, -1.0));
    }
    return capacity;
}

} // namespace

JointHinges::JointHinges(const Model& model) : served_(model.elements.size()) {
    // The ends of hinge elements at each node, as (element, end).
    std::vector<std::vector<std::array<int, 2>>> ends(model.nodes.size());
    std::vector<int> members(model.nodes.size(), 0);
    std::vector<bool> released(model.nodes.size(), false); // a member end there is released: no rigid joint
    for (std::size_t e = 0; e < model.elements.size(); ++e) {
        const ElementSpec& spec = model.elements[e];
        ++members[spec.node_i], ++members[spec.node_j];
        if (spec.released[0]) released[spec.node_i] = true;
        if (spec.released[1]) released[spec.node_j] = true;
        if (model.sections[spec.section].plasticity != Plasticity::hinges) continue;
        ends[spec.node_i].push_back({static_cast<int>(e), 0});
        ends[spec.node_j].push_back({static_cast<int>(e), 1});
    }
    const std::vector<bool> taken = rotation_taken(model);
    const std::vector<double> capacity = section_capacities(model);
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        if (members[n] != 2 || ends[n].size() != 2 || taken[n] || released[n]) continue;
        Joint joint;
        joint.ends = {ends[n][0], ends[n][1]};
        const std::array<double, 2> strength{capacity[model.elements[ends[n][0][0]].section],
                                             capacity[model.elements[ends[n][1][0]].section]};
        joint.equal_sections = model.elements[ends[n][0][0]].section == model.elements[ends[n][1][0]].section ||
                               strength[0] == strength[1];
        // Equal sections: the first end, as listed.
        joint.serving = strength[1] < strength[0] ? 1 : 0;
        joint.capacity_floor = capacity_floor * std::min(strength[0], strength[1]);
        apply(joint);
        joints_.push_back(joint);
    }
}

void JointHinges::apply(const Joint& joint) {
    for (int k = 0; k < 2; ++k) {
        const bool serves = k == joint.serving;
        const std::array<int, 2>& end = joint.ends[k];
        served_[end[0]].capacity[end[1]] = serves ? 2 : 0;
        // Equal sections yield alike, so their pseudo-springs go soft together: one spring
        // stands for both, or the node's rotation between two nearly free springs would make
        // the tangent nearly singular. A stronger section's end keeps its own (stiffer) spring.
        served_[end[0]].spring[end[1]] = joint.equal_sections ? (serves ? 2 : 0) : 1;
    }
}

int JointHinges::reassign(std::vector<CorotationalBeam>& elements) {
    int changed = 0;
    for (Joint& joint : joints_) {
        const auto report = [&](int k) {
            const std::array<int, 2>& end = joint.ends[k];
            return elements[end[0]].law().hinge(end[1]);
        };
        const HingeReport served = report(joint.serving), other = report(1 - joint.serving);
        // The hinge moves to the other end where that end's capacity has fallen below the
        // serving end's by more than equal_band, measured against no less than a tenth of
        // M_p(0): near the squash load M_p(N) falls to nothing, and the two ends' capacities
        // cross as they flow.
        const bool weaker = served.capacity - other.capacity > equal_band * std::max(served.capacity, joint.capacity_floor);
        if (!weaker) continue;
        joint.serving = 1 - joint.serving;
        apply(joint);
        for (const std::array<int, 2>& end : joint.ends) elements[end[0]].serve_hinge_ends(served_[end[0]]);
        ++changed;
    }
    return changed;
}

std::vector<HingeEnds> allocate_hinge_capacity(const Model& model) { return JointHinges(model).ends_served(); }

} // namespace plastica
