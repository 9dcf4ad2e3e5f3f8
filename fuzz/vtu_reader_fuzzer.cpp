// libFuzzer target: a step file of a result series of someone else's making, read back by
// plastica.open (io/results/vtu_reader.hpp). It must give a dataset or a VtuReadError — never a crash,
// an uncaught exception or a read past the bytes.
#include "vtu_reader.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        (void)plastica::parse_unstructured_grid(text, "step.vtu");
    } catch (const plastica::VtuReadError&) {
    }
    return 0;
}
