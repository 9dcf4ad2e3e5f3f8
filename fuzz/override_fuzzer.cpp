// libFuzzer target: any text given as `--set PATH=VALUE` to a valid scene must give a Model or a
// located SceneError — never a crash, an overflow or an uncaught exception.
#include "scene_error.hpp"
#include "scene_overrides.hpp"
#include "scene_reader.hpp"

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>

namespace {
// A shipped scene with named tables (material[steel], section[bar]) and every kind of value.
std::string scene_text() {
    std::ifstream in(std::string(PLASTICA_SOURCE_DIR) + "/models/cantilever_tip_load.toml");
    return std::string(std::istreambuf_iterator<char>(in), {});
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::string scene = scene_text();
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        (void)plastica::read_scene_text(scene, "cantilever_tip_load.toml", {plastica::parse_override(text)});
    } catch (const plastica::SceneError&) {
    }
    return 0;
}
