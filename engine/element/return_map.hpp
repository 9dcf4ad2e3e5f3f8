// Return map of multi-surface stress-resultant plasticity with linear hardening, for the
// three basic forces q of a beam. Each yield row k reads a_k·q − H_k γ_k ≤ c_k, with its flow
// along a_k (normality): q = q_trial − K Σ γ_k a_k, γ_k ≥ 0, and complementarity. The
// multipliers solve a linear complementarity problem with the symmetric positive definite
// matrix M = A K Aᵀ + diag(H) (every row has some hardening), found by an active-set method:
// Lawson and Hanson's method: exact for linear rows, finite, free of cycling. The consistent tangent with the active
// rows is K − K Aₐᵀ M_aa⁻¹ Aₐ K.
#pragma once

#include <Eigen/Dense>
#include <boost/container/static_vector.hpp>
#include <vector>

namespace plastica {

// Sets of rows and their multipliers, at most eight rows (element/plastic_hinge_law.hpp): held in
// place, since the return map runs at every evaluation of a hinged member.
constexpr int max_yield_rows = 8;
using RowSet = boost::container::static_vector<int, max_yield_rows>;
using RowValues = boost::container::static_vector<double, max_yield_rows>;

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
    RowSet active;                 // rows with γ > 0 (or the frozen set)
    RowValues multipliers;
    bool consistent = true;        // with a frozen set: every γ ≥ 0 and every other row holds
};

// K − K Aₐᵀ (Aₐ K Aₐᵀ + H)⁻¹ Aₐ K for the given active rows.
Eigen::Matrix3d elastoplastic_tangent(const Eigen::Matrix3d& K, const std::vector<YieldRow>& rows, const RowSet& active);

// working: with frozen, the rows kept active (the method otherwise starts from no active row).
ReturnMap return_map(const Eigen::Matrix3d& K, const Eigen::Vector3d& q_trial,
                     const std::vector<YieldRow>& rows, const RowSet& working, bool frozen);

} // namespace plastica
