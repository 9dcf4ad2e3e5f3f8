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

// Widens box (x min, x max, y min, y max) by `length` on the sides arrows come from (bits of
// `sides`: 1 left, 2 right, 4 below, 8 above), where their tails lie.
inline void widen_for_arrows(double box[4], int sides, double length) {
    if (sides & 1) box[0] -= length;
    if (sides & 2) box[1] += length;
    if (sides & 4) box[2] -= length;
    if (sides & 8) box[3] += length;
}

struct LayerKind {
    const char* name; // for --hide and --show
    // The layer, or null where the series has nothing of it to draw.
    std::function<std::unique_ptr<Layer>(const SeriesSummary&, vtkUnstructuredGrid* first_step, vtkPolyData* base)> make;
    bool on_request = false; // drawn only when --show names it
};

} // namespace plastica::render
