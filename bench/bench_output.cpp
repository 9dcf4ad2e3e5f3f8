// The output's costs: one VTU step of the ring, and one 1280 × 720 frame drawn and encoded.
#include "bench_scenes.hpp"

#include "analysis/path_following.hpp"
#include "frame_composer.hpp"
#include "png_file.hpp"
#include "result_series.hpp"
#include "series_summary.hpp"
#include "vtu_series_writer.hpp"

#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <benchmark/benchmark.h>

#include <filesystem>

namespace fs = std::filesystem;

namespace plastica::bench {

namespace {

// The inelastic ring solved once into a temporary folder, with its last step kept.
struct SolvedRing {
    fs::path folder = fs::temp_directory_path() / "plastica_bench_ring";
    Model model = ring("ring_inelastic");
    StepResult last;
    SolvedRing() {
        fs::remove_all(folder);
        VtuSeriesWriter writer(model, folder.string(), {20, SeriesTime::step});
        PathFollowing analysis(model);
        analysis.run({std::ref(writer), [&](const StepResult& r) { last = r; }});
        writer.finish();
    }
};

const SolvedRing& solved() {
    static const SolvedRing ring;
    return ring;
}

} // namespace

// One step of a 200-step series: the VTU and the PVD rewritten with its entry (the PVD grows
// with the series, so the writer starts a new series every 200 steps, untimed).
void write_vtu_step(benchmark::State& state) {
    const SolvedRing& r = solved();
    const fs::path folder = fs::temp_directory_path() / "plastica_bench_vtu";
    fs::remove_all(folder);
    auto writer = std::make_unique<VtuSeriesWriter>(r.model, folder.string());
    StepResult step = r.last;
    step.step = 0;
    for (auto _ : state) {
        (*writer)(step);
        if (++step.step == 200) {
            state.PauseTiming();
            writer.reset();
            fs::remove_all(folder);
            writer = std::make_unique<VtuSeriesWriter>(r.model, folder.string());
            step.step = 0;
            state.ResumeTiming();
        }
    }
}
BENCHMARK(write_vtu_step)->Unit(benchmark::kMicrosecond);

void render_frame(benchmark::State& state) {
    using namespace plastica::render;
    const SolvedRing& r = solved();
    const ResultSeries series = open_series(r.folder.string());
    const SeriesSummary summary = summarise(series, "bending_moment");
    auto first = read_step(series.steps.front().file);
    auto last = read_step(series.steps.back().file);
    auto base = read_base(series.base_file);
    FrameComposer composer(summary, first, base, 1280, 720);
    const bool encode = state.range(0) != 0;
    for (auto _ : state) {
        auto image = composer.draw(last, series.steps.size() - 1);
        if (encode) benchmark::DoNotOptimize(encode_png(image));
    }
}
BENCHMARK(render_frame)->ArgName("with_png")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

} // namespace plastica::bench
