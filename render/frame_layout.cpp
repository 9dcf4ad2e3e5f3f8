#include "frame_layout.hpp"
#include "figure_text.hpp"

#include <algorithm>
#include <cmath>

namespace plastica::render {

namespace {

// Side by side: the structure's share of the width, and the legend column's share of that.
constexpr double split = 0.57;
constexpr double side_column = 0.25;
// Stacked: the structure's band takes at most this share of the height under the title band
// (the chart keeps the rest), at least the smaller share; the legend's two columns (colour bar,
// entries) are as wide as the side-by-side column, each.
constexpr double most_band = 0.5, least_band = 0.3;
constexpr double legend_share = 2 * side_column * split;
// A stacked frame must draw the structure this much larger to be chosen: the chart is smaller.
constexpr double worth_stacking = 1.25;

int pixels(double share, int size) { return static_cast<int>(std::lround(share * size)); }

FrameLayout side_by_side(int width, int height) {
    FrameLayout layout;
    layout.structure = {0.0, 0.0, split, 1.0 - band, pixels(split, width), pixels(1.0 - band, height)};
    layout.legend_column = side_column;
    layout.chart[0] = split, layout.chart[1] = 0.0, layout.chart[2] = 1.0, layout.chart[3] = 1.0 - band;
    return layout;
}

FrameLayout stacked(double box_width, double box_height, int width, int height) {
    // The band's height that draws the structure across the whole width, within its bounds.
    const double room = (1.0 - band) * height;
    const double wanted = width * box_height / box_width / room;
    const double share = std::clamp(wanted, least_band, most_band) * (1.0 - band);
    const double top = 1.0 - band, bottom = top - share;
    FrameLayout layout;
    layout.structure = {0.0, bottom, 1.0, top, width, pixels(share, height)};
    layout.legend = Viewport{0.0, 0.0, legend_share, bottom, pixels(legend_share, width), pixels(bottom, height)};
    layout.chart[0] = legend_share, layout.chart[1] = 0.0, layout.chart[2] = 1.0, layout.chart[3] = bottom;
    return layout;
}

} // namespace

double structure_scale(const FrameLayout& layout, double box_width, double box_height) {
    const double usable_w = layout.structure.width_px * (1.0 - layout.legend_column);
    return std::min(usable_w / box_width, layout.structure.height_px / box_height);
}

FrameLayout choose_frame_layout(double box_width, double box_height, int width, int height) {
    box_width = std::max(box_width, 1e-300);
    box_height = std::max(box_height, 1e-300);
    FrameLayout beside = side_by_side(width, height);
    FrameLayout under = stacked(box_width, box_height, width, height);
    const bool wide = structure_scale(under, box_width, box_height) >=
                      worth_stacking * structure_scale(beside, box_width, box_height);
    return wide ? under : beside;
}

} // namespace plastica::render
