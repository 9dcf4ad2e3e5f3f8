#include "solver/linear_solver.hpp"

#include <cmath>

namespace plastica {

bool LinearSolver::factorize(const SparseMatrix& K) {
    if (!analysed_) {
        ldlt_.analyzePattern(K);
        analysed_ = true;
    }
    ldlt_.factorize(K);
    using_lu_ = false;
    // Inertia and the weakest pivot, also when a zero pivot stopped the factorisation (its D
    // holds that zero): it names the DOF of a mechanism.
    if (ldlt_.vectorD().size() == K.rows()) {
        const Eigen::VectorXd D = ldlt_.vectorD();
        const double largest = D.cwiseAbs().maxCoeff();
        Eigen::Index smallest_at = 0;
        const double smallest = D.cwiseAbs().minCoeff(&smallest_at);
        negative_pivots_ = static_cast<int>((D.array() < 0.0).count());
        pivot_ratio_ = largest > 0.0 ? smallest / largest : 0.0;
        // D is in the permuted order; report the equation it belongs to.
        weakest_ = ldlt_.permutationPinv().indices()[smallest_at];
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
    return using_lu_ ? Eigen::VectorXd(lu_.solve(b)) : Eigen::VectorXd(ldlt_.solve(b));
}

} // namespace plastica
