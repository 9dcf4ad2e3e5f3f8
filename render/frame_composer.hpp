// One frame of the animation: a title band (scene, step, load and displacement), the structure
// view on the left and the load–displacement chart on the right (the whole curve faint, the curve
// so far, the current step marked). The window, the actors and the camera are built once; each
// frame only swaps the step's data in.
#pragma once

#include "layer_list.hpp"

#include "load_chart.hpp"
#include "offscreen_window.hpp"
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

} // namespace plastica::render
