// The output's costs: one VTU step of the ring, and one 1280 × 720 frame drawn and encoded.
#include "bench_scenes.hpp"

#include "analysis/path_following.hpp"
#include "frame_composer.hpp"
#include "png_file.hpp"
#include "result_series.hpp"
#include "series_summary.hpp"
#include "vtu_series_writer.hpp"

// read_step, read_base and draw hand these back.
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

// One step of a series of state.range(0) steps (restarted, untimed, when it is complete),
// compressed as state.range(1) says (0 none, 1 LZ4, 2 zlib): a step must cost the same in a
// series of 200 and of 10 000 (the PVD is appended to in O(1), never rewritten).
void write_vtu_step(benchmark::State& state) {
    const SolvedRing& r = solved();
    const fs::path folder = fs::temp_directory_path() / "plastica_bench_vtu";
    const int length = static_cast<int>(state.range(0));
    const SeriesOptions options{1, SeriesTime::step, static_cast<Compression>(state.range(1))};
    fs::remove_all(folder);
    auto writer = std::make_unique<VtuSeriesWriter>(r.model, folder.string(), options);
    StepResult step = r.last;
    step.step = 0;
    double bytes = 0.0;
    for (auto _ : state) {
        (*writer)(step);
        if (++step.step == length) {
            state.PauseTiming();
            bytes = static_cast<double>(fs::file_size(folder / "vtu" / step_file_name(0)));
            writer.reset();
            fs::remove_all(folder);
            writer = std::make_unique<VtuSeriesWriter>(r.model, folder.string(), options);
            step.step = 0;
            state.ResumeTiming();
        }
    }
    state.counters["bytes_per_step"] = bytes;
}
BENCHMARK(write_vtu_step)
    ->ArgNames({"steps", "compression"})
    ->Args({200, 0})->Args({200, 1})->Args({200, 2})
    ->Args({10000, 0})->Args({10000, 2})
    ->Iterations(10000)
    ->Unit(benchmark::kMicrosecond);

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
