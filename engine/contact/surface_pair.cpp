#include "contact/surface_pair.hpp"

namespace plastica {

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

double perp_dot(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a[0] * b[1] - a[1] * b[0]; }

} // namespace

void press(SurfaceContact& c, const Eigen::Vector2d& x, const Eigen::Vector2d& a_end, const Eigen::Vector2d& b_end) {
    // Π = ½·k·g², g = d − reach: force k·g·∇d, tangent k·∇d∇dᵀ + k·g·∇²d, over the point x and
    // the segment's ends; a point along a member then shares its part between its element's
    // ends as (1 − eta, eta).
    Vector6 grad = Vector6::Zero();
    Matrix6 hess = Matrix6::Zero();
    if (c.segment[0] == c.segment[1]) { // a segment end
        const Eigen::Vector2d d = x - a_end;
        const double distance = d.norm();
        c.gap = distance - c.reach;
        c.normal = d / distance;
        grad.head<2>() = c.normal;
        grad.segment<2>(2) = -c.normal;
        const Eigen::Matrix2d q = (Eigen::Matrix2d::Identity() - c.normal * c.normal.transpose()) / distance;
        hess.block<2, 2>(0, 0) = q;
        hess.block<2, 2>(0, 2) = -q;
        hess.block<2, 2>(2, 0) = -q;
        hess.block<2, 2>(2, 2) = q;
    } else {
        // d = σ·A/L, A = e × r the doubled area of (a, b, x), e = b − a, r = x − a, L = |e|.
        const Eigen::Vector2d e = b_end - a_end, r = x - a_end;
        const double L = e.norm(), area = perp_dot(e, r);
        const double sigma = area >= 0.0 ? 1.0 : -1.0;
        const Eigen::Vector2d t = e / L;
        const Eigen::Vector2d je(-e[1], e[0]), jr(-r[1], r[0]);
        // Over (x, a, b): ∂e = (0, −I, I), ∂r = (I, −I, 0).
        const double ce[3] = {0.0, -1.0, 1.0}, cr[3] = {1.0, -1.0, 0.0};
        Vector6 grad_area, grad_length;
        grad_area << je, jr - je, -jr;
        for (int i = 0; i < 3; ++i) grad_length.segment<2>(2 * i) = ce[i] * t;
        Eigen::Matrix2d m;
        m << 0.0, 1.0, -1.0, 0.0; // A = eᵀ·m·r
        const Eigen::Matrix2d p = (Eigen::Matrix2d::Identity() - t * t.transpose()) / L;
        Matrix6 hess_area, hess_length;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                hess_area.block<2, 2>(2 * i, 2 * j) = ce[i] * cr[j] * m + cr[i] * ce[j] * m.transpose();
                hess_length.block<2, 2>(2 * i, 2 * j) = ce[i] * ce[j] * p;
            }
        c.gap = sigma * area / L - c.reach;
        grad = sigma * (grad_area / L - area * grad_length / (L * L));
        hess = sigma * (hess_area / L - (grad_area * grad_length.transpose() + grad_length * grad_area.transpose()) / (L * L) -
                        area * hess_length / (L * L) + 2.0 * area * grad_length * grad_length.transpose() / (L * L * L));
        c.normal = sigma * Eigen::Vector2d(-t[1], t[0]);
    }
    // Slots: point[0], segment[0], segment[1], point[1]; x = (1 − eta)·point[0] + eta·point[1].
    Eigen::Matrix<double, 6, 8> spread = Eigen::Matrix<double, 6, 8>::Zero();
    spread.block<2, 2>(0, 0) = (1.0 - c.eta) * Eigen::Matrix2d::Identity();
    spread.block<2, 2>(0, 6) = c.eta * Eigen::Matrix2d::Identity();
    spread.block<4, 4>(2, 2).setIdentity();
    c.force = c.stiffness * c.gap * spread.transpose() * grad;
    c.tangent = c.stiffness * spread.transpose() * (grad * grad.transpose() + c.gap * hess) * spread;
}

} // namespace plastica
