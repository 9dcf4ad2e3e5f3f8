#include "solver/linear_solver.hpp"

#include <Eigen/OrderingMethods>
#include <cmath>

namespace plastica {

void LinearSolver::analyse(const SparseMatrix& K) {
    const SparseMatrix full = K.selfadjointView<Eigen::Lower>();
    Eigen::AMDOrdering<int> amd;
    amd(full, order_inverse_);
    order_ = order_inverse_.inverse();
    // Permute a copy of K whose values are their own indices: the result tells each value of
    // the permuted triangle where it comes from (a symmetric permutation only moves values).
    SparseMatrix indices = K;
    for (Eigen::Index k = 0; k < indices.nonZeros(); ++k) indices.valuePtr()[k] = static_cast<double>(k);
    permuted_.resize(K.rows(), K.cols());
    permuted_.selfadjointView<Eigen::Upper>() = indices.selfadjointView<Eigen::Lower>().twistedBy(order_);
    permuted_.makeCompressed();
    source_.resize(static_cast<std::size_t>(permuted_.nonZeros()));
    for (Eigen::Index k = 0; k < permuted_.nonZeros(); ++k)
        source_[static_cast<std::size_t>(k)] = static_cast<int>(permuted_.valuePtr()[k]);
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
        const Eigen::VectorXd& D = ldlt_.vectorD();
        const double largest = D.cwiseAbs().maxCoeff();
        Eigen::Index smallest_at = 0;
        const double smallest = D.cwiseAbs().minCoeff(&smallest_at);
        negative_pivots_ = static_cast<int>((D.array() < 0.0).count());
        pivot_ratio_ = largest > 0.0 ? smallest / largest : 0.0;
        // D is in the permuted order; report the equation it belongs to.
        weakest_ = order_inverse_.indices()[smallest_at];
        if (ldlt_.info() == Eigen::Success && std::isfinite(pivot_ratio_) && pivot_ratio_ > 1e-15) return true;
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
