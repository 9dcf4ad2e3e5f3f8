// The scenes the benchmarks run: the stored rings, optionally with another element count.
#pragma once

#include "scene_reader.hpp"

#include <fstream>
#include <sstream>
#include <string>

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

} // namespace plastica::bench
