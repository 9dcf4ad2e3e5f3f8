// Charts as pictures of their own (a title band over the chart): any set of series, and the
// load–displacement chart of one or more runs.
#pragma once

#include "load_chart.hpp"
#include "reference_points.hpp"
#include "series_summary.hpp"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkImageData;

namespace plastica::render {

// A chart on its own: a title band over a chart of the given series.
struct ChartFigure {
    std::string title, x_label, y_label;
    std::vector<ChartSeries> series;
    bool legend = false;
    bool axes_through_zero = true; // ranges include the origin
    bool log_scale = false;        // both axes logarithmic (error against time)
    double load_axis_cut[2] = {0.0, 0.0}; // the vertical axis' range, when set (data beyond it is cut)
    int width = 1280, height = 720;
};
vtkSmartPointer<vtkImageData> draw_chart(const ChartFigure& figure);

// The whole load–displacement curve of one or more runs (the first is the main one, its first
// yield and contact spreading marked), with a legend when there is more than one run.
// Reference points (published or measured) are drawn as markers, each set in the legend.
vtkSmartPointer<vtkImageData> draw_curve_chart(const std::vector<const SeriesSummary*>& runs, int width, int height,
                                               const std::vector<ReferencePoints>& references = {});
// A series in time: the supports' horizontal reaction (base shear) against the reported
// displacement, its hysteresis.
vtkSmartPointer<vtkImageData> draw_hysteresis_chart(const SeriesSummary& run, int width, int height);
// A series in time: its energy accounts against time (the terms that are not zero throughout).
vtkSmartPointer<vtkImageData> draw_energy_chart(const SeriesSummary& run, int width, int height);

} // namespace plastica::render
