// How a frame shares its picture between the structure, its legend and the chart. A structure
// about as tall as it is wide goes on the left, with its colour bar and legend in a column at its
// right, beside the chart. A wide one (a flat beam, a frame of several bays) would fill only a
// thin strip there; it is drawn across the whole picture, with the colour bar, the legend and
// the chart in a band beneath it. The layout is chosen by which draws the structure larger.
#pragma once

#include <optional>

namespace plastica::render {

struct Viewport {
    double x0, y0, x1, y1; // normalised window coordinates
    int width_px, height_px;
};

struct FrameLayout {
    Viewport structure;
    // The colour bar and the legend in a viewport of their own; without one they take the
    // right-hand column of the structure's viewport (`legend_column` of its width).
    std::optional<Viewport> legend;
    double legend_column = 0.0;
    double chart[4] = {0, 0, 1, 1}; // normalised x0, y0, x1, y1
};

// Under the title band of a width × height picture, for a structure (with the room its marks
// need) of box_width × box_height in world units.
FrameLayout choose_frame_layout(double box_width, double box_height, int width, int height);

// The structure's pixels per world unit in a layout.
double structure_scale(const FrameLayout& layout, double box_width, double box_height);

} // namespace plastica::render
