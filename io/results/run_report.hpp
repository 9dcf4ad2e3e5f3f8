// run.json: what ran (scene, model size), how it ended and converged, timings per stage.
#pragma once

#include "analysis/step_result.hpp"
#include "analysis/support_reactions.hpp"
#include "model/model.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace plastica {

// What run.json says of the last converged step: kept instead of the step itself, whose
// element results were copied at every step and held through the analysis (a tenth of the
// peak memory of a large model).
struct FinalState {
    double load_factor = 0.0;
    double load = 0.0;
    double control_displacement = 0.0;
    int contact_count = 0;
    int hinge_count = 0;
    int section_failures = 0;                 // summed over the hinges
    std::vector<SupportReaction> reactions;   // empty when the step carries none
};
FinalState final_state(const Model& model, const StepResult& step);

// Where [[self_contact]] first closed: in a flattening test the walls meet there, and the load
// beyond is the penalty's, not the crushing curve's.
struct SelfContactMarks {
    int first_step = 0; // 0: never closed
    double load = 0.0, control_displacement = 0.0;
    double last_force = 0.0; // the pairs' force at the last step, as the reported load counts it (load_scale)
};

struct RunReport {
    std::string scene_file;
    std::vector<std::pair<std::string, std::string>> overrides; // --set KEY=VALUE, in order
    const Model* model = nullptr;
    RunSummary summary;
    std::vector<std::pair<std::string, double>> stage_seconds;
    FinalState last;        // of the last converged step
    // The largest reported load up to the path's first limit point (before self-contact
    // closed, where the scene has it); a higher one met past that point is the later maximum.
    double peak_load = 0.0;
    double peak_load_displacement = 0.0;
    struct LaterMaximum {
        int step = 0;
        double load = 0.0, control_displacement = 0.0;
    };
    std::optional<LaterMaximum> later_maximum;
    std::vector<std::optional<double>> load_at; // at ReportSpec::load_at, where reached
    SelfContactMarks self_contact;
    std::vector<std::string> drawing_notes; // drawing options that could not act, and why
    double previous_load = 0.0, previous_displacement = 0.0; // the step before, for load_at

    // Takes in a converged step: the last state, the peak, the loads at given displacements.
    void note(const StepResult& step);
};

std::string to_json(const RunReport& report);
void write_run_report(const std::string& path, const RunReport& report);
// Written when a run starts ("status": "running"), so that a folder whose run was killed
// still says which scene it holds.
void write_run_started(const std::string& path, const Model& model, const std::string& scene_file);
// The scene named by a run.json of Plastica's, or "" (no file, not JSON, another program's).
std::string recorded_scene(const std::string& run_json);

} // namespace plastica
