#include "material/bilinear_steel.hpp"

#include <cmath>

namespace plastica {

BilinearSteel::BilinearSteel(const SteelSpec& spec, double residual_stress)
    : E_(spec.E), fy_(spec.fy), eu_(spec.ultimate_strain), eps_residual_(residual_stress / spec.E) {
    set_trial_strain(0.0);
    commit();
}

StressTangent BilinearSteel::set_trial_strain_on_branch(double strain) {
    const int branch = trial_.branch;
    if (committed_.failed) return set_trial_strain(strain);
    State s = committed_;
    s.strain = strain;
    s.branch = branch;
    const double total = strain + eps_residual_;
    if (branch == 0) {
        s.stress = E_ * (total - s.plastic_strain);
        s.tangent = E_;
    } else {
        s.stress = branch * fy_;
        s.plastic_strain = total - s.stress / E_;
        s.tangent = 0.0;
    }
    trial_ = s;
    return {s.stress, s.tangent};
}

bool BilinearSteel::branch_consistent() const {
    // Relative slack of 1e-9 of the yield strain: round-off of an equilibrium state.
    const double slack = 1e-9 * fy_ / E_;
    if (trial_.failed) return true;
    if (trial_.branch == 0) return std::abs(trial_.stress) <= fy_ * (1.0 + 1e-9);
    return trial_.branch * (trial_.plastic_strain - committed_.plastic_strain) >= -slack;
}

} // namespace plastica
