// Output safety: a scene writes only under its own folder; a folder that holds another
// scene's results is not mixed with this one unless the user forces it; stale steps of an
// earlier run of the same scene are cleared first.
#pragma once

#include <string>

namespace plastica::cli {

std::string default_output_folder(const std::string& scene_name);
// Throws std::runtime_error with a message for the user when the folder may not be used.
void prepare_output_folder(const std::string& folder, const std::string& scene_name, bool force);

} // namespace plastica::cli
