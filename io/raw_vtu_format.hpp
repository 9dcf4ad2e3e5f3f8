// A lean serialiser of the VTK XML UnstructuredGrid format (version 0.1 as VTK 9.1 writes it, appended raw data,
// UInt64 block headers, no compression): the same file VTK's writer produces without
// compression, written in one pass over the arrays. VTK's writer spends most of a step in range
// computations and per-array bookkeeping; this writes the ring's 18 kB step in tens of µs.
// Reads back through VTK's own XML readers (tests/test_vtu_series.cpp).
#pragma once

#include <string>

class vtkUnstructuredGrid;

namespace plastica {

// The grid's points, line cells, point, cell and field data (Float64, Int32 and String arrays).
std::string raw_vtu(vtkUnstructuredGrid* grid);

} // namespace plastica
