// How long a force's arrow is drawn, and the values written beside arrows not drawn to scale.
// Arrows of one kind are in proportion to the force up to a reference (the longest drawn), but
// never shorter than a share of it, so that a load far smaller than the largest still shows,
// and never longer than it, so that a spike (a penalty taking over the load) does not shrink
// every other arrow to a stub. An arrow off its scale carries its value.
#pragma once

#include "layer.hpp"
#include "palette.hpp"

#include <vtkSmartPointer.h>

#include <array>
#include <string>
#include <vector>

class vtkTextActor;

namespace plastica::render {

struct ArrowScale {
    double reference = 0.0; // the force drawn at full length
    double full_length = 0.0; // world length of the longest arrow
    double shortest = 0.3;  // the shortest arrow, as a share of the longest

    bool to_scale(double force) const { return force >= shortest * reference && force <= reference; }
    double length(double force) const;
};

// A value as written beside an arrow or in a legend: "12.5 kN", or "12.5" without a unit.
std::string force_text(double value, const std::string& unit);

// The note under an arrow layer's legend entry: the longest arrow's force, with its unit.
std::string longest_arrow_note(double largest, const std::string& unit);

// Values written beside arrows, in world coordinates, the text actors kept from frame to frame.
class ArrowLabels {
public:
    void attach(const ViewGeometry& view, const AddProp& add, Rgb colour);
    void clear();
    // A value at the tail of an arrow pointing along (dx, dy); a value already written in this
    // frame is not written again (a line load's equal nodal forces), nor one that would cover
    // another, and at most six are. Values stay inside the drawing's sides.
    // With every_time, the value is written even where it was already (each loaded member's own).
    void add(const double tail[2], double dx, double dy, const std::string& text, bool every_time = false);

private:
    ViewGeometry view_;
    AddProp add_;
    Rgb colour_{0, 0, 0};
    std::vector<vtkSmartPointer<vtkTextActor>> actors_;
    std::vector<std::string> written_;
    std::vector<std::array<double, 4>> boxes_; // the written values' world boxes: x0, x1, y0, y1
    std::size_t used_ = 0;
};

} // namespace plastica::render
