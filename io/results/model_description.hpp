// What a run's model is, for people: its sections with their capacities, supports, loads by
// pattern, the stages and the analysis settings. Written into run.json ("model") and shown by the
// report page, so that a result folder says what was computed without its scene file.
#pragma once

#include "model/model.hpp"

#include <nlohmann/json.hpp>

namespace plastica {

nlohmann::ordered_json describe_model(const Model& model);

} // namespace plastica
