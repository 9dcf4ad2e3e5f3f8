#include "solver/tangent_spectrum.hpp"

#include "solver/shifted_inverse.hpp"

#include <Eigen/Eigenvalues>
#include <Spectra/SymEigsShiftSolver.h>
#include <algorithm>
#include <cmath>
#include <memory>

namespace plastica {

namespace {
constexpr Eigen::Index dense_tangent_limit = 800; // DOFs solved densely (about 0.3 s at the limit)
}

std::vector<TangentEigenpair> eigenpairs_nearest_zero(const SparseMatrix& K, int count) {
    std::vector<TangentEigenpair> out;
    const Eigen::Index n = K.rows();
    if (n == 0 || count <= 0) return out;
    if (n <= dense_tangent_limit || count >= n / 2) {
        const Eigen::MatrixXd dense = K;
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(dense);
        if (eig.info() != Eigen::Success) return out;
        for (Eigen::Index k = 0; k < n; ++k) out.push_back({eig.eigenvalues()[k], Eigen::VectorXd(eig.eigenvectors().col(k))});
    } else {
        SparseMatrix identity(n, n);
        identity.setIdentity();
        ShiftedInverse op(K, identity);
        const Eigen::Index nev = std::min<Eigen::Index>(count, n - 1);
        const Eigen::Index ncv = std::min<Eigen::Index>(n, std::max<Eigen::Index>(2 * nev + 1, 20));
        using Solver = Spectra::SymEigsShiftSolver<ShiftedInverse>;
        try {
            Solver solver(op, nev, ncv, 0.0);
            solver.init();
            solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10, Spectra::SortRule::SmallestAlge);
            if (solver.info() != Spectra::CompInfo::Successful) return out;
            const Eigen::VectorXd values = solver.eigenvalues();
            const Eigen::MatrixXd vectors = solver.eigenvectors();
            for (Eigen::Index k = 0; k < values.size(); ++k) out.push_back({values[k], Eigen::VectorXd(vectors.col(k))});
        } catch (const std::runtime_error&) {
            return {};
        }
    }
    std::sort(out.begin(), out.end(), [](const TangentEigenpair& a, const TangentEigenpair& b) { return std::abs(a.value) < std::abs(b.value); });
    if (out.size() > static_cast<std::size_t>(count)) out.resize(static_cast<std::size_t>(count));
    std::sort(out.begin(), out.end(), [](const TangentEigenpair& a, const TangentEigenpair& b) { return a.value < b.value; });
    return out;
}

} // namespace plastica
