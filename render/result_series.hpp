// A result series as the engine wrote it: the PVD's steps (part 0, one VTU each) and
// the optional base file (part 1), read only through VTK's XML parser and readers. Every failure
// names the file and says why: a missing file, a truncated VTU, or a file Plastica did not write.
#pragma once

#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkPolyData;
class vtkUnstructuredGrid;

namespace plastica::render {

struct SeriesStep {
    double time = 0.0;
    std::string file; // path of the VTU
};

struct ResultSeries {
    std::string pvd;    // path of the collection
    std::string folder; // where it lies
    std::vector<SeriesStep> steps;
    std::string base_file; // empty when the scene has no base or springs
};

// Opens OUT_DIR (holding exactly one .pvd) or a .pvd path; throws RenderError.
ResultSeries open_series(const std::string& folder_or_pvd);

// One step, checked to carry what Plastica writes (points, displacement, initial_position, load).
vtkSmartPointer<vtkUnstructuredGrid> read_step(const std::string& file);
vtkSmartPointer<vtkPolyData> read_base(const std::string& file);

// A number or text of a step's field data (throws RenderError naming the array when absent).
double field_value(vtkUnstructuredGrid* grid, const char* name);
std::string field_text(vtkUnstructuredGrid* grid, const char* name, const std::string& fallback = "");

} // namespace plastica::render
