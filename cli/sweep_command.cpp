// plastica sweep: a plan of runs (grid, zipped lists or a Monte Carlo sample of scene
// overrides), run by a pool of `plastica run --curves-only` processes, one per core, or written
// as jobs for GNU Parallel and a Slurm array; plastica merge: sweep.csv from whatever runs exist.
#include "commands.hpp"
#include "options.hpp"
#include "progress.hpp"
#include "default_folder.hpp"

#include "atomic_file.hpp"
#include "safe_names.hpp"

#include "scene_error.hpp"
#include "scene_overrides.hpp"
#include "scene_reader.hpp"
#include "step_dataset.hpp"
#include "study_error.hpp"
#include "sweep.hpp"

#include "render_error.hpp"
#include "sweep_charts.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace plastica::cli {

namespace {

namespace fs = std::filesystem;

std::atomic<bool> sweep_stop_requested{false};
extern "C" void request_sweep_stop(int) { sweep_stop_requested = true; }

std::vector<std::string> split(const std::string& text, char by) {
    std::vector<std::string> parts;
    std::stringstream in(text);
    for (std::string p; std::getline(in, p, by);) parts.push_back(p);
    return parts;
}

std::vector<double> displacements(const po::variables_map& vm) {
    std::vector<double> at;
    if (!vm.count("at")) return at;
    for (const std::string& t : split(vm["at"].as<std::string>(), ',')) {
        try {
            at.push_back(std::stod(t));
        } catch (const std::exception&) {
            throw StudyError("--at: '" + t + "' is not a number");
        }
    }
    return at;
}

// The lean plastica beside this program (plastica-draw), so that every run is the same
// plastica and starts without the rendering libraries.
std::string self() {
    std::error_code ec;
    const fs::path p = fs::read_symlink("/proc/self/exe", ec);
    return ec ? std::string("plastica") : (p.parent_path() / "plastica").string();
}

pid_t launch(const std::string& program, const std::vector<std::string>& args, const fs::path& log) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    std::vector<char*> argv{const_cast<char*>(program.c_str())};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid = -1;
    const int error = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    return error == 0 ? pid : -1;
}

// The charts of the runs that finished (drawn by the render stage from the results).
void draw_charts(const std::string& dir, const std::string& scene_file, bool sampled) {
    const SweepPlan plan = read_plan(dir);
    render::SweepCharts charts;
    charts.keys = plan.keys;
    charts.sampled = sampled;
    const std::vector<SweepRunResult> results = read_sweep_results(dir, plan);
    // Names and labels from the scene (given, or as the runs recorded it).
    std::string file = scene_file;
    for (const SweepRunResult& r : results)
        // A recorded name from a folder of elsewhere is read only as a scene (a .toml file).
        if (file.empty() && r.finished && fs::path(r.scene_file).extension() == ".toml") file = r.scene_file;
    charts.scene = "sweep";
    try {
        const Model model = read_scene(file);
        charts.scene = model.name;
        charts.load_label = model.report.load_label;
        charts.displacement_label = model.report.displacement_label;
        std::tie(charts.load_unit, charts.displacement_unit) = reported_units(model);
    } catch (const SceneError&) {
        // The scene moved or changed: the charts keep generic labels.
    }
    for (const SweepRunResult& r : results) {
        if (!r.finished || r.displacement.size() < 2) continue;
        render::SweepChartRun run;
        for (const std::string& v : r.values) {
            char* end = nullptr;
            const double x = std::strtod(v.c_str(), &end);
            run.values.push_back(end && *end == '\0' && end != v.c_str() ? x : NAN);
        }
        run.peak_load = r.peak_load;
        run.displacement = r.displacement;
        run.load = r.load;
        charts.runs.push_back(std::move(run));
    }
    try {
        for (const std::string& file : render::draw_sweep_charts(charts, dir)) std::cout << "-> " << file << "\n";
    } catch (const render::RenderError& e) {
        std::cerr << "plastica: cannot draw the sweep's charts: " << e.what() << "\n";
    }
}

// The runs of a plan that give key k this value: "runs r0002, r0004" (the first ten, and how many more).
std::string runs_taking(const SweepPlan& plan, std::size_t k, const std::string& value) {
    std::vector<std::string> ids;
    for (std::size_t r = 0; r < plan.ids.size(); ++r)
        if (plan.values[r][k] == value) ids.push_back(plan.ids[r]);
    if (ids.empty()) return "no run of the plan (a value a sample's range reaches)";
    std::string text = ids.size() == 1 ? "run " : "runs ";
    for (std::size_t i = 0; i < ids.size() && i < 10; ++i) text += (i ? ", " : "") + ids[i];
    if (ids.size() > 10) text += " and " + std::to_string(ids.size() - 10) + " more";
    return text;
}

int report(const std::string& dir, const std::vector<double>& at) {
    const SweepSummary s = write_sweep_csv(dir, at);
    std::cout << dir << "/sweep.csv: " << s.runs << " runs, " << s.completed << " completed, " << s.stopped
              << " stopped early, " << s.failed << " failed, " << s.missing << " missing\n";
    auto list = [](const char* what, const std::vector<std::string>& ids) {
        if (ids.empty()) return;
        std::cout << what << ":";
        for (const std::string& id : ids) std::cout << ' ' << id;
        std::cout << "\n";
    };
    list("failed (see logs/<id>.txt)", s.failed_ids);
    list("missing (run the sweep again to run only these)", s.missing_ids);
    return s.missing > 0 || s.failed > 0 ? stopped_early : ok;
}

} // namespace

int sweep_command(const Args& args) {
    po::options_description options("Options");
    options.add_options()
        ("scene", po::value<std::string>()->required(), "scene file (TOML)")
        ("vary", po::value<std::vector<std::string>>()->composing(), "KEY=v1,v2,… (repeatable): a grid over the values")
        ("zip", "take the --vary lists side by side instead of their grid")
        ("sample", po::value<std::vector<std::string>>()->composing(), "KEY=normal:μ:σ | lognormal:μ:σ | uniform:a:b (repeatable)")
        ("samples", po::value<int>()->default_value(100), "number of sampled runs")
        ("seed", po::value<std::uint64_t>()->default_value(1), "seed of the sample (the same seed, the same values)")
        ("output,o", po::value<std::string>(), "sweep folder (default out/<scene>/sweep)")
        ("jobs,j", po::value<int>()->default_value(static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))), "runs at a time")
        ("emit", po::value<std::string>(), "'jobs': write jobs.txt and sweep.sbatch instead of running")
        ("at", po::value<std::string>(), "displacements where sweep.csv reports the load, e.g. 50,100")
        ("no-charts", "sweep.csv only, no charts")
        ("quiet,q", "no progress on stderr")
        ("run-output", po::value<std::string>()->default_value("curves"),
         "what each run writes: curves (curve.csv, run.json), series (and its VTU series) or pictures (and its frames, chart and animation)");
    po::positional_options_description positional;
    positional.add("scene", 1);
    po::variables_map vm;
    if (auto code = parse_options(args, "plastica sweep SCENE --vary KEY=v1,v2 [--vary …] [--zip] | --sample KEY=law:a:b --samples N --seed S [-o DIR] [--emit jobs]",
                                  options, positional, vm))
        return *code;
    const std::string scene = fs::absolute(vm["scene"].as<std::string>()).string();
    std::string dir;
    SweepPlan plan;
    std::vector<double> at;
    RunOutput output = RunOutput::curves;
    try {
        output = parse_run_output(vm["run-output"].as<std::string>());
        const Model model = read_scene(scene);
        // Absolute: jobs.txt and the Slurm script may run from any directory.
        dir = fs::absolute(vm.count("output") ? fs::path(vm["output"].as<std::string>())
                                              : fs::path(default_output_folder(model.name)) / "sweep").lexically_normal().string();
        // Every run's folder and log is named in jobs.txt and in a Slurm script: one line each.
        if (has_control_character(dir)) throw StudyError("the output folder may not hold a newline or another control character");
        at = displacements(vm);
        if (vm.count("sample")) {
            if (vm.count("vary")) throw StudyError("give --vary (a grid) or --sample (Monte Carlo), not both");
            std::vector<SampledKey> keys;
            for (const std::string& t : vm["sample"].as<std::vector<std::string>>()) keys.push_back(parse_sample(t));
            plan = sample_plan(keys, vm["samples"].as<int>(), vm["seed"].as<std::uint64_t>());
        } else {
            if (!vm.count("vary")) throw StudyError("give --vary KEY=v1,v2,… or --sample KEY=law:a:b");
            std::vector<std::pair<std::string, std::vector<std::string>>> lists;
            for (const std::string& t : vm["vary"].as<std::vector<std::string>>()) {
                const auto eq = t.find('=');
                if (eq == std::string::npos || eq == 0) throw StudyError("--vary takes KEY=v1,v2,… (got '" + t + "')");
                lists.push_back({t.substr(0, eq), split(t.substr(eq + 1), ',')});
            }
            plan = grid_plan(lists, vm.count("zip") > 0);
        }
        // The keys must exist and take such values: before any run starts (or a job is written),
        // the scene is read with each value a grid gives each key (a sample's smallest and
        // largest), the other keys at the first run's values.
        std::vector<Override> first;
        for (std::size_t k = 0; k < plan.keys.size(); ++k) first.push_back({plan.keys[k], plan.values.front()[k]});
        read_scene(scene, first);
        for (std::size_t k = 0; k < plan.keys.size(); ++k)
            for (const std::string& value : values_to_check(plan, k, vm.count("sample") > 0)) {
                std::vector<Override> one = first;
                one[k].value = value;
                try {
                    read_scene(scene, one);
                } catch (const SceneError& e) {
                    std::cerr << "plastica: " << e.what() << "\n  refused before any run: " << plan.keys[k] << " = " << value
                              << " in " << runs_taking(plan, k, value) << "\n";
                    return bad_input;
                }
            }
    } catch (const SceneError& e) {
        std::cerr << "plastica: " << e.what() << "\n";
        return bad_input;
    } catch (const StudyError& e) {
        std::cerr << "plastica: " << vm["scene"].as<std::string>() << ": " << e.what() << "\n";
        return bad_input;
    }
    try {
        // A folder with another plan is not mixed into this one.
        const SweepPlan earlier = fs::exists(fs::path(dir) / "plan.csv") ? read_plan(dir) : plan;
        if (earlier.keys != plan.keys || earlier.values != plan.values) {
            std::cerr << "plastica: " << dir << " holds another sweep (plan.csv differs); choose another folder with -o\n";
            return bad_input;
        }
        write_plan(dir, plan);
        if (vm.count("sample")) {
            std::ostringstream laws;
            for (const std::string& t : vm["sample"].as<std::vector<std::string>>()) laws << "--sample " << t << "\n";
            laws << "--samples " << vm["samples"].as<int>() << "\n--seed " << vm["seed"].as<std::uint64_t>() << "\n";
            write_file_atomically((fs::path(dir) / "sample.txt").string(), laws.str());
        }
        fs::create_directories(fs::path(dir) / "logs");
        if (vm.count("emit")) {
            if (vm["emit"].as<std::string>() != "jobs") {
                std::cerr << "plastica: --emit takes 'jobs'\n";
                return bad_input;
            }
            write_jobs(dir, self(), scene, plan, output);
            // Commands to paste into a shell: every path one word.
            const auto in_dir = [&](const char* name) { return quoted_for_shell((fs::path(dir) / name).string()); };
            std::cout << dir << "/jobs.txt: " << plan.ids.size() << " runs. Run them with GNU Parallel:\n"
                      << "  parallel --joblog " << in_dir("joblog") << " < " << in_dir("jobs.txt") << "\n"
                      << "or as a Slurm array: sbatch " << in_dir("sweep.sbatch") << "\n"
                      << "then: plastica merge " << quoted_for_shell(dir) << "\n";
            return ok;
        }
    } catch (const StudyError& e) {
        std::cerr << "plastica: " << e.what() << "\n";
        return bad_input;
    } catch (const std::exception& e) {
        std::cerr << "plastica: cannot write the sweep's files in " << dir << ": " << e.what() << "\n";
        return stopped_early;
    }
    // The pool: up to --jobs runs at a time; a finished run (an earlier, interrupted sweep) is
    // not run again.
    std::signal(SIGINT, request_sweep_stop);
    std::signal(SIGTERM, request_sweep_stop);
    const int jobs = std::max(1, vm["jobs"].as<int>());
    const std::string program = self();
    std::map<pid_t, std::string> running;
    std::size_t next = 0, skipped = 0, finished = 0;
    Progress progress("running", 0, "runs"); // on a terminal only: a sweep's log stays as it was
    const auto count_finished = [&](const std::string& id) {
        ++finished;
        if (!vm.count("quiet"))
            progress.update(static_cast<int>(finished), static_cast<double>(finished) / static_cast<double>(plan.ids.size()),
                            "run " + std::to_string(finished) + " of " + std::to_string(plan.ids.size()) + " (" + id + " done)");
    };
    while ((next < plan.ids.size() && !sweep_stop_requested) || !running.empty()) {
        while (!sweep_stop_requested && next < plan.ids.size() && static_cast<int>(running.size()) < jobs) {
            const std::size_t r = next++;
            if (run_finished(dir, plan.ids[r])) {
                ++skipped;
                count_finished(plan.ids[r]);
                continue;
            }
            const pid_t pid = launch(program, run_arguments(scene, dir, plan, r, output), fs::path(dir) / "logs" / (plan.ids[r] + ".txt"));
            if (pid > 0) running[pid] = plan.ids[r];
        }
        if (running.empty()) break;
        int status = 0;
        const pid_t done = ::waitpid(-1, &status, 0);
        if (done > 0 && running.count(done)) {
            count_finished(running[done]);
            running.erase(done);
        }
    }
    progress.finish();
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    if (skipped > 0) std::cout << skipped << " runs had finished before and were kept\n";
    const int code = report(dir, at);
    if (!vm.count("no-charts")) draw_charts(dir, scene, vm.count("sample") > 0);
    return sweep_stop_requested ? interrupted : code;
}

int merge_command(const Args& args) {
    po::options_description options("Options");
    options.add_options()
        ("folder", po::value<std::string>()->required(), "sweep folder")
        ("scene", po::value<std::string>(), "the sweep's scene file, for the labels of the charts")
        ("at", po::value<std::string>(), "displacements where sweep.csv reports the load, e.g. 50,100");
    po::positional_options_description positional;
    positional.add("folder", 1);
    po::variables_map vm;
    if (auto code = parse_options(args, "plastica merge SWEEP_DIR [--at d1,d2]", options, positional, vm)) return *code;
    try {
        const std::string dir = vm["folder"].as<std::string>();
        const int code = report(dir, displacements(vm));
        // A sampled sweep left its laws in sample.txt: then the distribution is drawn too.
        draw_charts(dir, vm.count("scene") ? vm["scene"].as<std::string>() : "", fs::exists(fs::path(dir) / "sample.txt"));
        return code;
    } catch (const StudyError& e) {
        std::cerr << "plastica: " << e.what() << "\n";
        return bad_input;
    } catch (const WriteError& e) {
        std::cerr << "plastica: " << e.what() << "\n";
        return stopped_early;
    } catch (const std::exception& e) {
        // A folder of elsewhere: a file too large, behind a link, or unreadable.
        std::cerr << "plastica: " << vm["folder"].as<std::string>() << ": " << e.what() << "\n";
        return bad_input;
    }
}

} // namespace plastica::cli
