#include "solver/buckling_eigenproblem.hpp"

#include "solver/linear_solver.hpp"
#include "solver/shifted_inverse.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

namespace plastica {

namespace {

// Up to this many DOFs a dense solution costs less than a millisecond to a second and needs no shift.
constexpr Eigen::Index dense_limit = 800;

struct Pair {
    double factor;
    Eigen::VectorXd shape;
};

// K = L Lᵀ: K φ = μ B φ becomes C y = (1/μ) y with C = L⁻¹ B L⁻ᵀ and φ = L⁻ᵀ y.
std::vector<Pair> dense_definite(const Eigen::MatrixXd& K, const Eigen::MatrixXd& B, const Eigen::LLT<Eigen::MatrixXd>& llt) {
    const Eigen::MatrixXd L = llt.matrixL();
    const auto lower = L.triangularView<Eigen::Lower>();
    Eigen::MatrixXd C = lower.solve(B);
    C = lower.solve(C.transpose()).eval();
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (C + C.transpose()));
    const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
    std::vector<Pair> out;
    for (Eigen::Index k = 0; k < K.rows(); ++k) {
        const double nu = eig.eigenvalues()[k];
        if (nu <= 1e-12 * largest) continue; // μ negative (the loads reversed) or infinite
        out.push_back({1.0 / nu, L.transpose().triangularView<Eigen::Upper>().solve(eig.eigenvectors().col(k))});
    }
    return out;
}

// K indefinite: the real, finite generalised eigenvalues of the pencil (K, B).
std::vector<Pair> dense_indefinite(const Eigen::MatrixXd& K, const Eigen::MatrixXd& B) {
    const Eigen::GeneralizedEigenSolver<Eigen::MatrixXd> qz(K, B, true);
    if (qz.info() != Eigen::Success) throw BucklingError("the QZ iteration for the buckling factors did not converge");
    const Eigen::VectorXd beta = qz.betas();
    const double scale = std::max(K.cwiseAbs().maxCoeff() / std::max(B.cwiseAbs().maxCoeff(), 1e-300), 1e-300);
    std::vector<Pair> out;
    for (Eigen::Index k = 0; k < K.rows(); ++k) {
        const std::complex<double> alpha = qz.alphas()[k];
        if (std::abs(beta[k]) * scale <= 1e-10 * std::abs(alpha) || std::abs(alpha.imag()) > 1e-8 * std::abs(alpha)) continue;
        const Eigen::VectorXd shape = qz.eigenvectors().col(k).real();
        if (shape.norm() > 0.0) out.push_back({alpha.real() / beta[k], shape});
    }
    return out;
}

// A first guess at the lowest factor by inverse iteration (x ← K⁻¹Bx), for Spectra's shift.
double estimate_lowest(const LinearSolver& solver, const SparseMatrix& K, const SparseMatrix& B) {
    Eigen::VectorXd x = Eigen::VectorXd::Ones(K.rows());
    for (int k = 0; k < 8; ++k) {
        x = solver.solve(B * x);
        const double n = x.norm();
        if (!(n > 0.0)) throw BucklingError("the loads put no member in compression: nothing buckles");
        x /= n;
    }
    return x.dot(K * x) / x.dot(B * x);
}

std::vector<Pair> sparse_definite(const SparseMatrix& K, const SparseMatrix& B, const LinearSolver& solver, int count) {
    const double lowest = estimate_lowest(solver, K, B);
    // Halfway to the lowest: the shift stays away from it and from zero.
    const double sigma = 0.5 * std::abs(lowest);
    ShiftedInverse op(K, B);
    Spectra::SparseSymMatProd<double> stiffness(K);
    const Eigen::Index n = K.rows();
    const Eigen::Index nev = std::min<Eigen::Index>(2 * count, n - 1);
    const Eigen::Index ncv = std::min<Eigen::Index>(n, std::max<Eigen::Index>(2 * nev + 1, 20));
    using Solver = Spectra::SymGEigsShiftSolver<ShiftedInverse, Spectra::SparseSymMatProd<double>, Spectra::GEigsMode::Buckling>;
    std::unique_ptr<Solver> solver_b;
    try {
        solver_b = std::make_unique<Solver>(op, stiffness, nev, ncv, sigma);
        solver_b->init();
        solver_b->compute(Spectra::SortRule::LargestMagn, 1000, 1e-10, Spectra::SortRule::SmallestAlge);
    } catch (const std::runtime_error& e) {
        throw BucklingError(std::string("K − σB: ") + e.what());
    }
    if (solver_b->info() != Spectra::CompInfo::Successful)
        throw BucklingError("the Lanczos iteration for the buckling factors did not converge");
    std::vector<Pair> out;
    const Eigen::VectorXd values = solver_b->eigenvalues();
    const Eigen::MatrixXd vectors = solver_b->eigenvectors();
    for (Eigen::Index k = 0; k < values.size(); ++k)
        if (values[k] > 0.0) out.push_back({values[k], vectors.col(k)});
    return out;
}

} // namespace

BucklingEigenpairs lowest_buckling_factors(const SparseMatrix& K, const SparseMatrix& B, int count) {
    BucklingEigenpairs out;
    const Eigen::Index n = K.rows();
    if (n == 0 || count <= 0) return out;
    if (B.cwiseAbs().sum() == 0.0) throw BucklingError("the loads put no member in compression: nothing buckles");
    LinearSolver solver;
    if (!solver.factorize(K)) throw BucklingError("the tangent is singular: the structure is a mechanism at this state");
    out.tangent_indefinite = solver.negative_pivots() > 0;
    std::vector<Pair> pairs;
    if (out.tangent_indefinite) {
        if (n > 3 * dense_limit)
            throw BucklingError("the tangent is indefinite (" + std::to_string(solver.negative_pivots()) +
                                " negative pivots) and the model too large for the dense solution that case needs");
        pairs = dense_indefinite(Eigen::MatrixXd(K), Eigen::MatrixXd(B));
    } else if (n <= dense_limit) {
        const Eigen::MatrixXd Kd(K);
        const Eigen::LLT<Eigen::MatrixXd> llt(Kd);
        if (llt.info() != Eigen::Success) throw BucklingError("the tangent is not positive definite");
        pairs = dense_definite(Kd, Eigen::MatrixXd(B), llt);
    } else {
        pairs = sparse_definite(K, B, solver, count);
    }
    // Nearest zero first where K is indefinite (some lie below the state), else lowest first.
    std::sort(pairs.begin(), pairs.end(), [&](const Pair& a, const Pair& b) {
        return out.tangent_indefinite ? std::abs(a.factor) < std::abs(b.factor) : a.factor < b.factor;
    });
    if (pairs.size() > static_cast<std::size_t>(count)) pairs.resize(static_cast<std::size_t>(count));
    std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.factor < b.factor; });
    if (pairs.empty()) throw BucklingError("no positive buckling factor: the loads put no member in compression");
    out.shapes.resize(n, static_cast<Eigen::Index>(pairs.size()));
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        Eigen::VectorXd phi = pairs[k].shape;
        Eigen::Index at = 0;
        phi.cwiseAbs().maxCoeff(&at);
        phi /= phi[at]; // the largest component +1: a sign and size one can compare
        out.factors.push_back(pairs[k].factor);
        out.shapes.col(static_cast<Eigen::Index>(k)) = phi;
    }
    return out;
}

} // namespace plastica
