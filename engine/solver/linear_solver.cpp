#include "solver/linear_solver.hpp"

#include <Eigen/OrderingMethods>
#include <algorithm>
#include <cmath>
#include <limits>

namespace plastica {

void LinearSolver::analyse(const SparseMatrix& K) {
    // From the self-adjoint view AMD forms the full pattern once; from a full matrix it would
    // form A + Aᵀ again (two more copies of K: a third of the peak memory of a large model).
    Eigen::AMDOrdering<int> amd;
    amd(K.selfadjointView<Eigen::Lower>(), order_inverse_);
    order_ = order_inverse_.inverse();
    // The upper triangle of order_·K·order_ᵀ: entry (i, j) of K's lower triangle moves to
    // (min, max) of its new positions. Its pattern, and for each of its values the index of
    // the value of K it comes from, are laid out as Eigen's symmetric permutation lays them
    // (columns counted, then filled in K's order), without the copy of K that the permutation
    // would need to carry the indices (a sixth of the peak memory of a large model).
    const int n = static_cast<int>(K.rows());
    const int* position = order_.indices().data();
    std::vector<int> next(static_cast<std::size_t>(n) + 1, 0);
    for (int col = 0; col < K.outerSize(); ++col)
        for (SparseMatrix::InnerIterator it(K, col); it; ++it)
            if (it.row() >= col) ++next[static_cast<std::size_t>(std::max(position[it.row()], position[col])) + 1];
    for (int j = 0; j < n; ++j) next[static_cast<std::size_t>(j) + 1] += next[static_cast<std::size_t>(j)];
    permuted_.resize(n, n);
    permuted_.resizeNonZeros(next[static_cast<std::size_t>(n)]);
    std::copy(next.begin(), next.end(), permuted_.outerIndexPtr());
    source_.resize(static_cast<std::size_t>(next[static_cast<std::size_t>(n)]));
    for (int col = 0; col < K.outerSize(); ++col)
        for (SparseMatrix::InnerIterator it(K, col); it; ++it) {
            if (it.row() < col) continue;
            const int a = position[it.row()], b = position[col];
            const int at = next[static_cast<std::size_t>(std::max(a, b))]++;
            permuted_.innerIndexPtr()[at] = std::min(a, b);
            permuted_.valuePtr()[at] = 0.0;
            source_[static_cast<std::size_t>(at)] = static_cast<int>(&it.value() - K.valuePtr());
        }
    // Where each permuted equation's diagonal entry sits among K's values (−1: none).
    diagonal_slot_.assign(static_cast<std::size_t>(K.rows()), -1);
    for (int col = 0; col < K.outerSize(); ++col)
        for (SparseMatrix::InnerIterator it(K, col); it; ++it)
            if (it.row() == col) diagonal_slot_[static_cast<std::size_t>(order_.indices()[col])] = static_cast<int>(&it.value() - K.valuePtr());
    ldlt_.analyzePattern(permuted_);
    analysed_ = true;
}

bool LinearSolver::factorize(const SparseMatrix& K) {
    if (!analysed_) analyse(K);
    const double* values = K.valuePtr();
    double* target = permuted_.valuePtr();
    for (std::size_t k = 0; k < source_.size(); ++k) target[k] = values[source_[k]];
    ldlt_.factorize(permuted_);
    using_lu_ = false;
    // Inertia and the weakest pivot, also when a zero pivot stopped the factorisation (its D
    // holds that zero): it names the DOF of a mechanism.
    if (ldlt_.vectorD().size() == K.rows()) {
        // Each pivot against its own diagonal entry: what elimination left of that equation's
        // stiffness. Scale-free: a spring of 1e300 beside a beam, or EA 1e12 times EI, does not
        // make the beam's pivots look small, as a ratio to the largest pivot would.
        const Eigen::VectorXd& D = ldlt_.vectorD();
        negative_pivots_ = 0;
        pivot_ratio_ = std::numeric_limits<double>::infinity();
        Eigen::Index smallest_at = 0;
        for (Eigen::Index k = 0; k < D.size(); ++k) {
            const int slot = diagonal_slot_[static_cast<std::size_t>(k)];
            const double diagonal = slot >= 0 ? std::abs(values[slot]) : 0.0;
            const double ratio = diagonal > 0.0 ? std::abs(D[k]) / diagonal : 0.0;
            // A pivot within round-off of zero has no sign.
            if (D[k] < 0.0 && ratio > zero_pivot) ++negative_pivots_;
            if (!(ratio >= pivot_ratio_)) {
                pivot_ratio_ = ratio;
                smallest_at = k;
            }
        }
        // D is in the permuted order; report the equation it belongs to.
        weakest_ = order_inverse_.indices()[smallest_at];
        if (ldlt_.info() == Eigen::Success && std::isfinite(pivot_ratio_) && pivot_ratio_ > zero_pivot) return true;
    }
    // A zero pivot: either a singular matrix or an unlucky order for LDLᵀ without pivoting.
    if (!lu_analysed_) {
        lu_.analyzePattern(K);
        lu_analysed_ = true;
    }
    lu_.factorize(K);
    using_lu_ = true;
    return lu_.info() == Eigen::Success;
}

Eigen::VectorXd LinearSolver::solve(const Eigen::VectorXd& b) const {
    if (using_lu_) return lu_.solve(b);
    const Eigen::VectorXd x = ldlt_.solve(order_ * b);
    return order_inverse_ * x;
}

} // namespace plastica
