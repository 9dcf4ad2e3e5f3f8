// The law of one fibre: a trial state set from a strain, committed at equilibrium and reverted
// after a failed increment. The fibre section sees materials only through this interface; a
// new law is one file pair and one line in material/material_registry.cpp. A law derives from
// UniaxialLaw<itself>, which gives it the section's loop over its fibres with its own update
// called directly (one virtual call per section, not per fibre).
#pragma once

#include <cmath>
#include <cstddef>
#include <memory>

namespace plastica {

// What a trial strain gives: σ and dσ/dε.
struct StressTangent {
    double stress = 0.0;
    double tangent = 0.0;
};

struct SectionFibre;

// What a section's fibres sum to at a trial strain: N = Σσ·A, M = −Σσ·A·y, and the tangent
// ∂(N, M)/∂(ε0, κ) = [k11 k12; k12 k22].
struct FibreSums {
    double N = 0.0, M = 0.0;
    double k11 = 0.0, k12 = 0.0, k22 = 0.0;
};

class UniaxialMaterial {
public:
    virtual ~UniaxialMaterial() = default;
    virtual std::unique_ptr<UniaxialMaterial> clone() const = 0;

    // Sets the trial total strain (measured from the unstressed state); returns the trial
    // stress and tangent (one call per fibre in the section's loop).
    virtual StressTangent set_trial_strain(double strain) = 0;
    // The same, kept on the branch (elastic, or yielding one way) of the previous trial, so
    // that the law is linear inside Newton like a frozen active set. Laws without branches
    // just set the strain.
    virtual StressTangent set_trial_strain_on_branch(double strain) { return set_trial_strain(strain); }
    // Whether the trial state satisfies the law it was kept to.
    virtual bool branch_consistent() const { return true; }

    virtual double stress() const = 0;
    virtual double tangent() const = 0;
    virtual double strain() const = 0;
    virtual double plastic_strain() const = 0;
    virtual bool failed() const = 0;
    virtual bool yielding() const = 0; // on a plastic branch
    // The stress of the fully plastic state in tension (sign > 0) or compression (magnitude):
    // the section's capacity N–M is built from these.
    virtual double limit_stress(double sign) const = 0;
    virtual double elastic_modulus() const = 0;
    // The strain limits of section design (EN 1992-1-1 §3.1.7, §6.1), as magnitudes: a bent
    // section's compressed face (εcu2), a wholly compressed section's strain (εc2), and the
    // tensile limit (εud). Infinity where the law sets none: steel without `ultimate_strain`.
    struct StrainLimits {
        double bending_compression = HUGE_VAL;
        double uniform_compression = HUGE_VAL;
        double tension = HUGE_VAL;
    };
    virtual StrainLimits strain_limits() const { return {}; }

    virtual void commit() = 0;
    virtual void revert() = 0;

    // Sets the trial strain ε0 − y·κ of the section's fibres [fibres, fibres + count), whose
    // laws are all of this one's kind (a section makes its fibres from one law), each kept on
    // its branch if asked; returns their sums.
    virtual FibreSums set_trial_fibres(SectionFibre* fibres, std::size_t count, double eps0, double curvature,
                                       bool on_branches) = 0;
};

// A material held by value: copies clone the law with its history.
class MaterialHolder {
public:
    MaterialHolder() = default;
    explicit MaterialHolder(std::unique_ptr<UniaxialMaterial> m) : m_(std::move(m)) {}
    MaterialHolder(const MaterialHolder& o) : m_(o.m_ ? o.m_->clone() : nullptr) {}
    MaterialHolder(MaterialHolder&&) noexcept = default;
    MaterialHolder& operator=(const MaterialHolder& o) {
        if (this != &o) m_ = o.m_ ? o.m_->clone() : nullptr;
        return *this;
    }
    MaterialHolder& operator=(MaterialHolder&&) noexcept = default;

    UniaxialMaterial& operator*() { return *m_; }
    UniaxialMaterial* operator->() { return m_.get(); }
    const UniaxialMaterial* operator->() const { return m_.get(); }

private:
    std::unique_ptr<UniaxialMaterial> m_;
};

// A fibre of a section: its area, distance y from the reference axis (strain ε0 − y·κ), its
// law's limit stresses (magnitudes) and residual stress, and the law with its history.
struct SectionFibre {
    double area;
    double y;
    double limit_tension;
    double limit_compression;
    double residual_stress;
    MaterialHolder material;
    double extent = 0.0; // half the fibre's height: its edges at y ± extent
};

// The base of each law: the section's loop over fibres, with the law's own update called
// directly (Law is final) and inlined where the law defines it.
template <class Law>
class UniaxialLaw : public UniaxialMaterial {
public:
    FibreSums set_trial_fibres(SectionFibre* fibres, std::size_t count, double eps0, double curvature,
                               bool on_branches) override {
        // Sums in locals: the compiler keeps them in registers across the fibres' laws.
        double N = 0.0, M = 0.0, k11 = 0.0, k12 = 0.0, k22 = 0.0;
        for (std::size_t i = 0; i < count; ++i) {
            SectionFibre& f = fibres[i];
            Law& law = static_cast<Law&>(*f.material); // every fibre of the section is of this law
            const double strain = eps0 - f.y * curvature;
            const StressTangent st = on_branches ? law.set_trial_strain_on_branch(strain) : law.set_trial_strain(strain);
            const double s = st.stress * f.area;
            const double t = st.tangent * f.area;
            N += s;
            M -= s * f.y;
            k11 += t;
            k12 -= t * f.y;
            k22 += t * f.y * f.y;
        }
        return {N, M, k11, k12, k22};
    }
};

} // namespace plastica
