// How each node moves in a transient scene: its velocity and acceleration (relative to a
// moving ground), zero in static steps.
#include "arrays/output_array.hpp"

namespace plastica {

namespace {

using namespace result;

void fill_motion(const StepView& v, XmlDataset& out) {
    if (!v.has(name::velocity)) return;
    const std::size_t n = v.model.nodes.size();
    XmlArray velocity = real_array(name::velocity, n, 3), acceleration = real_array(name::acceleration, n, 3);
    const std::vector<double>& vel = v.result.velocity;
    const std::vector<double>& acc = v.result.acceleration;
    for (std::size_t i = 0; i < n; ++i) {
        if (vel.size() >= 3 * n) set3(velocity, i, vel[3 * i], vel[3 * i + 1], vel[3 * i + 2]);
        if (acc.size() >= 3 * n) set3(acceleration, i, acc[3 * i], acc[3 * i + 1], acc[3 * i + 2]);
    }
    out.point_data.push_back(std::move(velocity));
    out.point_data.push_back(std::move(acceleration));
}

} // namespace

OutputGroup motion_arrays() {
    return {{
                {name::velocity, Where::point, Type::float64, 3, Quantity::velocity, When::transient, "vx, vy, θ̇ (relative to the ground)"},
                {name::acceleration, Where::point, Type::float64, 3, Quantity::acceleration, When::transient, "ax, ay, θ̈ (relative to the ground)"},
            },
            fill_motion};
}

} // namespace plastica
