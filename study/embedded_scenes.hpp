// Scene files compiled into the program (models/ring_inelastic.toml and the gallery scenes
// that the robustness matrix of `plastica stability` varies).
#pragma once

#include <map>
#include <string>

namespace plastica {

// The text of models/<name>.toml; throws std::out_of_range for a scene that is not embedded.
const std::string& embedded_scene(const std::string& name);

} // namespace plastica
