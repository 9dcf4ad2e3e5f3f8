#include "analysis/path_extrapolation.hpp"

#include <algorithm>
#include <cmath>

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

std::optional<double> PathExtrapolation::peak_with(double s2, double l2, double* at) const {
    if (count_ < 2) return std::nullopt;
    const PathPoint& before = points_[static_cast<std::size_t>(count_ - 2)];
    const PathPoint& last = points_[static_cast<std::size_t>(count_ - 1)];
    const double s0 = before.parameter, l0 = before.load_factor;
    const double s1 = last.parameter, l1 = last.load_factor;
    if (s0 == s1 || s1 == s2 || s0 == s2) return std::nullopt;
    // Newton's form λ(s) = l0 + d01 (s − s0) + c (s − s0)(s − s1); λ' vanishes at the vertex.
    const double d01 = (l1 - l0) / (s1 - s0), d12 = (l2 - l1) / (s2 - s1);
    const double c = (d12 - d01) / (s2 - s0);
    if (c == 0.0) return std::nullopt;
    const double vertex = 0.5 * (s0 + s1) - d01 / (2.0 * c);
    // The pivot turned within the last step: its maximum lies between its ends.
    const double lo = std::min(s1, s2), hi = std::max(s1, s2);
    if (vertex < lo || vertex > hi) return std::nullopt;
    const double peak = l0 + d01 * (vertex - s0) + c * (vertex - s0) * (vertex - s1);
    if (std::abs(peak) < std::max(std::abs(l0), std::abs(l2))) return std::nullopt; // a minimum of |λ|
    // A quadratic bent by a far first point (the unloaded state before a first step that went
    // almost to the peak) overshoots: the peak rises above the step's ends by no more than the
    // step's own change of λ, or a thousandth of it.
    if (std::abs(peak) - std::max(std::abs(l1), std::abs(l2)) > std::max(std::abs(l2 - l1), 1e-3 * std::abs(peak))) return std::nullopt;
    if (at) *at = vertex;
    return peak;
}

} // namespace plastica
