#include "contact/member_overlap.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace plastica {

namespace {

// The gap's derivatives by the six DOFs at s (Hermite shape functions h), and its second
// derivatives by the rotations.
struct GapShape {
    Eigen::Matrix<double, 6, 1> gradient;
    std::array<double, 2> rotation_curvature; // ∂²g/∂θ_i², ∂²g/∂θ_j²
};

std::array<double, 4> hermite(double s) {
    return {1.0 - 3.0 * s * s + 2.0 * s * s * s, s - 2.0 * s * s + s * s * s, 3.0 * s * s - 2.0 * s * s * s, -s * s + s * s * s};
}

// The gap g(s) = Σ h_k(s)·c_k, where c holds the nodes' gaps and the tangents' components along
// the normal times the length, as power coefficients a0 + a1 s + a2 s² + a3 s³.
std::array<double, 4> power_coefficients(const std::array<double, 4>& c) {
    return {c[0], c[1], -3.0 * c[0] - 2.0 * c[1] + 3.0 * c[2] - c[3], 2.0 * c[0] + c[1] - 2.0 * c[2] + c[3]};
}

double evaluate(const std::array<double, 4>& a, double s) { return a[0] + s * (a[1] + s * (a[2] + s * a[3])); }

// The roots of the cubic in (0, 1), in order: the interval is split where the derivative
// vanishes, and each monotone piece with a sign change is bisected to round-off.
std::vector<double> roots_in_unit_interval(const std::array<double, 4>& a) {
    std::vector<double> cuts{0.0};
    const double qa = 3.0 * a[3], qb = 2.0 * a[2], qc = a[1]; // the derivative
    if (std::abs(qa) > 0.0) {
        const double disc = qb * qb - 4.0 * qa * qc;
        if (disc > 0.0) {
            const double r = std::sqrt(disc);
            for (double x : {(-qb - r) / (2.0 * qa), (-qb + r) / (2.0 * qa)})
                if (x > 0.0 && x < 1.0) cuts.push_back(x);
        }
    } else if (std::abs(qb) > 0.0) {
        const double x = -qc / qb;
        if (x > 0.0 && x < 1.0) cuts.push_back(x);
    }
    cuts.push_back(1.0);
    std::sort(cuts.begin(), cuts.end());
    std::vector<double> roots;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        double lo = cuts[k], hi = cuts[k + 1];
        double g_lo = evaluate(a, lo);
        if ((g_lo < 0.0) == (evaluate(a, hi) < 0.0)) continue;
        for (int it = 0; it < 60 && hi - lo > 1e-15; ++it) {
            const double mid = 0.5 * (lo + hi), g_mid = evaluate(a, mid);
            if ((g_mid < 0.0) == (g_lo < 0.0)) { lo = mid; g_lo = g_mid; } else { hi = mid; }
        }
        roots.push_back(0.5 * (lo + hi));
    }
    return roots;
}

} // namespace

MemberOverlap member_overlap(const MemberCurve& m, const Eigen::Vector2d& point, const Eigen::Vector2d& normal, double k) {
    const double L = m.length;
    std::array<Eigen::Vector2d, 2> tangent, turned; // unit tangents, and turned by +90° (∂t/∂θ)
    for (int e = 0; e < 2; ++e) {
        tangent[e] = Eigen::Vector2d(std::cos(m.tangent_angle[e]), std::sin(m.tangent_angle[e]));
        turned[e] = Eigen::Vector2d(-tangent[e][1], tangent[e][0]);
    }
    const Eigen::Vector2d chord = m.position[1] - m.position[0];
    const double gap_i = (m.position[0] - point).dot(normal), gap_j = (m.position[1] - point).dot(normal);
    // The chord is the Hermite curve whose end tangents are the chord itself.
    const std::array<double, 4> c = m.straight ? std::array<double, 4>{gap_i, chord.dot(normal), gap_j, chord.dot(normal)}
                                               : std::array<double, 4>{gap_i, L * tangent[0].dot(normal), gap_j, L * tangent[1].dot(normal)};
    const std::array<double, 4> a = power_coefficients(c);

    MemberOverlap out;
    std::vector<double> ends{0.0};
    for (double r : roots_in_unit_interval(a)) ends.push_back(r);
    ends.push_back(1.0);
    static const double gauss_x[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
    static const double gauss_w[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
    for (std::size_t piece = 0; piece + 1 < ends.size(); ++piece) {
        const double s0 = ends[piece], s1 = ends[piece + 1];
        if (s1 <= s0 || evaluate(a, 0.5 * (s0 + s1)) >= 0.0) continue;
        out.fraction += s1 - s0;
        // Exact: the integrands are polynomials of degree 6 in s.
        for (int q = 0; q < 4; ++q) {
            const double s = 0.5 * (s0 + s1) + 0.5 * (s1 - s0) * gauss_x[q];
            const double w = 0.5 * (s1 - s0) * gauss_w[q] * k * L;
            const double penetration = -evaluate(a, s);
            if (penetration <= 0.0) continue;
            const std::array<double, 4> h = hermite(s);
            Eigen::Matrix<double, 6, 1> g_q;
            double curvature_i = 0.0, curvature_j = 0.0;
            if (m.straight) {
                // The chord's point (1 − s)·x_i + s·x_j.
                g_q << (1.0 - s) * normal, 0.0, s * normal, 0.0;
            } else {
                g_q << h[0] * normal, h[1] * L * turned[0].dot(normal), h[2] * normal, h[3] * L * turned[1].dot(normal);
                curvature_i = -h[1] * L * tangent[0].dot(normal);
                curvature_j = -h[3] * L * tangent[1].dot(normal);
            }
            out.internal_force -= w * penetration * g_q;
            out.resultant += w * penetration;
            out.stiffness += w * g_q * g_q.transpose();
            out.stiffness(2, 2) -= w * penetration * curvature_i;
            out.stiffness(5, 5) -= w * penetration * curvature_j;
        }
    }
    return out;
}

} // namespace plastica
