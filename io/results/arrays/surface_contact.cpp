// Contact between the members' surfaces ([[self_contact]]): the force other surfaces press each
// node with.
#include "arrays/output_array.hpp"

namespace plastica {

namespace {

using namespace result;

void fill_surface_contact(const StepView& v, XmlDataset& out) {
    if (!v.has(name::surface_contact_force)) return;
    // Each pair presses its node (or its point, shared between its element's ends) one way and
    // the segment's ends the other, shared as the segment's linear shape functions share the
    // point where it is touched.
    XmlArray surface = real_array(name::surface_contact_force, v.model.nodes.size(), 3);
    for (const SurfaceContactResult& c : v.result.surface_contacts) {
        const double shares[2] = {c.segment[0] == c.segment[1] ? 1.0 : 1.0 - c.xi, c.segment[0] == c.segment[1] ? 0.0 : c.xi};
        for (int d = 0; d < 2; ++d) {
            real(surface)[3 * static_cast<std::size_t>(c.point[0]) + d] += (1.0 - c.eta) * c.force[d];
            real(surface)[3 * static_cast<std::size_t>(c.point[1]) + d] += c.eta * c.force[d];
            for (int end = 0; end < 2; ++end)
                real(surface)[3 * static_cast<std::size_t>(c.segment[end]) + d] -= shares[end] * c.force[d];
        }
    }
    out.point_data.push_back(std::move(surface));
}

} // namespace

OutputGroup surface_contact_arrays() {
    return {{
                {name::surface_contact_force, Where::point, Type::float64, 3, Quantity::force, When::self_contact, "fx, fy, 0 other surfaces press the node with (as a touching node, an end of an element whose points touch, or a segment's end)"},
            },
            fill_surface_contact};
}

} // namespace plastica
