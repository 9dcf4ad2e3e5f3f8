// Deformed configurations at several load levels drawn over each other in one picture, one
// panel per run side by side at one scale (an elastic and an inelastic ring): the second figure of
// Silva et al.'s CS-ASA paper. `plastica render SERIES --shapes d1,d2,… [--overlay OTHER]` writes shapes.png.
#pragma once

#include "series_summary.hpp"

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkImageData;

namespace plastica::render {

struct ShapesPanel {
    const SeriesSummary* summary = nullptr;
    const ResultSeries* series = nullptr;
};

// For each panel, the steps nearest the requested control displacements (and the unloaded
// state), drawn from light to dark. Throws RenderError when a panel's run never reaches a value.
vtkSmartPointer<vtkImageData> draw_shapes(const std::vector<ShapesPanel>& panels, const std::vector<double>& displacements,
                                          int width, int height);

} // namespace plastica::render
