// Two-node co-rotational beam-column in 2D (Crisfield 1991; Battini 2002). The chord carries a
// local frame; the basic law sees only the deformational part of the motion. With c, s of the
// current chord, r = [−c −s 0 c s 0]ᵀ and z = [s −c 0 −s c 0]ᵀ, the global tangent is
//   K = Bᵀ k_b B + z zᵀ N / L + (r zᵀ + z rᵀ)(M_i + M_j) / L².
// The rigid rotation is measured by atan2 from the initial chord and unwrapped against the
// committed value, so a member may turn through any number of full circles.
// At first order (Geometry::first_order) the chord stays the initial one: the basic deformations
// are linear in d, the forces act on the initial geometry and the tangent is Bᵀ k_b B alone.
#pragma once

#include "element/basic_law.hpp"
#include "model/model.hpp"

#include <Eigen/Dense>
#include <memory>

namespace plastica {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

// End forces of a beam in its basic frame and the shear they imply.
struct BeamForces {
    double axial = 0.0;    // N, tension positive
    double moment_i = 0.0; // sagging moment EI·dθ/ds at the first node
    double moment_j = 0.0; // … at the second node
    double shear = 0.0;    // (M_i + M_j)/L from the end moments
};

class CorotationalBeam {
public:
    CorotationalBeam(const Node& a, const Node& b, std::unique_ptr<BasicLaw> law, bool first_order = false);
    CorotationalBeam(const CorotationalBeam& other);
    CorotationalBeam& operator=(const CorotationalBeam&) = delete;
    CorotationalBeam(CorotationalBeam&&) = default;

    // Trial state from the global displacements d = [u_i v_i θ_i u_j v_j θ_j]; returns the
    // internal force vector and, if asked, the tangent.
    void compute(const Vector6& d, Vector6& force, Matrix6* tangent);
    // The tangent at the last trial state (after compute).
    void tangent(Matrix6& k) const { tangent(k, q_trial_[0]); }
    // The same with the geometric stiffness of another axial force (the trial's stretch may be
    // an extrapolation's error, which a stiff membrane turns into a wild force).
    void tangent(Matrix6& k, double axial_force) const;
    // Linear buckling's terms at the trial state (analysis/linear_buckling.hpp): the rate of
    // the axial force along a rate of the nodal displacements, and the geometric stiffness of
    // an axial force N with the member's transverse shape cubic between its ends (Hermitian;
    // the chord's N/L z zᵀ plus N·L/30·[4 −1; −1 4] on the end rotations relative to the chord,
    // N·L/5 on the one end left where the other's moment is released), or with cubic = false
    // the chord's part alone, as the tangent above carries it: the nonlinear path's own, which
    // converges to the same loads with the mesh (1.3 % above Euler's on 8 elements a half-wave).
    double axial_force_rate(const Vector6& displacement_rate) const;
    void geometric_stiffness(double axial_force, Matrix6& k, bool cubic = true) const;
    void commit();
    void revert();
    void freeze_states(bool frozen) { law_->freeze_states(frozen); }
    void predict_unloading() { law_->predict_unloading(); }
    void stiffen_capacity(double ratio) { law_->stiffen_capacity(ratio); }
    double trial_yield_advance() const { return law_->trial_yield_advance(); }
    void serve_hinge_ends(const HingeEnds& ends) { law_->serve_hinge_ends(ends); }

    BeamForces forces() const;
    double trial_axial_force() const { return q_trial_[0]; }
    const BasicLaw& law() const { return *law_; }
    double initial_length() const { return L0_; }
    double rigid_rotation() const { return alpha_trial_; }

private:
    void compute_first_order(const Vector6& d, double ddx, double ddy, Vector6& force, Matrix6* tangent);

    double dx0_, dy0_;
    double L0_, c0_, s0_;
    bool first_order_;
    std::unique_ptr<BasicLaw> law_;
    double alpha_committed_ = 0.0;
    double alpha_trial_ = 0.0;
    double length_trial_ = 0.0;
    double c_trial_ = 1.0, s_trial_ = 0.0; // the trial chord's direction
    Eigen::Vector3d q_trial_ = Eigen::Vector3d::Zero();
    Eigen::Vector3d q_committed_ = Eigen::Vector3d::Zero();
    double length_committed_ = 0.0;
};

} // namespace plastica
