// The layers of the structure view, one file each (see layer.hpp); layer_list.cpp decides which
// a series needs.
#pragma once

#include "layer.hpp"
#include "series_summary.hpp"

#include <vtkType.h>

#include <memory>

class vtkPolyData;
class vtkUnstructuredGrid;

namespace plastica::render {

// The deformed end points of a step's element c; false for a cell that is not a two-node member.
bool member_ends(vtkUnstructuredGrid* step, vtkIdType c, double a[3], double b[3]);
// The point a share t of the way from one end of a member to the other (end 0: from a).
void along_member(const double a[3], const double b[3], int end, double t, double& x, double& y);

// The undeformed members, faint behind the deformed ones.
std::unique_ptr<Layer> initial_shape_layer(vtkUnstructuredGrid* first_step);
// The rigid base line with hatching, and the anchors of bilateral springs.
std::unique_ptr<Layer> base_layer(const SeriesSummary& summary, vtkPolyData* base);
// Contact forces of the base as arrows whose tips touch the structure.
std::unique_ptr<Layer> contact_layer(const SeriesSummary& summary);
// Forces between surfaces in contact ([[self_contact]]): arrows from each pressed node along
// the push it takes.
std::unique_ptr<Layer> surface_contact_layer(const SeriesSummary& summary);
// Plastic hinges at element ends: yielding (gold to orange by utilisation), fully plastic,
// failed fibres.
std::unique_ptr<Layer> hinge_layer(const SeriesSummary& summary);
// Open circles at released member ends (scenes with releases).
std::unique_ptr<Layer> release_layer();
// Support symbols at the supported nodes: clamp, pin, roller, guide.
std::unique_ptr<Layer> support_layer(const SeriesSummary& summary, vtkUnstructuredGrid* first_step);
// Applied loads as arrows pointing at their nodes (moments as curved arrows), scaled to the
// largest in the run.
std::unique_ptr<Layer> load_layer(const SeriesSummary& summary);
std::unique_ptr<Layer> reaction_layer(const SeriesSummary& summary); // on request

} // namespace plastica::render
