// The natural modes of a structure at a state: the tangent there (hinges, fibres and contacts
// as the system holds them, axial forces in its geometric stiffness) against the mass matrix,
// with periods, frequencies and effective modal masses in x and y (Chopra, Dynamics of
// Structures, 2012, §13.2): Γ = φᵀM r for unit-mass shapes, M_eff = Γ², r the rigid
// translation of every DOF in the direction.
#pragma once

#include "analysis/structural_system.hpp"
#include "model/model.hpp"

#include <Eigen/Dense>
#include <vector>

namespace plastica {

struct ModeRow {
    int mode = 1;
    double omega = 0.0;     // rad per unit time
    double period = 0.0;    // ∞ for a rigid motion
    double frequency = 0.0; // cycles per unit time
    double effective_mass_x = 0.0, effective_mass_y = 0.0;
    std::vector<double> shape; // full DOF vector (3 per node), φᵀMφ = 1
};

struct ModalResult {
    std::vector<ModeRow> modes;
    double mass_x = 0.0, mass_y = 0.0; // the mass that moves with the free translations: Σ M_eff over all modes
};

// The `count` lowest modes at the full displacement vector u (the system evaluated there).
// Throws ModalError (dynamics/modal_analysis.hpp) where they cannot be found.
ModalResult structure_modes(StructuralSystem& system, const Model& model, const Eigen::VectorXd& u, int count);

} // namespace plastica
