#include "analysis/increment_constraints.hpp"

#include <cmath>
#include <limits>

namespace plastica {

namespace {
constexpr double no_root = std::numeric_limits<double>::quiet_NaN();
}

double DisplacementControl::load_change(int, const Eigen::VectorXd& increment,
                                        const Eigen::VectorXd& du_residual, const Eigen::VectorXd& du_load) {
    // Keep the controlled equation's increment at h: its total after this correction.
    const double target = h_ - increment[equation_];
    if (std::abs(du_load[equation_]) < 1e-300) return no_root;
    return (target - du_residual[equation_]) / du_load[equation_];
}

double ArcLength::load_change(int iteration, const Eigen::VectorXd& increment,
                              const Eigen::VectorXd& du_residual, const Eigen::VectorXd& du_load) {
    if (iteration == 0) {
        double sign = h_ >= 0.0 ? 1.0 : -1.0;
        if (previous_.size() == du_load.size() && previous_.norm() > 0.0)
            sign = previous_.dot(du_load) >= 0.0 ? 1.0 : -1.0;
        return sign * std::abs(h_) / std::max(du_load.norm(), 1e-300);
    }
    const Eigen::VectorXd base = increment + du_residual;
    const double qa = du_load.squaredNorm();
    const double qb = 2.0 * base.dot(du_load);
    const double qc = base.squaredNorm() - h_ * h_;
    const double disc = qb * qb - 4.0 * qa * qc;
    // No point of this correction's line lies on the arc (the residual's part alone leaves the
    // sphere, as near a sharp turn of the path). When asked, take the line's point nearest to
    // it: the increment's length is off by what the missing root would have fixed, and the
    // iterations that follow draw it back to the arc where they can.
    if (disc < 0.0) return nearest_when_no_root_ && qa > 0.0 ? -qb / (2.0 * qa) : no_root;
    const double root = std::sqrt(disc);
    const double l1 = (-qb + root) / (2.0 * qa);
    const double l2 = (-qb - root) / (2.0 * qa);
    // The root whose increment stays closest to the current one.
    const double c1 = (base + l1 * du_load).dot(increment);
    const double c2 = (base + l2 * du_load).dot(increment);
    return c1 >= c2 ? l1 : l2;
}

} // namespace plastica
