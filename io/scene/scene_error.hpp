// An error in a scene file, located: file, line, key, and what was expected. Line 0: no line
// (a file that cannot be opened, a command-line override).
#pragma once

#include <stdexcept>
#include <string>

namespace plastica {

class SceneError : public std::runtime_error {
public:
    SceneError(const std::string& file, int line, const std::string& key, const std::string& what)
        : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " +
                             (key.empty() ? std::string() : "'" + key + "': ") + what),
          file_(file), line_(line), key_(key), reason_(what) {}
    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& key() const { return key_; }
    const std::string& reason() const { return reason_; } // what was expected, without the place

private:
    std::string file_;
    int line_;
    std::string key_;
    std::string reason_;
};

} // namespace plastica
