// Moment releases at a member's ends (a pin inside a frame: a beam hinged to its columns, a
// brace pinned at both ends). The end's rotation inside the member is its own unknown, set so
// that the end carries no moment, and condensed out: the wrapped law sees the member's true
// end rotations, the element sees basic forces with zero moment at a released end and the
// condensed tangent K_cc − K_cr·K_rr⁻¹·K_rc (zero rows and columns at the released end).
#pragma once

#include "element/basic_law.hpp"

#include <array>
#include <memory>

namespace plastica {

class ReleasedEndsLaw final : public BasicLaw {
public:
    // released[0]: the first end, released[1]: the second; at least one.
    ReleasedEndsLaw(std::unique_ptr<BasicLaw> inner, std::array<bool, 2> released);
    ReleasedEndsLaw(const ReleasedEndsLaw& other);

    void trial(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) override;
    void trial_tangent(Eigen::Matrix3d& k) const override { k = k_condensed_; }
    void commit() override;
    void revert() override;
    bool has_hinges() const override { return inner_->has_hinges(); }
    std::array<bool, 2> released_ends() const override { return released_; }
    void serve_hinge_ends(const HingeEnds& ends) override { inner_->serve_hinge_ends(ends); }
    HingeReport hinge(int end) const override { return inner_->hinge(end); }
    std::vector<SectionReport> sections() const override { return inner_->sections(); }
    Eigen::Vector3d plastic_deformation() const override { return inner_->plastic_deformation(); }
    void freeze_states(bool frozen) override { inner_->freeze_states(frozen); }
    void predict_unloading() override { inner_->predict_unloading(); }
    void stiffen_capacity(double ratio) override { inner_->stiffen_capacity(ratio); }
    bool states_consistent() const override { return inner_->states_consistent(); }
    double trial_yield_advance() const override { return inner_->trial_yield_advance(); }
    std::unique_ptr<BasicLaw> clone() const override { return std::make_unique<ReleasedEndsLaw>(*this); }

    // The member's own rotations at its ends, relative to the chord (trial state): at a
    // released end the one that leaves it free of moment, elsewhere the node's.
    const Eigen::Vector3d& inner_deformation() const { return e_inner_; }

private:
    std::unique_ptr<BasicLaw> inner_;
    std::array<bool, 2> released_;
    Eigen::Vector3d e_inner_ = Eigen::Vector3d::Zero();     // trial
    Eigen::Vector3d e_committed_ = Eigen::Vector3d::Zero(); // the released rotations at the last commit
    Eigen::Matrix3d k_condensed_ = Eigen::Matrix3d::Zero();
};

} // namespace plastica
