// The exact equilibrium of Roorda's L-frame as two inextensible elasticas (L = EI = 1): the
// column from its pin at (0, 0) up to the rigid joint at (0, 1), the beam from the joint to its
// pin at (1, 1), a load P down at the joint. Given the joint's rotation θ (counter-clockwise),
// shooting finds P with the column's starting angle and the beam's end forces: the beam's end
// sits on its pin and carries no moment. Each member is integrated by classical Runge–Kutta.
#pragma once

#include <Eigen/Dense>

#include <cmath>

namespace plastica::testing {

class RoordaElastica {
public:
    // The load P at joint rotation θ, from Newton's iteration on the shooting residual.
    static double load_at(double theta) {
        Eigen::Vector4d u(pi / 2.0 - 0.5 * theta, 0.0, 0.0, 13.8859); // column angle at the base, beam force (Fx, Fy), P
        for (int iteration = 0; iteration < 30; ++iteration) {
            const Eigen::Vector4d r = residual(u, theta);
            if (r.cwiseAbs().maxCoeff() < 1e-12) break;
            Eigen::Matrix4d J;
            for (int j = 0; j < 4; ++j) {
                Eigen::Vector4d v = u;
                v[j] += 1e-7;
                J.col(j) = (residual(v, theta) - r) / 1e-7;
            }
            u -= J.partialPivLu().solve(r);
        }
        return u[3];
    }

private:
    static constexpr double pi = 3.14159265358979323846;
    static constexpr int steps = 1000;

    // State (x, y, tangent angle, moment) along a member; the internal force F is constant:
    // x' = cos a, y' = sin a, a' = M, M' = F_x sin a − F_y cos a.
    static Eigen::Vector4d rate(const Eigen::Vector4d& y, const Eigen::Vector2d& F) {
        return {std::cos(y[2]), std::sin(y[2]), y[3], F[0] * std::sin(y[2]) - F[1] * std::cos(y[2])};
    }
    static Eigen::Vector4d member(Eigen::Vector4d y, const Eigen::Vector2d& F) {
        const double h = 1.0 / steps;
        for (int k = 0; k < steps; ++k) {
            const Eigen::Vector4d k1 = rate(y, F), k2 = rate(y + h / 2 * k1, F), k3 = rate(y + h / 2 * k2, F), k4 = rate(y + h * k3, F);
            y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
        }
        return y;
    }
    // The joint passes the beam's force on to the column with the load added, and the moment
    // unchanged; the members meet at a right angle.
    static Eigen::Vector4d residual(const Eigen::Vector4d& u, double theta) {
        const Eigen::Vector2d beam_force(u[1], u[2]), column_force(u[1], u[2] - u[3]);
        const Eigen::Vector4d top = member(Eigen::Vector4d(0.0, 0.0, u[0], 0.0), column_force);
        const Eigen::Vector4d end = member(Eigen::Vector4d(top[0], top[1], top[2] - pi / 2.0, top[3]), beam_force);
        return {top[2] - pi / 2.0 - theta, end[3], end[0] - 1.0, end[1] - 1.0};
    }
};

} // namespace plastica::testing
