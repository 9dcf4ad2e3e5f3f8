#include "render_series.hpp"
#include "interruption.hpp"
#include "safe_names.hpp"
#include "reference_points.hpp"
#include "shapes_figure.hpp"
#include "animation.hpp"
#include "contact_sheet.hpp"
#include "charts.hpp"
#include "frame_composer.hpp"
#include "frame_workers.hpp"
#include "layer_list.hpp"
#include "offscreen_context.hpp"
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
#include <cstdlib>
#include <filesystem>
#include <future>
#include <iostream>
#include <memory>

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

// The animation's frame rate (GifWriter's default).
constexpr double frames_per_second = 12.0;

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
    if (summary.in_time && options.every == 1 && count > 1) {
        // Sampled by model time: the step nearest to each frame's time, 12 frames a second.
        const double start = summary.curve.front().time, span = summary.curve.back().time - start;
        const double speed = options.speed > 0.0 ? options.speed : span / 10.0;
        const double spacing = speed / frames_per_second;
        std::size_t i = 0;
        for (double t = start; t <= summary.curve.back().time + 1e-9 * spacing && spacing > 0.0; t += spacing) {
            while (i + 1 < count && std::abs(summary.curve[i + 1].time - t) <= std::abs(summary.curve[i].time - t)) ++i;
            if (chosen.empty() || chosen.back() != i) chosen.push_back(i);
        }
        if (chosen.empty() || chosen.back() != count - 1) chosen.push_back(count - 1);
        return chosen;
    }
    const int every = options.every;
    for (std::size_t i = 0; i < count; i += static_cast<std::size_t>(every)) chosen.push_back(i);
    if (chosen.back() != count - 1) chosen.push_back(count - 1);
    // The steps a report names are drawn whatever --every skips: the first yield, the peak and
    // the first critical point.
    std::size_t peak = 0;
    for (std::size_t i = 0; i < count; ++i)
        if (summary.curve[i].load > summary.curve[peak].load) peak = i;
    const auto yielded = std::find_if(summary.curve.begin(), summary.curve.end(), [](const CurvePoint& c) { return c.hinge_count > 0; });
    const auto critical = std::find_if(summary.curve.begin(), summary.curve.end(), [](const CurvePoint& c) { return c.critical != 0; });
    for (std::size_t key : {peak, static_cast<std::size_t>(yielded - summary.curve.begin()), static_cast<std::size_t>(critical - summary.curve.begin())})
        if (key < count && !std::binary_search(chosen.begin(), chosen.end(), key)) chosen.insert(std::upper_bound(chosen.begin(), chosen.end(), key), key);
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

    // llvmpipe rasterises in the drawing thread itself: its own rasteriser threads only contend
    // with the other drawing processes, and even alone they cost more in hand-offs than they
    // save on frames this simple (measured: 201 frames in one process 3.6 s against 4.3 s).
    setenv("LP_NUM_THREADS", "0", 0);
    RenderReport report;
    report.output = options.output.empty() ? series.folder : options.output;
    report.notes = summary.notes;
    const fs::path out(report.output);
    const fs::path frames = out / "frames";

    vtkSmartPointer<vtkPolyData> base;
    if (!series.base_file.empty()) base = read_base(series.base_file);
    auto first = magnified(read_step(series.steps.front().file), summary.magnify);
    const LayerChoice layers{options.hide, options.show};
    const auto steps = chosen_steps(summary, options);
    auto grid_of = [&](std::size_t index) {
        return index == 0 ? first : magnified(read_step(series.steps[index].file), summary.magnify);
    };
    // Refuses a layer name that is not one, before anything is cleared.
    for (std::string& note : layer_choice_notes(summary, first, base, layers)) report.notes.push_back(std::move(note));
    if (!options.steps.empty() && options.every != 1)
        report.notes.push_back("--every " + std::to_string(options.every) + " changes nothing: --steps names the steps to draw");
    // Only now, with every option found good, do the earlier pictures go.
    clear_frames(frames);
    // The animation's frames, shrunk, go into one file that every drawing process writes to.
    const int shrink = animation_shrink(options.width);
    std::unique_ptr<GifWriter> gif;
    if (options.animation)
        gif = std::make_unique<GifWriter>((out / (file_stem_for(summary.scene) + ".gif")).string(), options.width / shrink,
                                          options.height / shrink);

    auto draw_share = [&](int worker, int workers, const FrameDone& done) {
        FrameComposer composer(summary, first, base, options.width, options.height, layers);
        std::future<void> encoding;
        for (std::size_t k = static_cast<std::size_t>(worker); k < steps.size(); k += static_cast<std::size_t>(workers)) {
            throw_if_render_stopped();
            const std::size_t index = steps[k];
            vtkSmartPointer<vtkImageData> image = composer.draw(grid_of(index), index);
            if (gif) write_animation_frame(gif->frame_file(), k, animation_pixels(image, shrink));
            if (encoding.valid()) encoding.get(); // one frame in flight at a time: memory stays flat
            const std::string path = (frames / frame_name(summary.curve[index].step)).string();
            encoding = std::async(std::launch::async, [image, path] { write_png(image, path); });
            done(k);
        }
        if (encoding.valid()) encoding.get();
    };

    // The parent's own pictures, drawn while the workers draw the frames.
    std::vector<ResultSeries> others;
    for (const std::string& other : options.overlays) others.push_back(open_series(other));
    auto parent_pictures = [&] {
        // The sheet's tiles are drawn at their own size with text a quarter larger, so that a
        // tile's legend stays readable (a shrunken full frame's text is 6 pixels high).
        ContactSheet sheet(steps.size(), 3, 3, 1.0);
        FrameComposer tiles(summary, first, base, options.width / 2, options.height / 2, layers, 1.25);
        for (std::size_t k = 0; k < steps.size(); ++k)
            if (sheet.wants(k)) throw_if_render_stopped(), sheet.keep(k, tiles.draw(grid_of(steps[k]), steps[k]));
        std::vector<const SeriesSummary*> runs{&summary};
        for (const SeriesSummary& o : overlays) runs.push_back(&o);
        write_png(draw_curve_chart(runs, options.width, options.height, references), (out / "chart.png").string());
        // Shaken on supports: the base shear's loops against the drift.
        const bool on_supports = std::any_of(summary.curve.begin(), summary.curve.end(), [](const CurvePoint& c) { return c.base_shear != 0.0; });
        if (summary.in_time && on_supports)
            write_png(draw_hysteresis_chart(summary, options.width, options.height), (out / "hysteresis.png").string());
        if (summary.in_time) write_png(draw_energy_chart(summary, options.width, options.height), (out / "energy.png").string());
        if (!options.shapes.empty()) {
            // This run's shapes, and each overlay's beside them at one scale.
            std::vector<ShapesPanel> panels{{&summary, &series}};
            for (std::size_t k = 0; k < others.size(); ++k) panels.push_back({&overlays[k], &others[k]});
            write_png(draw_shapes(panels, options.shapes, options.width, options.height), (out / "shapes.png").string());
        }
        if (auto image = sheet.compose()) write_png(image, (out / "contact_sheet.png").string());
        return tiles.gl_renderer();
    };

    const auto t0 = std::chrono::steady_clock::now();
    std::future<std::string> pictures;
    std::vector<bool> finished(steps.size(), false);
    std::size_t next_to_animate = 0, frames_done = 0;
    auto animate_in_order = [&](std::size_t k) {
        finished.at(k) = true;
        for (; gif && next_to_animate < steps.size() && finished[next_to_animate]; ++next_to_animate)
            gif->add(next_to_animate);
        if (options.on_frame) options.on_frame(static_cast<int>(++frames_done), static_cast<int>(steps.size()));
    };
    int workers = std::min<int>(options.workers > 0 ? options.workers : default_worker_count(), static_cast<int>(steps.size()));
    if (workers > 1 && !mesa_started_in_this_process()) {
        draw_in_workers(
            workers, draw_share,
            [&] {
                pictures = std::async(std::launch::async, parent_pictures);
                if (gif) gif->start();
            },
            animate_in_order);
    } else {
        // One process draws everything, one picture after another (VTK's rendering stays on
        // one thread).
        workers = 1;
        if (gif) gif->start();
        draw_share(0, 1, animate_in_order);
        pictures = std::async(std::launch::deferred, parent_pictures);
    }
    report.gl_renderer = pictures.get();
    report.frames = static_cast<int>(steps.size());
    report.workers = workers;
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    report.frames_per_second = report.frames / std::max(report.seconds, 1e-9);
    if (gif) {
        report.animation = gif->finish(steps.size()).message;
    } else {
        report.animation = "no animation requested";
    }
    return report;
}

} // namespace plastica::render
