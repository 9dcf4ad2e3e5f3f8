// The layers a series needs, in drawing order, each only when the scene has what it draws: no
// hinge layer for an elastic scene, no contact arrows without contact, no supports or loads
// where the series has none. `--hide` leaves out layers by name; a few are drawn only on request
// (`--show reactions`).
#pragma once

#include "layer.hpp"
#include "series_summary.hpp"

#include <memory>
#include <string>
#include <vector>

class vtkPolyData;
class vtkUnstructuredGrid;

namespace plastica::render {

// Layers left out (--hide) and layers drawn on request (--show), by name.
struct LayerChoice {
    std::vector<std::string> hide, show;
};

// Throws RenderError for a name that is not a layer's (or, for show, not one drawn on request).
std::vector<std::unique_ptr<Layer>> make_layers(const SeriesSummary& summary, vtkUnstructuredGrid* first_step,
                                                vtkPolyData* base, const LayerChoice& choice);

// What --hide and --show could not do in this series, each saying why: a layer hidden that the
// series would not draw anyway (no hinges in an elastic scene), or one asked for that it has
// nothing for (no reactions). Throws RenderError for a name that is not a layer's, as make_layers.
std::vector<std::string> layer_choice_notes(const SeriesSummary& summary, vtkUnstructuredGrid* first_step,
                                            vtkPolyData* base, const LayerChoice& choice);

// The names --hide takes, in drawing order.
std::vector<std::string> hideable_layers();
// The names --show takes: layers drawn only on request.
std::vector<std::string> on_request_layers();

} // namespace plastica::render
