// The structure's mass matrix M(u) on its DOFs.
//
// Consistent mass (the default): each member's linear-elastic consistent matrix — linear
// axial, Hermitian (cubic) transverse, and the rotary inertia ρI of the same cubic field — in
// the frame of its current chord: M_e = Tᵀ(β) M_local T(β). Rigid translations and rotations are
// carried exactly (the axial block gives a rotating member its centripetal forces). The change
// of T with β is left out of the inertia force and its tangent; for members whose local
// deflections are small against their length, Le, Battini & Hjiaj ("A consistent 2D
// corotational formulation for nonlinear dynamic analysis of planar beams", Comput. Methods
// Appl. Mech. Eng. 269, 2014) find this simplification agrees with the fully consistent
// inertia. Lumped mass: ρAℓ/2 on each end's translations, ρIℓ/2 on its rotation. Nodal masses
// ([[mass]]) add to the diagonal.
#pragma once

#include "model/model.hpp"
#include "solver/block_assembler.hpp"

#include <Eigen/Dense>
#include <vector>

namespace plastica {

class MassMatrix {
public:
    // equation: each DOF's equation number, −1 where it is held (StructuralSystem::equation).
    MassMatrix(const Model& model, MassKind kind, std::vector<int> equation, int free_count);

    // M at the full displacement vector u, on the free DOFs.
    SparseMatrix assemble(const Eigen::VectorXd& u) const;
    // M(u)·v of full vectors, for every DOF (held ones too): momentum and kinetic energy.
    Eigen::VectorXd times(const Eigen::VectorXd& u, const Eigen::VectorXd& v) const;
    // The mass that moves with the free translations along x (0) or y (1): M·r for the
    // ground-motion influence vector r of that direction, free DOFs.
    Eigen::VectorXd influence(const Eigen::VectorXd& u, int direction) const;
    double total_mass() const { return total_mass_; }
    MassKind kind() const { return kind_; }

private:
    struct Member {
        int node_i, node_j;
        double dx0, dy0, length;
        double mass_per_length, rotary_per_length;
    };
    using Matrix6 = Eigen::Matrix<double, 6, 6>;
    Matrix6 element_matrix(const Member& m, const Eigen::VectorXd& u) const;

    MassKind kind_;
    std::vector<int> equation_;
    int free_count_;
    std::vector<Member> members_;
    std::vector<NodalMass> nodal_;
    double total_mass_ = 0.0;
};

} // namespace plastica
