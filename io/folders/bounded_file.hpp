// Reading files that may come from someone else (a scene from a pull request, a result folder
// from a CI artefact): only regular files, never more than a stated size, and, for a file that a
// folder names, only inside that folder and never through a symbolic link.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace plastica {

// The reason names the file and the limit; callers turn it into their own located error.
class FileReadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The limits, each in the message that refuses a larger file.
inline constexpr std::size_t scene_file_limit = 16u << 20;   // a scene of a million lines
inline constexpr std::size_t result_file_limit = 256u << 20; // a run.json, curve.csv or plan
inline constexpr std::size_t picture_file_limit = 64u << 20; // a PNG or GIF

// The whole of a regular file at `path` (a device, a FIFO or a folder is refused, so that
// /dev/zero cannot be read for ever), at most max_bytes.
std::string read_bounded_file(const std::string& path, std::size_t max_bytes);
// A file named by `relative` (plain components, safe_names.hpp) inside `folder`: every component
// opened without following a symbolic link, so that nothing outside the folder is read.
std::string read_file_inside(const std::string& folder, const std::string& relative, std::size_t max_bytes);
// Whether `relative` names a regular file inside `folder`, reached without a symbolic link.
bool is_file_inside(const std::string& folder, const std::string& relative);

} // namespace plastica
