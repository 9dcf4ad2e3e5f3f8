// y = (A − σB)⁻¹ x, the operator Spectra's shift-invert and buckling modes ask for, with the
// factorisation by the engine's own LDLᵀ (linear_solver.hpp). Shared by the natural modes
// (A = K, B = M: dynamics/modal_analysis.hpp) and linear buckling (A = K, B = −K_G:
// solver/buckling_eigenproblem.hpp).
#pragma once

#include "solver/linear_solver.hpp"

#include <stdexcept>
#include <string>

namespace plastica {

class ShiftedInverse {
public:
    using Scalar = double;
    ShiftedInverse(const SparseMatrix& A, const SparseMatrix& B) : A_(A), B_(B) {}
    Eigen::Index rows() const { return A_.rows(); }
    Eigen::Index cols() const { return A_.cols(); }
    // Throws std::runtime_error where A − σB is singular.
    void set_shift(double sigma) {
        const SparseMatrix shifted = A_ - sigma * B_;
        if (!solver_.factorize(shifted))
            throw std::runtime_error("the shifted matrix is singular at the shift σ = " + std::to_string(sigma));
    }
    void perform_op(const double* x_in, double* y_out) const {
        const Eigen::Map<const Eigen::VectorXd> x(x_in, rows());
        Eigen::Map<Eigen::VectorXd>(y_out, rows()) = solver_.solve(x);
    }

private:
    const SparseMatrix& A_;
    const SparseMatrix& B_;
    LinearSolver solver_;
};

} // namespace plastica
