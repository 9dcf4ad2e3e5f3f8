// One frame of the animation: a title band (scene, step, load and displacement), the structure
// view on the left and the load–displacement chart on the right (the whole curve faint, the curve
// so far, the current step marked). The window, the actors and the camera are built once; each
// frame only swaps the step's data in.
#pragma once

#include "layer_list.hpp"

#include "load_chart.hpp"
#include "offscreen_window.hpp"
#include "reference_points.hpp"
#include "series_summary.hpp"
#include "structure_view.hpp"

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <memory>

class vtkImageData;
class vtkPolyData;
class vtkRenderer;
class vtkTextActor;
class vtkUnstructuredGrid;

namespace plastica::render {

class FrameComposer {
public:
    // layers: left out or drawn on request by name (layer_list.hpp); text_boost enlarges text and marks over
    // their size for the picture (small pictures that must stay legible: the contact sheet).
    FrameComposer(const SeriesSummary& summary, vtkUnstructuredGrid* first_step, vtkPolyData* base, int width, int height,
                  const LayerChoice& layers = {}, double text_boost = 1.0);
    ~FrameComposer();

    // Draws step `index` of the summary's curve, whose data is `step`.
    vtkSmartPointer<vtkImageData> draw(vtkUnstructuredGrid* step, std::size_t index);
    const std::string& gl_renderer() const { return window_.gl_renderer(); }

private:
    const SeriesSummary& summary_;
    OffscreenWindow window_;
    vtkNew<vtkRenderer> title_band_, chart_area_;
    vtkNew<vtkTextActor> title_, status_;
    std::unique_ptr<StructureView> structure_;
    LoadChart chart_;
    int progress_line_ = 0, current_point_ = 0;
};

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

// "%.4g" without trailing noise.
std::string number(double value);

} // namespace plastica::render
