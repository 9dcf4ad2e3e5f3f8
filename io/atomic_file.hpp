// Writes a file under a temporary name and renames it into place, so that no reader ever
// sees a half-written file under its final name.
#pragma once

#include <string>

namespace plastica {

void write_file_atomically(const std::string& path, const std::string& contents);
std::string temporary_name(const std::string& path);
void rename_into_place(const std::string& temporary, const std::string& path);

} // namespace plastica
