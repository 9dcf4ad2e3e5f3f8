#include "element/released_ends_law.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

namespace {
// Newton on the released rotations: the wrapped law is piecewise smooth (hinges, fibres), so a
// few iterations settle it; an elastic one takes a single step.
constexpr int max_local_iterations = 50;
constexpr double local_tolerance = 1e-13;
} // namespace

ReleasedEndsLaw::ReleasedEndsLaw(std::unique_ptr<BasicLaw> inner, std::array<bool, 2> released)
    : inner_(std::move(inner)), released_(released) {}

ReleasedEndsLaw::ReleasedEndsLaw(const ReleasedEndsLaw& other)
    : BasicLaw(other), inner_(other.inner_->clone()), released_(other.released_), e_inner_(other.e_inner_),
      e_committed_(other.e_committed_), k_condensed_(other.k_condensed_) {}

void ReleasedEndsLaw::trial(const Eigen::Vector3d& e, Eigen::Vector3d& q, Eigen::Matrix3d& k) {
    // The member's own rotation at a released end starts from its last trial value; the axial
    // stretch and a held end's rotation are the element's.
    e_inner_[0] = e[0];
    for (int end = 0; end < 2; ++end)
        if (!released_[end]) e_inner_[1 + end] = e[1 + end];
    const bool both = released_[0] && released_[1];
    const int only = released_[0] ? 1 : 2; // the released row when one end is released
    for (int it = 0;; ++it) {
        inner_->trial(e_inner_, q, k);
        const double scale = std::max({std::abs(k(1, 1)), std::abs(k(2, 2)), 1e-300}) *
                             std::max({std::abs(e_inner_[1]), std::abs(e_inner_[2]), 1e-300});
        const double residual = both ? std::max(std::abs(q[1]), std::abs(q[2])) : std::abs(q[only]);
        if (residual <= local_tolerance * scale || it == max_local_iterations) break;
        if (both) {
            const Eigen::Matrix2d krr = k.block<2, 2>(1, 1);
            if (!(std::abs(krr.determinant()) > 0.0)) break;
            e_inner_.tail<2>() -= krr.inverse() * q.tail<2>();
        } else {
            if (!(k(only, only) != 0.0)) break;
            e_inner_[only] -= q[only] / k(only, only);
        }
    }
    // Condense the released rows: K_cc − K_cr·K_rr⁻¹·K_rc.
    if (both) {
        const Eigen::Matrix2d krr = k.block<2, 2>(1, 1);
        double k00 = k(0, 0);
        if (std::abs(krr.determinant()) > 0.0) k00 -= k.block<1, 2>(0, 1) * krr.inverse() * k.block<2, 1>(1, 0);
        k.setZero();
        k(0, 0) = k00;
    } else {
        const double krr = k(only, only);
        Eigen::Matrix3d condensed = k;
        if (krr != 0.0) condensed -= k.col(only) * k.row(only) / krr;
        condensed.row(only).setZero();
        condensed.col(only).setZero();
        k = condensed;
    }
    for (int end = 0; end < 2; ++end)
        if (released_[end]) q[1 + end] = 0.0;
    k_condensed_ = k;
}

void ReleasedEndsLaw::commit() {
    inner_->commit();
    e_committed_ = e_inner_;
}

void ReleasedEndsLaw::revert() {
    inner_->revert();
    e_inner_ = e_committed_;
}

} // namespace plastica
