// The render stage as one call: read a result series (the VTU/PVD files are the only
// input), draw every k-th step into frames/frame_NNNNNN.png (NNNNNN is the step number), and
// chart.png, contact_sheet.png and <scene>.gif. The frames are drawn by one process per core
// (frame_workers.hpp), each encoding its PNGs on a second thread while it draws the next frame;
// the parent meanwhile draws the chart and the contact sheet and streams the frames, in order,
// to the animation.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace plastica::render {

struct RenderOptions {
    std::string output;                   // folder for the pictures (default: the series folder)
    int width = 1280, height = 720;
    std::string field; // point or cell array colouring the structure; empty: yielded_share or bending_moment
    int every = 1;                        // draw every k-th step (the first, the first yield, the peak and the last always)
    std::vector<int> steps;               // draw exactly these step numbers instead (snapshots)
    std::vector<std::string> hide;        // layers left out: initial, base, hinges, contact, supports, loads
    std::vector<std::string> show;        // layers drawn on request: reactions
    std::vector<std::string> overlays;    // further series whose curves join chart.png
    std::vector<std::string> reference_points; // FILE:label CSVs of points that join chart.png
    std::vector<double> shapes;           // control displacements for shapes.png (empty: none)
    double magnify = 1.0;                 // displacements drawn × this; 0: chosen (see summarise)
    bool animation = true;
    // A series in time: model seconds per second of animation; its frames are the steps nearest
    // to times 12 a second apart in the animation (0: the whole run in about 10 s). --every and
    // --steps choose steps instead.
    double speed = 0.0;
    int workers = 0;                      // drawing processes; 0: one per core
    bool quiet = false;
    // Called after each frame with the frames done and the total (progress display); may be empty.
    std::function<void(int done, int total)> on_frame;
};

struct RenderReport {
    int frames = 0;
    double seconds = 0.0;       // drawing and encoding the frames
    double frames_per_second = 0.0;
    int workers = 1;            // drawing processes used
    std::string gl_renderer;
    std::string animation;      // the GIF's path, or why there is none
    std::string output;         // the folder written
    std::vector<std::string> notes; // options that could not act, and why
};

// Throws RenderError naming the file at fault; frames already written stay.
RenderReport render_series(const std::string& folder_or_pvd, const RenderOptions& options);

} // namespace plastica::render
