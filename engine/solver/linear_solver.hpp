// Solves K x = b for the symmetric tangent. LDLᵀ (no pivoting) tolerates the indefinite
// tangent past a limit point and gives its inertia: the number of negative pivots counts the
// eigenvalues below zero (Sylvester). The order and the symbolic analysis are computed once:
// 3 × 3 node blocks in a bandwidth-reducing order where their envelope is narrow (chains, rings,
// frames of a few bays: block_profile_ldlt.hpp), else a fill-reducing (AMD) order and the
// general sparse factorisation (sparse_ldlt.hpp). K's lower triangle is copied straight into the
// storage the factorisation reads, through a fixed slot map. If a pivot vanishes, sparse LU
// with partial pivoting takes over for that factorisation.
#pragma once

#include "solver/block_assembler.hpp"
#include "solver/block_profile_ldlt.hpp"
#include "solver/sparse_ldlt.hpp"

#include <Eigen/SparseLU>
#include <vector>

namespace plastica {

class LinearSolver {
public:
    // Returns false when the matrix is singular (also for LU). A pattern of K other than the
    // last call's is analysed again (the assembler keeps it fixed until surfaces touch or part).
    bool factorize(const SparseMatrix& K);
    Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
    // The same into x, without allocating once x has its size (Newton's corrections).
    void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
    // Two right-hand sides in one pass over the factor, each with the bits solve() gives it.
    void solve(const Eigen::VectorXd& b1, const Eigen::VectorXd& b2, Eigen::VectorXd& x1, Eigen::VectorXd& x2) const;
    // Pivots below zero_pivot of their own diagonal entry are round-off: neither counted as
    // negative nor trusted (LU takes over).
    static constexpr double zero_pivot = 1e-15;
    int negative_pivots() const { return negative_pivots_; }
    // The equation whose pivot is smallest relative to its diagonal entry: the DOF that is
    // nearly free.
    int weakest_equation() const { return weakest_; }
    double pivot_ratio() const { return pivot_ratio_; }
    // The factorisation the first call chose: node blocks in a narrow envelope, or general sparse.
    bool uses_node_blocks() const { return blocks_used_; }

private:
    using Permutation = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;
    void analyse(const SparseMatrix& K);
    void analyse_sparse(const SparseMatrix& K); // AMD order, permuted copy, sparse symbolic analysis
    int pivot_of(int equation) const;           // its position in elimination order
    int equation_of(std::size_t pivot) const;

    Permutation order_;         // new position of each equation
    Permutation order_inverse_; // equation at each new position
    SparseMatrix permuted_k_;   // upper triangle of order_·K·order_ᵀ
    std::vector<int> source_;   // for each value of permuted_k_, its index in K's values
    std::vector<int> diagonal_slot_; // for each pivot, its equation's diagonal entry's index in K's values
    SparseLdlt ldlt_;
    BlockProfileLdlt blocks_;
    bool blocks_used_ = false; // node blocks (true) or the general sparse factorisation
    Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> lu_;
    bool analysed_ = false;
    std::vector<int> pattern_outer_, pattern_inner_; // K's pattern when it was analysed
    bool same_pattern(const SparseMatrix& K) const;
    bool lu_analysed_ = false;
    bool using_lu_ = false;
    int negative_pivots_ = 0;
    int weakest_ = -1;
    double pivot_ratio_ = 1.0;
    mutable Eigen::VectorXd permuted_, permuted2_; // work space of solve
};

} // namespace plastica
