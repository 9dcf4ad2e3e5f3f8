// Distributed plasticity (plastic zone): the basic law of a displacement-based co-rotational
// beam that integrates fibre sections at Gauss–Legendre points along the member.
//
// In the basic frame the member is a shallow Euler–Bernoulli beam whose rotation relative to
// the chord is cubic (Hermite), so the curvature is linear, κ(ξ) = [(6ξ − 4)θ_i + (6ξ − 2)θ_j]/L0.
// The axial force is one along the member, as equilibrium wants: each point's section has an
// axial strain of its own, found by element iterations so that every section carries the same
// N and the strains add up to the chord's stretch, Σ w·ε_k = u_l/L0 (the axial part of a
// flexibility-based element; Alemdar & White, "Displacement, flexibility, and mixed beam–column
// finite element formulations for distributed plasticity analysis", J. Struct. Eng. 131(12),
// 2005, show what one strain per element costs on frames: a yielded column base then carries
// M_p(0) beside a member in compression). With f = Σ w/EA_k and s_k = ES_k/EA_k:
//   N = (u_l/L0 + Σ w s_k dκ_k)/f at first order,   dM_k = (ES_k/EA_k) dN + (EI_k − ES_k²/EA_k) dκ_k,
//   q = [N, Σ w L0 b_i M_k, Σ w L0 b_j M_k],  b = ∂κ/∂θ.
// Sections of one material in elastic bending have ε_k = u_l/L0: the plain displacement element.
// A tiny elastic stiffness (1e-9 of the member's in bending, 1e-6 of each section's EA) acts in
// parallel with the fibres, so a member whose every section has yielded keeps a regular tangent;
// it changes forces by that share of their elastic values.
#pragma once

#include "element/basic_law.hpp"
#include "element/quadrature.hpp"
#include "element/step_stiffening.hpp"
#include "section/fibre_section.hpp"

#include <vector>

namespace plastica {

class DistributedPlasticityLaw final : public TrialTangentLaw {
public:
    static constexpr double regularising_stiffness = 1e-9;

    // How the axial strain varies along the member: one N at every section (the sections'
    // strains found by element iterations), or one strain for the whole member (a segment of
    // segmented_plasticity_law.hpp, whose axial motion is shared in proportion to length).
    enum class Axial { equilibrated, uniform_strain };

    // regularisation: the parallel elastic stiffness, as a fraction of the member's.
    DistributedPlasticityLaw(const SectionSpec& section, double L0, int integration_points,
                             double regularisation = regularising_stiffness, Axial axial = Axial::equilibrated);

    void commit() override;
    void revert() override;
    std::vector<SectionReport> sections() const override;
    // Fibre branches (elastic, yielding) settle inside Newton like an active set: kept once
    // frozen, then checked at equilibrium and re-decided where the state contradicts them.
    void freeze_states(bool frozen) override { frozen_ = frozen; }
    bool states_consistent() const override { return consistent_; }
    void stiffen_capacity(double ratio) override { stiffening_.set(ratio); }
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
        double curvature = 0.0;        // trial
        double strain = 0.0;           // the section's axial strain, trial
        double committed_strain = 0.0;
    };
    // Sections at the strains given, their N in step with the regularising stiffness.
    void evaluate_sections(const Eigen::Vector3d& e);
    void evaluate_section(IntegrationPoint& p); // at its strain and curvature
    // Moves a section's strain until it carries N (within round-off), at its curvature.
    void section_strain_for(IntegrationPoint& p, double N);
    // The common N and the sections' strains by bracketed solves; whether they settled.
    bool settle_axial_safeguarded(double chord_strain);
    // The displacement-based law with one strain per member: q = Σ w L0 Bᵀ s(B e), k = Σ w L0 Bᵀ k_s B.
    void uniform_strain_response(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k);
    // The law with one N along the member (the header's formulas).
    void equilibrated_response(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k);
    Axial axial_;
    double L0_;
    Eigen::Matrix3d k_regular_; // the parallel elastic stiffness (equilibrated: bending only, the axial part is in each section)
    double regular_ea_;         // the parallel axial stiffness EA of each section (equilibrated)
    double strain_scale_;       // the yield strain: the scale of the sections' axial strains
    double force_scale_;        // the squash load EA·ε_y
    std::vector<IntegrationPoint> points_;
    StepStiffening stiffening_;
    bool frozen_ = false;
    bool consistent_ = true;
};

} // namespace plastica
