#include "scene_warnings.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace plastica {

namespace {

std::string warning_number(double v) {
    std::ostringstream s;
    s.precision(3);
    s << v;
    return s.str();
}

// The section's depth: the fibres' extent, or for an elastic section the depth of the rectangle
// of its area and inertia (√(12 I/A), a little above an I-section's depth).
double section_depth(const SectionSpec& s) {
    if (!s.fibres.empty()) {
        double lo = s.fibres.front().y, hi = lo;
        for (const Fibre& f : s.fibres) lo = std::min(lo, f.y), hi = std::max(hi, f.y);
        return hi - lo;
    }
    return s.area > 0.0 ? std::sqrt(12.0 * s.inertia / s.area) : 0.0;
}

// A load in time on a node without mass moves it only as far as statics does: where that is
// meant (a massless bar to a tip mass) it is right, where the density was forgotten it is not.
void massless_load_warnings(const Model& model, std::vector<std::string>& warnings) {
    std::vector<double> translational(model.nodes.size(), 0.0), rotational(model.nodes.size(), 0.0);
    for (const ElementSpec& e : model.elements) {
        const SectionSpec& s = model.sections[static_cast<std::size_t>(e.section)];
        for (int n : {e.node_i, e.node_j}) {
            translational[static_cast<std::size_t>(n)] += s.mass_per_length;
            rotational[static_cast<std::size_t>(n)] += s.rotary_inertia_per_length;
        }
    }
    for (const NodalMass& m : model.dynamics.masses) {
        translational[static_cast<std::size_t>(m.node)] += m.mass;
        rotational[static_cast<std::size_t>(m.node)] += m.rotational;
    }
    for (const NodalLoad& l : model.loads) {
        const std::size_t n = static_cast<std::size_t>(l.node);
        const bool pushed = (l.value[0] != 0.0 || l.value[1] != 0.0) && translational[n] == 0.0;
        const bool turned = l.value[2] != 0.0 && rotational[n] == 0.0;
        if (!pushed && !turned) continue;
        const Node& p = model.nodes[n];
        warnings.push_back("the load at (" + warning_number(p.x) + ", " + warning_number(p.y) + ") acts on a node without " +
                           (pushed ? "mass" : "rotational inertia") +
                           ": in time it moves there as statics says; give the members a density or the node a [[mass]] if it should not");
    }
}

} // namespace

std::vector<std::string> scene_warnings(const Model& model) {
    std::vector<std::string> warnings;
    // Structural steels have fy/E near 1e-3 (S235: 1.1e-3, S690: 3.3e-3). The range leaves room
    // for any metal and for the non-dimensional ring of models/ring_inelastic.toml (3.65e-5),
    // while fy in MPa beside E in kN/m² (1.7e-6) or E in GPa (1.7 and more) falls outside.
    for (const SectionSpec& s : model.sections) {
        if (!s.steel || !(s.steel->E > 0.0)) continue;
        const double ratio = s.steel->fy / s.steel->E;
        if (ratio < 1e-5 || ratio > 2e-2)
            warnings.push_back("section '" + s.name + "': its material's fy/E is " + warning_number(ratio) +
                               ", outside 1e-5 … 2e-2 (steels lie near 1e-3): are E and fy in the same units?");
    }
    // A section deeper than a quarter of the whole structure: a depth in millimetres on members in
    // metres (a thousand times too deep), or a beam theory past its reach. A stocky column, 500
    // deep and 3000 tall, is neither.
    double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
    for (const Node& n : model.nodes) lo_x = std::min(lo_x, n.x), hi_x = std::max(hi_x, n.x), lo_y = std::min(lo_y, n.y), hi_y = std::max(hi_y, n.y);
    const double extent = model.nodes.empty() ? 0.0 : std::hypot(hi_x - lo_x, hi_y - lo_y);
    for (const SectionSpec& s : model.sections) {
        const double depth = section_depth(s);
        if (extent > 0.0 && depth > 0.25 * extent)
            warnings.push_back("section '" + s.name + "': " + warning_number(depth) + " deep on a structure " + warning_number(extent) +
                               " across, more than a quarter of it: are the section and the geometry in the same length unit?");
    }
    // A spring whose stiffness dwarfs every element's axial stiffness EA/L: its penalty sets
    // the round-off floor of the residual (1e6 × leaves it near 1e-10 of the load).
    double stiffest = 0.0;
    for (const ElementSpec& e : model.elements) {
        const SectionSpec& s = model.sections[static_cast<std::size_t>(e.section)];
        const Node &a = model.nodes[e.node_i], &b = model.nodes[e.node_j];
        const double L = std::hypot(b.x - a.x, b.y - a.y);
        if (L > 0.0) stiffest = std::max(stiffest, s.E * s.area / L);
    }
    double spring = 0.0;
    for (const FoundationSpring& f : model.springs) spring = std::max({spring, f.kx, f.ky});
    if (stiffest > 0.0 && spring > 1e6 * stiffest)
        warnings.push_back("a foundation spring of stiffness " + warning_number(spring) + " is " + warning_number(spring / stiffest) +
                           " times the stiffest element's EA/L (" + warning_number(stiffest) +
                           "): its round-off may stop the run; a penalty of 1e2 to 1e4 times that holds as well");
    if (model.transient()) massless_load_warnings(model, warnings);
    return warnings;
}

} // namespace plastica
