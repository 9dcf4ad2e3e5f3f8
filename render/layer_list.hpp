// The layers a series needs, in drawing order, each only when the scene has what it draws: no
// hinge layer for an elastic scene, no contact arrows without contact, no supports or loads
// where the series has none. `--hide` leaves out layers by name.
#pragma once

#include "layer.hpp"
#include "series_summary.hpp"

#include <memory>
#include <string>
#include <vector>

class vtkPolyData;
class vtkUnstructuredGrid;

namespace plastica::render {

// Throws RenderError for a hidden name that is not a layer's.
std::vector<std::unique_ptr<Layer>> make_layers(const SeriesSummary& summary, vtkUnstructuredGrid* first_step,
                                                vtkPolyData* base, const std::vector<std::string>& hidden);

// The names --hide takes, in drawing order.
std::vector<std::string> hideable_layers();

} // namespace plastica::render
