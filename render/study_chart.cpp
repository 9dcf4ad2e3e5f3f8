#include "study_chart.hpp"

#include "figure_text.hpp"

#include <algorithm>
#include <cmath>

namespace plastica::render {

ChartFigure study_chart(const std::string& scene, const StudyReport& report) {
    const bool compared = !report.levels.empty() && !report.levels.front().method.empty();
    ChartFigure chart{scene + (compared ? ": error against " + report.reference : ": error of the load-displacement curve against run time"),
                      "wall time of the analysis (s)", "max error of the load / peak load", {}, true};
    chart.log_scale = true;
    const Rgb colours[] = {{31, 90, 180}, {230, 120, 20}, {40, 150, 70}, {170, 40, 150}, {120, 120, 120}, {200, 50, 50}};
    // One line per method and parameter, in the order of the observed orders.
    int k = 0;
    for (const StudyReport::Order& order : report.observed_order) {
        const std::string name = (order.method.empty() ? "" : order.method + ", ") + order.parameter + " ";
        ChartSeries line{name, {}, {}, colours[k % 6], 2.5f};
        ChartSeries dots{"", {}, {}, colours[k % 6], 9.0f, true};
        std::vector<double> levels;
        for (const StudyLevel& l : report.levels)
            if (l.parameter == order.parameter && l.method == order.method && !l.is_reference && l.error.max > 0) {
                line.x.push_back(l.seconds);
                line.y.push_back(l.error.max);
                levels.push_back(l.level);
            }
        const std::vector<std::string> labels = distinct_numbers(levels);
        for (std::size_t i = 0; i < labels.size(); ++i) line.label += (i == 0 ? "" : ", ") + labels[i];
        if (std::isfinite(order.order)) line.label += "  (order " + number(order.order) + ")";
        dots.x = line.x;
        dots.y = line.y;
        chart.series.push_back(line);
        chart.series.push_back(dots);
        ++k;
    }
    // The distance between methods' limits as a level across the time axis: refining further than
    // where a method's error falls below it cannot decide between the methods.
    double t0 = 1e300, t1 = 0.0;
    for (const StudyLevel& l : report.levels)
        if (l.seconds > 0) t0 = std::min(t0, l.seconds), t1 = std::max(t1, l.seconds);
    for (const StudyReport::LimitGap& g : report.limit_gaps)
        if (g.gap.max > 0 && t1 > 0)
            chart.series.push_back({"limits of " + g.method + " and " + g.against + " apart (" + g.parameter + ")", {t0, t1},
                                    {g.gap.max, g.gap.max}, {110, 110, 110}, 1.5f});
    return chart;
}

} // namespace plastica::render
