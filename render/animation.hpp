// The animation of a frame folder as a GIF, made by Debian's ffmpeg program (Debian's VTK has
// no video writer): a two-pass palette filter keeps the colours clean. Without ffmpeg the PNG
// frames stand alone and the caller is told why there is no GIF.
#pragma once

#include <string>

namespace plastica::render {

struct AnimationResult {
    bool written = false;
    std::string message; // what happened, for the user
};

AnimationResult write_gif(const std::string& frames_folder, const std::string& gif_path, int frames_per_second = 12,
                          int width = 640);

} // namespace plastica::render
