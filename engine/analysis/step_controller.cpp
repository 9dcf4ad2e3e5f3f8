#include "analysis/step_controller.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

double StepController::after_failure(double tried) {
    steps_since_cut_ = 0;
    return 0.5 * tried;
}

double StepController::refined(double tried, double advance, double smallest) {
    const bool jumps = refined_advance_ > 0.0 && advance >= 0.9 * refined_advance_;
    if (advance > max_yield_advance && std::abs(tried) * 0.5 >= smallest && !jumps) {
        refined_advance_ = advance;
        return tried * std::max(0.25, 0.9 * max_yield_advance / advance);
    }
    refined_advance_ = 0.0;
    return 0.0;
}

double StepController::after_success(const AnalysisSpec& a, double h, double tried, const NewtonResult& outcome,
                                     double advance) {
    ++steps_since_cut_;
    const double sign = h >= 0.0 ? 1.0 : -1.0;
    double next = std::abs(h);
    if (a.adaptive) {
        // Toward the desired iteration count, as √(desired/iterations). Iterations spent after
        // equilibrium was first reached, re-deciding contradicted active sets (fibres, hinges,
        // contacts), do not count: that takes the same few iterations at any increment, so
        // shrinking for them would keep the increment small for good. Likewise a step whose last
        // iteration still contracted the residual tenfold was inside Newton's basin.
        const int iterations = outcome.iterations_before_settling > 0 ? outcome.iterations_before_settling : outcome.iterations;
        double factor = std::sqrt(static_cast<double>(a.desired_iterations) / std::max(iterations, 1));
        if (outcome.contraction <= 0.1) factor = std::max(factor, 1.0);
        if (advance > 0.0) factor = std::min(factor, max_yield_advance / advance);
        next = std::abs(tried) * std::clamp(factor, 0.5, 2.0);
        if (std::abs(tried) < std::abs(h) && factor >= 1.0) next = std::max(next, std::abs(h)); // a landing step
    } else if (next < std::abs(a.initial_increment) && steps_since_cut_ >= 3) {
        // Recover after a cut, once three steps have passed at the smaller increment: where
        // the full increment failed, the next one tried at once mostly fails as well.
        next = std::min(2.0 * next, std::abs(a.initial_increment));
    }
    if (a.max_increment > 0.0) next = std::min(next, a.max_increment);
    if (next > std::abs(h)) steps_since_cut_ = 0;
    return sign * next;
}

} // namespace plastica
