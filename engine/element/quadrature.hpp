// Gauss–Legendre quadrature on [0, 1]: n points integrate polynomials of degree 2n − 1 exactly.
#pragma once

#include <vector>

namespace plastica {

struct QuadraturePoint {
    double xi = 0.0;     // position along the member, 0 … 1
    double weight = 0.0; // weights sum to 1
};

std::vector<QuadraturePoint> gauss_legendre(int points);

} // namespace plastica
