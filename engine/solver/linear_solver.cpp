#include "solver/linear_solver.hpp"

#include <Eigen/OrderingMethods>
#include <algorithm>
#include <cmath>
#include <limits>

namespace plastica {

namespace {
// The node blocks serve while their envelope holds at most this many blocks per nonzero block
// of the lower triangle: chains, rings and frames of a few bays. Past it a fill-reducing order
// and the general sparse factorisation do less work.
constexpr double max_block_fill = 3.0;
} // namespace

void LinearSolver::analyse(const SparseMatrix& K) {
    analysed_ = true;
    blocks_used_ = blocks_.analyse(K, max_block_fill);
    if (!blocks_used_) analyse_sparse(K);
    // Where each pivot's equation has its diagonal entry among K's values (−1: none).
    diagonal_slot_.assign(static_cast<std::size_t>(K.rows()), -1);
    for (int col = 0; col < K.outerSize(); ++col)
        for (SparseMatrix::InnerIterator it(K, col); it; ++it)
            if (it.row() == col) diagonal_slot_[static_cast<std::size_t>(pivot_of(col))] = static_cast<int>(&it.value() - K.valuePtr());
}

int LinearSolver::pivot_of(int equation) const {
    return blocks_used_ ? blocks_.pivot_of(equation) : order_.indices()[equation];
}

int LinearSolver::equation_of(std::size_t pivot) const {
    return blocks_used_ ? blocks_.pivot_equations()[pivot] : order_inverse_.indices()[static_cast<Eigen::Index>(pivot)];
}

void LinearSolver::analyse_sparse(const SparseMatrix& K) {
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
    permuted_k_.resize(n, n);
    permuted_k_.resizeNonZeros(next[static_cast<std::size_t>(n)]);
    std::copy(next.begin(), next.end(), permuted_k_.outerIndexPtr());
    source_.resize(static_cast<std::size_t>(next[static_cast<std::size_t>(n)]));
    for (int col = 0; col < K.outerSize(); ++col)
        for (SparseMatrix::InnerIterator it(K, col); it; ++it) {
            if (it.row() < col) continue;
            const int a = position[it.row()], b = position[col];
            const int at = next[static_cast<std::size_t>(std::max(a, b))]++;
            permuted_k_.innerIndexPtr()[at] = std::min(a, b);
            permuted_k_.valuePtr()[at] = 0.0;
            source_[static_cast<std::size_t>(at)] = static_cast<int>(&it.value() - K.valuePtr());
        }
    ldlt_.analyse(permuted_k_);
}

bool LinearSolver::same_pattern(const SparseMatrix& K) const {
    return K.nonZeros() == static_cast<Eigen::Index>(pattern_inner_.size()) &&
           K.outerSize() + 1 == static_cast<Eigen::Index>(pattern_outer_.size()) &&
           std::equal(pattern_outer_.begin(), pattern_outer_.end(), K.outerIndexPtr()) &&
           std::equal(pattern_inner_.begin(), pattern_inner_.end(), K.innerIndexPtr());
}

bool LinearSolver::factorize(const SparseMatrix& K) {
    // Surfaces that touch couple new nodes, and those that part uncouple them: a pattern that
    // is not the analysed one is analysed again (comparing it costs a read of its indices, a
    // small part of a factorisation).
    if (!analysed_ || !same_pattern(K)) {
        analyse(K);
        pattern_outer_.assign(K.outerIndexPtr(), K.outerIndexPtr() + K.outerSize() + 1);
        pattern_inner_.assign(K.innerIndexPtr(), K.innerIndexPtr() + K.nonZeros());
        lu_analysed_ = false;
    }
    const double* values = K.valuePtr();
    bool nonzero_pivots = false;
    if (blocks_used_) {
        nonzero_pivots = blocks_.factorize(K);
    } else {
        double* target = permuted_k_.valuePtr();
        for (std::size_t k = 0; k < source_.size(); ++k) target[k] = values[source_[k]];
        nonzero_pivots = ldlt_.factorize(permuted_k_);
    }
    using_lu_ = false;
    // Inertia and the weakest pivot, also when a zero pivot stopped the factorisation (its D
    // holds that zero): it names the DOF of a mechanism. Each pivot against its own diagonal
    // entry: what elimination left of that equation's stiffness. Scale-free: a spring of 1e300
    // beside a beam, or EA 1e12 times EI, does not make the beam's pivots look small, as a
    // ratio to the largest pivot would.
    const double* D = blocks_used_ ? blocks_.pivots().data() : ldlt_.pivots().data();
    const std::size_t n = static_cast<std::size_t>(K.rows());
    negative_pivots_ = 0;
    pivot_ratio_ = std::numeric_limits<double>::infinity();
    std::size_t smallest_at = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const int slot = diagonal_slot_[k];
        const double diagonal = slot >= 0 ? std::abs(values[slot]) : 0.0;
        const double ratio = diagonal > 0.0 ? std::abs(D[k]) / diagonal : 0.0;
        // A pivot within round-off of zero has no sign.
        if (D[k] < 0.0 && ratio > zero_pivot) ++negative_pivots_;
        if (!(ratio >= pivot_ratio_)) {
            pivot_ratio_ = ratio;
            smallest_at = k;
        }
    }
    // The pivots are in elimination order; report the equation the weakest belongs to.
    if (n > 0) weakest_ = equation_of(smallest_at);
    if (nonzero_pivots && std::isfinite(pivot_ratio_) && pivot_ratio_ > zero_pivot) return true;
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
    Eigen::VectorXd x(b.size());
    solve(b, x);
    return x;
}

void LinearSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
    if (using_lu_) {
        x = lu_.solve(b);
        return;
    }
    if (blocks_used_) {
        blocks_.solve(b, x);
        return;
    }
    permuted_ = order_ * b;
    ldlt_.solve_in_place(permuted_);
    x = order_inverse_ * permuted_;
}

void LinearSolver::solve(const Eigen::VectorXd& b1, const Eigen::VectorXd& b2, Eigen::VectorXd& x1,
                         Eigen::VectorXd& x2) const {
    if (using_lu_) {
        x1 = lu_.solve(b1);
        x2 = lu_.solve(b2);
        return;
    }
    if (blocks_used_) {
        blocks_.solve(b1, b2, x1, x2);
        return;
    }
    permuted_ = order_ * b1;
    permuted2_ = order_ * b2;
    ldlt_.solve_in_place(permuted_, permuted2_);
    x1 = order_inverse_ * permuted_;
    x2 = order_inverse_ * permuted2_;
}

} // namespace plastica
