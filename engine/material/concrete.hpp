// Concrete fibre. Envelope in compression: the parabola–rectangle of EN 1992-1-1 §3.1.7,
// σ = −fc·[1 − (1 − ε/εc2)ⁿ] up to εc2, then −fc; past εcu2 the stress stays −fc (εcu2 is the
// design limit that `plastica section` measures capacity against, not a fracture: a fibre
// that lost its load at once would make every converged state depend on the step size).
// Unloading and reloading as OpenSees' Concrete01: a straight line from the most compressed
// point of the envelope to the plastic strain of Karsan & Jirsa (1969), εp/εc2 = 0.145η² + 0.13η
// for η = εmin/εc2 < 2, else 0.707(η − 2) + 0.834, but no steeper than the initial slope.
// Tension: none by default; with ft, linear to ft and then softening linearly to zero at εtu
// (measured from εp); unloading from tension runs back towards εp along the secant.
#pragma once

#include "material/uniaxial_material.hpp"
#include "model/model.hpp"

namespace plastica {

class Concrete final : public UniaxialLaw<Concrete> {
public:
    // spec.fy is fc; spec.parameters hold eps_c2, eps_cu2, n, ft and eps_tu.
    Concrete(const SteelSpec& spec, double residual_stress);

    std::unique_ptr<UniaxialMaterial> clone() const override { return std::make_unique<Concrete>(*this); }
    StressTangent set_trial_strain(double strain) override;
    double stress() const override { return trial_.stress; }
    double tangent() const override { return trial_.tangent; }
    double strain() const override { return trial_.strain; }
    double plastic_strain() const override { return trial_.end_strain; }
    bool failed() const override { return false; }
    // On the plateau of the envelope: the fibre carries fc and no more.
    bool yielding() const override { return trial_.strain <= -eps_c2_ && trial_.strain <= trial_.min_strain; }
    // Capacity counts no tension: the tensile strength is for the response, not the resistance.
    double limit_stress(double sign) const override { return sign > 0.0 ? 0.0 : fc_; }
    double elastic_modulus() const override { return E_; }
    StrainLimits strain_limits() const override { return {eps_cu2_, eps_c2_, HUGE_VAL}; }

    void commit() override { committed_ = trial_; }
    void revert() override { trial_ = committed_; }

    // The compressive envelope at a strain ε ≤ 0.
    StressTangent envelope(double strain) const;

private:
    struct State {
        double strain = 0.0;
        double stress = 0.0;
        double tangent = 0.0;
        double min_strain = 0.0;   // the most compressive strain reached (≤ 0)
        double end_strain = 0.0;   // where the unloading line meets zero stress (εp ≤ 0)
        double unload_slope = 0.0;
        double max_opening = 0.0;  // the largest tensile strain beyond εp reached (≥ 0)
    };
    void unload_from(State& s) const; // εp and the slope after reaching min_strain
    StressTangent tension(const State& s, double opening) const;

    double fc_ = 0.0, E_ = 0.0, eps_c2_ = 0.0, eps_cu2_ = 0.0, n_ = 2.0, ft_ = 0.0, eps_tu_ = 0.0;
    State trial_, committed_;
};

} // namespace plastica
