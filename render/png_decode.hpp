// PNG decoding of files that may come from anywhere (a reference picture, a CI artefact):
// through libpng with its dimensions bounded before any pixel memory is taken, and every
// libpng error (a truncated file, a bad header or checksum) turned into a message.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace plastica::render {

// The largest picture read: 16384 pixels a side and 2^28 pixels in all (1 GiB as RGBA).
inline constexpr unsigned max_png_side = 16384;
inline constexpr std::size_t max_png_pixels = std::size_t(1) << 28;

struct DecodedPng {
    int width = 0, height = 0, channels = 0; // channels 1 to 4 (grey, grey + alpha, RGB, RGBA)
    std::vector<unsigned char> pixels;       // 8 bits a channel, rows from the top
};

// The picture, or nothing with `why` saying what is wrong with it.
std::optional<DecodedPng> decode_png(const std::string& bytes, std::string& why);

} // namespace plastica::render
