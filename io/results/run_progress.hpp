// How far a run has come toward its end, for progress displays (the command line's bar, Python's
// progress callback): the share of its target reached by a step.
#pragma once

#include "analysis/step_result.hpp"
#include "model/model.hpp"

namespace plastica {

// In [0, 1]: model time over the duration (a scene in time), the control displacement over its
// target, or λ over its target; negative where the share is not known (a scene of several stages).
double share_done(const Model& model, const StepResult& step);

} // namespace plastica
