#include "default_folder.hpp"

#include <filesystem>

namespace plastica::cli {

std::string default_output_folder(const std::string& scene_name) { return (std::filesystem::path("out") / scene_name).string(); }

} // namespace plastica::cli
