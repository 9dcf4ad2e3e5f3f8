#include "dynamics/initial_acceleration.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <vector>

namespace plastica {

namespace {

// The rows and columns of A at the given positions.
SparseMatrix block(const SparseMatrix& A, const std::vector<int>& rows, const std::vector<int>& cols) {
    std::vector<int> row_at(static_cast<std::size_t>(A.rows()), -1), col_at(static_cast<std::size_t>(A.cols()), -1);
    for (std::size_t k = 0; k < rows.size(); ++k) row_at[static_cast<std::size_t>(rows[k])] = static_cast<int>(k);
    for (std::size_t k = 0; k < cols.size(); ++k) col_at[static_cast<std::size_t>(cols[k])] = static_cast<int>(k);
    std::vector<Eigen::Triplet<double>> entries;
    for (int c = 0; c < A.outerSize(); ++c)
        for (SparseMatrix::InnerIterator it(A, c); it; ++it) {
            const int i = row_at[static_cast<std::size_t>(it.row())], j = col_at[static_cast<std::size_t>(it.col())];
            if (i >= 0 && j >= 0) entries.emplace_back(i, j, it.value());
        }
    SparseMatrix out(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(cols.size()));
    out.setFromTriplets(entries.begin(), entries.end());
    return out;
}

Eigen::VectorXd pick(const Eigen::VectorXd& v, const std::vector<int>& at) {
    Eigen::VectorXd out(static_cast<Eigen::Index>(at.size()));
    for (std::size_t k = 0; k < at.size(); ++k) out[static_cast<Eigen::Index>(k)] = v[at[k]];
    return out;
}

} // namespace

Eigen::VectorXd initial_acceleration(const SparseMatrix& M, const SparseMatrix& K, const Eigen::VectorXd& r) {
    Eigen::VectorXd a = Eigen::VectorXd::Zero(r.size());
    const Eigen::VectorXd diagonal = M.diagonal();
    const double heaviest = diagonal.size() > 0 ? diagonal.cwiseAbs().maxCoeff() : 0.0;
    if (!(heaviest > 0.0)) return a;
    std::vector<int> massed, massless;
    for (Eigen::Index i = 0; i < diagonal.size(); ++i)
        (diagonal[i] > 1e-12 * heaviest ? massed : massless).push_back(static_cast<int>(i));
    Eigen::SimplicialLDLT<SparseMatrix> inertia(block(M, massed, massed));
    if (inertia.info() != Eigen::Success) return a;
    const Eigen::VectorXd a_massed = inertia.solve(pick(r, massed));
    if (!a_massed.allFinite()) return a;
    for (std::size_t k = 0; k < massed.size(); ++k) a[massed[k]] = a_massed[static_cast<Eigen::Index>(k)];
    if (massless.empty() || K.rows() != r.size()) return a;
    Eigen::SparseLU<SparseMatrix> statics;
    statics.compute(block(K, massless, massless));
    if (statics.info() != Eigen::Success) return a;
    const Eigen::VectorXd a_massless = statics.solve(-(block(K, massless, massed) * a_massed));
    if (statics.info() != Eigen::Success || !a_massless.allFinite()) return a;
    for (std::size_t k = 0; k < massless.size(); ++k) a[massless[k]] = a_massless[static_cast<Eigen::Index>(k)];
    return a;
}

} // namespace plastica
