// The acceleration a transient stage starts with, in equilibrium: M a₀ = r (r = F − f − C v₀,
// ground motion included) on the DOFs that carry mass. A DOF without mass has no inertia row;
// its acceleration follows the massed ones through the tangent's static condensation,
// K₀₀ a₀ = −K₀ₘ aₘ (the second time derivative of its equilibrium, velocity terms left out).
// Newmark with massless DOFs is well posed (the effective stiffness holds them); only the start
// needs this split (Bathe, Finite Element Procedures, 2014, §9.2.4).
#pragma once

#include "solver/block_assembler.hpp"

#include <Eigen/Dense>

namespace plastica {

// M and K on the free DOFs, r the out-of-balance force there. DOFs whose mass is below 1e-12 of
// the largest are massless; where K₀₀ is singular (a mechanism of massless DOFs) their
// accelerations are left at zero.
Eigen::VectorXd initial_acceleration(const SparseMatrix& M, const SparseMatrix& K, const Eigen::VectorXd& r);

} // namespace plastica
