// Return map of multi-surface stress-resultant plasticity with linear hardening, for the
// three basic forces q of a beam. Each yield row k reads a_k·q − H_k γ_k ≤ c_k, with its flow
// along a_k (normality): q = q_trial − K Σ γ_k a_k, γ_k ≥ 0, and complementarity. The
// multipliers solve a linear complementarity problem with the symmetric positive definite
// matrix M = A K Aᵀ + diag(H) (every row has some hardening), found by an active-set method:
// Lawson and Hanson's method: exact for linear rows, finite, free of cycling. The consistent tangent with the active
// rows is K − K Aₐᵀ M_aa⁻¹ Aₐ K.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace plastica {

struct YieldRow {
    Eigen::Vector3d a = Eigen::Vector3d::Zero();
    double limit = 0.0;     // c
    double hardening = 0.0; // H > 0
};

struct ReturnMap {
    bool ok = false;               // false: no solution within the swap limit
    Eigen::Vector3d q = Eigen::Vector3d::Zero();
    Eigen::Vector3d flow = Eigen::Vector3d::Zero(); // Σ γ_k a_k
    Eigen::Matrix3d tangent = Eigen::Matrix3d::Zero();
    std::vector<int> active;       // rows with γ > 0 (or the frozen set)
    std::vector<double> multipliers;
    bool consistent = true;        // with a frozen set: every γ ≥ 0 and every other row holds
};

// K − K Aₐᵀ (Aₐ K Aₐᵀ + H)⁻¹ Aₐ K for the given active rows.
Eigen::Matrix3d elastoplastic_tangent(const Eigen::Matrix3d& K, const std::vector<YieldRow>& rows,
                                      const std::vector<int>& active);

// working: rows to start from (warm start) or, with frozen, the rows kept active.
ReturnMap return_map(const Eigen::Matrix3d& K, const Eigen::Vector3d& q_trial,
                     const std::vector<YieldRow>& rows, std::vector<int> working, bool frozen);

} // namespace plastica
