// The critical factors of K φ = μ B φ nearest zero, K the tangent and B = −K_G the geometric
// stiffness of the loads' axial forces per unit factor, negated (analysis/linear_buckling.hpp).
// Where K is positive definite: the lowest positive μ, by Spectra's buckling mode
// ((K − σB)⁻¹K, over the engine's own LDLᵀ) or, for a few hundred DOFs, densely through the
// Cholesky factor of K. Where K is already indefinite (a state past a bifurcation), densely by
// the QZ algorithm: the μ nearest zero, of either sign.
#pragma once

#include "solver/block_assembler.hpp"

#include <Eigen/Dense>
#include <stdexcept>
#include <vector>

namespace plastica {

struct BucklingEigenpairs {
    std::vector<double> factors; // ascending
    Eigen::MatrixXd shapes;      // one column per factor, largest component +1
    bool tangent_indefinite = false;
};

class BucklingError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws BucklingError where K is singular, B vanishes, or the iteration does not converge.
BucklingEigenpairs lowest_buckling_factors(const SparseMatrix& K, const SparseMatrix& B, int count);

} // namespace plastica
