// The Python extension `plastica._plastica`: reads a scene (a file, TOML text, or the TOML text
// of a dict), runs it with the GIL released, and keeps every converged step, so that Python gets
// the curve and run.json as the command line writes them, each step's arrays by the result
// schema's names (io/results/step_dataset.hpp), and the same files on request. python/plastica/ wraps it.
#include "analysis/eigen_at_step.hpp"
#include "analysis/path_following.hpp"
#include "atomic_file.hpp"
#include "curve_writer.hpp"
#include "model_building.hpp"
#include "output_folder.hpp"
#include "run_progress.hpp"
#include "run_report.hpp"
#include "scene_overrides.hpp"
#include "scene_reader.hpp"
#include "step_dataset.hpp"
#include "vtu_series_writer.hpp"
#include "numpy_arrays.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;
using namespace plastica;

namespace {

// Ctrl-C during a run: Python's own handler would only mark the signal for the main thread,
// which waits in the run without the GIL. Plastica's stops the run between two Newton
// iterations; KeyboardInterrupt is raised once the run has returned.
std::atomic<bool>* interrupting_run = nullptr;
std::atomic<bool> interrupted_by_signal{false};
extern "C" void interrupt_run(int) {
    interrupted_by_signal = true;
    if (interrupting_run) *interrupting_run = true;
}

// Installs interrupt_run for SIGINT while it lives and puts Python's handler back after.
class InterruptibleRun {
public:
    explicit InterruptibleRun(std::atomic<bool>& stop) {
        interrupted_by_signal = false;
        interrupting_run = &stop;
        struct sigaction action {};
        action.sa_handler = interrupt_run;
        sigemptyset(&action.sa_mask);
        installed_ = sigaction(SIGINT, &action, &previous_) == 0;
    }
    ~InterruptibleRun() {
        if (installed_) sigaction(SIGINT, &previous_, nullptr);
        interrupting_run = nullptr;
    }
    InterruptibleRun(const InterruptibleRun&) = delete;
    InterruptibleRun& operator=(const InterruptibleRun&) = delete;

private:
    struct sigaction previous_ {};
    bool installed_ = false;
};

// One run: the model, its summary, every converged step, and the texts the CLI would write.
struct Run {
    Model model;
    std::string scene_file;
    std::vector<Override> overrides;
    RunSummary summary;
    std::vector<StepResult> steps;
    std::string curve_csv;
    RunReport report; // its model is this run's
    std::optional<StepDataset> dataset; // each step's arrays

    std::string report_json() const { return to_json(report); }
};

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Reads and runs a scene: `source` is a path, or TOML text when `name` is given (then `name`
// stands for the file in messages; "" for a dict, whose errors name key paths only).
// `progress`, unless None, is called with (step, share done or −1, load, control displacement)
// at most ten times a second and at the last step, with the GIL; what it raises stops the run and
// is raised again.
std::shared_ptr<Run> run_scene(const std::string& source, bool is_text, const std::string& name,
                               const std::vector<std::pair<std::string, std::string>>& overrides, const py::object& progress) {
    auto run = std::make_shared<Run>();
    for (const auto& [path, value] : overrides) run->overrides.push_back({path, value});
    const auto t0 = std::chrono::steady_clock::now();
    {
        py::gil_scoped_release unlocked;
        try {
            run->model = is_text ? read_scene_text(source, name.empty() ? "scene" : name, run->overrides)
                                 : read_scene(source, run->overrides);
        } catch (const SceneError& e) {
            // A dict has no lines: its errors name the key path alone; an override's, the override.
            const bool names_override = e.file().rfind("--set ", 0) == 0;
            if (is_text && name.empty() && !names_override) throw SceneError(e.key().empty() ? "scene" : e.key(), 0, "", e.reason());
            throw;
        }
        run->scene_file = is_text ? (name.empty() ? "(dict)" : name) : source;
        run->dataset.emplace(run->model);
        run->report.model = &run->model;
        const double read_seconds = seconds_since(t0);
        if (const std::optional<std::string> why = setup_too_large(run->model)) throw SceneError(run->scene_file, 0, "", *why);
        PathFollowing analysis(run->model);
        if (const std::string m = analysis.initial_mechanism(); !m.empty()) throw SceneError(run->scene_file, 0, "", m);
        RunReport& report = run->report;
        report.scene_file = run->scene_file;
        for (const Override& o : run->overrides) report.overrides.emplace_back(o.path, o.value);
        run->curve_csv = curve_header(run->model);
        const auto t1 = std::chrono::steady_clock::now();
        std::atomic<bool> stop{false};
        std::optional<py::error_already_set> raised;
        auto shown = t1 - std::chrono::seconds(1); // the first step is shown
        const auto show = [&](const StepResult& r, bool last) {
            const auto now = std::chrono::steady_clock::now();
            if (progress.is_none() || raised || (!last && now - shown < std::chrono::milliseconds(100))) return;
            shown = now;
            py::gil_scoped_acquire locked;
            try {
                progress(r.step, share_done(run->model, r), r.load, r.control_displacement);
            } catch (py::error_already_set& e) {
                raised.emplace(std::move(e));
                stop = true;
            }
        };
        RunControl control;
        control.interrupt = &stop;
        {
            const InterruptibleRun interruptible(stop);
            report.summary = analysis.run({[&](const StepResult& r) {
                show(r, false);
                run->curve_csv += curve_row(run->model, r);
                report.note(r);
                run->steps.push_back(r);
            }}, control);
        }
        if (!run->steps.empty()) show(run->steps.back(), true);
        if (raised) {
            py::gil_scoped_acquire locked;
            throw std::move(*raised);
        }
        if (interrupted_by_signal) {
            py::gil_scoped_acquire locked;
            PyErr_SetNone(PyExc_KeyboardInterrupt);
            throw py::error_already_set();
        }
        report.stage_seconds = {{"read", read_seconds}, {"analysis", seconds_since(t1)}};
        run->summary = report.summary;
    }
    return run;
}

// A scene (a file or TOML text) read with its overrides, and `find` at step `step` of its
// run, without the GIL.
template <class Found, class Find>
Found at_step_of_scene(const std::string& source, bool is_text, const std::string& name,
                       const std::vector<std::pair<std::string, std::string>>& overrides, int count, int step, Find find) {
    std::vector<Override> parsed;
    for (const auto& [path, value] : overrides) parsed.push_back({path, value});
    py::gil_scoped_release unlocked;
    const Model model = is_text ? read_scene_text(source, name.empty() ? "scene" : name, parsed) : read_scene(source, parsed);
    return find(model, count, step);
}

// The natural modes of a scene at step `step` of its run (plastica modes): one dict per mode.
py::list modes_of_scene(const std::string& source, bool is_text, const std::string& name,
                        const std::vector<std::pair<std::string, std::string>>& overrides, int count, int step) {
    const ModesAtStep found = at_step_of_scene<ModesAtStep>(source, is_text, name, overrides, count, step, modes_at_step);
    py::list out;
    for (const ModeRow& m : found.modes.modes) {
        py::dict row;
        row["mode"] = m.mode;
        row["period"] = m.period;
        row["frequency"] = m.frequency;
        row["omega"] = m.omega;
        row["effective_mass_x"] = m.effective_mass_x;
        row["effective_mass_y"] = m.effective_mass_y;
        row["share_x"] = found.modes.mass_x > 0.0 ? m.effective_mass_x / found.modes.mass_x : 0.0;
        row["share_y"] = found.modes.mass_y > 0.0 ? m.effective_mass_y / found.modes.mass_y : 0.0;
        py::array_t<double> shape({static_cast<py::ssize_t>(m.shape.size() / 3), static_cast<py::ssize_t>(3)});
        std::copy(m.shape.begin(), m.shape.end(), shape.mutable_data());
        row["shape"] = shape;
        out.append(row);
    }
    return out;
}

// The critical load factors and buckling modes of a scene's loads at step `step` of its run
// (plastica buckling): one dict per mode.
py::list buckling_of_scene(const std::string& source, bool is_text, const std::string& name,
                           const std::vector<std::pair<std::string, std::string>>& overrides, int count, int step) {
    const BucklingAtStep found = at_step_of_scene<BucklingAtStep>(source, is_text, name, overrides, count, step, buckling_at_step);
    py::list out;
    for (const BucklingMode& m : found.buckling.modes) {
        py::dict row;
        row["mode"] = m.mode;
        row["load_factor"] = m.load_factor;
        row["above_state"] = m.above_state;
        py::array_t<double> shape({static_cast<py::ssize_t>(m.shape.size() / 3), static_cast<py::ssize_t>(3)});
        std::copy(m.shape.begin(), m.shape.end(), shape.mutable_data());
        row["shape"] = shape;
        out.append(row);
    }
    return out;
}

// Writes what `plastica run --no-render` writes: the VTU/PVD series, curve.csv and run.json.
void write_run(const Run& run, const std::string& folder) {
    namespace fs = std::filesystem;
    py::gil_scoped_release unlocked;
    // Held while writing: another thread or process writing into the same folder is refused.
    OutputFolderOptions options;
    options.scene_name = run.model.name;
    options.force = true; // a Result is written where the script says, as before
    options.holder = "a Python Result.write";
    const OutputFolder output(folder, std::move(options));
    {
        VtuSeriesWriter series(run.model, folder);
        for (const StepResult& s : run.steps) series(s);
        series.finish();
    }
    write_file_atomically((fs::path(folder) / "curve.csv").string(), run.curve_csv);
    write_run_report((fs::path(folder) / "run.json").string(), run.report);
}

// One step's arrays (numpy_arrays.hpp).
py::dict step_arrays(const Run& run, int k) {
    if (k < 0) k += static_cast<int>(run.steps.size());
    if (k < 0 || k >= static_cast<int>(run.steps.size())) throw py::index_error("no step " + std::to_string(k));
    const StepResult& s = run.steps[static_cast<std::size_t>(k)];
    return dataset_arrays((*run.dataset)(s, static_cast<double>(s.step)));
}

} // namespace

PYBIND11_MODULE(_plastica, m) {
    m.doc() = "Plastica's engine: co-rotational beams with plastic hinges, fibre sections and contact";
    static py::exception<SceneError> scene_error(m, "SceneError", PyExc_ValueError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const SceneError& e) {
            scene_error(e.what());
        }
    });
    py::class_<Run, std::shared_ptr<Run>>(m, "Run")
        .def_property_readonly("status", [](const Run& r) { return std::string(to_string(r.summary.status)); })
        .def_property_readonly("reason", [](const Run& r) { return r.summary.reason; })
        .def_property_readonly("scene_name", [](const Run& r) { return r.model.name; })
        .def_property_readonly("curve_csv", [](const Run& r) { return r.curve_csv; })
        .def_property_readonly("report_json", &Run::report_json)
        .def_property_readonly("step_count", [](const Run& r) { return r.steps.size(); })
        .def("step_arrays", &step_arrays, py::arg("k"))
        .def("write", &write_run, py::arg("folder"));
    m.def("run_scene", &run_scene, py::arg("source"), py::arg("is_text"), py::arg("name"), py::arg("overrides"),
          py::arg("progress") = py::none());
    m.def("modes_of_scene", &modes_of_scene, py::arg("source"), py::arg("is_text"), py::arg("name"), py::arg("overrides"),
          py::arg("count"), py::arg("step"));
    m.def("buckling_of_scene", &buckling_of_scene, py::arg("source"), py::arg("is_text"), py::arg("name"), py::arg("overrides"),
          py::arg("count"), py::arg("step"));
    bind_result_folder(m);
    m.attr("version") = PLASTICA_VERSION;
}
