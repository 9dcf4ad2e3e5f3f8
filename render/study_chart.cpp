#include "study_chart.hpp"

#include "figure_text.hpp"

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
    return chart;
}

} // namespace plastica::render
