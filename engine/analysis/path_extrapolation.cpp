#include "analysis/path_extrapolation.hpp"

namespace plastica {

void PathExtrapolation::add(double parameter, const Eigen::VectorXd& displacement, double load_factor,
                            const Eigen::VectorXd& axial_forces) {
    // Points at distinct parameters only (the quadratic through them divides by their spacing):
    // a state at the same parameter replaces the one there.
    if (count_ > 0 && parameter == points_[count_ - 1].parameter) --count_;
    if (count_ == 3) {
        std::swap(points_[0], points_[1]);
        std::swap(points_[1], points_[2]);
        --count_;
    }
    PathPoint& p = points_[count_++];
    p.parameter = parameter;
    p.displacement = displacement;
    p.load_factor = load_factor;
    p.axial_forces = axial_forces;
}

PathPoint PathExtrapolation::at(double s) const {
    // Lagrange weights of the quadratic through the three points.
    std::array<double, 3> w{};
    for (int i = 0; i < 3; ++i) {
        w[i] = 1.0;
        for (int j = 0; j < 3; ++j)
            if (j != i) w[i] *= (s - points_[j].parameter) / (points_[i].parameter - points_[j].parameter);
    }
    PathPoint p;
    p.parameter = s;
    p.displacement = w[0] * points_[0].displacement + w[1] * points_[1].displacement + w[2] * points_[2].displacement;
    p.load_factor = w[0] * points_[0].load_factor + w[1] * points_[1].load_factor + w[2] * points_[2].load_factor;
    p.axial_forces = w[0] * points_[0].axial_forces + w[1] * points_[1].axial_forces + w[2] * points_[2].axial_forces;
    return p;
}

} // namespace plastica
