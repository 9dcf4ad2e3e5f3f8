#include "element/quadrature.hpp"

#include <cmath>
#include <stdexcept>

namespace plastica {

std::vector<QuadraturePoint> gauss_legendre(int n) {
    if (n < 1) throw std::invalid_argument("gauss_legendre: at least one point");
    std::vector<QuadraturePoint> points(n);
    // Roots of P_n by Newton from Tricomi's estimate; P_n and P_n' by the three-term recurrence.
    for (int i = 0; i < (n + 1) / 2; ++i) {
        double x = std::cos(M_PI * (i + 0.75) / (n + 0.5));
        double derivative = 1.0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1.0, p1 = x;
            for (int k = 2; k <= n; ++k) {
                const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            derivative = n * (x * p1 - p0) / (x * x - 1.0);
            const double dx = p1 / derivative;
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

} // namespace plastica
