// Distributed plasticity (plastic zone): the basic law of a displacement-based co-rotational
// beam that integrates fibre sections at Gauss–Legendre points along the member.
//
// In the basic frame the member is a shallow Euler–Bernoulli beam: axial strain constant,
// ε0 = u_l/L0, and the rotation relative to the chord cubic (Hermite), so the curvature is
// linear, κ(ξ) = [(6ξ − 4)θ_i + (6ξ − 2)θ_j]/L0. Each point's section is strain driven (no
// section iterations, so a fully plastic section is just a section without stiffness):
//   q = Σ w L0 Bᵀ s(B e),   k = Σ w L0 Bᵀ k_s B,   B(ξ) = [1/L0 0 0; 0 (6ξ−4)/L0 (6ξ−2)/L0].
// Two points integrate the elastic stiffness exactly. A tiny elastic stiffness (1e-9 of the
// member's) acts in parallel with the fibres, so a member whose every section has yielded
// keeps a regular tangent; it changes forces by 1e-9 of their elastic values.
#pragma once

#include "element/basic_law.hpp"
#include "element/quadrature.hpp"
#include "section/fibre_section.hpp"

#include <vector>

namespace plastica {

class DistributedPlasticityLaw final : public TrialTangentLaw {
public:
    static constexpr double regularising_stiffness = 1e-9;

    // regularisation: the parallel elastic stiffness, as a fraction of the member's.
    DistributedPlasticityLaw(const SectionSpec& section, double L0, int integration_points,
                             double regularisation = regularising_stiffness);

    void commit() override;
    void revert() override;
    std::vector<SectionReport> sections() const override;
    // Fibre branches (elastic, yielding) settle inside Newton like an active set: kept once
    // frozen, then checked at equilibrium and re-decided where the state contradicts them.
    void freeze_states(bool frozen) override { frozen_ = frozen; }
    bool states_consistent() const override { return consistent_; }
    std::unique_ptr<BasicLaw> clone() const override {
        return std::make_unique<DistributedPlasticityLaw>(*this);
    }

private:
    void trial_response(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) override;
    struct IntegrationPoint {
        QuadraturePoint at;
        FibreSection section;
        double curvature_per_theta_i; // ∂κ/∂θ_i
        double curvature_per_theta_j; // ∂κ/∂θ_j
        SectionResponse trial;
        SectionResponse committed;
    };
    double L0_;
    Eigen::Matrix3d k_regular_; // the parallel elastic stiffness
    std::vector<IntegrationPoint> points_;
    bool frozen_ = false;
    bool consistent_ = true;
};

} // namespace plastica
