// Bilinear elastic-perfectly-plastic steel fibre (seed eq. 6) with a trial/commit history:
// σ = E(ε − εp) inside the elastic range, ±fy while yielding; unloading is elastic and keeps
// the plastic strain εp. Past the ultimate strain εu the fibre has failed and carries nothing.
#pragma once

#include "model/model.hpp"

namespace plastica {

class BilinearSteel {
public:
    BilinearSteel() = default;
    BilinearSteel(const SteelSpec& spec, double residual_stress);

    // Sets the trial total strain (mechanical strain measured from the unstressed state).
    void set_trial_strain(double strain);
    // The same, kept on the branch (elastic, yielding in tension or in compression) of the
    // previous trial: the law is then linear, as a frozen active set inside Newton.
    void set_trial_strain_on_branch(double strain);
    // Whether the trial state satisfies the law it was kept to: an elastic stress within ±fy,
    // a plastic strain that grows in the direction of yielding.
    bool branch_consistent() const;
    double stress() const { return trial_.stress; }
    double tangent() const { return trial_.tangent; }
    bool failed() const { return trial_.failed; }
    double plastic_strain() const { return trial_.plastic_strain; }
    double strain() const { return trial_.strain; }
    bool yielding() const { return trial_.tangent == 0.0 && !trial_.failed; }

    void commit() { committed_ = trial_; }
    void revert() { trial_ = committed_; }

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

} // namespace plastica
