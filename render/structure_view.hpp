// The drawing of the structure in one viewport: the deformed shape as a ribbon coloured by a
// field (fixed range over the run, labelled colour bar), the initial shape faint behind it, the
// rigid base with hatching and any spring anchors, contact-force arrows, plastic-hinge markers at
// element ends, and a legend of exactly the layers the run needs. The camera is fixed from the
// bounds of the whole motion, so frames do not jump, with true aspect ratio.
#pragma once

#include "flat_marks.hpp"
#include "series_summary.hpp"

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkActor;
class vtkGeometryFilter;
class vtkLookupTable;
class vtkPolyData;
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

// Layers a user may leave out (`--hide`); those a scene does not need are left out anyway.
struct Layers {
    bool initial_shape = true, hinges = true, contact = true;
};

class StructureView {
public:
    // first_step gives the initial shape; base may be null.
    StructureView(const SeriesSummary& summary, vtkUnstructuredGrid* first_step, vtkPolyData* base,
                  const Viewport& viewport, double text_scale, const Layers& layers = {});
    ~StructureView();

    vtkRenderer* renderer() { return renderer_; }
    void show(vtkUnstructuredGrid* step);

private:
    void fix_camera();
    void add_initial_shape(vtkUnstructuredGrid* first_step);
    void add_with_mirror(vtkActor* actor); // and its mirror image for a half model
    void add_base(vtkPolyData* base);
    void add_colour_bar(double text_scale);
    void add_legend(double text_scale, const Layers& layers);
    void draw_contact_forces(vtkUnstructuredGrid* step);
    void draw_hinges(vtkUnstructuredGrid* step);
    double pixels(double n) const { return n * world_per_pixel_; }

    const SeriesSummary& summary_;
    Viewport viewport_;
    bool show_hinges_, show_contact_;
    vtkNew<vtkRenderer> renderer_;
    vtkNew<vtkLookupTable> colours_;
    vtkNew<vtkGeometryFilter> geometry_;
    vtkNew<vtkRibbonFilter> ribbon_, outline_;
    vtkNew<vtkScalarBarActor> colour_bar_;
    FlatMarks base_{-3.0}, anchors_{2.5}, contact_{3.0}, hinge_under_{4.0}, hinge_{5.0}, hinge_failed_{6.0};
    FlatMarks legend_marks_{0.0, true};
    std::vector<vtkSmartPointer<vtkTextActor>> notes_;
    double view_[4] = {0, 0, 0, 0};   // world rectangle shown: x min, x max, y min, y max
    double world_per_pixel_ = 1.0;
    double ribbon_width_ = 1.0;
    double arrow_scale_ = 0.0;        // world length per unit contact force
    bool has_base_ = false;     // a rigid base line
    bool has_anchors_ = false;  // bilateral spring anchors
};

// "bending_moment" → "bending moment".
std::string readable(std::string name);

} // namespace plastica::render
