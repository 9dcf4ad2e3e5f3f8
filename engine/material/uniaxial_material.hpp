// The law of one fibre: a trial state set from a strain, committed at equilibrium and reverted
// after a failed increment. The fibre section sees materials only through this interface; a
// new law is one file pair and one line in material/material_registry.cpp.
#pragma once

#include <memory>

namespace plastica {

// What a trial strain gives: σ and dσ/dε.
struct StressTangent {
    double stress = 0.0;
    double tangent = 0.0;
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

    virtual void commit() = 0;
    virtual void revert() = 0;
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

} // namespace plastica
