// Where a scene's results go when no -o is given. What may be done in that folder, and by
// whom, is io/folders/output_folder.hpp's.
#pragma once

#include <string>

namespace plastica::cli {

std::string default_output_folder(const std::string& scene_name);

} // namespace plastica::cli
