#include "run_progress.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

double share_done(const Model& model, const StepResult& step) {
    if (!model.stages.empty()) return -1.0;
    const AnalysisSpec& a = model.analysis;
    double share = 0.0;
    if (a.scheme == Scheme::transient && a.transient.duration > 0.0) share = step.time / a.transient.duration;
    else if (a.target_displacement && *a.target_displacement != 0.0) share = step.control_displacement / *a.target_displacement;
    else if (a.target_load_factor && *a.target_load_factor != 0.0) share = std::abs(step.load_factor / *a.target_load_factor);
    else return -1.0;
    return std::clamp(share, 0.0, 1.0) + 0.0; // a path may first move away from its target; no −0
}

} // namespace plastica
