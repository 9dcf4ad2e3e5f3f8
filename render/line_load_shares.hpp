// Line loads ([[distributed_load]] wx, wy) reach the analysis as nodal loads, half of each
// element's to each of its ends; the step's `applied_load` holds them with the point loads.
// Drawn as loads along the members (layers/line_load_layer.cpp), they leave the nodal arrows:
// these are the shares to take off each node's applied load.
#pragma once

#include <vector>

class vtkUnstructuredGrid;

namespace plastica::render {

// fx, fy per point: Σ over the point's elements of line_load · L0/2 (L0 from initial_position);
// empty where the step has no line loads.
std::vector<double> line_load_shares(vtkUnstructuredGrid* step);

} // namespace plastica::render
