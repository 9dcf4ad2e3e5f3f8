#include "material/kinematic_hardening_steel.hpp"

#include "material/material_registry.hpp"

#include <cmath>

namespace plastica {

KinematicHardeningSteel::KinematicHardeningSteel(const SteelSpec& spec, double residual_stress)
    : E_(spec.E), fy_(spec.fy), eu_(spec.ultimate_strain), eps_residual_(residual_stress / spec.E) {
    const double ratio = hardening_ratio(spec);
    if (!(ratio >= 0.0 && ratio < 1.0)) throw MaterialParameterError("hardening_ratio", "expected a ratio b = Esh/E in [0, 1)");
    H_ = ratio * E_ / (1.0 - ratio);
    set_trial_strain(0.0);
    commit();
}

KinematicHardeningSteel::State KinematicHardeningSteel::on_branch(double strain, int branch) const {
    State s = committed_;
    s.strain = strain;
    s.branch = branch;
    const double total = strain + eps_residual_; // the residual stress as an initial elastic strain
    const double trial = E_ * (total - s.plastic_strain);
    if (branch == 0) {
        s.stress = trial;
        s.tangent = E_;
        return s;
    }
    // Return map of linear kinematic hardening: the overstress beyond the moved yield surface
    // is shared between plastic strain and back stress in the ratio E : H.
    const double overstress = branch * (trial - s.back_stress) - fy_;
    const double plastic = overstress / (E_ + H_);
    s.plastic_strain += branch * plastic;
    s.back_stress += branch * H_ * plastic;
    s.stress = trial - branch * E_ * plastic;
    s.tangent = E_ * H_ / (E_ + H_);
    return s;
}

StressTangent KinematicHardeningSteel::set_trial_strain(double strain) {
    if (committed_.failed || (eu_ > 0.0 && std::abs(strain + eps_residual_) > eu_)) {
        trial_ = committed_;
        trial_.strain = strain;
        trial_.failed = true;
        trial_.stress = trial_.tangent = 0.0;
        return {};
    }
    const State elastic = on_branch(strain, 0);
    const double relative = elastic.stress - committed_.back_stress;
    trial_ = std::abs(relative) <= fy_ ? elastic : on_branch(strain, relative > 0.0 ? 1 : -1);
    return {trial_.stress, trial_.tangent};
}

StressTangent KinematicHardeningSteel::set_trial_strain_on_branch(double strain) {
    if (committed_.failed) return set_trial_strain(strain);
    trial_ = on_branch(strain, trial_.branch);
    return {trial_.stress, trial_.tangent};
}

bool KinematicHardeningSteel::branch_consistent() const {
    if (trial_.failed) return true;
    if (trial_.branch == 0) return std::abs(trial_.stress - committed_.back_stress) <= fy_ * (1.0 + 1e-9);
    return trial_.branch * (trial_.plastic_strain - committed_.plastic_strain) >= -1e-9 * fy_ / E_;
}

} // namespace plastica
