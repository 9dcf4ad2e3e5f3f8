#include "analysis/plastic_sites.hpp"

#include "model/rigid_motions.hpp"

#include <set>

namespace plastica {

namespace {
// A hinge this close to its capacity turns with the mechanism: at the last converged step
// before the limit, one hinge of a beam mechanism may still be closing in on M_p(N).
constexpr double at_capacity = 0.99;
constexpr std::size_t most_sites = 8;
} // namespace

std::string plastic_sites(const Model& model, const StructuralSystem& system) {
    std::set<int> nodes; // ordered by node number, each once
    const std::vector<CorotationalBeam>& elements = system.elements();
    for (std::size_t e = 0; e < elements.size(); ++e) {
        const BasicLaw& law = elements[e].law();
        if (!law.has_hinges()) continue;
        const int ends[2] = {model.elements[e].node_i, model.elements[e].node_j};
        for (int end = 0; end < 2; ++end) {
            const HingeReport hinge = law.hinge(end);
            if (hinge.state == HingeState::plastic || hinge.state == HingeState::failed || hinge.utilisation >= at_capacity)
                nodes.insert(ends[end]);
        }
    }
    std::string list;
    std::size_t listed = 0;
    for (int n : nodes) {
        if (listed++ == most_sites) {
            list += ", …";
            break;
        }
        list += (list.empty() ? "" : ", ") + point_text(model, model.nodes[n].x, model.nodes[n].y);
    }
    return list;
}

} // namespace plastica
