// The constitutive part of a co-rotational beam, in the element's basic (local) frame:
// basic deformations e = [u_l, θ_i, θ_j] (chord stretch, end rotations relative to the chord)
// to basic forces q = [N, M_i, M_j] (end moments, counter-clockwise positive) and their
// tangent. Path-dependent laws follow the trial/commit protocol.
#pragma once

#include "element/hinge_ends.hpp"

#include <Eigen/Dense>
#include <array>
#include <memory>
#include <vector>

namespace plastica {

enum class HingeState { elastic = 0, yielding = 1, plastic = 2, failed = 3 };

// What a plastic hinge reports about one element end.
struct HingeReport {
    double utilisation = 0.0; // |M| / M_p(N) of this end at its own N: 0 elastic … 1 at capacity
    double capacity = 0.0;    // M_p(N) at the end's axial force, on the side it bends to
    HingeState state = HingeState::elastic;
    double ei_ratio = 1.0;    // EI_T / EI of the end section
    double ea_ratio = 1.0;    // EA_T / EA
    int failed_fibres = 0;
    int section_failures = 0; // section solves that did not converge (stiffness kept)
};

// The state of one section along a member with distributed plasticity.
struct SectionReport {
    double xi = 0.0;            // position along the member, 0 … 1
    double yielded_share = 0.0; // share of the section's area yielded (or failed)
    double curvature = 0.0;     // κ = dθ/ds
    double moment = 0.0;        // sagging moment, as the element's end moments
    double axial_force = 0.0;
};

class BasicLaw {
public:
    virtual ~BasicLaw() = default;
    // Trial state for the basic deformations e; returns q and ∂q/∂e.
    virtual void trial(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) = 0;
    // ∂q/∂e at the last trial state (the element asks for it only when its tangent is needed).
    virtual void trial_tangent(Eigen::Matrix3d& k) const = 0;
    virtual void commit() = 0;
    virtual void revert() = 0;
    virtual bool has_hinges() const { return false; }
    // Ends whose moment is released (a pin inside a frame): the transverse shape a geometric
    // stiffness integrates differs there.
    virtual std::array<bool, 2> released_ends() const { return {false, false}; }
    // Which ends carry capacity rows and pseudo-springs (element/hinge_ends.hpp), re-decided
    // between steps where two members meet (analysis/hinge_allocation.hpp).
    virtual void serve_hinge_ends(const HingeEnds& /*ends*/) {}
    virtual HingeReport hinge(int /*end*/) const { return {}; }
    // Sections along the member (committed state); empty for a law without them.
    virtual std::vector<SectionReport> sections() const { return {}; }
    // Committed plastic part of the basic deformations (zero for an elastic law).
    virtual Eigen::Vector3d plastic_deformation() const { return Eigen::Vector3d::Zero(); }
    // Hinge states (loading/unloading, active capacity sides) settle inside Newton like a
    // contact active set: frozen after some iterations, then checked for consistency.
    virtual void freeze_states(bool /*frozen*/) {}
    // The next increment's predictor, taken at the committed state, follows the elastic
    // stiffness instead of continued loading (where the load turns back); until the next commit.
    virtual void predict_unloading() {}
    // For a step the path cannot take with the law's own hardening (analysis/path_limits.cpp): a
    // hinge's capacity rows harden by at least `ratio` of its elastic stiffness (and more than
    // their own); a fibre member adds `ratio` of its elastic stiffness on the step's increment
    // (element/step_stiffening.hpp). 0 restores the law; what the step gathered stays.
    virtual void stiffen_capacity(double /*ratio*/) {}
    virtual bool states_consistent() const { return true; }
    // How far the trial step carries a section into its yielding range, as the rise of
    // |M|/M_p(N) above the larger of the committed value and first yield (0 … 1), for a law
    // that integrates its stiffness explicitly over a step (the hinges' pseudo-springs take η
    // from the start of the step): adaptive increments keep it small. 0 for a law whose
    // response does not depend on the step size.
    virtual double trial_yield_advance() const { return 0.0; }
    virtual std::unique_ptr<BasicLaw> clone() const = 0;
};

// A law whose tangent comes out of its trial response (a return map, section solves): it keeps
// that tangent for trial_tangent().
class TrialTangentLaw : public BasicLaw {
public:
    void trial(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) final {
        trial_response(e, q, k);
        k_t_ = k;
    }
    void trial_tangent(Eigen::Matrix3d& k) const final { k = k_t_; }

protected:
    virtual void trial_response(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) = 0;

private:
    Eigen::Matrix3d k_t_ = Eigen::Matrix3d::Zero(); // the tangent of the last trial
};

// Elastic Euler–Bernoulli beam: N = EA u_l / L0, M_i = EI/L0 (4θ_i + 2θ_j), M_j = EI/L0 (2θ_i + 4θ_j).
Eigen::Matrix3d elastic_basic_stiffness(double EA, double EI, double L0);

class ElasticLaw final : public BasicLaw {
public:
    ElasticLaw(double EA, double EI, double L0) {
        const Eigen::Matrix3d k = elastic_basic_stiffness(EA, EI, L0);
        axial_ = k(0, 0), near_ = k(1, 1), far_ = k(1, 2);
    }
    void trial(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) override {
        trial_tangent(k);
        // k·e without the products with k's zeros (the general 3 × 3 product was 4 % of an
        // elastic run's time): every sum that is not zero is the same to the bit.
        q[0] = axial_ * e[0];
        q[1] = near_ * e[1] + far_ * e[2];
        q[2] = far_ * e[1] + near_ * e[2];
    }
    void trial_tangent(Eigen::Matrix3d& k) const override {
        k << axial_, 0.0, 0.0, 0.0, near_, far_, 0.0, far_, near_;
    }
    void commit() override {}
    void revert() override {}
    std::unique_ptr<BasicLaw> clone() const override { return std::make_unique<ElasticLaw>(*this); }

private:
    // The three distinct entries of the stiffness, kept instead of the matrix: a large model's
    // memory is mostly its elements.
    double axial_, near_, far_; // EA/L0, 4EI/L0, 2EI/L0
};

} // namespace plastica
