#include "structure_view.hpp"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkColorTransferFunction.h>
#include <vtkDataArray.h>
#include <vtkGeometryFilter.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkRibbonFilter.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace plastica::render {

namespace {

// Share of the viewport width kept free on the right for the colour bar and the legend.
constexpr double side_column = 0.25;

void style_text(vtkTextProperty* p, double size, bool bold = false) {
    p->SetFontFamilyToArial();
    p->SetFontSize(static_cast<int>(std::lround(size)));
    p->SetColor(colour::text.red(), colour::text.green(), colour::text.blue());
    p->SetBold(bold);
    p->SetShadow(false);
}

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

vtkSmartPointer<vtkActor> ribbon_actor(vtkRibbonFilter* ribbon, double z) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(ribbon->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->LightingOff();
    actor->SetPosition(0, 0, z);
    return actor;
}

void set_ribbon(vtkRibbonFilter* ribbon, double width) {
    ribbon->SetWidth(width / 2); // VTK's width is the half width
    ribbon->UseDefaultNormalOn();
    ribbon->SetDefaultNormal(0, 0, 1); // the ribbon lies in the drawing plane
    ribbon->VaryWidthOff();
}

} // namespace

std::string readable(std::string name) {
    std::replace(name.begin(), name.end(), '_', ' ');
    return name;
}

StructureView::StructureView(const SeriesSummary& summary, vtkUnstructuredGrid* first_step, vtkPolyData* base,
                             const Viewport& viewport, double text_scale, const Layers& layers)
    : summary_(summary), viewport_(viewport), show_hinges_(summary.inelastic && layers.hinges),
      show_contact_(summary.any_contact && layers.contact) {
    renderer_->SetViewport(viewport.x0, viewport.y0, viewport.x1, viewport.y1);
    renderer_->SetBackground(colour::background.red(), colour::background.green(), colour::background.blue());
    has_base_ = base && base->GetNumberOfLines() > 0;
    has_anchors_ = base && base->GetNumberOfVerts() > 0;
    fix_camera();

    // The field's colours: cool–warm, centred on zero when the values change sign.
    double lo = summary.field_range[0], hi = summary.field_range[1];
    if (lo < 0 && hi > 0) hi = std::max(-lo, hi), lo = -hi;
    if (hi - lo <= 1e-300 * (1 + std::abs(hi))) lo -= 1, hi += 1;
    vtkNew<vtkColorTransferFunction> map;
    map->SetColorSpaceToDiverging();
    map->AddRGBPoint(0.0, 0.230, 0.299, 0.754);
    map->AddRGBPoint(1.0, 0.706, 0.016, 0.150);
    colours_->SetNumberOfTableValues(256);
    for (int i = 0; i < 256; ++i) {
        double rgb[3];
        map->GetColor(i / 255.0, rgb);
        colours_->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
    }
    colours_->SetRange(lo, hi);
    if (summary.field.components > 1) colours_->SetVectorModeToMagnitude();

    set_ribbon(ribbon_, ribbon_width_);
    set_ribbon(outline_, ribbon_width_ + pixels(3));
    ribbon_->SetInputConnection(geometry_->GetOutputPort());
    outline_->SetInputConnection(geometry_->GetOutputPort());
    auto shape = ribbon_actor(ribbon_, 0.0);
    auto* mapper = static_cast<vtkPolyDataMapper*>(shape->GetMapper());
    mapper->SetLookupTable(colours_);
    mapper->UseLookupTableScalarRangeOn();
    mapper->SetScalarModeToUsePointFieldData();
    if (summary.field.on_cells) mapper->SetScalarModeToUseCellFieldData();
    mapper->SelectColorArray(summary.field.name.c_str());
    mapper->ScalarVisibilityOn();
    auto outline = ribbon_actor(outline_, -0.5);
    outline->GetMapper()->ScalarVisibilityOff();
    outline->GetProperty()->SetColor(colour::outline.red(), colour::outline.green(), colour::outline.blue());

    if (layers.initial_shape) add_initial_shape(first_step);
    if (has_base_ || has_anchors_) add_base(base);
    add_with_mirror(outline);
    add_with_mirror(shape);
    renderer_->AddViewProp(base_.prop()); // the base line already spans both halves
    for (FlatMarks* m : {&anchors_, &contact_, &hinge_under_, &hinge_, &hinge_failed_})
        add_with_mirror(vtkActor::SafeDownCast(m->prop()));
    add_colour_bar(text_scale);
    add_legend(text_scale, layers);
}

StructureView::~StructureView() = default;

void StructureView::fix_camera() {
    const double* b = summary_.bounds;
    double width = std::max(b[1] - b[0], 1e-9), height = std::max(b[3] - b[2], 1e-9);
    const double size = std::max(width, height);
    ribbon_width_ = 0.012 * size;
    double box[4] = {b[0] - 0.04 * size, b[1] + 0.04 * size, b[2] - 0.04 * size, b[3] + 0.04 * size};
    // Room under the base for the contact arrows (their tips touch the structure) and hatching.
    if (show_contact_ && summary_.max_contact_force > 0) {
        arrow_scale_ = 0.14 * size / summary_.max_contact_force;
        box[2] -= 0.14 * size;
    }
    if (has_base_) box[2] -= 0.05 * size;
    width = box[1] - box[0];
    height = box[3] - box[2];
    // The structure gets the viewport minus the side column, at true aspect ratio.
    const double usable_w = viewport_.width_px * (1.0 - side_column), usable_h = viewport_.height_px;
    world_per_pixel_ = std::max(width / usable_w, height / usable_h);
    const double cx = 0.5 * (box[0] + box[1]), cy = 0.5 * (box[2] + box[3]);
    view_[0] = cx - 0.5 * usable_w * world_per_pixel_;
    view_[1] = view_[0] + viewport_.width_px * world_per_pixel_;
    view_[2] = cy - 0.5 * usable_h * world_per_pixel_;
    view_[3] = cy + 0.5 * usable_h * world_per_pixel_;
    vtkCamera* camera = renderer_->GetActiveCamera();
    camera->ParallelProjectionOn();
    const double fx = 0.5 * (view_[0] + view_[1]), fy = 0.5 * (view_[2] + view_[3]);
    camera->SetFocalPoint(fx, fy, 0);
    camera->SetPosition(fx, fy, 10 * size);
    camera->SetViewUp(0, 1, 0);
    camera->SetParallelScale(0.5 * (view_[3] - view_[2]));
    camera->SetClippingRange(size, 20 * size);
}

void StructureView::add_initial_shape(vtkUnstructuredGrid* first_step) {
    vtkNew<vtkPolyData> initial;
    vtkNew<vtkPoints> points;
    vtkDataArray* positions = first_step->GetPointData()->GetArray("initial_position");
    points->SetNumberOfPoints(first_step->GetNumberOfPoints());
    for (vtkIdType i = 0; i < first_step->GetNumberOfPoints(); ++i) points->SetPoint(i, positions->GetTuple3(i));
    vtkNew<vtkCellArray> lines;
    for (vtkIdType c = 0; c < first_step->GetNumberOfCells(); ++c) {
        vtkIdType n;
        const vtkIdType* ids;
        first_step->GetCellPoints(c, n, ids);
        lines->InsertNextCell(n, ids);
    }
    initial->SetPoints(points);
    initial->SetLines(lines);
    vtkNew<vtkRibbonFilter> ribbon;
    ribbon->SetInputData(initial);
    set_ribbon(ribbon, 0.6 * ribbon_width_);
    auto actor = ribbon_actor(ribbon, -2.0);
    actor->GetProperty()->SetColor(colour::initial_shape.red(), colour::initial_shape.green(), colour::initial_shape.blue());
    add_with_mirror(actor);
}

void StructureView::add_with_mirror(vtkActor* actor) {
    renderer_->AddActor(actor);
    if (!summary_.mirrored) return;
    // The same data drawn reflected about x = mirror_x: x → 2·mirror_x − x.
    vtkNew<vtkTransform> reflect;
    reflect->Translate(summary_.mirror_x, 0, 0);
    reflect->Scale(-1, 1, 1);
    reflect->Translate(-summary_.mirror_x, 0, 0);
    vtkNew<vtkActor> twin;
    twin->ShallowCopy(actor);
    twin->SetUserTransform(reflect);
    renderer_->AddActor(twin);
}

void StructureView::add_base(vtkPolyData* base) {
    vtkDataArray* kind = base->GetCellData()->GetArray("kind");
    vtkCellArray* lines = base->GetLines();
    lines->InitTraversal();
    vtkIdType n;
    const vtkIdType* ids;
    const double cx = 0.5 * (summary_.bounds[0] + summary_.bounds[1]);
    const double cy = 0.5 * (summary_.bounds[2] + summary_.bounds[3]);
    const vtkIdType first_line = base->GetNumberOfVerts();
    for (vtkIdType c = 0; lines->GetNextCell(n, ids); ++c) {
        if (n < 2 || (kind && kind->GetComponent(first_line + c, 0) != 1)) continue;
        double a[3], b[3];
        base->GetPoint(ids[0], a);
        base->GetPoint(ids[n - 1], b);
        const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
        const double tx = (b[0] - a[0]) / length, ty = (b[1] - a[1]) / length;
        double nx = -ty, ny = tx;
        if ((cx - a[0]) * nx + (cy - a[1]) * ny < 0) nx = -nx, ny = -ny;
        // Only the part left of the legend column is drawn, so the legend stays clear.
        const double right = view_[0] + (1.0 - side_column) * (view_[1] - view_[0]);
        double s0 = 0.0, s1 = length;
        if (std::abs(tx) > 1e-12) {
            const double sa = (view_[0] - a[0]) / tx, sb = (right - a[0]) / tx;
            s0 = std::max(s0, std::min(sa, sb));
            s1 = std::min(s1, std::max(sa, sb));
        }
        if (s1 <= s0) continue;
        const double from[2] = {a[0] + s0 * tx, a[1] + s0 * ty}, to[2] = {a[0] + s1 * tx, a[1] + s1 * ty};
        base_.bar(from, to, pixels(3), colour::base);
        // Hatching on the far side, every 14 pixels.
        const double step = pixels(14), tick = pixels(12);
        for (double s = s0 + 0.5 * step; s <= s1; s += step) {
            const double p[2] = {a[0] + s * tx, a[1] + s * ty};
            if (p[1] < view_[2] - tick || p[1] > view_[3] + tick) continue;
            const double q[2] = {p[0] - tick * (nx + tx) * M_SQRT1_2, p[1] - tick * (ny + ty) * M_SQRT1_2};
            base_.bar(p, q, pixels(1.5), colour::hatching);
        }
    }
    vtkCellArray* verts = base->GetVerts();
    verts->InitTraversal();
    while (verts->GetNextCell(n, ids)) {
        double p[3];
        base->GetPoint(ids[0], p);
        anchors_.disc(p[0], p[1], pixels(4), colour::spring_anchor);
    }
}

void StructureView::add_colour_bar(double text_scale) {
    colour_bar_->SetLookupTable(colours_);
    colour_bar_->SetTitle(readable(summary_.field.name).c_str());
    colour_bar_->SetNumberOfLabels(5);
    colour_bar_->SetLabelFormat("%-#8.3g");
    colour_bar_->SetOrientationToVertical();
    colour_bar_->UnconstrainedFontSizeOn();
    colour_bar_->SetBarRatio(0.22);
    colour_bar_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    colour_bar_->GetPositionCoordinate()->SetValue(1.0 - side_column + 0.03, 0.50);
    colour_bar_->SetWidth(side_column - 0.05);
    colour_bar_->SetHeight(0.45);
    colour_bar_->SetTextPositionToPrecedeScalarBar();
    colour_bar_->SetTextPositionToSucceedScalarBar();
    style_text(colour_bar_->GetTitleTextProperty(), 15 * text_scale, true);
    style_text(colour_bar_->GetLabelTextProperty(), 13 * text_scale);
    colour_bar_->GetTitleTextProperty()->SetJustificationToLeft();
    renderer_->AddViewProp(colour_bar_);
}

void StructureView::add_legend(double text_scale, const Layers& layers) {
    struct Entry { Rgb colour; double radius; bool cross; bool arrow; std::string text; bool outlined = false; };
    std::vector<Entry> entries;
    if (layers.initial_shape) entries.push_back({colour::initial_shape, 0, false, false, "initial shape"});
    if (has_anchors_) entries.push_back({colour::spring_anchor, 4, false, false, "spring anchor"});
    if (show_hinges_ && summary_.any_yielding)
        entries.push_back({colour::hinge_yielding_high, 5, false, false, "yielding end"});
    if (show_hinges_ && summary_.any_plastic)
        entries.push_back({colour::hinge_plastic, 6, false, false, "fully plastic end", true});
    if (show_hinges_ && summary_.any_failed)
        entries.push_back({colour::hinge_failed, 6, true, false, "failed fibres"});
    if (show_contact_)
        entries.push_back({colour::contact_force, 0, false, true, "contact force"});
    const double s = text_scale;
    const double x = viewport_.width_px * (1.0 - side_column + 0.03);
    double y = viewport_.height_px * 0.42;
    for (const Entry& e : entries) {
        const double cx = x + 10 * s, cy = y;
        if (e.arrow) {
            const double tail[2] = {cx, cy - 9 * s}, tip[2] = {cx, cy + 9 * s};
            legend_marks_.arrow(tail, tip, 3 * s, e.colour);
        } else if (e.cross) {
            legend_marks_.cross(cx, cy, 11 * s, 2.5 * s, e.colour);
        } else if (e.radius > 0) {
            // Overlay polygons share one depth and the depth test keeps the first one drawn,
            // so the marker goes before its outline.
            legend_marks_.disc(cx, cy, e.radius * s, e.colour);
            if (e.outlined) legend_marks_.disc(cx, cy, (e.radius + 1.5) * s, colour::outline);
        } else {
            const double a[2] = {cx - 9 * s, cy}, b[2] = {cx + 9 * s, cy};
            legend_marks_.bar(a, b, 5 * s, e.colour);
        }
        auto text = vtkSmartPointer<vtkTextActor>::New();
        text->SetInput(e.text.c_str());
        style_text(text->GetTextProperty(), 13 * s);
        text->GetTextProperty()->SetVerticalJustificationToCentered();
        text->SetPosition(x + 26 * s, y);
        notes_.push_back(text);
        y -= 26 * s;
    }
    if (summary_.mirrored) {
        auto note = vtkSmartPointer<vtkTextActor>::New();
        note->SetInput(("half model, drawn mirrored\nabout x = " + format("%g", summary_.mirror_x)).c_str());
        style_text(note->GetTextProperty(), 12 * s);
        note->GetTextProperty()->SetVerticalJustificationToTop();
        note->SetPosition(x, viewport_.height_px * 0.06 + 12 * s);
        notes_.push_back(note);
    }
    if (show_contact_) {
        auto note = vtkSmartPointer<vtkTextActor>::New();
        const std::string text = "longest arrow: " + format("%.4g", summary_.max_contact_force) + "\n(largest in the run)";
        note->SetInput(text.c_str());
        style_text(note->GetTextProperty(), 12 * s);
        note->GetTextProperty()->SetVerticalJustificationToTop();
        note->SetPosition(x + 26 * s, y + 8 * s);
        notes_.push_back(note);
    }
    renderer_->AddViewProp(legend_marks_.prop());
    for (auto& n : notes_) renderer_->AddViewProp(n);
}

void StructureView::show(vtkUnstructuredGrid* step) {
    geometry_->SetInputData(step);
    draw_contact_forces(step);
    draw_hinges(step);
}

void StructureView::draw_contact_forces(vtkUnstructuredGrid* step) {
    contact_.clear();
    if (!show_contact_) return;
    vtkDataArray* force = step->GetPointData()->GetArray("contact_force");
    vtkDataArray* state = step->GetPointData()->GetArray("contact");
    if (!force) return;
    for (vtkIdType i = 0; i < step->GetNumberOfPoints(); ++i) {
        if (state && state->GetComponent(i, 0) <= 0) continue;
        const double fx = force->GetComponent(i, 0), fy = force->GetComponent(i, 1);
        const double magnitude = std::hypot(fx, fy);
        if (magnitude <= 0) continue;
        double p[3];
        step->GetPoint(i, p);
        const double length = arrow_scale_ * magnitude;
        const double tip[2] = {p[0] - 0.5 * ribbon_width_ * fx / magnitude, p[1] - 0.5 * ribbon_width_ * fy / magnitude};
        const double tail[2] = {tip[0] - length * fx / magnitude, tip[1] - length * fy / magnitude};
        contact_.arrow(tail, tip, pixels(3.5), colour::contact_force);
    }
}

void StructureView::draw_hinges(vtkUnstructuredGrid* step) {
    hinge_.clear();
    hinge_under_.clear();
    hinge_failed_.clear();
    if (!show_hinges_) return;
    vtkDataArray* states[2] = {step->GetCellData()->GetArray("hinge_state_i"), step->GetCellData()->GetArray("hinge_state_j")};
    vtkDataArray* use[2] = {step->GetCellData()->GetArray("utilisation_i"), step->GetCellData()->GetArray("utilisation_j")};
    if (!states[0] || !states[1] || !use[0] || !use[1]) return;
    const double r = pixels(4.5);
    for (vtkIdType c = 0; c < step->GetNumberOfCells(); ++c) {
        vtkIdType n;
        const vtkIdType* ids;
        step->GetCellPoints(c, n, ids);
        if (n != 2) continue;
        double a[3], b[3];
        step->GetPoint(ids[0], a);
        step->GetPoint(ids[1], b);
        for (int end = 0; end < 2; ++end) {
            const int state = static_cast<int>(states[end]->GetComponent(c, 0));
            if (state == 0) continue;
            const double u = std::clamp(use[end]->GetComponent(c, 0), 0.0, 1.0);
            // A quarter of the element in from its end, so the two ends meeting at a node stay apart.
            const double* from = end == 0 ? a : b;
            const double* to = end == 0 ? b : a;
            const double x = from[0] + 0.25 * (to[0] - from[0]), y = from[1] + 0.25 * (to[1] - from[1]);
            if (state == 1) {
                hinge_.disc(x, y, r * (0.5 + 0.6 * u), mix(colour::hinge_yielding_low, colour::hinge_yielding_high, u));
            } else {
                hinge_under_.disc(x, y, 1.55 * r, colour::outline);
                hinge_.disc(x, y, 1.3 * r, colour::hinge_plastic);
                if (state == 3) hinge_failed_.cross(x, y, 2.2 * r, pixels(2), colour::hinge_failed);
            }
        }
    }
}

} // namespace plastica::render
