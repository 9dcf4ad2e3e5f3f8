// Quadrature rules on [0, 1]. Gauss–Legendre: n points integrate polynomials of degree 2n − 1
// exactly. Gauss–Lobatto: n points, both ends among them, degree 2n − 3 (a force-based member
// samples its end sections, where the moment peaks).
#pragma once

#include <vector>

namespace plastica {

struct QuadraturePoint {
    double xi = 0.0;     // position along the member, 0 … 1
    double weight = 0.0; // weights sum to 1
};

std::vector<QuadraturePoint> gauss_legendre(int points);
std::vector<QuadraturePoint> gauss_lobatto(int points); // points ≥ 2

} // namespace plastica
