// Distributed plasticity (plastic zone) by a force-based member: the basic law of a
// co-rotational beam whose section forces follow from the end forces by equilibrium,
//   N(ξ) = N,   M(ξ) = (ξ − 1)·M_i + ξ·M_j   (sagging; s = b(ξ)·q),
// exactly, whatever the sections do, and whose end deformations add up the sections' strains
// and curvatures, e = L0 ∫ bᵀ d dξ, with fibre sections at Gauss–Lobatto points (the ends
// among them, where a frame's moments peak). The flexibility F = L0 ∫ bᵀ f_s b dξ is inverted
// for the tangent. Spacone, Filippou & Taucer, "Fibre beam–column model for non-linear
// analysis of R/C frames", Earthq. Eng. Struct. Dyn. 25, 1996; Neuenhofer & Filippou,
// "Evaluation of nonlinear frame finite-element models", J. Struct. Eng. 123(7), 1997.
//
// Why beside the displacement-based law: that law's curvature is linear along the element, so
// where a section reaches its capacity the curvature cannot concentrate and the collapse load
// comes out first-order high in the element length (3.6 % on an 8-element portal column). Here
// the curvature is whatever each section needs for its exact moment: a yielded end section
// flows alone, and every section carries the member's N.
//
// State determination (the element iterations): Newton on the basic forces q and the sections'
// deformations d_k together; each iteration takes
//   F Δq = e − L0 Σ w bᵀ (d_k + f_k r_k),  r_k = b_k q − s_k(d_k),  d_k += f_k (r_k + b_k Δq),
// from the last trial state, and where that does not settle, from the committed state along
// the increment in parts; each with a backtracking line search on the correction's work.
// A small elastic stiffness in parallel with each section (1e-9 of EI, 1e-4 of EA) keeps f_k
// finite where a section has yielded through. The axial share is the larger because a trial
// that squashes a whole member leaves its shortening shared among sections by that stiffness
// alone: at 1e-6 and 1e-5, Vogel's frame on 16/24 elements and the flattened pipe stopped
// there; at 1e-4 they complete. Its cost: a fully plastic end section in compression carries
// 1e-4·EA times its axial strain more, which on a perfectly plastic portal grows as the end
// sections shorten (peak +0.08 % at 8 elements per member, +0.3 % at 32).
#pragma once

#include "element/basic_law.hpp"
#include "element/quadrature.hpp"
#include "element/step_stiffening.hpp"
#include "section/fibre_section.hpp"

#include <vector>

namespace plastica {

class ForceBasedPlasticityLaw final : public TrialTangentLaw {
public:
    ForceBasedPlasticityLaw(const SectionSpec& section, double L0, int integration_points);

    void commit() override;
    void revert() override;
    std::vector<SectionReport> sections() const override;
    // Fibre branches settle inside Newton like an active set (as distributed_plasticity_law.hpp).
    void freeze_states(bool frozen) override {
        if (frozen != frozen_) sections_current_ = false; // evaluated the other way
        frozen_ = frozen;
    }
    // False also while the element iterations have not settled: Newton may not accept then.
    bool states_consistent() const override { return consistent_ && settled_; }
    void stiffen_capacity(double ratio) override { stiffening_.set(ratio); }
    std::unique_ptr<BasicLaw> clone() const override { return std::make_unique<ForceBasedPlasticityLaw>(*this); }

private:
    void trial_response(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) override;
    struct IntegrationPoint {
        QuadraturePoint at;
        FibreSection section;
        Eigen::Vector2d deformation = Eigen::Vector2d::Zero(); // (ε0, κ), trial
        Eigen::Vector2d committed_deformation = Eigen::Vector2d::Zero();
        SectionResponse trial;
        SectionResponse committed;
        Eigen::Matrix2d flexibility = Eigen::Matrix2d::Zero(); // of the last evaluation
        Eigen::Vector2d step_start = Eigen::Vector2d::Zero(), step = Eigen::Vector2d::Zero(); // the last element iteration's
    };
    // Section forces b(ξ)·q.
    static Eigen::Vector2d section_forces(double xi, const Eigen::Vector3d& q) {
        return {q[0], (xi - 1.0) * q[1] + xi * q[2]};
    }
    // A section's share of the end deformations per unit length, bᵀ d.
    static Eigen::Vector3d end_share(double xi, const Eigen::Vector2d& d) { return {d[0], (xi - 1.0) * d[1], xi * d[1]}; }
    void evaluate(IntegrationPoint& p); // the section at its deformation, with the parallel stiffness
    // Element iterations toward e from the current trial state (q_t_ and the sections'
    // deformations); whether they settled. Leaves F in flexibility_.
    bool iterate(const Eigen::Vector3d& e);
    double L0_;
    Eigen::Vector2d regular_;            // the parallel section stiffness (EA, EI shares)
    double work_scale_;                  // N_y·ε_y·L0 + M_y·κ_y·L0: what "small" means for the iterations
    std::vector<IntegrationPoint> points_;
    StepStiffening stiffening_;
    Eigen::Vector3d q_t_ = Eigen::Vector3d::Zero(), q_c_ = Eigen::Vector3d::Zero();
    Eigen::Matrix3d flexibility_ = Eigen::Matrix3d::Zero(); // F of the last element iteration
    bool frozen_ = false;
    bool consistent_ = true;
    bool settled_ = true;
    bool sections_current_ = false; // the sections' trial responses are those at their deformations
};

} // namespace plastica
