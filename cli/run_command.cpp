// plastica run: read a scene, solve it, write curve.csv, run.json and the VTU/PVD series,
// then render the series unless --no-render (--curves-only: curve.csv and run.json alone).
#include "background_output.hpp"
#include "commands.hpp"
#include "drawing_program.hpp"
#include "options.hpp"
#include "default_folder.hpp"
#include "output_folder.hpp"
#include "progress.hpp"
#include "render_stage.hpp"
#include "reference_points.hpp"

#include "analysis/path_following.hpp"
#include "curve_writer.hpp"
#include "model_building.hpp"
#include "run_progress.hpp"
#include "run_report.hpp"
#include "scene_overrides.hpp"
#include "scene_reader.hpp"
#include "scene_warnings.hpp"
#include "vtu_series_writer.hpp"

#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <cmath>
#include <iostream>
#include <sstream>
#include <new>
#include <optional>

namespace plastica::cli {

namespace {

// The PVD's time: as asked, or for a scene in motion its own time unless asked otherwise.
SeriesTime series_time(const std::string& asked, bool left_out, const Model& model) {
    if (asked == "model" || (left_out && model.transient())) return SeriesTime::model;
    return asked == "arc_length" ? SeriesTime::arc_length : SeriesTime::step;
}

// What a user reads when the path passes a critical point: a bifurcation left behind is a
// warning (the path goes on where the structure would not), one followed and a limit are notes.
std::string critical_point_message(const CriticalPoint& c) {
    std::ostringstream s;
    s << (c.kind == CriticalKind::bifurcation && !c.followed ? "warning: " : "note: ") << "step " << c.step << " passed a "
      << (c.kind == CriticalKind::bifurcation ? "bifurcation" : "limit point") << " at load factor " << c.load_factor;
    if (c.kind == CriticalKind::limit) s << " (the load's maximum along the path)";
    else if (c.followed) s << "; the path follows the buckled branch";
    else s << ": the path goes on along the fundamental branch, unstable beyond it ([analysis] bifurcation = \"switch\" "
              "follows the buckled one; `plastica buckling` gives the modes)";
    return s.str();
}

std::atomic<bool> stop_requested{false};
extern "C" void request_stop(int) { stop_requested = true; }

// Adds the seconds of its scope to a total, also when the scope is left by an exception.
class AddsElapsed {
public:
    explicit AddsElapsed(double& total) : total_(total) {}
    ~AddsElapsed() { total_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count(); }
    AddsElapsed(const AddsElapsed&) = delete;
    AddsElapsed& operator=(const AddsElapsed&) = delete;

private:
    double& total_;
    std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
};

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

} // namespace

int run_command(const Args& args) {
    po::options_description options("Options");
    options.add_options()
        ("scene", po::value<std::string>()->required(), "scene file (TOML)")
        ("set", po::value<std::vector<std::string>>()->composing(),
         "KEY=VALUE: override a scene key by its path, e.g. material[steel].fy=250, analysis.increment=0.25 (repeatable)")
        ("output,o", po::value<std::string>(), "output folder (default out/<scene>)")
        ("every", po::value<int>()->default_value(1), "write every k-th step (first and last always)")
        ("time", po::value<std::string>()->default_value("step"), "PVD time: step, arc_length or model (a transient scene's time, its default)")
        ("compression", po::value<std::string>()->default_value("none"), "VTU compression: none (the fastest, default), lz4 or zlib; ParaView reads all three")
        ("no-render", "solve and write results only, draw nothing")
        ("curves-only", "write curve.csv and run.json only: no VTU series, no pictures (sweeps)")
        ("force", "use an output folder that holds another scene's results")
        ("quiet,q", "no progress on stderr");
    add_render_options(options);
    po::positional_options_description positional;
    positional.add("scene", 1);
    po::variables_map vm;
    if (auto code = parse_options(args, "plastica run SCENE [-o DIR] [options]", options, positional, vm))
        return *code;

    const auto t0 = std::chrono::steady_clock::now();
    const std::string scene_file = vm["scene"].as<std::string>();
    Model model;
    std::vector<Override> overrides;
    try {
        if (vm.count("set"))
            for (const std::string& text : vm["set"].as<std::vector<std::string>>()) overrides.push_back(parse_override(text));
        model = read_scene(scene_file, overrides);
    } catch (const SceneError& e) {
        std::cerr << "plastica: " << e.what() << "\n";
        return bad_input;
    }
    for (const std::string& warning : scene_warnings(model)) std::cerr << "plastica: " << scene_file << ": warning: " << warning << "\n";
    const int every = vm["every"].as<int>();
    render::RenderOptions render_options;
    if (auto code = read_render_options(vm, render_options)) return *code;
    const std::string time = vm["time"].as<std::string>();
    if (every < 1 || (time != "step" && time != "arc_length" && time != "model")) {
        std::cerr << "plastica: --every takes a whole number ≥ 1 and --time 'step', 'arc_length' or 'model'\n";
        return bad_input;
    }
    const std::string compression = vm["compression"].as<std::string>();
    if (compression != "none" && compression != "lz4" && compression != "zlib") {
        std::cerr << "plastica: --compression takes none, lz4 or zlib, got '" << compression << "'\n";
        return bad_input;
    }
    // Unbounded work is refused before it starts: the series could hold up to max_steps/every
    // VTU files (fewer when a fixed increment reaches the target sooner).
    if (!vm.count("curves-only")) {
        const AnalysisSpec& a = model.analysis;
        double steps = a.max_steps;
        if (!a.adaptive && a.target_load_factor && a.scheme == Scheme::load_control)
            steps = std::min(steps, std::ceil(*a.target_load_factor / a.initial_increment));
        if (!a.adaptive && a.target_displacement && a.scheme == Scheme::displacement_control)
            steps = std::min(steps, std::ceil(*a.target_displacement / a.initial_increment));
        // Transient stages take their steps beyond the static limit: duration / time step each.
        for (const StageSpec& s : model.stages)
            if (s.scheme == Scheme::transient) steps += std::ceil(s.transient.duration / s.transient.time_step);
        const double files = std::floor(steps / every) + 2;
        const double bytes = files * (120.0 * model.nodes.size() + 150.0 * model.elements.size() + 2000.0);
        if (files > 1e6 || bytes > 20e9) {
            std::ostringstream why;
            why.precision(3);
            why << "plastica: " << scene_file << ": the series could hold " << files << " VTU files, about "
                << bytes / 1e9 << " GB (up to " << steps << " steps, every " << every
                << "); pass --every K to write every K-th step, or --curves-only\n";
            std::cerr << why.str();
            return bad_input;
        }
    }
    // The lean plastica has no drawing linked in: a run that draws is plastica-draw's, whole.
    const bool draws = !vm.count("no-render") && !vm.count("curves-only");
    if (draws && !can_draw()) return hand_over_to_drawing("run", args);
    // Set-up beyond this machine's memory is refused before it starts; a long one is announced.
    if (const std::optional<std::string> why = setup_too_large(model)) {
        std::cerr << "plastica: " << scene_file << ": " << *why << "\n";
        return bad_input;
    }
    if (const double states = fibre_states(model); states > 1e6 && !vm.count("quiet"))
        std::cerr << "plastica: setting up " << states << " fibre states (about " << std::lround(states * bytes_per_fibre_state / 1e6)
                  << " MB)...\n";
    std::optional<PathFollowing> analysis;
    try {
        analysis.emplace(model);
        if (const std::string m = analysis->initial_mechanism(); !m.empty()) {
            std::cerr << "plastica: " << scene_file << ": " << m << "\n";
            return bad_input;
        }
    } catch (const std::bad_alloc&) {
        std::cerr << "plastica: " << scene_file << ": out of memory while setting up the model of " << model.elements.size()
                  << " elements and " << model.nodes.size() << " nodes: it needs more memory than this process may have\n";
        return stopped_early;
    }
    const std::string folder = vm.count("output") ? vm["output"].as<std::string>() : default_output_folder(model.name);
    // The folder is this run's own until it ends: a second writer is refused, and a rerun
    // removes only what an earlier run wrote, never this run's inputs.
    std::optional<OutputFolder> output_folder;
    try {
        OutputFolderOptions o;
        o.scene_name = model.name;
        o.force = vm.count("force") > 0;
        o.keep_step_files = !vm.count("curves-only");
        o.inputs = render_options.overlays;
        for (const std::string& points : render_options.reference_points) o.inputs.push_back(render::reference_points_file(points));
        o.inputs.push_back(scene_file);
        o.holder = "plastica run " + scene_file;
        output_folder.emplace(folder, std::move(o));
    } catch (const std::exception& e) {
        std::cerr << "plastica: " << e.what() << "\n";
        return bad_input;
    }
    const double read_seconds = seconds_since(t0);
    write_run_started((std::filesystem::path(folder) / "run.json").string(), model, scene_file);

    namespace fs = std::filesystem;
    CurveWriter curve((fs::path(folder) / "curve.csv").string(), model);
    const bool curves_only = vm.count("curves-only") > 0;
    std::optional<VtuSeriesWriter> series;
    if (!curves_only)
        series.emplace(model, folder,
                       SeriesOptions{every, series_time(time, vm["time"].defaulted(), model),
                                     compression == "none" ? Compression::none
                                     : compression == "lz4" ? Compression::lz4 : Compression::zlib});
    RunReport report;
    report.scene_file = scene_file;
    for (const Override& o : overrides) report.overrides.emplace_back(o.path, o.value);
    report.model = &model;
    if (!draws) {
        report.drawing_notes = render_options_left_unused(vm, vm.count("curves-only") ? "--curves-only" : "--no-render");
        for (const std::string& note : report.drawing_notes) std::cerr << "plastica: note: " << note << "\n";
    }
    const bool quiet = vm.count("quiet") > 0;
    Progress progress("solving", 20, "steps");
    auto track = [&](const StepResult& r) {
        report.note(r);
        if (r.critical) {
            progress.finish();
            std::cerr << "plastica: " << scene_file << ": " << critical_point_message(*r.critical) << "\n";
        }
        if (quiet) return;
        const double done = share_done(model, r);
        std::ostringstream status;
        status << "step " << r.step << "  " << model.report.load_label << " " << r.load + 0.0 << "  "
               << model.report.displacement_label << " " << r.control_displacement + 0.0 << "  iterations " << r.iterations;
        progress.update(r.step, done, status.str());
    };
    std::signal(SIGINT, request_stop);
    std::signal(SIGTERM, request_stop);
    RunControl control;
    control.interrupt = &stop_requested;
    control.report_sections = !curves_only;
    const auto t1 = std::chrono::steady_clock::now();
    // A step is written everywhere or nowhere: when the series cannot take it (a full disk),
    // its curve row is taken back, and the run stops with every output at the step before.
    double output_seconds = 0.0; // inside the writers, for run.json's split of the time
    const auto folder_removed = [&] { return std::runtime_error("the output folder " + folder + " was removed or replaced during the run"); };
    auto write_step = [&](const StepResult& r) {
        const AddsElapsed timing(output_seconds);
        if (!output_folder->still_there()) throw folder_removed();
        curve(r);
        if (series) try {
                (*series)(r);
            } catch (...) {
                curve.take_back_last_row();
                // A folder removed while the step was written (rm -r takes vtu/ before the
                // folder itself) is named as such, not as the file that could not be written.
                if (!output_folder->still_there() || !std::filesystem::is_directory(std::filesystem::path(folder) / "vtu"))
                    throw folder_removed();
                throw;
            }
        track(r);
    };
    // A curve row costs less than handing the step to another thread: only a series is
    // written beside the analysis (background_output.hpp).
    std::optional<BackgroundOutput> output;
    if (series) output.emplace(write_step);
    report.summary = analysis->run({[&](const StepResult& r) { output ? output->push(r) : write_step(r); }}, control);
    const double analysis_seconds = seconds_since(t1); // waits on a full queue included
    if (output) output->finish();
    if (const std::optional<OutputFailure> failed = output ? output->failure() : std::nullopt) {
        report.summary.status = RunStatus::output_failed;
        report.summary.reason = "the results of step " + std::to_string(failed->step) + " could not be written: " + failed->message;
        report.summary.steps = std::max(failed->step - 1, 0);
    }
    progress.finish();
    if (series) try {
            series->finish();
        } catch (const std::exception& e) {
            // The last step, skipped by --every, could not be added: the series ends earlier.
            report.summary.status = RunStatus::output_failed;
            report.summary.reason = std::string("the last step could not be added to the series: ") + e.what();
        }
    // The output's seconds are the writers' own, spent beside the analysis.
    report.stage_seconds = {{"read", read_seconds}, {"analysis", analysis_seconds}, {"output", output_seconds}};
    try {
        write_run_report((fs::path(folder) / "run.json").string(), report);
    } catch (const std::exception& e) {
        std::cerr << "plastica: " << e.what() << " (run.json keeps the state it had when the run started)\n";
        if (report.summary.status == RunStatus::completed) {
            report.summary.status = RunStatus::output_failed;
            report.summary.reason = e.what();
        }
    }
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);

    if (!quiet)
        std::cerr << model.name << ": " << report.summary.reason << " after " << report.summary.steps
                  << " steps (" << report.summary.iterations << " iterations); peak load "
                  << report.peak_load << "; output in " << folder << "\n";
    if (report.later_maximum)
        std::cerr << "plastica: " << scene_file << ": note: past its first limit point the path reached a higher load, "
                  << report.later_maximum->load << " at step " << report.later_maximum->step
                  << ", on another branch: the peak reported is the first limit point's (run.json 'later_maximum')\n";
    if (report.summary.status == RunStatus::interrupted) return interrupted;
    // The converged steps are drawn even when the analysis stopped early.
#ifdef PLASTICA_DRAWING
    if (draws && report.summary.steps > 0) {
        render_options.quiet = quiet;
        const auto t2 = std::chrono::steady_clock::now();
        if (const int code = render_and_report(folder, render_options, &report.drawing_notes); code != ok) {
            // run.json says why the pictures are not all there: an interruption, or output that
            // could not be written (a full disk: exit 3, never "bad input").
            report.drawing_notes.push_back(code == interrupted ? "drawing interrupted: the frames drawn so far are kept"
                                                               : "drawing stopped: the pictures could not all be written");
            if (code == stopped_early && report.summary.status == RunStatus::completed) {
                report.summary.status = RunStatus::output_failed;
                report.summary.reason = "the analysis completed, but its pictures could not all be written";
            }
            try {
                write_run_report((fs::path(folder) / "run.json").string(), report);
            } catch (const std::exception& e) {
                std::cerr << "plastica: " << e.what() << "\n";
            }
            return code;
        }
        report.stage_seconds.emplace_back("drawing", seconds_since(t2));
        try {
            write_run_report((fs::path(folder) / "run.json").string(), report);
        } catch (const std::exception& e) {
            std::cerr << "plastica: " << e.what() << " (run.json lacks the drawing time)\n";
        }
    }
#endif
    if (report.summary.status != RunStatus::completed) {
        std::cerr << "plastica: " << scene_file << ": analysis stopped early: " << report.summary.reason
                  << " (the " << report.summary.steps << " converged steps are kept)\n";
        return stopped_early;
    }
    return ok;
}

} // namespace plastica::cli
