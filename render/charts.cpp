#include "charts.hpp"
#include "figure_text.hpp"
#include "legend_corner.hpp"
#include "offscreen_window.hpp"
#include "palette.hpp"
#include "result_schema.hpp"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include <algorithm>
#include <cmath>

namespace plastica::render {

vtkSmartPointer<vtkImageData> draw_chart(const ChartFigure& f) {
    const double s = text_scale(f.width, f.height);
    OffscreenWindow window(f.width, f.height);
    vtkNew<vtkRenderer> band_area, chart_area;
    band_area->SetViewport(0.0, 1.0 - band, 1.0, 1.0);
    band_area->SetBackground(colour::title_band.red(), colour::title_band.green(), colour::title_band.blue());
    chart_area->SetViewport(0.0, 0.0, 1.0, 1.0 - band);
    chart_area->SetBackground(1, 1, 1);
    vtkNew<vtkTextActor> title;
    title->SetInput(f.title.c_str());
    style(title, 22 * s, true);
    title->SetPosition(16 * s, 0.11 * f.height * 0.35);
    band_area->AddViewProp(title);

    LoadChart chart(f.x_label, f.y_label, s);
    std::vector<double> all_x, all_y;
    for (const ChartSeries& series : f.series) {
        all_x.insert(all_x.end(), series.x.begin(), series.x.end());
        all_y.insert(all_y.end(), series.y.begin(), series.y.end());
        chart.add(series);
    }
    double x0, x1, y0, y1;
    if (f.log_scale) {
        // A factor of two of room around the positive data, on both axes.
        auto span = [](const std::vector<double>& v, double& lo, double& hi) {
            lo = 1e300, hi = 0;
            for (double x : v)
                if (x > 0 && std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
            if (hi <= 0) lo = 1, hi = 10;
            lo /= 2, hi *= 2;
        };
        span(all_x, x0, x1);
        span(all_y, y0, y1);
        chart.set_log_scale();
    } else {
        if (f.axes_through_zero) {
            all_x.push_back(0.0);
            all_y.push_back(0.0);
            padded_range(all_x, x0, x1);
            padded_range(all_y, y0, y1);
            if (f.load_axis_cut[1] > f.load_axis_cut[0]) y0 = f.load_axis_cut[0], y1 = f.load_axis_cut[1];
        } else {
            // The data's own span, 5 % of room on either side (a scatter far from the origin).
            auto tight = [](const std::vector<double>& v, double& lo, double& hi) {
                lo = INFINITY, hi = -INFINITY;
                for (double x : v)
                    if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
                if (!(hi >= lo)) lo = 0, hi = 1;
                const double pad = 0.05 * (hi > lo ? hi - lo : std::max(std::abs(hi), 1.0));
                lo -= pad, hi += pad;
            };
            tight(all_x, x0, x1);
            tight(all_y, y0, y1);
        }
    }
    chart.set_ranges(x0, x1, y0, y1);
    chart.show_legend(f.legend);
    if (f.legend) {
        // The legend's size against the plot's, from its longest label and its entries (VTK
        // sets 13-point labels with a marker beside them; the plot fills most of the chart).
        std::size_t entries = 0, longest = 0;
        for (const ChartSeries& series : f.series)
            if (!series.label.empty()) ++entries, longest = std::max(longest, series.label.size());
        const double plot_width = 0.85 * f.width, plot_height = 0.8 * (1.0 - band) * f.height;
        const double box_width = std::min(0.6, (7.5 * static_cast<double>(longest) + 50.0) * s / plot_width);
        const double box_height = std::min(0.6, (19.0 * static_cast<double>(entries) + 12.0) * s / plot_height);
        const LegendCorner corner = clearest_corner(f.series, x0, x1, y0, y1, box_width, box_height, f.log_scale);
        chart.set_legend_corner(corner.right, corner.bottom);
    }
    chart.place_in(chart_area);
    window.add(band_area);
    window.add(chart_area);
    // A log axis becomes active while the first frame is painted, after the plots have laid out
    // their points on the linear scale: on log axes the lines only appear from the second frame.
    if (f.log_scale) window.capture();
    return window.capture();
}

vtkSmartPointer<vtkImageData> draw_curve_chart(const std::vector<const SeriesSummary*>& runs, int width, int height,
                                               const std::vector<ReferencePoints>& references) {
    const SeriesSummary& main = *runs.front();
    ChartFigure f;
    f.title = (main.in_time ? main.displacement_label + " against time: " : main.load_label + " against " + main.displacement_label + ": ") +
              scene_heading(main);
    f.x_label = chart_x_title(main);
    f.y_label = chart_y_title(main);
    if (!main.in_time) std::copy(main.load_axis_cut, main.load_axis_cut + 2, f.load_axis_cut);
    f.width = width;
    f.height = height;
    // The main run in the progress blue, drawn last so it stays on top; the others in colours
    // that no marker uses.
    const Rgb others[] = {{105, 105, 105}, {140, 86, 75}, {227, 119, 194}, {23, 190, 207}};
    for (std::size_t k = runs.size(); k-- > 0;) {
        const Rgb c = k == 0 ? colour::curve_progress : others[(k - 1) % 4];
        f.series.push_back({runs.size() > 1 ? runs[k]->scene : "", chart_x(*runs[k], runs[k]->curve.size()),
                            chart_y(*runs[k], runs[k]->curve.size()), c, k == 0 ? 3.0f : 2.0f});
    }
    // Reference points as open markers in colours no run or event uses.
    const Rgb marks[] = {{0, 0, 0}, {120, 60, 160}, {190, 120, 0}, {0, 110, 110}};
    for (std::size_t k = 0; k < references.size(); ++k)
        f.series.push_back({references[k].label, references[k].displacement, references[k].load, marks[k % 4], 9.0f, true});
    // Events of the main run that explain the shape of its curve.
    const bool cut = main.load_axis_cut[1] > main.load_axis_cut[0];
    auto mark = [&](const char* label, Rgb colour, auto happened) {
        for (const CurvePoint& c : main.curve)
            if (happened(c)) {
                if (cut && (c.load < main.load_axis_cut[0] || c.load > main.load_axis_cut[1])) return false; // off the chart
                f.series.push_back({label, {main.in_time ? c.time : c.displacement}, {main.in_time ? c.displacement : c.load}, colour, 12.0f, true});
                return true;
            }
        return false;
    };
    bool marked = false;
    if (main.inelastic) marked |= mark("first yield", colour::hinge_yielding_high, [](const CurvePoint& c) { return c.hinge_count > 0; });
    // The first bifurcation and limit point the path passed, at the step that passed each.
    const int bifurcation = static_cast<int>(result::CriticalCode::bifurcation), limit = static_cast<int>(result::CriticalCode::limit_point);
    if (!main.in_time) {
        marked |= mark("bifurcation", {148, 103, 189}, [&](const CurvePoint& c) { return c.critical == bifurcation; });
        marked |= mark("limit point", {188, 189, 34}, [&](const CurvePoint& c) { return c.critical == limit; });
    }
    // Contact spreads where more nodes touch than at the start and than one (a ring first
    // touches at a node). A zone that grows from the first loaded step on (a pipe on a bed) has
    // no such point: the mark would only sit on the origin, so it is left out.
    if (main.unilateral && main.curve.size() > 2) {
        const int at_start = std::max(1, main.curve.front().contact_count);
        if (main.curve[1].contact_count <= at_start)
            marked |= mark("contact spreads", colour::contact_force, [&](const CurvePoint& c) { return c.contact_count > at_start; });
    }
    f.legend = runs.size() > 1 || marked || !references.empty();
    return draw_chart(f);
}

vtkSmartPointer<vtkImageData> draw_hysteresis_chart(const SeriesSummary& run, int width, int height) {
    ChartFigure f;
    f.title = "base shear against " + run.displacement_label + ": " + (run.title.empty() ? run.scene : run.title);
    f.x_label = with_unit(run.displacement_label, run.displacement_unit);
    f.y_label = with_unit("base shear (on the supports, along x)", run.force_unit);
    f.width = width;
    f.height = height;
    std::vector<double> drift, shear;
    for (const CurvePoint& c : run.curve) drift.push_back(c.displacement), shear.push_back(c.base_shear);
    f.series.push_back({"", drift, shear, colour::curve_progress, 2.0f});
    return draw_chart(f);
}

vtkSmartPointer<vtkImageData> draw_energy_chart(const SeriesSummary& run, int width, int height) {
    ChartFigure f;
    f.title = "energy against time: " + (run.title.empty() ? run.scene : run.title);
    f.x_label = "time (s)";
    const std::string unit = run.force_unit.empty() || run.length_unit.empty() ? "" : run.force_unit + "·" + run.length_unit;
    f.y_label = with_unit("energy", unit);
    f.width = width;
    f.height = height;
    const char* names[7] = {"kinetic", "strain", "plastic dissipation", "damping", "contact", "external work", "ground motion work"};
    const Rgb colours[7] = {{31, 78, 153}, {44, 160, 44}, {214, 39, 40}, {148, 103, 189}, {23, 190, 207}, {105, 105, 105}, {255, 127, 14}};
    std::vector<double> time;
    for (const CurvePoint& c : run.curve) time.push_back(c.time);
    for (std::size_t k = 0; k < 7; ++k) {
        std::vector<double> values;
        bool any = false;
        for (const CurvePoint& c : run.curve) values.push_back(c.energy[k]), any = any || c.energy[k] != 0.0;
        if (any) f.series.push_back({names[k], time, values, colours[k], 2.0f});
    }
    f.legend = true;
    return draw_chart(f);
}

} // namespace plastica::render
