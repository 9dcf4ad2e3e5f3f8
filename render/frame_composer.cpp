#include "frame_composer.hpp"
#include "figure_text.hpp"
#include "layer_list.hpp"
#include "text_and_mirror.hpp"

#include <vtkImageData.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace plastica::render {

namespace {

// " kN" after a value, or nothing.
std::string unit_after(const std::string& unit) { return unit.empty() ? "" : " " + unit; }

} // namespace

FrameComposer::FrameComposer(const SeriesSummary& summary, vtkUnstructuredGrid* first_step, vtkPolyData* base, int width, int height,
                             const LayerChoice& layers, double text_boost)
    : summary_(summary), window_(width, height),
      chart_(chart_x_title(summary), chart_y_title(summary),
             text_boost * text_scale(width, height)) {
    const double s = text_boost * text_scale(width, height);
    auto structure_layers = make_layers(summary, first_step, base, layers);
    double box[4], size;
    StructureView::view_box(summary, structure_layers, box, size);
    const FrameLayout layout = choose_frame_layout(box[1] - box[0], box[3] - box[2], width, height);
    structure_ = std::make_unique<StructureView>(summary, std::move(structure_layers), layout, s);

    title_band_->SetViewport(0.0, 1.0 - band, 1.0, 1.0);
    title_band_->SetBackground(colour::title_band.red(), colour::title_band.green(), colour::title_band.blue());
    title_->SetInput(scene_heading(summary).c_str());
    style(title_, 22 * s, true);
    title_->SetPosition(16 * s, 0.11 * height * 0.52);
    status_->SetPosition(16 * s, 0.11 * height * 0.14);
    style(status_, 17 * s, false);
    title_band_->AddViewProp(title_);
    title_band_->AddViewProp(status_);

    chart_area_->SetViewport(layout.chart[0], layout.chart[1], layout.chart[2], layout.chart[3]);
    chart_area_->SetBackground(1, 1, 1);
    const auto xs = chart_x(summary, summary.curve.size());
    const auto ys = chart_y(summary, summary.curve.size());
    chart_.add({"", xs, ys, colour::curve_full, 2.0f});
    progress_line_ = chart_.add({"", {}, {}, colour::curve_progress, 3.0f});
    current_point_ = chart_.add({"", {}, {}, colour::current_point, 11.0f, true});
    double x0, x1, y0, y1;
    padded_range(xs, x0, x1);
    padded_range(ys, y0, y1);
    if (!summary.in_time && summary.load_axis_cut[1] > summary.load_axis_cut[0]) y0 = summary.load_axis_cut[0], y1 = summary.load_axis_cut[1];
    chart_.set_ranges(x0, x1, y0, y1);
    chart_.place_in(chart_area_);

    window_.add(title_band_);
    window_.add(structure_->renderer());
    if (vtkRenderer* legend = structure_->legend_renderer()) window_.add(legend);
    window_.add(chart_area_);
}

FrameComposer::~FrameComposer() = default;

vtkSmartPointer<vtkImageData> FrameComposer::draw(vtkUnstructuredGrid* step, std::size_t index) {
    const CurvePoint& c = summary_.curve.at(index);
    // In time, the time leads and the load (gravity held) is left out.
    const std::string status = "step " + std::to_string(c.step) + " of " + std::to_string(summary_.curve.back().step) +
                               (summary_.in_time ? "      t = " + number(c.time) + " s"
                                                 : "      " + summary_.load_label + " = " + number(c.load) + unit_after(summary_.load_unit)) +
                               "      " + summary_.displacement_label + " = " + number(c.displacement) +
                               unit_after(summary_.displacement_unit);
    status_->SetInput(status.c_str());
    structure_->show(step);
    // A line needs two points; the first step is the marker alone.
    const std::size_t shown = index == 0 ? 0 : index + 1;
    chart_.replace(progress_line_, chart_x(summary_, shown), chart_y(summary_, shown));
    if (summary_.in_time) chart_.replace(current_point_, {c.time}, {c.displacement});
    else chart_.replace(current_point_, {c.displacement}, {c.load});
    return window_.capture();
}

} // namespace plastica::render
