#include "arrow_scale.hpp"
#include "figure_text.hpp"
#include "text_and_mirror.hpp"

#include <vtkCoordinate.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace plastica::render {

double ArrowScale::length(double force) const {
    if (reference <= 0) return 0.0;
    return full_length * std::clamp(force / reference, shortest, 1.0);
}

void ArrowLabels::attach(const ViewGeometry& view, const AddProp& add, Rgb colour) {
    view_ = view;
    add_ = add;
    colour_ = colour;
}

void ArrowLabels::clear() {
    for (auto& actor : actors_) actor->SetVisibility(false);
    written_.clear();
    boxes_.clear();
    used_ = 0;
}

void ArrowLabels::add(const double tail[2], double dx, double dy, const std::string& text, bool every_time) {
    // A few values tell the scale; more would cover the structure.
    if (written_.size() >= 6 || (!every_time && std::find(written_.begin(), written_.end(), text) != written_.end())) return;
    if (used_ == actors_.size()) {
        auto actor = vtkSmartPointer<vtkTextActor>::New();
        style_text(actor->GetTextProperty(), 12 * view_.text_scale, true);
        actor->GetTextProperty()->SetColor(colour_.red(), colour_.green(), colour_.blue());
        actor->GetPositionCoordinate()->SetCoordinateSystemToWorld();
        actor->SetVisibility(false);
        add_(actor, false);
        actors_.push_back(actor);
    }
    vtkTextActor* actor = actors_[used_];
    // Beyond the tail, on the side the arrow comes from: right-aligned when it comes from the
    // left, above when it comes from below.
    const double norm = std::max(std::hypot(dx, dy), 1e-300);
    const double ux = dx / norm, uy = dy / norm, gap = view_.pixels(4);
    vtkTextProperty* p = actor->GetTextProperty();
    int across = ux > 0.5 ? VTK_TEXT_RIGHT : ux < -0.5 ? VTK_TEXT_LEFT : VTK_TEXT_CENTERED;
    int up = uy > 0.5 ? VTK_TEXT_TOP : uy < -0.5 ? VTK_TEXT_BOTTOM : VTK_TEXT_CENTERED;
    double x = tail[0] - gap * ux, y = tail[1] - gap * uy;
    // A value that would run off the picture's side (a sway load at the frame's edge) sits
    // above its arrow instead, from the tail inward.
    const double width = view_.pixels(text_width(p, text)), height = view_.pixels(14 * view_.text_scale);
    if ((ux > 0.5 && x - width < view_.view[0]) || (ux < -0.5 && x + width > view_.drawing_right)) {
        across = ux > 0.5 ? VTK_TEXT_LEFT : VTK_TEXT_RIGHT;
        up = VTK_TEXT_BOTTOM;
        x = tail[0];
        y = tail[1] + gap;
    }
    // A centred value (over a vertical arrow at the drawing's side) is moved inside it.
    if (across == VTK_TEXT_CENTERED)
        x = std::clamp(x, view_.view[0] + 0.5 * width, std::max(view_.view[0] + 0.5 * width, view_.drawing_right - 0.5 * width));
    const double left = across == VTK_TEXT_RIGHT ? x - width : across == VTK_TEXT_LEFT ? x : x - 0.5 * width;
    const double bottom = up == VTK_TEXT_TOP ? y - height : up == VTK_TEXT_BOTTOM ? y : y - 0.5 * height;
    const std::array<double, 4> box{left, left + width, bottom, bottom + height};
    const auto covers = [&box](const std::array<double, 4>& b) {
        return box[0] < b[1] && b[0] < box[1] && box[2] < b[3] && b[2] < box[3];
    };
    if (std::any_of(boxes_.begin(), boxes_.end(), covers)) return;
    written_.push_back(text);
    boxes_.push_back(box);
    ++used_;
    p->SetJustification(across);
    p->SetVerticalJustification(up);
    actor->SetInput(text.c_str());
    actor->SetPosition(x, y);
    actor->SetVisibility(true);
}

std::string force_text(double value, const std::string& unit) { return number(value) + (unit.empty() ? "" : " " + unit); }

std::string longest_arrow_note(double largest, const std::string& unit) {
    char text[64];
    std::snprintf(text, sizeof text, "%.4g", largest);
    return "longest " + std::string(text) + (unit.empty() ? "" : " " + unit);
}

} // namespace plastica::render
