// Where a chart's legend goes: the corner of the plot whose legend-sized box covers the least
// of the drawn data (a curve that peaks early and falls away leaves the top right free, one
// that rises to its end leaves the bottom right), so the legend never hides the curve it names.
#pragma once

#include "load_chart.hpp"

#include <vector>

namespace plastica::render {

struct LegendCorner {
    bool right = false;
    bool bottom = false;
};

// box_width, box_height: the legend's size as fractions of the plot's; log: both axes
// logarithmic. Ties go to the top left, then the top right, bottom right, bottom left.
LegendCorner clearest_corner(const std::vector<ChartSeries>& series, double x0, double x1, double y0, double y1,
                             double box_width, double box_height, bool log = false);

} // namespace plastica::render
