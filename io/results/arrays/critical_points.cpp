// The critical point a step of an elastic path passed (analysis/path_critical.cpp): its mode
// and where it lies, written only in the VTU of that step.
#include "arrays/output_array.hpp"

namespace plastica {

namespace {

using namespace result;

void fill_critical_point(const StepView& v, XmlDataset& out) {
    if (!v.has(name::critical_mode) || !v.result.critical) return;
    const CriticalPoint& c = *v.result.critical;
    const std::size_t n = v.model.nodes.size();
    XmlArray mode = real_array(name::critical_mode, n, 3);
    for (std::size_t i = 0; i < n && c.mode.size() >= 3 * n; ++i) set3(mode, i, c.mode[3 * i], c.mode[3 * i + 1], c.mode[3 * i + 2]);
    out.point_data.push_back(std::move(mode));
    XmlArray kind = integer_array(name::critical_point, 1);
    integer(kind)[0] = static_cast<std::int32_t>(c.kind == CriticalKind::bifurcation ? CriticalCode::bifurcation : CriticalCode::limit_point);
    out.field_data.push_back(std::move(kind));
    out.field_data.push_back(field_value(name::critical_load_factor, c.load_factor));
}

} // namespace

OutputGroup critical_point_arrays() {
    return {{
                {name::critical_mode, Where::point, Type::float64, 3, Quantity::none, When::critical_step,
                 "the critical mode (ux, uy, θ; its largest translation 1) of the bifurcation or limit point this step passed"},
                {name::critical_point, Where::field, Type::int32, 1, Quantity::none, When::critical_step,
                 "1 a bifurcation, 2 a limit point: the kind of critical point this step passed"},
                {name::critical_load_factor, Where::field, Type::float64, 1, Quantity::none, When::critical_step,
                 "the load factor where the tangent's lowest eigenvalue passes zero"},
            },
            fill_critical_point};
}

} // namespace plastica
