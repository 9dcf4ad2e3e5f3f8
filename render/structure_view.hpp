// The drawing of the structure in one viewport: the deformed shape as a ribbon coloured by a
// field (fixed range over the run, labelled colour bar), then the layers the series needs (its
// initial shape, the base, contact forces, plastic hinges, supports, loads; layer_list.hpp) and
// a legend of exactly those layers. The camera is fixed from the bounds of the whole motion and
// the room the layers ask for, so frames do not jump, with true aspect ratio.
#pragma once

#include "flat_marks.hpp"
#include "layer.hpp"
#include "series_summary.hpp"

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <memory>
#include <string>
#include <vector>

class vtkActor;
class vtkGeometryFilter;
class vtkLookupTable;
class vtkRenderer;
class vtkRibbonFilter;
class vtkScalarBarActor;
class vtkTextActor;
class vtkUnstructuredGrid;

namespace plastica::render {

struct Viewport {
    double x0, y0, x1, y1; // normalised window coordinates
    int width_px, height_px;
};

class StructureView {
public:
    StructureView(const SeriesSummary& summary, std::vector<std::unique_ptr<Layer>> layers, const Viewport& viewport,
                  double text_scale);
    ~StructureView();

    vtkRenderer* renderer() { return renderer_; }
    void show(vtkUnstructuredGrid* step);

private:
    ViewGeometry fix_camera();
    void add_with_mirror(vtkProp* prop, bool mirror); // and its mirror image for a half model
    void add_colour_bar(double text_scale);
    void add_legend(double text_scale);
    // Lays the legend's marks and text out at a text scale; returns how far down it reached.
    double lay_out_legend(double text_scale);

    const SeriesSummary& summary_;
    std::vector<std::unique_ptr<Layer>> layers_;
    Viewport viewport_;
    vtkNew<vtkRenderer> renderer_;
    vtkNew<vtkLookupTable> colours_;
    vtkNew<vtkGeometryFilter> geometry_;
    vtkNew<vtkRibbonFilter> ribbon_, outline_;
    vtkNew<vtkScalarBarActor> colour_bar_;
    FlatMarks legend_marks_{0.0, true};
    std::vector<vtkSmartPointer<vtkTextActor>> notes_;
};

// "bending_moment" → "bending moment".
std::string readable(std::string name);

} // namespace plastica::render
