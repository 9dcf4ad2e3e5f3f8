// The eigenpairs of a symmetric tangent nearest zero (K φ = ω φ): where the path's tangent
// loses its definiteness, the eigenvalue that passes zero and its mode. Densely for a few hundred
// DOFs, else by Spectra's shift-invert Lanczos about zero over the engine's own LDLᵀ (which
// factorises an indefinite tangent as well).
#pragma once

#include "solver/block_assembler.hpp"

#include <Eigen/Dense>
#include <vector>

namespace plastica {

struct TangentEigenpair {
    double value = 0.0;
    Eigen::VectorXd vector; // unit length
};

// The `count` eigenpairs nearest zero, ascending; empty where they cannot be found (a singular
// tangent, Lanczos without convergence).
std::vector<TangentEigenpair> eigenpairs_nearest_zero(const SparseMatrix& K, int count);

} // namespace plastica
