// Overrides of scene keys from the command line (`plastica run SCENE --set KEY=VALUE`), by the
// path error messages print: `analysis.increment`, `material[1].fy`, and for tables that have a
// name, by name: `material[steel].fy`, `arc[ring].elements`. The value is read as TOML (a
// number, true/false, a quoted string, an array); a bare word is a string. The scene with its
// overrides is validated like a file, and an error in an overridden value names the override.
#pragma once

#include "model/model.hpp"

#include <string>
#include <vector>

namespace plastica {

struct Override {
    std::string path;  // as given
    std::string value; // TOML text
};

// "KEY=VALUE" into an override; throws SceneError naming the text when it has no '='.
Override parse_override(const std::string& text);

// Reads the scene file with the overrides applied, in order.
Model read_scene(const std::string& path, const std::vector<Override>& overrides);
// The same for a scene's text; name_for_errors stands for the file in messages.
Model read_scene_text(const std::string& text, const std::string& name_for_errors, const std::vector<Override>& overrides);

} // namespace plastica
