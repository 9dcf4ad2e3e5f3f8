// A scene file with one discretisation parameter changed, read through the scene reader (so a
// variant is validated like any scene): `elements` of every [[line]] and [[arc]], `fibres` of
// every [[section]], or the analysis `increment` (max_steps grows to match).
#pragma once

#include "model/model.hpp"

#include <string>

namespace plastica {

// Throws StudyError naming the file when the scene has no such key to vary.
Model scene_variant(const std::string& file, const std::string& parameter, double value);

} // namespace plastica
