#include "model_description.hpp"

#include "section/fibre_section.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace plastica {

namespace {

using Json = nlohmann::ordered_json;

const char* scheme_name(Scheme s) {
    switch (s) {
    case Scheme::load_control: return "load_control";
    case Scheme::displacement_control: return "displacement_control";
    case Scheme::arc_length: return "arc_length";
    case Scheme::transient: return "transient";
    }
    return "";
}

const char* plasticity_name(Plasticity p) {
    switch (p) {
    case Plasticity::none: return "elastic";
    case Plasticity::hinges: return "hinges";
    case Plasticity::distributed: return "distributed";
    }
    return "";
}

Json target(const std::optional<double>& load_factor, const std::optional<double>& displacement) {
    if (load_factor) return {{"load_factor", *load_factor}};
    if (displacement) return {{"control_displacement", *displacement}};
    return nullptr;
}

const char* dof_name(int dof) {
    static const char* names[] = {"ux", "uy", "rz"};
    return names[dof];
}

// The largest coordinate of any node.
double extent(const Model& m) {
    double e = 0.0;
    for (const Node& n : m.nodes) e = std::max({e, std::abs(n.x), std::abs(n.y)});
    return e;
}

// A node's position as the user placed it: a coordinate within round-off of zero (a node on a
// ring's axis, R·cos 90° = 6e-15) reads 0.
Json position(const Model& m, int node, double extent) {
    const Node& n = m.nodes.at(static_cast<std::size_t>(node));
    const auto clean = [extent](double v) { return std::abs(v) <= 1e-12 * extent ? 0.0 : v; };
    return {clean(n.x), clean(n.y)};
}

Json dof(const Model& m, const DofRef& d, double extent) {
    return {{"at", position(m, d.node, extent)}, {"dof", dof_name(d.dof)}};
}

} // namespace

Json describe_model(const Model& m) {
    const double size = extent(m);
    Json j;
    if (!m.report.length_unit.empty() || !m.report.force_unit.empty())
        j["units"] = {{"length", m.report.length_unit}, {"force", m.report.force_unit}};
    Json sections = Json::array();
    for (const SectionSpec& s : m.sections) {
        Json e = {{"name", s.name}, {"E", s.E}, {"area", s.area}, {"inertia", s.inertia}, {"plasticity", plasticity_name(s.plasticity)}};
        if (s.steel) {
            const FibreSection fibres(s);
            e["fy"] = s.steel->fy;
            e["law"] = s.steel->law;
            e["squash_load"] = fibres.axial_capacity_tension();
            e["plastic_moment"] = fibres.moment_capacity(0.0, 1.0);
            e["fibres"] = s.fibres.size();
        }
        sections.push_back(e);
    }
    j["sections"] = sections;
    Json supports = Json::array();
    for (const Support& s : m.supports) {
        Json fixed = Json::array();
        for (int k = 0; k < dofs_per_node; ++k)
            if (s.fixed[static_cast<std::size_t>(k)]) fixed.push_back(dof_name(k));
        supports.push_back({{"at", position(m, s.node, size)}, {"fixed", fixed}});
    }
    j["supports"] = supports;
    // Loads per pattern: nodal loads (point and lumped line loads) summed, and how many nodes
    // carry them; pressures and prescribed displacements counted.
    Json patterns = Json::array();
    for (std::size_t p = 0; p < m.patterns.size(); ++p) {
        const int id = static_cast<int>(p);
        int nodes = 0, pressures = 0, prescribed = 0;
        double fx = 0.0, fy = 0.0, moment = 0.0;
        for (const NodalLoad& l : m.loads)
            if (l.pattern == id) ++nodes, fx += l.value[0], fy += l.value[1], moment += l.value[2];
        for (const ElementPressure& e : m.pressures) pressures += e.pattern == id;
        for (const PrescribedDisplacement& d : m.prescribed) prescribed += d.pattern == id;
        Json e = {{"name", m.patterns[p]}, {"loaded_nodes", nodes}, {"sum_fx", fx}, {"sum_fy", fy}, {"sum_moment", moment}};
        if (pressures > 0) e["pressure_elements"] = pressures;
        if (prescribed > 0) e["prescribed_displacements"] = prescribed;
        patterns.push_back(e);
    }
    j["load_patterns"] = patterns;
    // Imperfections from buckling modes: the nodes above are the imperfect ones.
    if (!m.imperfections.empty()) {
        Json imperfections = Json::array();
        for (const ImperfectionSpec& i : m.imperfections)
            imperfections.push_back({{"mode", i.mode}, {"amplitude", i.amplitude}, {"pattern", m.patterns[static_cast<std::size_t>(i.pattern)]},
                                     {"critical_load_factor", i.load_factor}});
        j["imperfections"] = imperfections;
    }
    if (!m.springs.empty()) j["foundation_springs"] = m.springs.size();
    const AnalysisSpec& a = m.analysis;
    j["analysis"] = {{"scheme", scheme_name(a.scheme)},
                     {"pattern", m.patterns.at(static_cast<std::size_t>(a.pattern))},
                     {"geometry", a.geometry == Geometry::first_order ? "first_order" : "large_displacement"},
                     {"increment", a.initial_increment},
                     {"adaptive", a.adaptive},
                     {"target", target(a.target_load_factor, a.target_displacement)},
                     {"control", dof(m, a.control, size)},
                     {"residual_tolerance", a.residual_tolerance},
                     {"max_iterations", a.max_iterations},
                     {"max_steps", a.max_steps}};
    if (!m.stages.empty()) {
        Json stages = Json::array();
        for (const StageSpec& s : m.stages)
            stages.push_back({{"scheme", scheme_name(s.scheme)}, {"pattern", m.patterns.at(static_cast<std::size_t>(s.pattern))},
                              {"target", target(s.target_load_factor, s.target_displacement)}});
        j["stages"] = stages;
    }
    return j;
}

} // namespace plastica
