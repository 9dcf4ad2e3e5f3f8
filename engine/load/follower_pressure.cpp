#include "load/follower_pressure.hpp"

namespace plastica {

FollowerPressure::FollowerPressure(const Model& model)
    : reference_(model.pressures), follows_(model.analysis.geometry != Geometry::first_order), elements_(model.elements),
      nodes_(model.nodes) {
    PatternFactors first(model.patterns.size());
    first.driven = model.analysis.pattern;
    set_pattern_factors(first);
    std::vector<bool> loaded(elements_.size(), false);
    for (const ElementPressure& p : reference_) loaded[static_cast<std::size_t>(p.element)] = loaded[static_cast<std::size_t>(p.element)] || p.value != 0.0;
    for (std::size_t e = 0; e < loaded.size(); ++e)
        if (loaded[e]) loaded_.push_back(e);
}

void FollowerPressure::set_pattern_factors(const PatternFactors& factors) {
    pressure_.assign(elements_.size(), 0.0);
    held_.assign(elements_.size(), 0.0);
    for (const ElementPressure& p : reference_) {
        pressure_[static_cast<std::size_t>(p.element)] += factors.rate(p.pattern) * p.value;
        held_[static_cast<std::size_t>(p.element)] += factors.constant(p.pattern) * p.value;
    }
}

void FollowerPressure::add_forces(const Eigen::VectorXd& u, const std::vector<double>& pressure, Eigen::VectorXd& force) const {
    for (std::size_t e : loaded_) {
        if (pressure[e] == 0.0) continue;
        const ElementSpec& s = elements_[e];
        const int i = dofs_per_node * s.node_i, j = dofs_per_node * s.node_j;
        const double moved = follows_ ? 1.0 : 0.0;
        const double cx = nodes_[s.node_j].x - nodes_[s.node_i].x + moved * (u[j] - u[i]);
        const double cy = nodes_[s.node_j].y - nodes_[s.node_i].y + moved * (u[j + 1] - u[i + 1]);
        // p·L/2 along the unit left normal (−cy, cx)/L: the length cancels.
        const double fx = -0.5 * pressure[e] * cy, fy = 0.5 * pressure[e] * cx;
        force[i] += fx, force[i + 1] += fy;
        force[j] += fx, force[j + 1] += fy;
    }
}

Eigen::Matrix<double, 6, 6> FollowerPressure::stiffness(std::size_t element, double load_factor) const {
    // ∂f/∂x = (p/2)[[−R, R], [−R, R]] with R the quarter turn [[0, −1], [1, 0]]; its symmetric
    // part is (p/2)[[0, R], [−R, 0]], and the stiffness is minus that at the pressure at λ.
    Eigen::Matrix<double, 6, 6> k = Eigen::Matrix<double, 6, 6>::Zero();
    const double a = -0.5 * (held_[element] + load_factor * pressure_[element]);
    k(0, 4) = -a, k(1, 3) = a;  // block (i, j) = a·R
    k(3, 1) = a, k(4, 0) = -a;  // block (j, i) = −a·R
    return k;
}

} // namespace plastica
