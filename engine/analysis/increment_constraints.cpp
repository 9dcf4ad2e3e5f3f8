#include "analysis/increment_constraints.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plastica {

namespace {
constexpr double no_root = std::numeric_limits<double>::quiet_NaN();
// Below this cosine between the last increment and the tangent's direction, Feng's criterion
// gives way to the last step's load sense (the tangent turned by more than 60°).
constexpr double weak_alignment = 0.5;
}

double DisplacementControl::load_change(int, const Eigen::VectorXd& increment, const Eigen::VectorXd& du_residual,
                                        const Eigen::VectorXd& du_load, int) {
    // Keep the controlled equation's increment at h: its total after this correction.
    const double target = h_ - increment[equation_];
    if (std::abs(du_load[equation_]) < 1e-300) return no_root;
    return (target - du_residual[equation_]) / du_load[equation_];
}

double ArcLength::load_change(int iteration, const Eigen::VectorXd& increment, const Eigen::VectorXd& du_residual,
                              const Eigen::VectorXd& du_load, int negative_pivots) {
    if (iteration == 0) {
        start_negative_pivots_ = negative_pivots;
        double sign = h_ >= 0.0 ? 1.0 : -1.0;
        const Eigen::VectorXd& previous = last_.increment;
        if (previous.size() == du_load.size() && previous.norm() > 0.0) {
            const double cosine = previous.dot(du_load) / (previous.norm() * std::max(du_load.norm(), 1e-300));
            if (std::abs(cosine) >= weak_alignment || last_.negative_pivots < 0 || last_.load_change == 0.0) {
                sign = cosine >= 0.0 ? 1.0 : -1.0;
            } else {
                const bool limit_passed = (negative_pivots - last_.negative_pivots) % 2 != 0;
                sign = (last_.load_change > 0.0) != limit_passed ? 1.0 : -1.0;
            }
        }
        return sign * std::abs(h_) / std::max(du_load.norm(), 1e-300);
    }
    const Eigen::VectorXd base = increment + du_residual;
    const double qa = du_load.squaredNorm();
    const double qb = 2.0 * base.dot(du_load);
    const double qc = base.squaredNorm() - h_ * h_;
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc < 0.0) return no_root; // no point on the arc: cut the step
    const double root = std::sqrt(disc);
    const double l1 = (-qb + root) / (2.0 * qa);
    const double l2 = (-qb - root) / (2.0 * qa);
    // The root whose increment stays closest to the current one.
    const double c1 = (base + l1 * du_load).dot(increment);
    const double c2 = (base + l2 * du_load).dot(increment);
    return c1 >= c2 ? l1 : l2;
}

} // namespace plastica
