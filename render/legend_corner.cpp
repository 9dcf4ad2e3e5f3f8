#include "legend_corner.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace plastica::render {

LegendCorner clearest_corner(const std::vector<ChartSeries>& series, double x0, double x1, double y0, double y1,
                             double box_width, double box_height, bool log) {
    auto to_unit = [log](double v, double lo, double hi) {
        if (log) v = std::log10(v), lo = std::log10(lo), hi = std::log10(hi);
        return hi > lo ? (v - lo) / (hi - lo) : 0.5;
    };
    const std::array<LegendCorner, 4> corners{{{false, false}, {true, false}, {true, true}, {false, true}}};
    std::array<long, 4> covered{};
    auto count = [&](double u, double v) {
        if (!std::isfinite(u) || !std::isfinite(v)) return;
        for (std::size_t c = 0; c < corners.size(); ++c) {
            const bool in_x = corners[c].right ? u >= 1.0 - box_width : u <= box_width;
            const bool in_y = corners[c].bottom ? v <= box_height : v >= 1.0 - box_height;
            if (in_x && in_y) ++covered[c];
        }
    };
    for (const ChartSeries& s : series) {
        const std::size_t n = std::min(s.x.size(), s.y.size());
        for (std::size_t k = 0; k < n; ++k) {
            const double u = to_unit(s.x[k], x0, x1), v = to_unit(s.y[k], y0, y1);
            if (s.points || k == 0) {
                count(u, v);
                continue;
            }
            // A line covers what lies between its points too: samples a hundredth of the plot apart.
            const double pu = to_unit(s.x[k - 1], x0, x1), pv = to_unit(s.y[k - 1], y0, y1);
            const int samples = std::clamp(static_cast<int>(std::hypot(u - pu, v - pv) * 100.0), 1, 1000);
            for (int i = 1; i <= samples; ++i) {
                const double t = static_cast<double>(i) / samples;
                count(pu + t * (u - pu), pv + t * (v - pv));
            }
        }
    }
    std::size_t best = 0;
    for (std::size_t c = 1; c < corners.size(); ++c)
        if (covered[c] < covered[best]) best = c;
    return corners[best];
}

} // namespace plastica::render
