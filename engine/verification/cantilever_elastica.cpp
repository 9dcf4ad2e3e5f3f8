#include "verification/cantilever_elastica.hpp"

#include <cmath>

namespace plastica {

namespace {

// √α as a function of θ0 (increasing on 0 < θ0 < π/2).
double root_alpha(double rotation) {
    const double p = std::sqrt((1.0 + std::sin(rotation)) / 2.0);
    const double phi1 = std::asin(std::min(1.0, 1.0 / (p * std::sqrt(2.0))));
    return std::comp_ellint_1(p) - std::ellint_1(p, phi1);
}

} // namespace

ElasticaTip cantilever_tip_load(double alpha) {
    // Bisection on θ0 ∈ (0, π/2): √α(θ0) is monotone.
    double lo = 0.0, hi = M_PI / 2.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (root_alpha(mid) < std::sqrt(alpha) ? lo : hi) = mid;
    }
    ElasticaTip t;
    t.alpha = alpha;
    t.rotation = 0.5 * (lo + hi);
    const double p = std::sqrt((1.0 + std::sin(t.rotation)) / 2.0);
    const double phi1 = std::asin(std::min(1.0, 1.0 / (p * std::sqrt(2.0))));
    t.deflection = 1.0 - 2.0 * (std::comp_ellint_2(p) - std::ellint_2(p, phi1)) / std::sqrt(alpha);
    t.shortening = 1.0 - std::sqrt(2.0 * std::sin(t.rotation) / alpha);
    return t;
}

double cantilever_load_for_deflection(double deflection) {
    double lo = 0.0, hi = 1.0;
    while (cantilever_tip_load(hi).deflection < deflection && hi < 1e8) hi *= 2.0;
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (mid > 0 && cantilever_tip_load(mid).deflection < deflection ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

} // namespace plastica
