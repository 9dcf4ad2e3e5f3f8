// Writes a file under a temporary name and renames it into place, so that no reader ever
// sees a half-written file under its final name.
#pragma once

#include <stdexcept>
#include <string>

namespace plastica {

// A file could not be written (a full disk, a removed folder, a refused link): not bad input,
// but output that stopped; commands exit 3 for it.
class WriteError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws WriteError naming the path and the reason (a full disk: "No space left on
// device") and leaves neither the temporary nor a partial file.
void write_file_atomically(const std::string& path, const std::string& contents);
// Writes the file under its final name, over an existing one in place (the file keeps its
// inode: creating one costs a file system like ext4 far more than filling it). For files that
// readers find only through a list written after them (a series' steps). On failure it
// throws as above and removes the partial file.
void write_file_in_place(const std::string& path, const std::string& contents);
// Writes all of it to an open descriptor, or throws naming the path and the reason.
void write_all(int fd, const char* data, std::size_t size, const std::string& path);
// The same at a position of the file (pwrite), without moving its offset.
void write_all_at(int fd, const std::string& text, long offset, const std::string& path);
std::string temporary_name(const std::string& path);
void rename_into_place(const std::string& temporary, const std::string& path);

} // namespace plastica
