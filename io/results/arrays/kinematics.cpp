// Where each node is: its displacement, rotation and initial position.
#include "arrays/output_array.hpp"

namespace plastica {

namespace {

using namespace result;

void fill_kinematics(const StepView& v, XmlDataset& out) {
    const std::size_t n = v.model.nodes.size();
    const std::vector<double>& u = v.result.displacement;
    XmlArray displacement = real_array(name::displacement, n, 3), rotation = real_array(name::rotation, n),
             initial = real_array(name::initial_position, n, 3);
    for (std::size_t i = 0; i < n; ++i) {
        set3(displacement, i, u[3 * i], u[3 * i + 1], 0.0);
        real(rotation)[i] = u[3 * i + 2];
        set3(initial, i, v.model.nodes[i].x, v.model.nodes[i].y, 0.0);
    }
    out.point_data.push_back(std::move(displacement));
    out.active_vectors = name::displacement;
    out.point_data.push_back(std::move(rotation));
    out.point_data.push_back(std::move(initial));
}

} // namespace

OutputGroup kinematic_arrays() {
    return {{
                {name::displacement, Where::point, Type::float64, 3, Quantity::length, When::always, "ux, uy, 0 (the active vectors; points are already at x0 + u)"},
                {name::rotation, Where::point, Type::float64, 1, Quantity::rotation, When::always, "nodal rotation θ"},
                {name::initial_position, Where::point, Type::float64, 3, Quantity::length, When::always, "x0, y0, 0"},
            },
            fill_kinematics};
}

} // namespace plastica
