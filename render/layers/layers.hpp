// The layers of the structure view, one file each (see layer.hpp). Each file gives its layer's
// kind: its name for --hide and --show, and the maker that draws it where a series needs it;
// render/layer_list.cpp lists the kinds in drawing order (one line each).
#pragma once

#include "layer.hpp"
#include "series_summary.hpp"

#include <vtkType.h>

#include <functional>
#include <memory>

class vtkPolyData;
class vtkUnstructuredGrid;

namespace plastica::render {

// The deformed end points of a step's element c; false for a cell that is not a two-node member.
bool member_ends(vtkUnstructuredGrid* step, vtkIdType c, double a[3], double b[3]);
// The point a share t of the way from one end of a member to the other (end 0: from a).
void along_member(const double a[3], const double b[3], int end, double t, double& x, double& y);

struct LayerKind {
    const char* name; // for --hide and --show
    // The layer, or null where the series has nothing of it to draw.
    std::function<std::unique_ptr<Layer>(const SeriesSummary&, vtkUnstructuredGrid* first_step, vtkPolyData* base)> make;
    bool on_request = false; // drawn only when --show names it
};

} // namespace plastica::render
