#include "sweep_charts.hpp"

#include "charts.hpp"
#include "figure_text.hpp"
#include "png_file.hpp"
#include "series_summary.hpp"

#include <vtkImageData.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace plastica::render {

namespace {

// Blue (low) to red (high) through grey: the colour of a run by its first parameter.
Rgb ramp(double t) {
    const Rgb low{31, 90, 180}, mid{150, 150, 150}, high{200, 40, 40};
    return t < 0.5 ? mix(low, mid, 2.0 * t) : mix(mid, high, 2.0 * t - 1.0);
}

} // namespace

std::vector<std::string> draw_sweep_charts(const SweepCharts& c, const std::string& folder) {
    namespace fs = std::filesystem;
    std::vector<std::string> written;
    if (c.runs.empty()) return written;
    auto save = [&](const ChartFigure& figure, const std::string& name) {
        const std::string path = (fs::path(folder) / name).string();
        write_png(draw_chart(figure), path);
        written.push_back(path);
    };
    // The family of curves, coloured by the first parameter. The legend names each value once
    // (on the first run that has it) when there are few, else the two ends; the labels have the
    // digits that keep them apart.
    double lo = INFINITY, hi = -INFINITY;
    std::vector<double> distinct;
    for (const SweepChartRun& r : c.runs)
        if (std::isfinite(r.values.front())) {
            lo = std::min(lo, r.values.front()), hi = std::max(hi, r.values.front());
            if (std::find(distinct.begin(), distinct.end(), r.values.front()) == distinct.end()) distinct.push_back(r.values.front());
        }
    std::sort(distinct.begin(), distinct.end());
    if (distinct.size() > 8) distinct = {distinct.front(), distinct.back()};
    const std::vector<std::string> labels = distinct_numbers(distinct);
    ChartFigure family{c.scene + ": " + std::to_string(c.runs.size()) + " runs, coloured by " + c.keys.front(),
                       with_unit(c.displacement_label, c.displacement_unit), with_unit(c.load_label, c.load_unit), {}, true};
    std::vector<bool> named(distinct.size(), false);
    for (const SweepChartRun& r : c.runs) {
        const double t = hi > lo && std::isfinite(r.values.front()) ? (r.values.front() - lo) / (hi - lo) : 0.5;
        ChartSeries line{"", r.displacement, r.load, ramp(t), 1.5f};
        const auto at = std::find(distinct.begin(), distinct.end(), r.values.front());
        if (at != distinct.end() && !named[static_cast<std::size_t>(at - distinct.begin())]) {
            named[static_cast<std::size_t>(at - distinct.begin())] = true;
            line.label = c.keys.front() + " = " + labels[static_cast<std::size_t>(at - distinct.begin())];
        }
        family.series.push_back(line);
    }
    save(family, "curves.png");
    // The peak load against each parameter.
    for (std::size_t k = 0; k < c.keys.size(); ++k) {
        ChartSeries dots{"", {}, {}, {31, 90, 180}, 8.0f, true};
        for (const SweepChartRun& r : c.runs)
            if (std::isfinite(r.values[k]) && std::isfinite(r.peak_load)) dots.x.push_back(r.values[k]), dots.y.push_back(r.peak_load);
        if (dots.x.empty()) continue;
        ChartFigure peak{c.scene + ": peak " + c.load_label + " against " + c.keys[k], c.keys[k],
                         with_unit("peak " + c.load_label, c.load_unit), {dots}, false};
        peak.axes_through_zero = false;
        save(peak, "peak_" + std::to_string(k + 1) + ".png");
    }
    if (!c.sampled) return written;
    // The empirical distribution of the peak load: histogram (as a step line) and CDF.
    std::vector<double> peaks;
    for (const SweepChartRun& r : c.runs)
        if (std::isfinite(r.peak_load)) peaks.push_back(r.peak_load);
    std::sort(peaks.begin(), peaks.end());
    if (peaks.size() < 2 || peaks.back() <= peaks.front()) return written;
    const int bins = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(peaks.size()))), 5, 30);
    const double width = (peaks.back() - peaks.front()) / bins;
    std::vector<int> count(bins, 0);
    for (double p : peaks) ++count[std::min(bins - 1, static_cast<int>((p - peaks.front()) / width))];
    ChartSeries histogram{"share of runs per bin", {}, {}, {31, 90, 180}, 2.5f};
    for (int b = 0; b < bins; ++b) {
        const double x0 = peaks.front() + b * width, share = static_cast<double>(count[b]) / peaks.size();
        histogram.x.insert(histogram.x.end(), {x0, x0, x0 + width, x0 + width});
        histogram.y.insert(histogram.y.end(), {0.0, share, share, 0.0});
    }
    ChartSeries cdf{"cumulative share", {}, {}, {200, 40, 40}, 2.5f};
    for (std::size_t i = 0; i < peaks.size(); ++i) {
        cdf.x.push_back(peaks[i]);
        cdf.y.push_back(static_cast<double>(i + 1) / peaks.size());
    }
    ChartFigure distribution{c.scene + ": peak " + c.load_label + ", n = " + std::to_string(peaks.size()) + " runs",
                             with_unit("peak " + c.load_label, c.load_unit), "share of runs", {histogram, cdf}, true};
    distribution.axes_through_zero = false;
    save(distribution, "peak_distribution.png");
    return written;
}

} // namespace plastica::render
