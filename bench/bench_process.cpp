// Whole processes, as a user starts them: plastica's start-up, a run with a VTU per step, a
// curves-only run, the render stage, and a sweep's throughput. Wall time of the child from spawn to exit.
#include <benchmark/benchmark.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace plastica::bench {

namespace {

namespace fs = std::filesystem;

// Runs plastica with these arguments, output to /dev/null; its exit code.
int plastica(std::vector<std::string> args) {
    args.insert(args.begin(), PLASTICA_BINARY);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    pid_t pid = -1;
    const int error = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0) throw std::runtime_error("cannot start " + args[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string scene(const char* name) { return std::string(PLASTICA_SOURCE_DIR) + "/models/" + name + ".toml"; }

void expect_success(benchmark::State& state, int code) {
    if (code != 0) state.SkipWithError(("plastica exited with " + std::to_string(code)).c_str());
}

} // namespace

void process_help(benchmark::State& state) {
    for (auto _ : state) expect_success(state, plastica({"--help"}));
}
BENCHMARK(process_help)->Unit(benchmark::kMillisecond)->UseRealTime();

// The ring as shipped (200 steps), every step written as a VTU, nothing drawn: into an empty
// folder, as a first run is, or again into the folder of the same run (its step files are
// rewritten in place).
enum class Folder { empty, rerun };
void process_ring_run(benchmark::State& state, const char* name, bool curves_only, Folder folder) {
    const std::string out = (fs::temp_directory_path() / "plastica_bench_process").string();
    std::vector<std::string> args{"run", scene(name), "-o", out, "-q", curves_only ? "--curves-only" : "--no-render"};
    fs::remove_all(out);
    if (folder == Folder::rerun) expect_success(state, plastica(args));
    for (auto _ : state) {
        if (folder == Folder::empty) {
            state.PauseTiming();
            fs::remove_all(out);
            state.ResumeTiming();
        }
        expect_success(state, plastica(args));
    }
}
BENCHMARK_CAPTURE(process_ring_run, elastic_vtu, "ring_elastic", false, Folder::empty)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(process_ring_run, inelastic_vtu, "ring_inelastic", false, Folder::empty)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(process_ring_run, elastic_vtu_again, "ring_elastic", false, Folder::rerun)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(process_ring_run, inelastic_vtu_again, "ring_inelastic", false, Folder::rerun)->Unit(benchmark::kMillisecond)->UseRealTime();

// The render stage as a user starts it: `plastica render` of the inelastic ring's 201 steps at
// 1280 × 720 (frames, chart, contact sheet; the GIF when asked), with one drawing process or one
// per core. frames_per_second: frames over the whole process's wall time.
void process_render(benchmark::State& state) {
    const std::string series = (fs::temp_directory_path() / "plastica_bench_render_series").string();
    const std::string pictures = (fs::temp_directory_path() / "plastica_bench_render_pictures").string();
    if (!fs::exists(fs::path(series) / "ring_inelastic.pvd"))
        expect_success(state, plastica({"run", scene("ring_inelastic"), "-o", series, "-q", "--no-render"}));
    std::vector<std::string> args{"render", series, "-o", pictures, "-q", "-j", std::to_string(state.range(0))};
    if (state.range(1) == 0) args.push_back("--no-animation");
    for (auto _ : state) expect_success(state, plastica(args));
    state.counters["frames_per_second"] = benchmark::Counter(201.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(process_render)->ArgNames({"processes", "gif"})->Args({1, 0})->Args({2, 0})->Args({1, 1})->Args({2, 1})
    ->Iterations(5)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK_CAPTURE(process_ring_run, elastic_curves_only, "ring_elastic", true, Folder::empty)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(process_ring_run, inelastic_curves_only, "ring_inelastic", true, Folder::empty)->Unit(benchmark::kMillisecond)->UseRealTime();

// A 3 × 3 sweep of the inelastic ring (fy × ky) on every core, from an empty folder: runs per second.
void process_sweep(benchmark::State& state) {
    const std::string dir = (fs::temp_directory_path() / "plastica_bench_sweep").string();
    const std::vector<std::string> args{"sweep", scene("ring_inelastic"), "--vary", "material[1].fy=30000,36518,43000",
                                        "--vary", "foundation[1].ky=600,1200,2400", "--no-charts", "-o", dir};
    for (auto _ : state) {
        state.PauseTiming();
        fs::remove_all(dir);
        state.ResumeTiming();
        expect_success(state, plastica(args));
    }
    state.counters["runs_per_second"] = benchmark::Counter(9.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(process_sweep)->Unit(benchmark::kMillisecond)->UseRealTime();

namespace {

// The mean of sweep.csv's last column: each run's own time (read, analysis, curve output).
double mean_run_seconds(const fs::path& csv) {
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line); // header
    double sum = 0.0;
    int rows = 0;
    while (std::getline(in, line)) {
        sum += std::stod(line.substr(line.rfind(',') + 1));
        ++rows;
    }
    return rows > 0 ? sum / rows : 0.0;
}

} // namespace

// The README's worked example: 1 000 runs of the 50-element ring with fy sampled, on every core,
// in-process (argument 0) or as jobs through GNU Parallel (1). Counters: runs per second, and the
// per-run overhead beyond a run's own work (cores × wall / runs − its mean time in sweep.csv).
void process_sweep_1000(benchmark::State& state) {
    const bool through_parallel = state.range(0) != 0;
    const fs::path dir = fs::temp_directory_path() / "plastica_bench_sweep_1000";
    const std::vector<std::string> sweep{"sweep", scene("ring_inelastic"), "--sample", "material[steel].fy=normal:36518:3000",
                                         "--samples", "1000", "--seed", "11", "--no-charts", "-o", dir.string()};
    const double cores = static_cast<double>(std::thread::hardware_concurrency());
    double wall = 0.0;
    for (auto _ : state) {
        state.PauseTiming();
        fs::remove_all(dir);
        std::vector<std::string> args = sweep;
        if (through_parallel) {
            args.push_back("--emit");
            args.push_back("jobs");
            expect_success(state, plastica(args));
        }
        state.ResumeTiming();
        const auto start = std::chrono::steady_clock::now();
        if (through_parallel) {
            const std::string command = "parallel --will-cite < " + (dir / "jobs.txt").string() + " > /dev/null 2>&1";
            if (std::system(command.c_str()) != 0) state.SkipWithError("GNU Parallel failed");
        } else {
            expect_success(state, plastica(args));
        }
        wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        state.PauseTiming();
        if (through_parallel) expect_success(state, plastica({"merge", dir.string()}));
        state.ResumeTiming();
    }
    state.counters["runs_per_second"] = 1000.0 / wall;
    state.counters["overhead_ms_per_run"] = 1e3 * (cores * wall / 1000.0 - mean_run_seconds(dir / "sweep.csv"));
}
BENCHMARK(process_sweep_1000)->ArgName("through_parallel")->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

} // namespace plastica::bench
