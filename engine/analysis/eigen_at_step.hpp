// A scene's natural modes or linear buckling at step K of its run (0: unloaded): the run is
// followed to that step and stopped there (`plastica modes`, `plastica buckling`, Python's
// plastica.modes and plastica.buckling).
#pragma once

#include "analysis/linear_buckling.hpp"
#include "analysis/step_result.hpp"
#include "dynamics/structure_modes.hpp"
#include "model/model.hpp"

#include <stdexcept>

namespace plastica {

struct ModesAtStep {
    ModalResult modes;
    StepResult state; // the step they are taken at
};

struct BucklingAtStep {
    BucklingResult buckling;
    StepResult state;
};

// Throw ModalError (dynamics/modal_analysis.hpp) or BucklingError
// (solver/buckling_eigenproblem.hpp) where the eigenproblem has no answer, and
// std::runtime_error (saying where it stopped) where the run ends before step K.
ModesAtStep modes_at_step(const Model& model, int count, int step);
BucklingAtStep buckling_at_step(const Model& model, int count, int step);

} // namespace plastica
