// Linear buckling of a stage's loads about a state (Bathe, Finite Element Procedures, 2014,
// §6.8.2; the "tangent eigenvalue" form where the state is loaded): with K_T the tangent there,
// the loads' rate f (per unit of the stage's factor, prescribed displacements and moving
// bases included) gives the displacement rate K_T⁻¹f, each member's axial force rate Ṅ, and
// the geometric stiffness K_G(Ṅ). The critical factors solve (K_T + μ K_G) φ = 0: the
// structure buckles at λ_cr = λ + μ. At the unloaded state this is the textbook
// (K₀ + λ K_G) φ = 0. Only the axial forces enter K_G: the bending moments' part and the
// change of the geometry before buckling are the nonlinear path's to follow.
#pragma once

#include "analysis/structural_system.hpp"
#include "model/model.hpp"
#include "solver/buckling_eigenproblem.hpp"

#include <Eigen/Dense>
#include <vector>

namespace plastica {

struct BucklingMode {
    int mode = 1;
    double load_factor = 0.0;     // λ_cr = λ + μ
    double above_state = 0.0;     // μ
    std::vector<double> shape;    // full DOF vector, its largest nodal translation 1
};

struct BucklingResult {
    double state_load_factor = 0.0; // λ of the state they are taken about
    bool tangent_indefinite = false; // the state lies beyond a bifurcation or limit already
    std::vector<BucklingMode> modes;
};

// At the system's last evaluation (the state u, λ; ubar: the prescribed displacements per
// unit λ, full). cubic: the members' Hermitian geometric stiffness (the textbook's, 3e-5 above
// Euler on 8 elements), else the chord's of the path's own tangent (where the path's pivots
// change sign). Throws BucklingError where no factor can be found.
BucklingResult linear_buckling(const StructuralSystem& system, const Eigen::VectorXd& ubar, double load_factor, int count,
                               bool cubic = true);

// A shape scaled so that its largest nodal translation is 1, sign kept (rotations follow).
void scale_to_unit_translation(std::vector<double>& shape);

} // namespace plastica
