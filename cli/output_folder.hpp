// Output safety: a scene writes only under its own folder; a folder that holds another
// scene's results is not mixed with this one unless the user forces it; an earlier run's
// results are cleared first (its step files by the series writer, which rewrites them).
#pragma once

#include <string>

namespace plastica::cli {

std::string default_output_folder(const std::string& scene_name);
// Throws std::runtime_error with a message for the user when the folder may not be used.
// keep_step_files: an earlier run's VTU step files stay, for the series writer to rewrite in
// place and to remove those it does not rewrite (VtuSeriesWriter).
void prepare_output_folder(const std::string& folder, const std::string& scene_name, bool force, bool keep_step_files = false);

} // namespace plastica::cli
