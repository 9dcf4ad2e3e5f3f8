// The built-in stability sweep: stiff, extreme and failing cases, each with the
// outcome it must have. `plastica stability` prints them as a table and the tests assert them.
#pragma once

#include "analysis/step_result.hpp"

#include <functional>
#include <string>
#include <vector>

namespace plastica {

struct StabilityCase {
    std::string name;        // what is pushed
    std::string parameter;   // its value in this case
    std::string scene;       // TOML text
    RunStatus expected;
    // A check on the converged steps beyond the outcome: returns an empty string when it holds,
    // else what is wrong.
    std::function<std::string(const std::vector<StepResult>&, const RunSummary&)> check;
};

struct StabilityRow {
    std::string name, parameter, outcome, reason, problem;
    bool passed = false;
    int steps = 0, iterations = 0, cut_steps = 0, max_negative_pivots = 0;
    double max_residual = 0.0, peak_load = 0.0;
    double seconds = 0.0; // analysis wall time
};

std::vector<StabilityCase> stability_cases();
StabilityRow run_stability_case(const StabilityCase& c);

} // namespace plastica
