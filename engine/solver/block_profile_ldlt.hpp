// LDLᵀ of a structure's tangent in 3 × 3 blocks, one per node, within the envelope of the
// block rows in a bandwidth-reducing order. A node's free DOFs have the same pattern (every
// member and spring couples all three), so the blocks are full and their products are fixed-size
// arithmetic with no index lists: on a chain, a ring or a frame of a few bays the envelope is a
// block or two wide, and a factorisation costs a fifth of the general sparse one's instructions.
// Each diagonal block is factorised as LDLᵀ itself (no pivoting), so the scalar pivots are those
// of the scalar LDLᵀ in the same order: their signs give the inertia.
#pragma once

#include "solver/block_assembler.hpp"

#include <Eigen/Core>
#include <array>
#include <vector>

namespace plastica {

class BlockProfileLdlt {
public:
    // Groups K's equations into blocks (consecutive equations with the same pattern, up to
    // three), orders the blocks and lays out the envelope. False, with nothing kept, when the
    // envelope holds more than max_fill blocks per nonzero block of the lower triangle: a
    // wide structure, which the general sparse factorisation serves better. K is stored whole
    // (both triangles); its lower triangle is read.
    bool analyse(const SparseMatrix& K, double max_fill);
    // False at an exactly zero pivot: the pivots up to it are the new ones.
    bool factorize(const SparseMatrix& K);
    void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const;
    void solve(const Eigen::VectorXd& b1, const Eigen::VectorXd& b2, Eigen::VectorXd& x1, Eigen::VectorXd& x2) const;
    // The scalar pivots in elimination order, and the equation of each.
    const std::vector<double>& pivots() const { return pivots_; }
    const std::vector<int>& pivot_equations() const { return pivot_equations_; }
    int pivot_of(int equation) const { return pivots_of_[static_cast<std::size_t>(equation)]; }

private:
    // A diagonal block's own LDLᵀ: D = l·diag(d)·lᵀ with l unit lower.
    struct BlockPivots {
        double d[3];
        double inverse[3]; // 1 / d
        double l10, l20, l21;
        void solve(double* v) const;
    };
    // L y = b, then D z = y and Lᵀ x = z, in place on each of the padded vectors: one pass over
    // the factor serves them all, each with the arithmetic it has alone.
    template <std::size_t Count>
    void forward(const std::array<double*, Count>& w) const;
    template <std::size_t Count>
    void backward(const std::array<double*, Count>& w) const;

    int blocks_ = 0;
    std::vector<int> padded_;        // each equation's index in the padded (3 per block) vector
    std::vector<int> first_;         // first block column of each block row
    std::vector<std::size_t> start_; // where each block row begins in value_ (its diagonal block last)
    std::vector<int> size_;          // equations in each block (the rest is identity padding)
    std::vector<double> value_;      // the blocks of L row by row, then D's; 3 × 3 row-major
    std::vector<int> from_, to_;     // K's values and where each goes in value_
    std::vector<int> unset_;         // the entries of value_ no value of K sets
    std::vector<BlockPivots> block_pivots_;
    std::vector<double> pivots_;
    std::vector<int> pivot_equations_;
    std::vector<int> pivots_of_; // the inverse of pivot_equations_
    mutable std::vector<double> work_, work2_; // the padded right-hand sides being solved
};

} // namespace plastica
