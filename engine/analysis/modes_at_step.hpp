// The natural modes of a scene's structure at step K of its run (0: unloaded): the run is
// followed to that step and stopped there (`plastica modes`, Python's plastica.modes).
#pragma once

#include "analysis/step_result.hpp"
#include "dynamics/structure_modes.hpp"
#include "model/model.hpp"

#include <stdexcept>

namespace plastica {

struct ModesAtStep {
    ModalResult modes;
    StepResult state; // the step they are taken at
};

// Throws ModalError where the modes cannot be found, and std::runtime_error (saying where it
// stopped) where the run ends before step K.
ModesAtStep modes_at_step(const Model& model, int count, int step);

} // namespace plastica
