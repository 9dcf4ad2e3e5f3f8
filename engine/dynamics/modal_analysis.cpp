#include "dynamics/modal_analysis.hpp"

#include "solver/linear_solver.hpp"
#include "solver/shifted_inverse.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <algorithm>
#include <cmath>
#include <memory>

namespace plastica {

namespace {

double shift_for(const SparseMatrix& K, const SparseMatrix& M) {
    LinearSolver probe;
    if (probe.factorize(K) && probe.negative_pivots() == 0) return 0.0;
    const double k = K.diagonal().cwiseAbs().sum(), m = M.diagonal().cwiseAbs().sum();
    return -1e-6 * k / std::max(m, 1e-300);
}

NaturalModes dense_modes(const SparseMatrix& K, const SparseMatrix& M, int count, double sigma) {
    const Eigen::MatrixXd A = Eigen::MatrixXd(K) - sigma * Eigen::MatrixXd(M);
    const Eigen::LLT<Eigen::MatrixXd> llt(A);
    if (llt.info() != Eigen::Success) throw ModalError("K − σM is not positive definite: the structure is unstable");
    const Eigen::MatrixXd L = llt.matrixL();
    const Eigen::MatrixXd Linv = L.triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(A.rows(), A.cols()));
    const Eigen::MatrixXd C = Linv * Eigen::MatrixXd(M) * Linv.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (C + C.transpose()));
    NaturalModes out;
    const Eigen::Index n = A.rows();
    std::vector<Eigen::VectorXd> shapes;
    for (Eigen::Index k = n - 1; k >= 0 && static_cast<int>(out.omega_squared.size()) < count; --k) {
        const double mu = eig.eigenvalues()[k];
        if (mu <= 1e-14 * eig.eigenvalues().cwiseAbs().maxCoeff()) break; // massless: no finite frequency
        out.omega_squared.push_back(sigma + 1.0 / mu);
        shapes.push_back(Linv.transpose() * eig.eigenvectors().col(k));
    }
    out.shapes.resize(n, static_cast<Eigen::Index>(shapes.size()));
    for (std::size_t k = 0; k < shapes.size(); ++k) out.shapes.col(static_cast<Eigen::Index>(k)) = shapes[k];
    return out;
}

} // namespace

NaturalModes lowest_modes(const SparseMatrix& K, const SparseMatrix& M, int count) {
    const Eigen::Index n = K.rows();
    NaturalModes out;
    if (n == 0 || count <= 0) return out;
    const double sigma = shift_for(K, M);
    if (n <= 60 || count >= n / 2) {
        out = dense_modes(K, M, count, sigma);
    } else {
        ShiftedInverse op(K, M);
        Spectra::SparseSymMatProd<double> mass(M);
        const Eigen::Index nev = count;
        const Eigen::Index ncv = std::min<Eigen::Index>(n, std::max<Eigen::Index>(2 * nev + 1, 20));
        using Solver = Spectra::SymGEigsShiftSolver<ShiftedInverse, Spectra::SparseSymMatProd<double>, Spectra::GEigsMode::ShiftInvert>;
        std::unique_ptr<Solver> solver;
        try { // the shift is factorised as the solver is made
            solver = std::make_unique<Solver>(op, mass, nev, ncv, sigma);
            solver->init();
            solver->compute(Spectra::SortRule::LargestMagn, 1000, 1e-10, Spectra::SortRule::SmallestAlge);
        } catch (const std::runtime_error& e) {
            throw ModalError(std::string("K − σM: ") + e.what());
        }
        if (solver->info() != Spectra::CompInfo::Successful) throw ModalError("the Lanczos iteration for the modes did not converge");
        const Eigen::VectorXd values = solver->eigenvalues();
        out.shapes = solver->eigenvectors();
        out.omega_squared.assign(values.data(), values.data() + values.size());
    }
    // Each shape scaled to unit modal mass, its largest component positive (a sign one can compare).
    for (Eigen::Index k = 0; k < out.shapes.cols(); ++k) {
        Eigen::VectorXd phi = out.shapes.col(k);
        const double modal_mass = phi.dot(M * phi);
        if (modal_mass > 0.0) phi /= std::sqrt(modal_mass);
        Eigen::Index at = 0;
        phi.cwiseAbs().maxCoeff(&at);
        if (phi[at] < 0.0) phi = -phi;
        out.shapes.col(k) = phi;
    }
    return out;
}

} // namespace plastica
