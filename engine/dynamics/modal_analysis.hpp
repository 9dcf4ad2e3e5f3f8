// The lowest natural modes of K φ = ω² M φ on the free DOFs: Spectra's shift-invert Lanczos
// (SymGEigsShiftSolver) with the factorisation of K − σM by the engine's own LDLᵀ, or, for a
// few dozen DOFs, a dense solution of the same shifted problem. The shift σ is 0 where K is
// positive definite, and slightly negative where the structure has rigid motions (a free
// body): its zero frequencies are then found too. Shared by `plastica modes` and Rayleigh
// damping by modal ratios.
#pragma once

#include "solver/block_assembler.hpp"

#include <Eigen/Dense>
#include <stdexcept>
#include <vector>

namespace plastica {

struct NaturalModes {
    std::vector<double> omega_squared; // ascending, ≥ 0 up to round-off
    Eigen::MatrixXd shapes;            // one column per mode, φᵀMφ = 1, free DOFs
};

class ModalError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The `count` lowest modes (fewer where the structure has fewer DOFs with mass). Throws
// ModalError where K − σM cannot be factorised or Lanczos does not converge.
NaturalModes lowest_modes(const SparseMatrix& K, const SparseMatrix& M, int count);

} // namespace plastica
