// What holds and what pushes: reactions at supported and prescribed DOFs (the force on the
// structure), which DOFs each node's support fixes, and the applied load λF (with pressure as
// it follows the members). Forces are vectors, moments scalars of their own.
#include "arrays/output_array.hpp"

namespace plastica {

void push_force_and_moment(XmlDataset& out, const char* force_name, const char* moment_name, const std::vector<double>& nodal) {
    const std::size_t n = nodal.size() / 3;
    XmlArray force = real_array(force_name, n, 3), moment = real_array(moment_name, n);
    for (std::size_t i = 0; i < n; ++i) {
        set3(force, i, nodal[3 * i], nodal[3 * i + 1], 0.0);
        real(moment)[i] = nodal[3 * i + 2];
    }
    out.point_data.push_back(std::move(force));
    out.point_data.push_back(std::move(moment));
}

namespace {

using namespace result;

void fill_supports_and_loads(const StepView& v, XmlDataset& out) {
    const std::size_t n = v.model.nodes.size();
    if (v.has(name::reaction)) push_force_and_moment(out, name::reaction, name::reaction_moment, v.result.reaction);
    if (v.has(name::support)) {
        XmlArray fixed = integer_array(name::support, n);
        for (const Support& s : v.model.supports)
            integer(fixed)[s.node] |= (s.fixed[0] ? fixes_ux : 0) | (s.fixed[1] ? fixes_uy : 0) | (s.fixed[2] ? fixes_rz : 0);
        out.point_data.push_back(std::move(fixed));
    }
    if (v.has(name::applied_load)) push_force_and_moment(out, name::applied_load, name::applied_moment, v.result.applied_load);
    if (v.has(name::line_load)) {
        XmlArray line = real_array(name::line_load, v.model.elements.size(), 3);
        const std::vector<double>& factors = v.result.pattern_factors;
        for (const ElementLineLoad& l : v.model.line_loads) {
            const auto p = static_cast<std::size_t>(l.pattern);
            const double factor = p < factors.size() ? factors[p] : v.result.load_factor;
            real(line)[3 * static_cast<std::size_t>(l.element)] += factor * l.wx;
            real(line)[3 * static_cast<std::size_t>(l.element) + 1] += factor * l.wy;
        }
        out.cell_data.push_back(std::move(line));
    }
}

} // namespace

OutputGroup support_and_load_arrays() {
    return {{
                {name::reaction, Where::point, Type::float64, 3, Quantity::force, When::supported_or_prescribed, "fx, fy, 0 the support exerts on the structure"},
                {name::reaction_moment, Where::point, Type::float64, 1, Quantity::moment, When::supported_or_prescribed, "moment the support exerts"},
                {name::support, Where::point, Type::int32, 1, Quantity::none, When::supported, "fixed DOFs: 1 ux + 2 uy + 4 rz"},
                {name::applied_load, Where::point, Type::float64, 3, Quantity::force, When::loaded, "fx, fy, 0: λ × the reference loads, pressure as it follows the members"},
                {name::applied_moment, Where::point, Type::float64, 1, Quantity::moment, When::loaded, "λ × the reference moments"},
                {name::line_load, Where::cell, Type::float64, 3, Quantity::force_per_length, When::line_loads,
                 "wx, wy, 0: the line load on the element per unit initial length at the step's factors (its nodal shares are in "
                 "applied_load)"},
            },
            fill_supports_and_loads};
}

} // namespace plastica
