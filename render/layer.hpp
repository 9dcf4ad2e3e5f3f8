// A layer of the structure view: one kind of thing drawn over the structure (its initial shape,
// the base, contact forces, plastic hinges, supports, loads). Each layer says whether a series
// needs it (layer_list.cpp), what room it needs around the motion, draws itself for a step and
// names its legend entries, so the view, the legend and `--hide` read one list of layers.
#pragma once

#include "palette.hpp"

#include <functional>
#include <string>
#include <vector>

class vtkProp;
class vtkUnstructuredGrid;

namespace plastica::render {

// One line of the legend: a mark and its text.
struct LegendEntry {
    enum class Mark { bar, disc, outlined_disc, cross, arrow, triangle, clamp, roller, square };
    Mark mark = Mark::bar;
    Rgb colour{0, 0, 0};
    double size = 0.0; // radius of a disc, in pixels at 1280 × 720
    std::string text;
};

// The view a layer draws into, fixed before any layer draws.
struct ViewGeometry {
    double view[4] = {0, 0, 0, 0};  // world rectangle shown: x min, x max, y min, y max
    double drawing_right = 0.0;     // world x where the legend column begins
    double world_per_pixel = 1.0;
    double ribbon_width = 1.0;      // world width of the structure's ribbon
    double size = 1.0;              // the larger side of the motion's bounds
    bool mirrored = false;          // a half model drawn with its mirror image
    double mirror_x = 0.0;
    double text_scale = 1.0;        // text size over its size in a 1280 × 720 frame
    double pixels(double n) const { return n * world_per_pixel; }
};

// Adds a prop to the view; `mirror` draws it reflected too for a half model.
using AddProp = std::function<void(vtkProp* prop, bool mirror)>;

class Layer {
public:
    virtual ~Layer() = default;
    // Widens box (x min, x max, y min, y max, world) by the room the layer's marks need
    // beyond the motion; `size` is the larger side of the motion's bounds.
    virtual void reserve(double box[4], double size) { (void)box, (void)size; }
    // Builds the layer's props once the view is fixed.
    virtual void attach(const ViewGeometry& view, const AddProp& add) = 0;
    // Redraws the marks that depend on the step.
    virtual void show(vtkUnstructuredGrid* step) { (void)step; }
    virtual std::vector<LegendEntry> legend() const = 0;
    // A remark under the layer's legend entries (the value of the longest arrow), or "".
    virtual std::string note() const { return {}; }
};

} // namespace plastica::render
