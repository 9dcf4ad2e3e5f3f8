#include "render_series.hpp"
#include "reference_points.hpp"
#include "shapes_figure.hpp"
#include "animation.hpp"
#include "contact_sheet.hpp"
#include "charts.hpp"
#include "frame_composer.hpp"
#include "png_file.hpp"
#include "render_error.hpp"
#include "result_series.hpp"
#include "series_summary.hpp"

#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <future>
#include <iostream>

namespace fs = std::filesystem;

namespace plastica::render {

namespace {

std::string frame_name(int step) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06d.png", step);
    return name;
}

// Frames of an earlier render (perhaps of more steps) must not mix with these.
void clear_frames(const fs::path& folder) {
    std::error_code ec;
    if (fs::is_directory(folder, ec))
        for (const auto& entry : fs::directory_iterator(folder))
            if (entry.path().extension() == ".png" && entry.path().filename().string().rfind("frame_", 0) == 0)
                fs::remove(entry.path(), ec);
    fs::create_directories(folder);
}

std::vector<std::size_t> chosen_steps(const SeriesSummary& summary, const RenderOptions& options) {
    std::vector<std::size_t> chosen;
    if (!options.steps.empty()) {
        for (int step : options.steps) {
            const auto at = std::find_if(summary.curve.begin(), summary.curve.end(), [step](const CurvePoint& c) { return c.step == step; });
            if (at == summary.curve.end()) throw RenderError("step " + std::to_string(step) + " is not in the series");
            chosen.push_back(static_cast<std::size_t>(at - summary.curve.begin()));
        }
        std::sort(chosen.begin(), chosen.end());
        chosen.erase(std::unique(chosen.begin(), chosen.end()), chosen.end());
        return chosen;
    }
    const std::size_t count = summary.curve.size();
    const int every = options.every;
    for (std::size_t i = 0; i < count; i += static_cast<std::size_t>(every)) chosen.push_back(i);
    if (chosen.back() != count - 1) chosen.push_back(count - 1);
    return chosen;
}

} // namespace

RenderReport render_series(const std::string& folder_or_pvd, const RenderOptions& options) {
    if (options.width < 64 || options.height < 64 || options.width > 8192 || options.height > 8192)
        throw RenderError("image size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
                          " is outside 64x64 … 8192x8192");
    if (options.every < 1) throw RenderError("--every takes a whole number ≥ 1");
    const ResultSeries series = open_series(folder_or_pvd);
    const SeriesSummary summary = summarise(series, options.field, options.magnify);
    std::vector<SeriesSummary> overlays;
    for (const std::string& other : options.overlays) overlays.push_back(summarise(open_series(other), "displacement"));
    std::vector<ReferencePoints> references;
    for (const std::string& file : options.reference_points) references.push_back(read_reference_points(file));

    RenderReport report;
    report.output = options.output.empty() ? series.folder : options.output;
    const fs::path out(report.output);
    const fs::path frames = out / "frames";

    vtkSmartPointer<vtkPolyData> base;
    if (!series.base_file.empty()) base = read_base(series.base_file);
    auto first = magnified(read_step(series.steps.front().file), summary.magnify);
    FrameComposer composer(summary, first, base, options.width, options.height, {options.hide, options.show});

    const auto steps = chosen_steps(summary, options);
    // The sheet's tiles are drawn at their own size with text a quarter larger, so that a
    // tile's legend stays readable (a shrunken full frame's text is 6 pixels high).
    ContactSheet sheet(steps.size(), 3, 3, 1.0);
    FrameComposer tiles(summary, first, base, options.width / 2, options.height / 2, {options.hide, options.show}, 1.25);
    // Only now, with every option found good, do the earlier pictures go.
    clear_frames(frames);
    const auto t0 = std::chrono::steady_clock::now();
    std::future<void> encoding;
    for (std::size_t k = 0; k < steps.size(); ++k) {
        const std::size_t index = steps[k];
        auto grid = index == 0 ? first : magnified(read_step(series.steps[index].file), summary.magnify);
        vtkSmartPointer<vtkImageData> image = composer.draw(grid, index);
        if (sheet.wants(k)) sheet.keep(k, tiles.draw(grid, index));
        if (encoding.valid()) encoding.get(); // one frame in flight at a time: memory stays flat
        const std::string path = (frames / frame_name(summary.curve[index].step)).string();
        encoding = std::async(std::launch::async, [image, path] { write_png(image, path); });
        if (options.on_frame) options.on_frame(static_cast<int>(k + 1), static_cast<int>(steps.size()));
    }
    if (encoding.valid()) encoding.get();
    report.frames = static_cast<int>(steps.size());
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    report.frames_per_second = report.frames / std::max(report.seconds, 1e-9);
    report.gl_renderer = composer.gl_renderer();

    std::vector<const SeriesSummary*> runs{&summary};
    for (const SeriesSummary& o : overlays) runs.push_back(&o);
    write_png(draw_curve_chart(runs, options.width, options.height, references), (out / "chart.png").string());
    if (!options.shapes.empty()) {
        // This run's shapes, and each overlay's beside them at one scale.
        std::vector<ResultSeries> others;
        for (const std::string& other : options.overlays) others.push_back(open_series(other));
        std::vector<ShapesPanel> panels{{&summary, &series}};
        for (std::size_t k = 0; k < others.size(); ++k) panels.push_back({&overlays[k], &others[k]});
        write_png(draw_shapes(panels, options.shapes, options.width, options.height), (out / "shapes.png").string());
    }
    if (auto image = sheet.compose()) write_png(image, (out / "contact_sheet.png").string());
    if (options.animation) {
        const AnimationResult gif = write_gif(frames.string(), (out / (summary.scene + ".gif")).string());
        report.animation = gif.message;
    } else {
        report.animation = "no animation requested";
    }
    return report;
}

} // namespace plastica::render
