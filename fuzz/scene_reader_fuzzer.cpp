// libFuzzer target (docs/ci.md, `make fuzz`): any byte string given to the scene reader must give
// a Model or a located SceneError — never a crash, a hang, an uncaught exception or undefined
// behaviour. It starts from the scenes in models/; an input that fails becomes a case in
// tests/test_scene_errors.cpp.
#include "analysis/path_following.hpp"
#include "scene_error.hpp"
#include "scene_reader.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const plastica::Model model = plastica::read_scene_text(text, "fuzz.toml");
        // A valid scene must also survive the check for mechanisms before loading.
        plastica::PathFollowing analysis(model);
        (void)analysis.initial_mechanism();
    } catch (const plastica::SceneError&) {
    }
    return 0;
}
