// LDLᵀ of a sparse symmetric matrix whose pattern never changes (a structure's tangent), given
// as its upper triangle in elimination order. The arithmetic is the up-looking algorithm of
// Eigen's SimplicialLDLT, operation for operation, so it gives the same bits; what differs is
// that the pattern of each row of L (the reach of its entries in the elimination tree) is
// found once, in analyse, instead of at every factorisation: a factorisation then only does
// arithmetic (a quarter of the instructions on the ring).
#pragma once

#include "solver/block_assembler.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <vector>

namespace plastica {

class SparseLdlt {
public:
    // The pattern of `upper` (compressed, column-major, rows ≤ column) fixes the structure of L.
    void analyse(const SparseMatrix& upper);
    // Numeric factorisation of a matrix with the analysed pattern. False at an exactly zero
    // pivot: D holds the pivots up to it, the later ones are those of the last factorisation.
    bool factorize(const SparseMatrix& upper);
    // Solves L D Lᵀ x = b in place.
    void solve_in_place(Eigen::VectorXd& x) const;
    // Two systems in one pass over L: the same operations on each as solve_in_place.
    void solve_in_place(Eigen::VectorXd& x, Eigen::VectorXd& y) const;
    const Eigen::VectorXd& pivots() const { return d_; }

private:
    int n_ = 0;
    std::vector<int> column_start_; // of L, by column: Lp
    std::vector<int> row_;          // row of each entry of L: Li
    std::vector<double> value_;     // Lx
    // For each row k of L, its nonzero columns i in the order they are eliminated.
    std::vector<int> reach_start_;
    std::vector<int> reach_column_;
    Eigen::VectorXd d_;
    std::vector<double> y_;   // the row being formed; all zero between factorisations
    std::vector<int> filled_; // entries of each column of L formed so far
};

} // namespace plastica
