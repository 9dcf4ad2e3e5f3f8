#include "result_schema.hpp"

#include "arrays/output_array.hpp"
#include "model/model.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace plastica::result {

namespace {

using Q = Quantity;

// The groups' rows (io/results/arrays/), points first, then cells, fields and base.vtp's: the order of
// each place is the groups' order.
std::vector<Array> gather_schema() {
    std::vector<Array> rows;
    for (const OutputGroup& g : output_groups()) rows.insert(rows.end(), g.arrays.begin(), g.arrays.end());
    std::stable_sort(rows.begin(), rows.end(), [](const Array& x, const Array& y) { return x.where < y.where; });
    return rows;
}

bool has_bilateral_springs(const Model& m) {
    return std::any_of(m.springs.begin(), m.springs.end(), [](const FoundationSpring& s) { return !s.unilateral; });
}

} // namespace

const std::vector<Array>& arrays() {
    static const std::vector<Array> schema = gather_schema();
    return schema;
}

const Array& find(std::string_view wanted) {
    for (const Array& a : arrays())
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
    case When::members: return !m.member_names.empty();
    case When::transient: return m.transient();
    case When::critical_step: return m.tracks_critical_points();
    case When::patterns: return !active_patterns(m).empty();
    case When::moving_base_patterns: return m.has_moving_base() && !active_patterns(m).empty();
    case When::line_loads: return !m.line_loads.empty();
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
    for (const Array& a : arrays())
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
    case Q::velocity: return length.empty() ? "" : length + "/s";
    case Q::acceleration: return length.empty() ? "" : length + "/s²";
    case Q::force_per_length: return force.empty() || length.empty() ? "" : force + "/" + length;
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
    static const char* quantity_text[] = {"", "length", "rad", "force", "force·length", "1/length", "load_unit", "displacement_unit", "length/s", "length/s²", "force/length"};
    static const char* when_text[] = {"always", "supports or prescribed displacements", "supports", "loads or pressure",
                                      "bilateral springs", "a rigid base or tensionless bed", "plastic hinges",
                                      "distributed plasticity", "a half model (`mirror_x`)", "units named in `[report]`",
                                      "springs or a rigid base", "a moving base", "stages (`[[stage]]`)",
                                      "two or more load patterns", "a moving base and two or more load patterns",
                                      "released member ends", "self-contact (`[[self_contact]]`)",
                                      "members (`[[line]]`, `[[arc]]`)", "a transient stage",
                                      "an elastic path, in the step that passes a bifurcation or limit point",
                                      "line loads (`[[distributed_load]]` `wx`, `wy`)"};
    std::ostringstream out;
    out << "| array | where | type | components | unit | written for | meaning |\n"
        << "|---|---|---|---|---|---|---|\n";
    for (const Array& a : arrays()) {
        out << "| `" << a.name << "` | " << where_text[static_cast<int>(a.where)] << " | "
            << type_text[static_cast<int>(a.type)] << " | "
            << (a.components == 0 ? std::string("one per integration point") : std::to_string(a.components)) << " | "
            << quantity_text[static_cast<int>(a.quantity)] << " | " << when_text[static_cast<int>(a.when)] << " | "
            << a.meaning << " |\n";
    }
    return out.str();
}

} // namespace plastica::result
