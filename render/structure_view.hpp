// The drawing of the structure in one viewport: the deformed shape as a ribbon coloured by a
// field (fixed range over the run, labelled colour bar), then the layers the series needs (its
// initial shape, the base, contact forces, plastic hinges, supports, loads; layer_list.hpp) and
// a legend of exactly those layers. The camera is fixed from the bounds of the whole motion and
// the room the layers ask for, so frames do not jump, with true aspect ratio. Where the colour
// bar and the legend go is the frame's layout (frame_layout.hpp).
#pragma once

#include "flat_marks.hpp"
#include "frame_layout.hpp"
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

class StructureView {
public:
    StructureView(const SeriesSummary& summary, std::vector<std::unique_ptr<Layer>> layers, const FrameLayout& layout,
                  double text_scale);
    ~StructureView();

    // The world box (x min, x max, y min, y max) the view must show: the motion's bounds, a
    // margin and the room the layers ask for; `size` is the larger side of the bounds.
    static void view_box(const SeriesSummary& summary, const std::vector<std::unique_ptr<Layer>>& layers, double box[4],
                         double& size);

    vtkRenderer* renderer() { return renderer_; }
    // The colour bar's and the legend's own renderer, or null where they share the structure's.
    vtkRenderer* legend_renderer() { return layout_.legend ? legend_renderer_.Get() : nullptr; }
    void show(vtkUnstructuredGrid* step);

private:
    ViewGeometry fix_camera();
    void add_with_mirror(vtkProp* prop, bool mirror); // and its mirror image for a half model
    void add_colour_bar(double text_scale);
    void add_legend(double text_scale);
    // Lays the legend's marks and text out at a text scale; returns how far down it reached.
    double lay_out_legend(double text_scale);
    // The renderer, its size and the column the colour bar and the legend take in it.
    struct LegendColumn;
    LegendColumn legend_column() const;

    const SeriesSummary& summary_;
    std::vector<std::unique_ptr<Layer>> layers_;
    FrameLayout layout_;
    vtkNew<vtkRenderer> renderer_, legend_renderer_;
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
