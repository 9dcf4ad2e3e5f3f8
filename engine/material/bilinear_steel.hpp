// Bilinear elastic-perfectly-plastic steel fibre (Silva et al., CS-ASA, eq. 6) with a trial/commit history:
// σ = E(ε − εp) inside the elastic range, ±fy while yielding; unloading is elastic and keeps
// the plastic strain εp. Past the ultimate strain εu the fibre has failed and carries nothing.
#pragma once

#include "material/uniaxial_material.hpp"
#include "model/model.hpp"

#include <cmath>

namespace plastica {

class BilinearSteel final : public UniaxialLaw<BilinearSteel> {
public:
    BilinearSteel() = default;
    BilinearSteel(const SteelSpec& spec, double residual_stress);

    std::unique_ptr<UniaxialMaterial> clone() const override { return std::make_unique<BilinearSteel>(*this); }
    StressTangent set_trial_strain(double strain) override;
    StressTangent set_trial_strain_on_branch(double strain) override;
    // An elastic stress within ±fy, a plastic strain that grows in the direction of yielding.
    bool branch_consistent() const override;
    double stress() const override { return trial_.stress; }
    double tangent() const override { return trial_.tangent; }
    bool failed() const override { return trial_.failed; }
    double plastic_strain() const override { return trial_.plastic_strain; }
    double strain() const override { return trial_.strain; }
    bool yielding() const override { return trial_.tangent == 0.0 && !trial_.failed; }
    double limit_stress(double) const override { return fy_; }
    double elastic_modulus() const override { return E_; }

    StrainLimits strain_limits() const override {
        StrainLimits limits;
        if (eu_ > 0.0) limits.tension = eu_;
        return limits;
    }

    void commit() override { committed_ = trial_; }
    void revert() override { trial_ = committed_; }

private:
    struct State {
        double strain = 0.0;
        double plastic_strain = 0.0;
        double stress = 0.0;
        double tangent = 0.0;
        int branch = 0; // 0 elastic, +1 yielding in tension, −1 in compression
        bool failed = false;
    };
    double E_ = 0.0;
    double fy_ = 0.0;
    double eu_ = 0.0;
    double eps_residual_ = 0.0; // strain offset that reproduces the residual stress at ε = 0
    State trial_;
    State committed_;
};

// Inline: the section's loop over fibres (UniaxialLaw) calls it for every fibre.
inline StressTangent BilinearSteel::set_trial_strain(double strain) {
    State& s = trial_;
    s = committed_;
    s.strain = strain;
    if (s.failed) {
        s.stress = 0.0;
        s.tangent = 0.0;
        return {s.stress, s.tangent};
    }
    // The residual stress acts as an initial elastic strain of the fibre.
    const double total = strain + eps_residual_;
    if (eu_ > 0.0 && std::abs(total) > eu_) {
        s.failed = true;
        s.stress = 0.0;
        s.tangent = 0.0;
        return {s.stress, s.tangent};
    }
    const double elastic_stress = E_ * (total - s.plastic_strain);
    if (std::abs(elastic_stress) <= fy_) {
        s.stress = elastic_stress;
        s.tangent = E_;
        s.branch = 0;
    } else {
        // Return mapping of perfect plasticity: the excess strain becomes plastic.
        const double sign = elastic_stress > 0.0 ? 1.0 : -1.0;
        s.stress = sign * fy_;
        s.plastic_strain = total - s.stress / E_;
        s.tangent = 0.0;
        s.branch = static_cast<int>(sign);
    }
    return {s.stress, s.tangent};
}

} // namespace plastica
