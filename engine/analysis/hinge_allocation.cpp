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

std::vector<HingeEnds> allocate_hinge_capacity(const Model& model) {
    std::vector<HingeEnds> served(model.elements.size());
    // The ends of hinge elements at each node, as (element, end).
    std::vector<std::vector<std::array<int, 2>>> ends(model.nodes.size());
    std::vector<int> members(model.nodes.size(), 0);
    for (std::size_t e = 0; e < model.elements.size(); ++e) {
        const ElementSpec& spec = model.elements[e];
        ++members[spec.node_i], ++members[spec.node_j];
        if (model.sections[spec.section].plasticity != Plasticity::hinges) continue;
        ends[spec.node_i].push_back({static_cast<int>(e), 0});
        ends[spec.node_j].push_back({static_cast<int>(e), 1});
    }
    const std::vector<bool> taken = rotation_taken(model);
    const std::vector<double> capacity = section_capacities(model);
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        if (members[n] != 2 || ends[n].size() != 2 || taken[n]) continue;
        const auto strength = [&](const std::array<int, 2>& end) {
            return capacity[model.elements[end[0]].section];
        };
        // Equal sections: the first end, as listed.
        const std::array<int, 2>& weaker = strength(ends[n][1]) < strength(ends[n][0]) ? ends[n][1] : ends[n][0];
        // Equal sections yield alike, so their pseudo-springs go soft together: one spring
        // stands for both, or the node's rotation between two nearly free springs would make
        // the tangent nearly singular. A stronger section's end keeps its own (stiffer) spring.
        const bool equal = strength(ends[n][0]) == strength(ends[n][1]);
        for (const std::array<int, 2>& end : ends[n]) {
            const bool serves = &end == &weaker;
            served[end[0]].capacity[end[1]] = serves ? 2 : 0;
            served[end[0]].spring[end[1]] = equal ? (serves ? 2 : 0) : 1;
        }
    }
    return served;
}

} // namespace plastica
