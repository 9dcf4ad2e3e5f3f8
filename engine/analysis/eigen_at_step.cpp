#include "analysis/eigen_at_step.hpp"

#include "analysis/path_following.hpp"

#include <atomic>
#include <functional>
#include <optional>

namespace plastica {

namespace {

// Follows the run to `step` and hands the analysis, stopped there, with that step's result.
void at_step(const Model& model, int step, const std::function<void(PathFollowing&, const StepResult&)>& take) {
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
    take(analysis, *state);
}

} // namespace

ModesAtStep modes_at_step(const Model& model, int count, int step) {
    ModesAtStep out;
    at_step(model, step, [&](PathFollowing& analysis, const StepResult& state) {
        out.modes = analysis.modes(count);
        out.state = state;
    });
    return out;
}

BucklingAtStep buckling_at_step(const Model& model, int count, int step) {
    BucklingAtStep out;
    at_step(model, step, [&](PathFollowing& analysis, const StepResult& state) {
        out.buckling = analysis.buckling(count);
        out.state = state;
    });
    return out;
}

} // namespace plastica
