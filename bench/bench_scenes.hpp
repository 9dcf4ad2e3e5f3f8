// The scenes the benchmarks run: the stored rings, optionally with another element count.
#pragma once

#include "scene_reader.hpp"

#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace plastica::bench {

inline Model ring(const std::string& scene, int elements = 50) {
    const std::string path = std::string(PLASTICA_SOURCE_DIR) + "/models/" + scene + ".toml";
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    std::string toml = text.str();
    const std::string key = "elements = 50";
    toml.replace(toml.find(key), key.size(), "elements = " + std::to_string(elements));
    return read_scene_text(toml, path);
}

// A scene of the repository with text replacements (every occurrence of each `from`).
inline Model edited_scene(const std::string& relative, const std::vector<std::pair<std::string, std::string>>& edits) {
    const std::string path = std::string(PLASTICA_SOURCE_DIR) + "/" + relative;
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    std::string toml = text.str();
    for (const auto& [from, to] : edits)
        for (std::size_t at = toml.find(from); at != std::string::npos; at = toml.find(from, at + to.size()))
            toml.replace(at, from.size(), to);
    return read_scene_text(toml, path);
}

} // namespace plastica::bench
