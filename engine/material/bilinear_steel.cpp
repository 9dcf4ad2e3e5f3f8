#include "material/bilinear_steel.hpp"

#include <cmath>

namespace plastica {

BilinearSteel::BilinearSteel(const SteelSpec& spec, double residual_stress)
    : E_(spec.E), fy_(spec.fy), eu_(spec.ultimate_strain), eps_residual_(residual_stress / spec.E) {
    set_trial_strain(0.0);
    commit();
}

void BilinearSteel::set_trial_strain(double strain) {
    State s = committed_;
    s.strain = strain;
    if (s.failed) {
        s.stress = 0.0;
        s.tangent = 0.0;
        trial_ = s;
        return;
    }
    // The residual stress acts as an initial elastic strain of the fibre.
    const double total = strain + eps_residual_;
    if (eu_ > 0.0 && std::abs(total) > eu_) {
        s.failed = true;
        s.stress = 0.0;
        s.tangent = 0.0;
        trial_ = s;
        return;
    }
    const double elastic_stress = E_ * (total - s.plastic_strain);
    if (std::abs(elastic_stress) <= fy_) {
        s.stress = elastic_stress;
        s.tangent = E_;
    } else {
        // Return mapping of perfect plasticity: the excess strain becomes plastic.
        const double sign = elastic_stress > 0.0 ? 1.0 : -1.0;
        s.stress = sign * fy_;
        s.plastic_strain = total - s.stress / E_;
        s.tangent = 0.0;
    }
    trial_ = s;
}

} // namespace plastica
