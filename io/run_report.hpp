// run.json: what ran (scene, model size), how it ended and converged, timings per stage.
#pragma once

#include "analysis/step_result.hpp"
#include "model/model.hpp"

#include <string>
#include <utility>
#include <vector>

namespace plastica {

struct RunReport {
    std::string scene_file;
    const Model* model = nullptr;
    RunSummary summary;
    std::vector<std::pair<std::string, double>> stage_seconds;
    StepResult last;        // last converged step
    double peak_load = 0.0; // largest reported load
    double peak_load_displacement = 0.0;
};

std::string to_json(const RunReport& report);
void write_run_report(const std::string& path, const RunReport& report);

} // namespace plastica
