// libFuzzer target: any byte string given to the PNG decoder of `plastica compare` must give a
// picture within the bounds or a message — never a crash, a huge allocation or a leak.
#include "png_decode.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string why;
    const auto png = plastica::render::decode_png(std::string(reinterpret_cast<const char*>(data), size), why);
    if (png && png->pixels.size() != static_cast<std::size_t>(png->width) * png->height * png->channels) __builtin_trap();
    return 0;
}
