// The forces of the bilateral foundation springs on their nodes.
#include "arrays/output_array.hpp"

namespace plastica {

namespace {

using namespace result;

void fill_springs(const StepView& v, XmlDataset& out) {
    if (!v.has(name::spring_force)) return;
    std::vector<double> nodal(3 * v.model.nodes.size(), 0.0);
    for (const SpringResult& s : v.result.springs)
        if (!s.unilateral)
            for (int k = 0; k < 3; ++k) nodal[3 * static_cast<std::size_t>(s.node) + k] = s.force[k];
    push_force_and_moment(out, name::spring_force, name::spring_moment, nodal);
}

} // namespace

OutputGroup spring_arrays() {
    return {{
                {name::spring_force, Where::point, Type::float64, 3, Quantity::force, When::bilateral_springs, "fx, fy, 0 of the bilateral springs on the node"},
                {name::spring_moment, Where::point, Type::float64, 1, Quantity::moment, When::bilateral_springs, "moment of the rotational spring kθ"},
            },
            fill_springs};
}

} // namespace plastica
