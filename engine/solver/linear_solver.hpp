// Solves K x = b for the symmetric tangent. LDLᵀ (no pivoting, AMD ordering, symbolic
// analysis done once) tolerates the indefinite tangent past a limit point and gives its
// inertia: the number of negative pivots counts the eigenvalues below zero (Sylvester).
// If a pivot vanishes, sparse LU with partial pivoting takes over for that factorisation.
#pragma once

#include "solver/block_assembler.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

namespace plastica {

class LinearSolver {
public:
    // Returns false when the matrix is singular (also for LU).
    bool factorize(const SparseMatrix& K);
    Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
    int negative_pivots() const { return negative_pivots_; }
    // Index of the smallest |pivot| relative to the largest: the DOF that is nearly free.
    int weakest_equation() const { return weakest_; }
    double pivot_ratio() const { return pivot_ratio_; }

private:
    Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt_;
    Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;
    bool analysed_ = false;
    bool lu_analysed_ = false;
    bool using_lu_ = false;
    int negative_pivots_ = 0;
    int weakest_ = -1;
    double pivot_ratio_ = 1.0;
};

} // namespace plastica
