#include "element/return_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace plastica {

namespace {

constexpr int max_rows = max_yield_rows; // fixed-capacity storage, no allocation
using SmallMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, max_rows, max_rows>;
using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, max_rows, 1>;
using RowBlock = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor, max_rows, 3>;

constexpr double tolerance = 1e-12; // in the rows' units (capacity rows are scaled to ≈ 1)

// Multipliers of the rows in `set` with those rows at equality.
bool solve_active(const Eigen::Matrix3d& K, const Eigen::Vector3d& q_trial, const std::vector<YieldRow>& rows,
                  const RowSet& set, SmallVector& gamma) {
    const int n = static_cast<int>(set.size());
    SmallMatrix M(n, n);
    SmallVector rhs(n);
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d Ka = K * rows[set[i]].a;
        for (int j = 0; j < n; ++j) M(i, j) = rows[set[j]].a.dot(Ka);
        M(i, i) += rows[set[i]].hardening;
        rhs[i] = rows[set[i]].a.dot(q_trial) - rows[set[i]].limit;
    }
    Eigen::LDLT<SmallMatrix> ldlt(M);
    if (ldlt.info() != Eigen::Success) return false;
    gamma = ldlt.solve(rhs);
    return gamma.allFinite();
}

} // namespace

Eigen::Matrix3d elastoplastic_tangent(const Eigen::Matrix3d& K, const std::vector<YieldRow>& rows, const RowSet& active) {
    if (active.empty()) return K;
    const int n = static_cast<int>(active.size());
    RowBlock AK(n, 3);
    SmallMatrix M(n, n);
    for (int i = 0; i < n; ++i) AK.row(i) = (K * rows[active[i]].a).transpose();
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) M(i, j) = rows[active[j]].a.dot(AK.row(i));
        M(i, i) += rows[active[i]].hardening;
    }
    return K - AK.transpose() * M.ldlt().solve(AK);
}

ReturnMap return_map(const Eigen::Matrix3d& K, const Eigen::Vector3d& q_trial,
                     const std::vector<YieldRow>& rows, const RowSet& working, bool frozen) {
    // Lawson and Hanson's active-set method for min ½γᵀMγ − γᵀd, γ ≥ 0 (finite, no cycling),
    // with d_k = a_k·q_trial − c_k. Only M's rows of the active set are ever formed; the
    // violation of an inactive row is read from q = q_trial − K Σγ a.
    ReturnMap out;
    const int rows_count = static_cast<int>(rows.size());
    if (rows_count > max_rows) return out; // beyond the fixed storage: reported as no solution
    std::array<double, max_rows> gamma{};
    RowSet passive;
    auto state = [&](const std::array<double, max_rows>& g) {
        Eigen::Vector3d flow = Eigen::Vector3d::Zero();
        for (int k : passive) flow += g[k] * rows[k].a;
        return flow;
    };
    auto violation = [&](int k, const Eigen::Vector3d& q) {
        return rows[k].a.dot(q) - rows[k].limit - rows[k].hardening * gamma[k];
    };
    auto finish = [&](bool consistent) {
        out.ok = true;
        out.consistent = consistent;
        out.active = passive;
        out.multipliers.clear();
        for (int k : passive) out.multipliers.push_back(gamma[k]);
        out.flow = state(gamma);
        out.q = q_trial - K * out.flow;
        out.tangent = elastoplastic_tangent(K, rows, passive);
        return out;
    };

    if (frozen) {
        // The given rows at equality, whatever their multipliers; then check.
        passive = working;
        SmallVector z;
        if (!solve_active(K, q_trial, rows, passive, z)) return out;
        for (std::size_t i = 0; i < passive.size(); ++i) gamma[passive[i]] = z[i];
        const Eigen::Vector3d q = q_trial - K * state(gamma);
        bool consistent = z.size() == 0 || z.minCoeff() >= -tolerance;
        for (int k = 0; k < rows_count && consistent; ++k)
            if (std::find(passive.begin(), passive.end(), k) == passive.end() && violation(k, q) > tolerance)
                consistent = false;
        return finish(consistent);
    }

    for (int outer = 0; outer < 3 * rows_count + 8; ++outer) {
        const Eigen::Vector3d q = q_trial - K * state(gamma);
        int enter = -1;
        double worst = tolerance;
        for (int k = 0; k < rows_count; ++k) {
            if (std::find(passive.begin(), passive.end(), k) != passive.end()) continue;
            const double v = violation(k, q);
            if (v > worst) worst = v, enter = k;
        }
        if (enter < 0) return finish(true);
        passive.push_back(enter);
        for (int inner = 0; inner < rows_count + 4; ++inner) {
            SmallVector z;
            if (!solve_active(K, q_trial, rows, passive, z)) return out;
            if (z.size() == 0 || z.minCoeff() > 0.0) {
                for (std::size_t i = 0; i < passive.size(); ++i) gamma[passive[i]] = z[i];
                break;
            }
            // Move toward z until the first multiplier reaches zero; drop those at zero.
            double alpha = 1.0;
            for (std::size_t i = 0; i < passive.size(); ++i)
                if (z[i] <= 0.0) alpha = std::min(alpha, gamma[passive[i]] / (gamma[passive[i]] - z[i]));
            for (std::size_t i = 0; i < passive.size(); ++i) gamma[passive[i]] += alpha * (z[i] - gamma[passive[i]]);
            RowSet kept;
            for (int k : passive) {
                if (gamma[k] > tolerance * 1e-3) kept.push_back(k);
                else gamma[k] = 0.0;
            }
            passive.swap(kept);
        }
    }
    return out;
}

} // namespace plastica
