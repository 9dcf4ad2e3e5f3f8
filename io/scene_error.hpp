// An error in a scene file, located: file, line, key, and what was expected.
#pragma once

#include <stdexcept>
#include <string>

namespace plastica {

class SceneError : public std::runtime_error {
public:
    SceneError(const std::string& file, int line, const std::string& key, const std::string& what)
        : std::runtime_error(file + ":" + std::to_string(line) + ": " +
                             (key.empty() ? std::string() : "'" + key + "': ") + what),
          file_(file), line_(line), key_(key) {}
    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& key() const { return key_; }

private:
    std::string file_;
    int line_;
    std::string key_;
};

} // namespace plastica
