#include "result_schema.hpp"

#include "model/model.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace plastica::result {

namespace {

using W = Where;
using T = Type;
using Q = Quantity;

const std::vector<Array> schema = {
    {name::displacement, W::point, T::float64, 3, Q::length, When::always, "ux, uy, 0 (the active vectors; points are already at x0 + u)"},
    {name::rotation, W::point, T::float64, 1, Q::rotation, When::always, "nodal rotation θ"},
    {name::initial_position, W::point, T::float64, 3, Q::length, When::always, "x0, y0, 0"},
    {name::bending_moment, W::point, T::float64, 1, Q::moment, When::always, "mean of the element-end moments at the node"},
    {name::reaction, W::point, T::float64, 3, Q::force, When::supported_or_prescribed, "fx, fy, 0 the support exerts on the structure"},
    {name::reaction_moment, W::point, T::float64, 1, Q::moment, When::supported_or_prescribed, "moment the support exerts"},
    {name::support, W::point, T::int32, 1, Q::none, When::supported, "fixed DOFs: 1 ux + 2 uy + 4 rz"},
    {name::applied_load, W::point, T::float64, 3, Q::force, When::loaded, "fx, fy, 0: λ × the reference loads, pressure as it follows the members"},
    {name::applied_moment, W::point, T::float64, 1, Q::moment, When::loaded, "λ × the reference moments"},
    {name::spring_force, W::point, T::float64, 3, Q::force, When::bilateral_springs, "fx, fy, 0 of the bilateral springs on the node"},
    {name::spring_moment, W::point, T::float64, 1, Q::moment, When::bilateral_springs, "moment of the rotational spring kθ"},
    {name::contact_force, W::point, T::float64, 3, Q::force, When::unilateral_base, "fx, fy, 0 the bases press with (summed over bases)"},
    {name::gap, W::point, T::float64, 1, Q::length, When::unilateral_base, "distance to the nearest base (negative: penetration)"},
    {name::contact, W::point, T::int32, 1, Q::none, When::unilateral_base, "0 open, 1 in contact"},
    {name::surface_contact_force, W::point, T::float64, 3, Q::force, When::self_contact, "fx, fy, 0 other surfaces press the node with (as a touching node or a segment's end)"},
    {name::plastic_utilisation, W::point, T::float64, 1, Q::none, When::hinges, "largest |M|/Mp(N) of the ends at the node, each end at its own N: 0 … 1 at capacity"},
    {name::hinge_state, W::point, T::int32, 1, Q::none, When::hinges, "0 elastic, 1 yielding, 2 fully plastic, 3 failed fibre (worst end)"},
    {name::axial_force, W::cell, T::float64, 1, Q::force, When::always, "N, positive in tension"},
    {name::moment_i, W::cell, T::float64, 1, Q::moment, When::always, "bending moment EI·dθ/ds at the first node"},
    {name::moment_j, W::cell, T::float64, 1, Q::moment, When::always, "bending moment at the second node"},
    {name::shear, W::cell, T::float64, 1, Q::force, When::always, "(M_i + M_j)/L of the basic end moments"},
    {name::released, W::cell, T::int32, 1, Q::none, When::releases, "moment releases: 1 at the first node, 2 at the second, 3 at both"},
    {name::yielded_share, W::cell, T::float64, 1, Q::none, When::distributed, "largest share of a section's area at the yield stress"},
    {name::section_yielded_share, W::cell, T::float64, 0, Q::none, When::distributed, "yielded share at each integration point, ξ order"},
    {name::section_curvature, W::cell, T::float64, 0, Q::curvature, When::distributed, "κ = dθ/ds at each integration point"},
    {name::section_moment, W::cell, T::float64, 0, Q::moment, When::distributed, "bending moment at each integration point"},
    {name::ei_ratio, W::cell, T::float64, 1, Q::none, When::hinges, "EI_T/EI of the softer end"},
    {name::utilisation_i, W::cell, T::float64, 1, Q::none, When::hinges, "|M|/Mp(N) at the first end, at its own N (1 at capacity)"},
    {name::utilisation_j, W::cell, T::float64, 1, Q::none, When::hinges, "|M|/Mp(N) at the second end, at its own N (1 at capacity)"},
    {name::hinge_state_i, W::cell, T::int32, 1, Q::none, When::hinges, "state of the first end, codes as hinge_state"},
    {name::hinge_state_j, W::cell, T::int32, 1, Q::none, When::hinges, "state of the second end"},
    {name::time_value, W::field, T::float64, 1, Q::none, When::always, "the PVD time: step index, or arc length"},
    {name::load_factor, W::field, T::float64, 1, Q::none, When::always, "λ"},
    {name::load, W::field, T::float64, 1, Q::reported_load, When::always, "the reported load (total in its direction, or λ)"},
    {name::control_displacement, W::field, T::float64, 1, Q::reported_displacement, When::always, "the controlled displacement"},
    {name::step, W::field, T::float64, 1, Q::none, When::always, "step number"},
    {name::iterations, W::field, T::float64, 1, Q::none, When::always, "Newton iterations of the step"},
    {name::contact_count, W::field, T::float64, 1, Q::none, When::always, "nodes in contact"},
    {name::surface_contact_count, W::field, T::float64, 1, Q::none, When::self_contact, "pairs of surfaces in contact (a node against a segment)"},
    {name::hinge_count, W::field, T::float64, 1, Q::none, When::always, "element ends yielding or fully plastic"},
    {name::stage, W::field, T::float64, 1, Q::none, When::staged, "1 for [analysis], then 2, 3, … for each [[stage]]"},
    {name::pattern_factors, W::field, T::float64, 1, Q::none, When::patterns, "each load pattern's factor, one value per pattern in the order of pattern_names"},
    {name::pattern_names, W::field, T::text, 1, Q::none, When::patterns, "the load patterns, comma-separated"},
    {name::mirror_x, W::field, T::float64, 1, Q::length, When::half_model, "x of the symmetry line of a half model"},
    {name::scene, W::field, T::text, 1, Q::none, When::always, "scene name"},
    {name::title, W::field, T::text, 1, Q::none, When::always, "scene title"},
    {name::load_label, W::field, T::text, 1, Q::none, When::always, "what the load axis shows"},
    {name::displacement_label, W::field, T::text, 1, Q::none, When::always, "what the displacement axis shows"},
    {name::length_unit, W::field, T::text, 1, Q::none, When::units, "[report] length_unit"},
    {name::force_unit, W::field, T::text, 1, Q::none, When::units, "[report] force_unit"},
    {name::load_unit, W::field, T::text, 1, Q::none, When::units, "unit of `load`"},
    {name::displacement_unit, W::field, T::text, 1, Q::none, When::units, "unit of `control_displacement`"},
    {name::base_kind, W::base, T::int32, 1, Q::none, When::spring_anchors, "0 spring anchor (vertex), 1 rigid base line"},
    {name::base_motion, W::base, T::float64, 3, Q::length, When::moving_base, "a platen's travel per unit factor of its pattern (lines only)"},
    {name::base_pattern, W::base, T::int32, 1, Q::none, When::moving_base_patterns, "the line's load pattern: its index in pattern_factors"},
};

bool has_bilateral_springs(const Model& m) {
    return std::any_of(m.springs.begin(), m.springs.end(), [](const FoundationSpring& s) { return !s.unilateral; });
}

} // namespace

const std::vector<Array>& arrays() { return schema; }

const Array& find(std::string_view wanted) {
    for (const Array& a : schema)
        if (a.name == wanted) return a;
    throw std::out_of_range("the result schema has no array '" + std::string(wanted) + "'");
}

bool present(const Array& a, const Model& m) {
    switch (a.when) {
    case When::always: return true;
    case When::supported_or_prescribed: return !m.supports.empty() || !m.prescribed.empty();
    case When::supported: return !m.supports.empty();
    case When::loaded: return !m.loads.empty() || !m.pressures.empty();
    case When::bilateral_springs: return has_bilateral_springs(m);
    case When::unilateral_base: return m.has_unilateral_base();
    case When::hinges: return m.has_plasticity(Plasticity::hinges);
    case When::distributed: return m.has_plasticity(Plasticity::distributed);
    case When::half_model: return m.report.mirror_x.has_value();
    case When::units: return !m.report.length_unit.empty() || !m.report.force_unit.empty();
    case When::spring_anchors: return !m.springs.empty();
    case When::moving_base: return m.has_moving_base();
    case When::staged: return !m.stages.empty();
    case When::releases: return m.has_releases();
    case When::self_contact: return !m.self_contact.empty();
    case When::patterns: return !active_patterns(m).empty();
    case When::moving_base_patterns: return m.has_moving_base() && !active_patterns(m).empty();
    }
    return false;
}

std::vector<int> active_patterns(const Model& m) {
    std::vector<int> out;
    if (m.patterns.size() < 2) return out; // the common case, once per curve row and VTU: no scan of the loads
    for (std::size_t p = 0; p < m.patterns.size(); ++p)
        if (m.loaded(static_cast<int>(p)) || m.has_moving_base(static_cast<int>(p))) out.push_back(static_cast<int>(p));
    if (out.size() < 2) out.clear();
    return out;
}

std::vector<std::string> names(Where where, const Model& m) {
    std::vector<std::string> out;
    for (const Array& a : schema)
        if (a.where == where && present(a, m)) out.emplace_back(a.name);
    return out;
}

std::string unit(const Array& a, const std::string& length, const std::string& force) {
    switch (a.quantity) {
    case Q::length: return length;
    case Q::rotation: return length.empty() && force.empty() ? "" : "rad";
    case Q::force: return force;
    case Q::moment: return force.empty() || length.empty() ? "" : force + "·" + length;
    case Q::curvature: return length.empty() ? "" : "1/" + length;
    case Q::none:
    case Q::reported_load:         // load_unit says it
    case Q::reported_displacement: // displacement_unit says it
        return {};
    }
    return {};
}

std::string markdown_table() {
    static const char* where_text[] = {"point", "cell", "field", "base.vtp cell"};
    static const char* type_text[] = {"Float64", "Int32", "String"};
    static const char* quantity_text[] = {"", "length", "rad", "force", "force·length", "1/length", "load_unit", "displacement_unit"};
    static const char* when_text[] = {"always", "supports or prescribed displacements", "supports", "loads or pressure",
                                      "bilateral springs", "a rigid base or tensionless bed", "plastic hinges",
                                      "distributed plasticity", "a half model (`mirror_x`)", "units named in `[report]`",
                                      "springs or a rigid base", "a moving base", "stages (`[[stage]]`)",
                                      "two or more load patterns", "a moving base and two or more load patterns",
                                      "released member ends", "self-contact (`[[self_contact]]`)"};
    std::ostringstream out;
    out << "| array | where | type | components | unit | written for | meaning |\n"
        << "|---|---|---|---|---|---|---|\n";
    for (const Array& a : schema) {
        out << "| `" << a.name << "` | " << where_text[static_cast<int>(a.where)] << " | "
            << type_text[static_cast<int>(a.type)] << " | "
            << (a.components == 0 ? std::string("one per integration point") : std::to_string(a.components)) << " | "
            << quantity_text[static_cast<int>(a.quantity)] << " | " << when_text[static_cast<int>(a.when)] << " | "
            << a.meaning << " |\n";
    }
    return out.str();
}

} // namespace plastica::result
