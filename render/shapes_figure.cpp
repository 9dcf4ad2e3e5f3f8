#include "shapes_figure.hpp"

#include "flat_marks.hpp"
#include "figure_text.hpp"
#include "offscreen_window.hpp"
#include "render_error.hpp"
#include "ribbon.hpp"
#include "text_and_mirror.hpp"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkGeometryFilter.h>
#include <vtkImageData.h>
#include <vtkMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkRibbonFilter.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace plastica::render {

namespace {

constexpr double legend = 0.3;  // share of each panel kept for its legend

// The index of the step whose control displacement is nearest d (first crossing).
std::size_t nearest_step(const SeriesSummary& s, double d) {
    for (std::size_t k = 1; k < s.curve.size(); ++k) {
        const double a = s.curve[k - 1].displacement, b = s.curve[k].displacement;
        if ((a - d) * (b - d) <= 0.0) return std::abs(a - d) <= std::abs(b - d) ? k - 1 : k;
    }
    throw RenderError(s.scene + ": the run does not reach " + s.displacement_label + " = " + number(d));
}

// Light to dark along the progress blue.
Rgb shade(std::size_t k, std::size_t count) {
    const double t = count <= 1 ? 1.0 : static_cast<double>(k) / (count - 1);
    return mix(Rgb{160, 190, 230}, Rgb{10, 40, 110}, t);
}

} // namespace

vtkSmartPointer<vtkImageData> draw_shapes(const std::vector<ShapesPanel>& panels, const std::vector<double>& displacements,
                                          int width, int height) {
    if (panels.empty() || displacements.empty()) throw RenderError("--shapes takes displacements, e.g. 25,50,75,100");
    const double s = std::min(height / 720.0, width / 1280.0);
    OffscreenWindow window(width, height);
    vtkNew<vtkRenderer> title_band;
    title_band->SetViewport(0.0, 1.0 - band, 1.0, 1.0);
    title_band->SetBackground(colour::title_band.red(), colour::title_band.green(), colour::title_band.blue());
    vtkNew<vtkTextActor> title;
    const SeriesSummary& main = *panels.front().summary;
    title->SetInput(("Deformed shapes at " + main.displacement_label + " = " + [&] {
                        std::string list;
                        for (double d : displacements) list += (list.empty() ? "" : ", ") + number(d);
                        return list;
                    }()).c_str());
    style(title, 22 * s, true);
    title->SetPosition(16 * s, 0.11 * height * 0.35);
    title_band->AddViewProp(title);
    window.add(title_band);

    // One world scale for every panel: the union of their bounds.
    double b[4] = {1e300, -1e300, 1e300, -1e300};
    for (const ShapesPanel& p : panels) {
        b[0] = std::min(b[0], p.summary->bounds[0]), b[1] = std::max(b[1], p.summary->bounds[1]);
        b[2] = std::min(b[2], p.summary->bounds[2]), b[3] = std::max(b[3], p.summary->bounds[3]);
    }
    const double size = std::max(b[1] - b[0], b[3] - b[2]);
    const double box[4] = {b[0] - 0.05 * size, b[1] + 0.05 * size, b[2] - 0.05 * size, b[3] + 0.05 * size};
    const double panel_w = static_cast<double>(width) / panels.size(), panel_h = (1.0 - band) * height;
    const double drawing_w = panel_w * (1.0 - legend);
    const double world_per_pixel = std::max((box[1] - box[0]) / drawing_w, (box[3] - box[2]) / panel_h);
    const double ribbon = std::max(2.0, 3.5 * s) * world_per_pixel;

    std::vector<vtkSmartPointer<vtkObject>> keep;     // filters outlive the capture
    std::vector<std::unique_ptr<FlatMarks>> legends;  // so do the legends' marks
    for (std::size_t k = 0; k < panels.size(); ++k) {
        const SeriesSummary& summary = *panels[k].summary;
        vtkNew<vtkRenderer> area;
        area->SetViewport(static_cast<double>(k) / panels.size(), 0.0, static_cast<double>(k + 1) / panels.size(), 1.0 - band);
        area->SetBackground(1, 1, 1);
        std::vector<std::size_t> chosen{0};
        for (double d : displacements) chosen.push_back(nearest_step(summary, d));
        legends.push_back(std::make_unique<FlatMarks>(0.0, true));
        FlatMarks& legend_marks = *legends.back();
        double y = panel_h * 0.9;
        auto add_label = [&](const std::string& text, Rgb c, bool heading) {
            auto t = vtkSmartPointer<vtkTextActor>::New();
            t->SetInput(text.c_str());
            style(t, (heading ? 15 : 13) * s, heading);
            t->GetTextProperty()->SetVerticalJustificationToCentered();
            const double x = panel_w * (1.0 - legend) + 8 * s;
            t->SetPosition(x + (heading ? 0 : 26 * s), y);
            area->AddViewProp(t);
            if (!heading) {
                const double a[2] = {x, y}, e[2] = {x + 18 * s, y};
                legend_marks.bar(a, e, 5 * s, c);
            }
            y -= 24 * s;
        };
        // The panel's name over its drawing, the legend's heading names the displacement.
        auto name = vtkSmartPointer<vtkTextActor>::New();
        name->SetInput((summary.title.empty() ? summary.scene : summary.title).c_str());
        style(name, 16 * s, true);
        name->GetTextProperty()->SetVerticalJustificationToTop();
        name->SetPosition(12 * s, panel_h - 10 * s);
        area->AddViewProp(name);
        add_label(summary.displacement_label, colour::text, true);
        for (std::size_t i = 0; i < chosen.size(); ++i) {
            auto grid = magnified(read_step(panels[k].series->steps[chosen[i]].file), summary.magnify);
            auto geometry = vtkSmartPointer<vtkGeometryFilter>::New();
            geometry->SetInputData(grid);
            auto ribbon_filter = vtkSmartPointer<vtkRibbonFilter>::New();
            ribbon_filter->SetInputConnection(geometry->GetOutputPort());
            set_ribbon(ribbon_filter, i == 0 ? 0.6 * ribbon : ribbon);
            auto actor = ribbon_actor(ribbon_filter, static_cast<double>(i));
            const Rgb c = i == 0 ? colour::initial_shape : shade(i - 1, chosen.size() - 1);
            actor->GetMapper()->ScalarVisibilityOff();
            actor->GetProperty()->SetColor(c.red(), c.green(), c.blue());
            area->AddActor(actor);
            if (summary.mirrored) area->AddActor(mirrored(actor, summary.mirror_x));
            keep.push_back(geometry);
            keep.push_back(ribbon_filter);
            const CurvePoint& c_point = summary.curve[chosen[i]];
            add_label(i == 0 ? "unloaded" : number(c_point.displacement) + "   " + summary.load_label + " = " + number(c_point.load), c, false);
        }
        area->AddViewProp(legend_marks.prop());
        // The camera: the common box, centred in the drawing part of this panel.
        const double cx = 0.5 * (box[0] + box[1]), cy = 0.5 * (box[2] + box[3]);
        const double view_w = panel_w * world_per_pixel;
        const double left = cx - 0.5 * drawing_w * world_per_pixel;
        vtkCamera* camera = area->GetActiveCamera();
        camera->ParallelProjectionOn();
        const double fx = left + 0.5 * view_w;
        camera->SetFocalPoint(fx, cy, 0);
        camera->SetPosition(fx, cy, 10 * size);
        camera->SetViewUp(0, 1, 0);
        camera->SetParallelScale(0.5 * panel_h * world_per_pixel);
        camera->SetClippingRange(size, 20 * size);
        window.add(area);
    }
    return window.capture();
}

} // namespace plastica::render
