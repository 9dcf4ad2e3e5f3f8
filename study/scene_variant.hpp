// A scene file with one discretisation parameter changed, read through the scene reader (so a
// variant is validated like any scene): `elements` of every [[line]] and [[arc]], `fibres` of
// every [[section]], or the analysis `increment` (max_steps grows to match); and, for a method
// comparison, how the inelastic sections yield.
#pragma once

#include "model/model.hpp"

#include <string>

namespace plastica {

// Throws StudyError naming the file when the scene has no such key to vary. A non-empty
// `plasticity` ("hinges", "distributed") sets how every inelastic section yields as well.
Model scene_variant(const std::string& file, const std::string& parameter, double value,
                    const std::string& plasticity = "");

} // namespace plastica
