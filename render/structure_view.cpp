#include "structure_view.hpp"
#include "ribbon.hpp"
#include "text_and_mirror.hpp"

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

#include <sstream>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace plastica::render {

namespace {

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

} // namespace

std::string readable(std::string name) {
    std::replace(name.begin(), name.end(), '_', ' ');
    return name;
}

StructureView::StructureView(const SeriesSummary& summary, std::vector<std::unique_ptr<Layer>> layers,
                             const FrameLayout& layout, double text_scale)
    : summary_(summary), layers_(std::move(layers)), layout_(layout) {
    renderer_->SetViewport(layout_.structure.x0, layout_.structure.y0, layout_.structure.x1, layout_.structure.y1);
    renderer_->SetBackground(colour::background.red(), colour::background.green(), colour::background.blue());
    if (layout_.legend) {
        const Viewport& v = *layout_.legend;
        legend_renderer_->SetViewport(v.x0, v.y0, v.x1, v.y1);
        legend_renderer_->SetBackground(colour::background.red(), colour::background.green(), colour::background.blue());
    }
    ViewGeometry view = fix_camera();
    view.text_scale = text_scale;

    // The field's colours: a signed field on the cool–warm scale with zero at its neutral middle
    // (compression blue, tension red, whatever the run's range); any other from that neutral
    // grey at zero to the warm end.
    double lo = summary.field_range[0], hi = summary.field_range[1];
    if (summary.field.is_signed) {
        hi = std::max(std::abs(lo), std::abs(hi));
        lo = -hi;
    } else {
        lo = std::min(lo, 0.0);
    }
    if (hi - lo <= 1e-300 * (1 + std::abs(hi))) hi = lo + 1;
    vtkNew<vtkColorTransferFunction> map;
    map->SetColorSpaceToDiverging();
    map->AddRGBPoint(0.0, 0.230, 0.299, 0.754);
    map->AddRGBPoint(1.0, 0.706, 0.016, 0.150);
    const double from = summary.field.is_signed || lo < 0 ? 0.0 : 0.5;
    colours_->SetNumberOfTableValues(256);
    for (int i = 0; i < 256; ++i) {
        double rgb[3];
        map->GetColor(from + (1.0 - from) * i / 255.0, rgb);
        colours_->SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0);
    }
    colours_->SetRange(lo, hi);
    if (summary.field.components > 1) colours_->SetVectorModeToMagnitude();

    set_ribbon(ribbon_, view.ribbon_width);
    set_ribbon(outline_, view.ribbon_width + view.pixels(3));
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

    const AddProp add = [this](vtkProp* prop, bool mirror) { add_with_mirror(prop, mirror); };
    for (auto& layer : layers_) layer->attach(view, add);
    add_with_mirror(outline, true);
    add_with_mirror(shape, true);
    add_colour_bar(text_scale);
    add_legend(text_scale);
}

StructureView::~StructureView() = default;

void StructureView::view_box(const SeriesSummary& summary, const std::vector<std::unique_ptr<Layer>>& layers,
                             double box[4], double& size) {
    const double* b = summary.bounds;
    const double width = std::max(b[1] - b[0], 1e-9), height = std::max(b[3] - b[2], 1e-9);
    size = std::max(width, height);
    box[0] = b[0] - 0.04 * size, box[1] = b[1] + 0.04 * size, box[2] = b[2] - 0.04 * size, box[3] = b[3] + 0.04 * size;
    for (auto& layer : layers) layer->reserve(box, size);
}

ViewGeometry StructureView::fix_camera() {
    double box[4], size;
    view_box(summary_, layers_, box, size);
    const double width = box[1] - box[0], height = box[3] - box[2];
    // The structure gets the viewport minus the legend's column (if it has one), at true aspect ratio.
    const double side_column = layout_.legend_column;
    const double usable_w = layout_.structure.width_px * (1.0 - side_column), usable_h = layout_.structure.height_px;
    ViewGeometry view;
    view.world_per_pixel = std::max(width / usable_w, height / usable_h);
    // The ribbon's width follows the structure's size, up to what a structure about as wide as it
    // is tall gets beside the chart (wider drawings would make it a band).
    const double picture_width = layout_.structure.width_px / (layout_.structure.x1 - layout_.structure.x0);
    view.ribbon_width = std::min(0.012 * size, 0.005 * picture_width * view.world_per_pixel);
    view.size = size;
    view.mirrored = summary_.mirrored;
    view.mirror_x = summary_.mirror_x;
    const double cx = 0.5 * (box[0] + box[1]), cy = 0.5 * (box[2] + box[3]);
    view.view[0] = cx - 0.5 * usable_w * view.world_per_pixel;
    view.view[1] = view.view[0] + layout_.structure.width_px * view.world_per_pixel;
    view.view[2] = cy - 0.5 * usable_h * view.world_per_pixel;
    view.view[3] = cy + 0.5 * usable_h * view.world_per_pixel;
    view.drawing_right = view.view[0] + (1.0 - side_column) * (view.view[1] - view.view[0]);
    vtkCamera* camera = renderer_->GetActiveCamera();
    camera->ParallelProjectionOn();
    const double fx = 0.5 * (view.view[0] + view.view[1]), fy = 0.5 * (view.view[2] + view.view[3]);
    camera->SetFocalPoint(fx, fy, 0);
    camera->SetPosition(fx, fy, 10 * size);
    camera->SetViewUp(0, 1, 0);
    camera->SetParallelScale(0.5 * (view.view[3] - view.view[2]));
    camera->SetClippingRange(size, 20 * size);
    return view;
}

void StructureView::add_with_mirror(vtkProp* prop, bool mirror) {
    renderer_->AddViewProp(prop);
    vtkActor* actor = vtkActor::SafeDownCast(prop);
    if (!mirror || !summary_.mirrored || !actor) return;
    renderer_->AddActor(mirrored(actor, summary_.mirror_x));
}

namespace {

// The text broken at spaces into lines no wider than `room` pixels, and then, where one word
// alone is wider, a smaller font: the legend column of a small picture (a contact sheet's tile)
// would otherwise cut its notes off.
std::string fit_width(vtkTextProperty* property, const std::string& text, double room) {
    std::string wrapped, line;
    std::istringstream lines(text);
    for (std::string given; std::getline(lines, given);) {
        std::istringstream words(given);
        line.clear();
        for (std::string word; words >> word;) {
            const std::string longer = line.empty() ? word : line + " " + word;
            if (!line.empty() && text_width(property, longer) > room) {
                wrapped += line + "\n";
                line = word;
            } else {
                line = longer;
            }
        }
        wrapped += line + "\n";
    }
    if (!wrapped.empty()) wrapped.pop_back();
    for (int size = property->GetFontSize(); size > 5 && text_width(property, wrapped) > room; property->SetFontSize(--size)) {
    }
    return wrapped;
}

} // namespace

struct StructureView::LegendColumn {
    vtkRenderer* renderer;
    double width_px, height_px; // of the renderer's viewport
    double bar[4];              // the colour bar: normalised x, y, width and height
    double title_room;          // pixels across for the colour bar's title
    double entries_x, entries_y; // pixels: where the first entry's mark goes
};

StructureView::LegendColumn StructureView::legend_column() const {
    if (!layout_.legend) { // the right-hand column of the structure's viewport
        const double left = 1.0 - layout_.legend_column, w = layout_.structure.width_px, h = layout_.structure.height_px;
        return {renderer_.Get(), w, h, {left + 0.03, 0.50, (1.0 - left) - 0.05, 0.45}, (1.0 - left - 0.03) * w,
                w * (left + 0.03), h * 0.42};
    }
    // A viewport of their own under the structure: the colour bar in its left half, the entries
    // in its right half.
    const double w = layout_.legend->width_px, h = layout_.legend->height_px;
    return {legend_renderer_.Get(), w, h, {0.06, 0.06, 0.4, 0.86}, 0.44 * w, 0.56 * w, 0.88 * h};
}

void StructureView::add_colour_bar(double text_scale) {
    const LegendColumn column = legend_column();
    colour_bar_->SetLookupTable(colours_);
    colour_bar_->SetNumberOfLabels(5);
    colour_bar_->SetLabelFormat("%-8.3g"); // 255, not "255."
    colour_bar_->SetOrientationToVertical();
    colour_bar_->UnconstrainedFontSizeOn();
    colour_bar_->SetBarRatio(0.22);
    colour_bar_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    colour_bar_->GetPositionCoordinate()->SetValue(column.bar[0], column.bar[1]);
    colour_bar_->SetWidth(column.bar[2]);
    colour_bar_->SetHeight(column.bar[3]);
    colour_bar_->SetTextPositionToPrecedeScalarBar();
    colour_bar_->SetTextPositionToSucceedScalarBar();
    style_text(colour_bar_->GetTitleTextProperty(), 15 * text_scale, true);
    style_text(colour_bar_->GetLabelTextProperty(), 13 * text_scale);
    colour_bar_->GetTitleTextProperty()->SetJustificationToLeft();
    // The top label is centred on the bar's end: half a label's height between the title and the
    // bar keeps it off the title.
    colour_bar_->SetVerticalTitleSeparation(static_cast<int>(std::ceil(0.5 * 13 * text_scale)) + 1);
    // The unit on a line of its own, and the name broken where the column is too narrow for it
    // (a contact sheet's tile): the column from the bar's left edge to the picture's.
    const std::string unit = array_unit_or_dimension(summary_, summary_.field.name);
    colour_bar_->SetTitle((fit_width(colour_bar_->GetTitleTextProperty(), readable(summary_.field.name), column.title_room) +
                           (unit.empty() ? "" : "\n(" + unit + ")")).c_str());
    column.renderer->AddViewProp(colour_bar_);
}

void StructureView::add_legend(double text_scale) {
    // Smaller, where the entries of a small picture (a contact sheet's tile) would run off its foot.
    for (double s = text_scale;; s *= 0.9) {
        legend_marks_.clear();
        notes_.clear();
        if (lay_out_legend(s) >= 0.0 || s < 0.75 * text_scale) break;
    }
    vtkRenderer* renderer = legend_column().renderer;
    renderer->AddViewProp(legend_marks_.prop());
    for (auto& n : notes_) renderer->AddViewProp(n);
}

double StructureView::lay_out_legend(double s) {
    const LegendColumn column = legend_column();
    const double x = column.entries_x;
    double y = column.entries_y;
    // Returns the number of lines the text took.
    auto add_text = [&](const std::string& content, double size, double at_x, double at_y, bool top) {
        auto text = vtkSmartPointer<vtkTextActor>::New();
        style_text(text->GetTextProperty(), size);
        if (top) text->GetTextProperty()->SetVerticalJustificationToTop();
        else text->GetTextProperty()->SetVerticalJustificationToCentered();
        const std::string fitted = fit_width(text->GetTextProperty(), content, column.width_px - at_x - 2.0);
        text->SetInput(fitted.c_str());
        text->SetPosition(at_x, at_y);
        notes_.push_back(text);
        return 1 + static_cast<int>(std::count(fitted.begin(), fitted.end(), '\n'));
    };
    for (const auto& layer : layers_) {
        for (const LegendEntry& e : layer->legend()) {
            const double cx = x + 10 * s, cy = y;
            switch (e.mark) {
            case LegendEntry::Mark::arrow: {
                const double tail[2] = {cx, cy - 9 * s}, tip[2] = {cx, cy + 9 * s};
                legend_marks_.arrow(tail, tip, 3 * s, e.colour);
                break;
            }
            case LegendEntry::Mark::cross: legend_marks_.cross(cx, cy, 11 * s, 2.5 * s, e.colour); break;
            case LegendEntry::Mark::disc: legend_marks_.disc(cx, cy, e.size * s, e.colour); break;
            case LegendEntry::Mark::outlined_disc:
                // Overlay polygons share one depth and the depth test keeps the first one drawn,
                // so the marker goes before its outline.
                legend_marks_.disc(cx, cy, e.size * s, e.colour);
                legend_marks_.disc(cx, cy, (e.size + 1.5) * s, colour::outline);
                break;
            case LegendEntry::Mark::triangle: {
                const double xy[6] = {cx, cy + 8 * s, cx - 8 * s, cy - 7 * s, cx + 8 * s, cy - 7 * s};
                legend_marks_.polygon(xy, 3, e.colour);
                break;
            }
            case LegendEntry::Mark::bar: {
                const double a[2] = {cx - 9 * s, cy}, b[2] = {cx + 9 * s, cy};
                legend_marks_.bar(a, b, 5 * s, e.colour);
                break;
            }
            case LegendEntry::Mark::clamp: { // a wall, hatched below, as the view draws a clamp
                const double a[2] = {cx - 10 * s, cy + 4 * s}, b[2] = {cx + 10 * s, cy + 4 * s};
                legend_marks_.bar(a, b, 4 * s, e.colour);
                for (int k = 0; k < 4; ++k) {
                    const double q[2] = {cx - 8 * s + k * 5.5 * s, cy + 2 * s}, r[2] = {q[0] - 5 * s, q[1] - 6 * s};
                    legend_marks_.bar(q, r, 1.5 * s, colour::hatching);
                }
                break;
            }
            case LegendEntry::Mark::roller: {
                const double xy[6] = {cx, cy + 9 * s, cx - 7 * s, cy - 3 * s, cx + 7 * s, cy - 3 * s};
                legend_marks_.polygon(xy, 3, e.colour);
                for (double side : {-3.5, 3.5}) legend_marks_.disc(cx + side * s, cy - 6 * s, 2.8 * s, e.colour);
                break;
            }
            case LegendEntry::Mark::square: {
                const double h = 6 * s;
                const double xy[8] = {cx - h, cy - h, cx + h, cy - h, cx + h, cy + h, cx - h, cy + h};
                legend_marks_.polygon(xy, 4, e.colour);
                break;
            }
            }
            add_text(e.text, 13 * s, x + 26 * s, y, false);
            y -= 26 * s;
        }
        if (const std::string note = layer->note(); !note.empty()) {
            const int lines = add_text(note, 12 * s, x + 26 * s, y + 8 * s, true);
            y -= (14 * lines + 6) * s;
        }
    }
    if (summary_.magnify != 1.0) {
        add_text("displacements × " + format("%g", summary_.magnify), 13 * s, x, y + 8 * s, true);
        y -= 26 * s;
    }
    // Under the entries (at the foot of the view when they are few).
    if (summary_.mirrored) {
        const double top = std::min(y + 4 * s, column.height_px * 0.06 + 24 * s);
        const int lines = add_text("half model,\ndrawn mirrored\nabout x = " + format("%g", summary_.mirror_x), 12 * s, x, top, true);
        y = top - 14 * lines * s;
    }
    return y; // below the last entry: negative when the legend runs off the view
}

void StructureView::show(vtkUnstructuredGrid* step) {
    geometry_->SetInputData(step);
    for (auto& layer : layers_) layer->show(step);
}

} // namespace plastica::render
