// Bilinear steel with linear kinematic hardening (Prager; the law of OpenSees' Steel01): past
// yield the tangent is b·E; the elastic range keeps its width 2·fy and moves with the back
// stress α, so a fibre loaded past yield in tension yields again in compression at α − fy
// (the Bauschinger effect). With the return map of linear hardening the update is exact for
// any strain increment. Scene keys: hardening_ratio = b in [0, 1).
#pragma once

#include "material/uniaxial_material.hpp"
#include "model/model.hpp"

namespace plastica {

class KinematicHardeningSteel final : public UniaxialLaw<KinematicHardeningSteel> {
public:
    KinematicHardeningSteel(const SteelSpec& spec, double residual_stress);

    std::unique_ptr<UniaxialMaterial> clone() const override { return std::make_unique<KinematicHardeningSteel>(*this); }
    StressTangent set_trial_strain(double strain) override;
    StressTangent set_trial_strain_on_branch(double strain) override;
    bool branch_consistent() const override;
    double stress() const override { return trial_.stress; }
    double tangent() const override { return trial_.tangent; }
    bool failed() const override { return trial_.failed; }
    double plastic_strain() const override { return trial_.plastic_strain; }
    double strain() const override { return trial_.strain; }
    bool yielding() const override { return trial_.branch != 0 && !trial_.failed; }
    // The fully plastic state of a section at first yield everywhere: the conventional Mp.
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
        double back_stress = 0.0;
        double stress = 0.0;
        double tangent = 0.0;
        int branch = 0; // 0 elastic, ±1 yielding in tension / compression
        bool failed = false;
    };
    // The state at a strain on a given branch (0: elastic) from the committed state.
    State on_branch(double strain, int branch) const;
    double E_ = 0.0, fy_ = 0.0, eu_ = 0.0;
    double H_ = 0.0; // plastic modulus: b·E/(1 − b)
    double eps_residual_ = 0.0;
    State trial_, committed_;
};

} // namespace plastica
