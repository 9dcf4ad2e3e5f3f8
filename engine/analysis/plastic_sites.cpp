#include "analysis/plastic_sites.hpp"

#include "model/rigid_motions.hpp"
#include "section/fibre_section.hpp"

#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace plastica {

namespace {
// A hinge (or a fibre section) this close to its capacity turns with the mechanism: at the last
// converged step before the limit, one hinge of a beam mechanism may still be closing in on M_p(N).
constexpr double at_capacity = 0.99;
constexpr std::size_t most_sites = 8;
} // namespace

std::string plastic_sites(const Model& model, const StructuralSystem& system) {
    std::vector<std::pair<double, double>> sites; // in the order found, each once
    const auto add = [&](double x, double y) {
        for (const auto& [sx, sy] : sites)
            if (sx == x && sy == y) return;
        sites.emplace_back(x, y);
    };
    std::map<int, FibreSection> capacity; // per section of the model, built where needed
    const std::vector<CorotationalBeam>& elements = system.elements();
    for (std::size_t e = 0; e < elements.size(); ++e) {
        const BasicLaw& law = elements[e].law();
        const Node& i = model.nodes[model.elements[e].node_i];
        const Node& j = model.nodes[model.elements[e].node_j];
        if (law.has_hinges()) {
            for (int end = 0; end < 2; ++end) {
                const HingeReport hinge = law.hinge(end);
                if (hinge.state == HingeState::plastic || hinge.state == HingeState::failed || hinge.utilisation >= at_capacity)
                    end == 0 ? add(i.x, i.y) : add(j.x, j.y);
            }
            continue;
        }
        // Fibre sections at capacity, |M| against their M_p(N) as for hinges, where the
        // utilisation peaks along the member (a zone's centre, not every section it spans):
        // named by the node of their half of the member, or in the middle by their own place.
        const std::vector<SectionReport> sections = law.sections();
        if (sections.empty()) continue;
        const int spec = model.elements[e].section;
        const FibreSection& fibres = capacity.try_emplace(spec, model.sections[spec]).first->second;
        std::vector<double> utilisation;
        for (const SectionReport& section : sections) {
            const double Mp = fibres.moment_capacity(section.axial_force, section.moment);
            utilisation.push_back(Mp > 0.0 ? std::abs(section.moment) / Mp : 0.0);
        }
        for (std::size_t k = 0; k < sections.size(); ++k) {
            const bool peak = (k == 0 || utilisation[k] >= utilisation[k - 1]) &&
                              (k + 1 == sections.size() || utilisation[k] >= utilisation[k + 1]);
            if (!peak || utilisation[k] < at_capacity) continue;
            const double xi = sections[k].xi;
            if (xi < 0.5) add(i.x, i.y);
            else if (xi > 0.5) add(j.x, j.y);
            else add(0.5 * (i.x + j.x), 0.5 * (i.y + j.y));
        }
    }
    std::string list;
    std::size_t listed = 0;
    for (const auto& [x, y] : sites) {
        if (listed++ == most_sites) {
            list += ", …";
            break;
        }
        list += (list.empty() ? "" : ", ") + point_text(model, x, y);
    }
    return list;
}

} // namespace plastica
