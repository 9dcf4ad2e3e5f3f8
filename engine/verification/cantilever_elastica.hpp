// The exact elastica of a cantilever under a transverse tip load P (Bisshopp and Drucker 1945;
// Mattiasson 1981's table is its tabulation). With α = PL²/EI and tip rotation θ0, p² = (1 + sin θ0)/2,
// sin φ1 = 1/(p√2):  √α = K(p) − F(φ1, p),
//   tip deflection along the load  v/L = 1 − 2[E(p) − E(φ1, p)]/√α,
//   tip shortening along the axis  u/L = 1 − √(2 sin θ0 / α).
#pragma once

#include <vector>

namespace plastica {

struct ElasticaTip {
    double alpha = 0.0;     // PL²/EI
    double rotation = 0.0;  // θ0
    double deflection = 0.0; // v/L
    double shortening = 0.0; // u/L
};

// The tip of the exact elastica for one load parameter α > 0.
ElasticaTip cantilever_tip_load(double alpha);

// The load parameter α at which the tip deflection v/L is reached (0 ≤ v/L < 1), by bisection.
double cantilever_load_for_deflection(double deflection);

} // namespace plastica
