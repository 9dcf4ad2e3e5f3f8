// Distributed plasticity with the member cut into segments inside one co-rotational element:
// each segment is the displacement-based fibre law of distributed_plasticity_law.hpp over its
// own length, and the transverse motion and rotation of the segments' inner nodes (in the
// element's basic frame) are condensed out by element iterations.
//
// Why: the displacement-based law has a linear curvature field, and near a fully plastic
// section the curvature concentrates; its error is first order in the element length there
// (the ring: 1.3 % at 50 elements). Segments give the plastic zone the resolution of a finer
// mesh without more global unknowns, while the co-rotational frame of the whole element
// carries the large rotations (within an element the rotations relative to its chord are
// small, so its inner kinematics are linear).
//
// The axial strain is one per element by default (`SharedAxialStrain`): each segment's sections
// then take the element's strain, and a section's N is not the member's. A yielded column base
// sits at M_p(0) beside a column in compression, and a portal whose columns carry axial load
// peaks 5.5 % high on 8 elements of 4 graded segments. `AxialStrainPerSegment` gives each
// segment a strain of its own through the inner nodes' axial motion, condensed with the rest,
// so that every segment carries the member's N: the portal then comes within 0.3 % of its
// converged peak on 8 elements of 8 graded segments (docs/method.md). It is not the default: on
// a shallow pinned arch of 10-fibre perfectly plastic sections snapping onto a floor, Newton
// then crosses a kink at nearly every step (as with the plain law's equilibrated N on a fine
// mesh) and the run stops where the shared strain gets through.
// With one segment the law is the plain displacement law.
//
// Segments may be graded toward the element ends, where the moment of a frame peaks at its
// joints, supports and point loads: each segment is `grading` times as long as its neighbour
// nearer the end. The sections next to a hinge then sit closer to it, and the collapse load's
// first-order excess, proportional to the length of the segment at the hinge, shrinks with it.
//
// In the basic frame, nodes k = 0 … n at x_k carry (u_k, w_k, θ_k) with u_k = (x_k/L0)·u_l
// (plus an inner node's own axial motion with a strain per segment), w_0 = w_n = 0, θ_0 = θ_i,
// θ_n = θ_j; the inner nodes' (w, θ), and (u, w, θ) with a strain per segment, are the unknowns. Segment s
// between nodes a and b has basic deformations [u_b − u_a, θ_a − β, θ_b − β], β = (w_b − w_a)/l_s.
// Element iterations (Newton with a backtracking line search, warm-started from the last state
// along the condensed tangent) solve the inner nodes' equilibrium; the basic forces are the
// work-conjugates of [u_l, θ_i, θ_j] and the tangent is the condensed stiffness
//   k = K_ee − K_ei K_ii⁻¹ K_ie   (K_ii block tridiagonal, eliminated node by node).
#pragma once

#include "element/basic_law.hpp"
#include "element/distributed_plasticity_law.hpp"
#include "element/step_stiffening.hpp"

#include <vector>

namespace plastica {

// InnerDofs: 2, an inner node's (w, θ) (one axial strain per element), or 3, its (u, w, θ).
template <int InnerDofs>
class SegmentedPlasticityLaw final : public TrialTangentLaw {
public:
    SegmentedPlasticityLaw(const SectionSpec& section, double L0, int segments, int integration_points, double grading);

    void commit() override;
    void revert() override;
    std::vector<SectionReport> sections() const override;
    // The segments' fibre branches are not kept across Newton iterations: the element
    // iterations settle them at every trial (keeping them, the global iterations jumped when
    // they were released: 21 cut steps on the ring against none).
    // False while the inner nodes are not in equilibrium: Newton then may not accept.
    bool states_consistent() const override { return inner_converged_; }
    void stiffen_capacity(double ratio) override { stiffening_.set(ratio); }
    std::unique_ptr<BasicLaw> clone() const override { return std::make_unique<SegmentedPlasticityLaw>(*this); }

private:
    void trial_response(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) override;
    using Inner = Eigen::Matrix<double, InnerDofs, 1>;         // (w, θ) or (u, w, θ) of an inner node
    using Block = Eigen::Matrix<double, InnerDofs, InnerDofs>;
    using Coupling = Eigen::Matrix<double, InnerDofs, 3>;      // an inner node against [u_l, θ_i, θ_j]
    using InnerMap = Eigen::Matrix<double, 3, InnerDofs>;      // a segment's deformations per inner node motion

    // Evaluates every segment at e and the inner nodes' motion.
    void evaluate(const Eigen::Vector3d& e, const std::vector<Inner>& inner);
    // From the last evaluation: the inner nodes' forces, the basic forces and the condensed
    // tangent; factorises K_ii.
    void condense(std::vector<Inner>& inner_forces, Eigen::Vector3d& q, Eigen::Matrix3d& k);
    // Solves K_ii x = b in place with the factorisation of the last condense.
    template <class Column>
    void solve_inner(std::vector<Column>& b) const;
    // The inner nodes' force norm (moments over the segment length).
    double inner_residual(const std::vector<Inner>& r) const;

    double L0_, segment_length_; // the element's, and its segments' mean length
    double EA_, EI_; // elastic, for the scale of the inner residual test
    std::vector<DistributedPlasticityLaw> segments_;
    StepStiffening stiffening_;
    std::vector<double> bounds_;                    // the segments' ends, from node i
    // Segment s's basic deformations [u_b − u_a, θ_a − β, θ_b − β], β = (w_b − w_a)/l_s, are
    // basic_map_[s]·e + near_[s]·(w, θ)_a + far_[s]·(w, θ)_b.
    std::vector<Eigen::Matrix3d> basic_map_;
    std::vector<InnerMap> near_, far_;
    std::vector<Eigen::Vector3d> segment_forces_;    // each segment's basic forces
    std::vector<Eigen::Matrix3d> segment_tangents_;  // and their tangent
    // Block LDLᵀ of K_ii: pivots' inverses, multipliers, upper blocks; and scratch.
    std::vector<Block> pivot_inverse_, multiplier_, upper_;
    std::vector<Coupling> coupling_, solved_;
    std::vector<Inner> residual_, step_, line_start_;

    Eigen::Vector3d e_t_ = Eigen::Vector3d::Zero(), e_c_ = Eigen::Vector3d::Zero();
    std::vector<Inner> inner_t_, inner_c_;
    // −K_ii⁻¹ K_ie, inner motion per basic deformation: the warm start of the next trial.
    std::vector<Coupling> condensation_t_, condensation_c_;
    bool inner_converged_ = true;
};

using SharedAxialStrain = SegmentedPlasticityLaw<2>;
using AxialStrainPerSegment = SegmentedPlasticityLaw<3>;

} // namespace plastica
