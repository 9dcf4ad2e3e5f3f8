// Reads a TOML scene file into a validated Model. Every mistake is a SceneError naming the
// file, the line, the key and what was expected; models/README.md documents every key.
#pragma once

#include "model/model.hpp"
#include "scene_error.hpp"
#include "section_shapes.hpp"

#include <toml++/toml.h>

#include <string>

namespace plastica {

inline constexpr int max_elements = 1'000'000; // refused before anything is allocated

Model read_scene(const std::string& path);
Model read_scene_text(const std::string& text, const std::string& name_for_errors);
// A parsed scene (possibly changed by overrides, scene_overrides.hpp) into a Model.
Model read_scene_table(const toml::table& root, const std::string& name_for_errors);

} // namespace plastica
