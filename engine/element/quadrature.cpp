#include "element/quadrature.hpp"

#include <cmath>
#include <stdexcept>

namespace plastica {

namespace {
// Legendre polynomials P_n(x) and P_{n−1}(x) by the three-term recurrence (P_{−1} taken as 0).
struct LegendrePair {
    double p_n, p_previous;
};
LegendrePair legendre(int n, double x) {
    double p0 = 1.0, p1 = x;
    if (n == 0) return {1.0, 0.0};
    for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
    }
    return {p1, p0};
}
} // namespace

std::vector<QuadraturePoint> gauss_legendre(int n) {
    if (n < 1) throw std::invalid_argument("gauss_legendre: at least one point");
    std::vector<QuadraturePoint> points(n);
    // Roots of P_n by Newton from Tricomi's estimate; P_n' from P_n and P_{n−1}.
    for (int i = 0; i < (n + 1) / 2; ++i) {
        double x = std::cos(M_PI * (i + 0.75) / (n + 0.5));
        double derivative = 1.0;
        for (int it = 0; it < 100; ++it) {
            const LegendrePair p = legendre(n, x);
            derivative = n * (x * p.p_n - p.p_previous) / (x * x - 1.0);
            const double dx = p.p_n / derivative;
            x -= dx;
            if (std::abs(dx) < 1e-16) break;
        }
        const double w = 2.0 / ((1.0 - x * x) * derivative * derivative);
        // Map [−1, 1] to [0, 1]: ξ = (1 + x)/2, weights halved.
        points[i] = {0.5 * (1.0 - x), 0.5 * w};
        points[n - 1 - i] = {0.5 * (1.0 + x), 0.5 * w};
    }
    return points;
}

std::vector<QuadraturePoint> gauss_lobatto(int n) {
    if (n < 2) throw std::invalid_argument("gauss_lobatto: at least two points");
    const int N = n - 1; // the inner points are the roots of P_N'
    std::vector<QuadraturePoint> points(n);
    // Newton on (1 − x²) P_N'(x) = N (P_{N−1} − x P_N), from the Chebyshev–Lobatto points.
    for (int i = 0; i < n; ++i) {
        double x = std::cos(M_PI * i / N);
        for (int it = 0; it < 100; ++it) {
            const LegendrePair p = legendre(N, x);
            const double dx = (x * p.p_n - p.p_previous) / (n * p.p_n);
            x -= dx;
            if (std::abs(dx) < 1e-16) break;
        }
        const double pn = legendre(N, x).p_n;
        // Weights 2/(N(N + 1) P_N²) on [−1, 1], halved on [0, 1].
        points[n - 1 - i] = {0.5 * (1.0 + x), 1.0 / (N * (N + 1.0) * pn * pn)};
    }
    return points;
}

} // namespace plastica
