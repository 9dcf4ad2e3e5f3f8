#include "load/follower_pressure.hpp"

namespace plastica {

FollowerPressure::FollowerPressure(const Model& model)
    : elements_(model.elements), nodes_(model.nodes), pressure_(model.elements.size(), 0.0) {
    for (const ElementPressure& p : model.pressures) pressure_[p.element] += p.value;
    for (std::size_t e = 0; e < pressure_.size(); ++e)
        if (pressure_[e] != 0.0) loaded_.push_back(e);
}

void FollowerPressure::add_forces(const Eigen::VectorXd& u, Eigen::VectorXd& force) const {
    for (std::size_t e : loaded_) {
        const ElementSpec& s = elements_[e];
        const int i = dofs_per_node * s.node_i, j = dofs_per_node * s.node_j;
        const double cx = nodes_[s.node_j].x + u[j] - nodes_[s.node_i].x - u[i];
        const double cy = nodes_[s.node_j].y + u[j + 1] - nodes_[s.node_i].y - u[i + 1];
        // p·L/2 along the unit left normal (−cy, cx)/L: the length cancels.
        const double fx = -0.5 * pressure_[e] * cy, fy = 0.5 * pressure_[e] * cx;
        force[i] += fx, force[i + 1] += fy;
        force[j] += fx, force[j + 1] += fy;
    }
}

Eigen::Matrix<double, 6, 6> FollowerPressure::stiffness(std::size_t element, double load_factor) const {
    // ∂f/∂x = (p/2)[[−R, R], [−R, R]] with R the quarter turn [[0, −1], [1, 0]]; its symmetric
    // part is (p/2)[[0, R], [−R, 0]], and the stiffness is minus λ times that.
    Eigen::Matrix<double, 6, 6> k = Eigen::Matrix<double, 6, 6>::Zero();
    const double a = -0.5 * load_factor * pressure_[element];
    k(0, 4) = -a, k(1, 3) = a;  // block (i, j) = a·R
    k(3, 1) = a, k(4, 0) = -a;  // block (j, i) = −a·R
    return k;
}

} // namespace plastica
