// Contact with rigid bases and tensionless beds: the force the bases press each node with, its
// gap to the nearest base and whether it touches.
#include "arrays/output_array.hpp"

#include <algorithm>

namespace plastica {

namespace {

using namespace result;

void fill_base_contact(const StepView& v, XmlDataset& out) {
    if (!v.has(name::contact_force)) return;
    const std::size_t n = v.model.nodes.size();
    XmlArray contact = real_array(name::contact_force, n, 3), gap = real_array(name::gap, n), state = integer_array(name::contact, n);
    // A node may face more than one base (a ring between plates): its forces add up, its gap is
    // to the nearest base, and it is in contact when any base holds it.
    std::vector<bool> seen(n, false);
    for (const SpringResult& s : v.result.springs) {
        if (!s.unilateral) continue;
        double* f = &real(contact)[3 * static_cast<std::size_t>(s.node)];
        f[0] += s.force[0];
        f[1] += s.force[1];
        double& g = real(gap)[s.node];
        g = seen[s.node] ? std::min(g, s.gap) : s.gap;
        seen[s.node] = true;
        if (s.active) integer(state)[s.node] = static_cast<int>(ContactCode::closed);
    }
    out.point_data.push_back(std::move(contact));
    out.point_data.push_back(std::move(gap));
    out.point_data.push_back(std::move(state));
}

} // namespace

OutputGroup base_contact_arrays() {
    return {{
                {name::contact_force, Where::point, Type::float64, 3, Quantity::force, When::unilateral_base, "fx, fy, 0 the bases press with (summed over bases)"},
                {name::gap, Where::point, Type::float64, 1, Quantity::length, When::unilateral_base, "distance to the nearest base (negative: penetration)"},
                {name::contact, Where::point, Type::int32, 1, Quantity::none, When::unilateral_base, "0 open, 1 in contact"},
            },
            fill_base_contact};
}

} // namespace plastica
