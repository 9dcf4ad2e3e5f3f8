#include "analysis/modes_at_step.hpp"

#include "analysis/path_following.hpp"

#include <atomic>
#include <optional>

namespace plastica {

ModesAtStep modes_at_step(const Model& model, int count, int step) {
    PathFollowing analysis(model);
    std::atomic<bool> reached{step == 0};
    std::optional<StepResult> state;
    RunControl control;
    control.interrupt = &reached; // the run stops cleanly once the step is published
    const auto keep = [&](const StepResult& r) {
        state = r;
        if (r.step >= step) reached = true;
    };
    const RunSummary summary = analysis.run({keep}, control);
    if (!state || state->step < step)
        throw std::runtime_error("the run ends at step " + std::to_string(state ? state->step : 0) + " (" + summary.reason +
                                 "), before step " + std::to_string(step));
    return {analysis.modes(count), *state};
}

} // namespace plastica
