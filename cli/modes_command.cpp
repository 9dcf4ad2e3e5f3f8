// plastica modes: the natural modes of a scene's structure, at its unloaded state or at a step of
// its run (hinges, fibres and contacts as they stand there): modes.csv with periods,
// frequencies and effective modal masses, a VTU series of the shapes, and their pictures.
#include "commands.hpp"
#include "default_folder.hpp"
#include "drawing_program.hpp"
#include "options.hpp"
#include "render_stage.hpp"

#include "analysis/modes_at_step.hpp"
#include "atomic_file.hpp"
#include "dynamics/modal_analysis.hpp"
#include "output_folder.hpp"
#include "scene_reader.hpp"
#include "vtu_series_writer.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

namespace plastica::cli {

namespace {

// A shape drawn with its largest translation a tenth of the structure's size.
double shape_scale(const Model& model, const std::vector<double>& shape) {
    double largest = 0.0, x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        largest = std::max(largest, std::hypot(shape[3 * n], shape[3 * n + 1]));
        x0 = std::min(x0, model.nodes[n].x), x1 = std::max(x1, model.nodes[n].x);
        y0 = std::min(y0, model.nodes[n].y), y1 = std::max(y1, model.nodes[n].y);
    }
    const double size = std::max(x1 - x0, y1 - y0);
    return largest > 0.0 ? 0.1 * size / largest : 0.0;
}

std::string modes_table(const ModalResult& modes) {
    std::ostringstream out;
    out.precision(10);
    out << "mode,period,frequency,omega,effective_mass_x,effective_mass_y,share_x,share_y\n";
    for (const ModeRow& m : modes.modes)
        out << m.mode << ',' << m.period << ',' << m.frequency << ',' << m.omega << ',' << m.effective_mass_x << ','
            << m.effective_mass_y << ',' << (modes.mass_x > 0.0 ? m.effective_mass_x / modes.mass_x : 0.0) << ','
            << (modes.mass_y > 0.0 ? m.effective_mass_y / modes.mass_y : 0.0) << '\n';
    return out.str();
}

} // namespace

int modes_command(const Args& args) {
    po::options_description options("Options");
    options.add_options()
        ("scene", po::value<std::string>()->required(), "scene file (TOML)")
        ("count,n", po::value<int>()->default_value(6), "modes to find")
        ("step", po::value<int>(), "at this step of the scene's run (default: the unloaded structure)")
        ("output,o", po::value<std::string>(), "output folder (default out/<scene>/modes)")
        ("no-render", "modes.csv and the VTU series only")
        ("quiet,q", "no progress on stderr");
    add_render_options(options);
    po::positional_options_description positional;
    positional.add("scene", 1);
    po::variables_map vm;
    if (auto code = parse_options(args, "plastica modes SCENE [-n N] [--step K] [-o DIR]", options, positional, vm)) return *code;
    const bool draws = !vm.count("no-render");
    if (draws && !can_draw()) return hand_over_to_drawing("modes", args);
    render::RenderOptions render_options;
    if (auto code = read_render_options(vm, render_options)) return *code;
    // A shape's forces are those of the state it is taken at, not the mode's: coloured by how far
    // each point moves, and without the state's loads.
    if (render_options.field.empty()) render_options.field = "displacement";
    const std::string scene_file = vm["scene"].as<std::string>();
    Model model;
    try {
        model = read_scene(scene_file);
    } catch (const SceneError& e) {
        std::cerr << "plastica: " << e.what() << "\n";
        return bad_input;
    }
    const int count = vm["count"].as<int>();
    if (count < 1 || count > 1000) {
        std::cerr << "plastica: --count takes a whole number from 1 to 1000\n";
        return bad_input;
    }
    const int at_step = vm.count("step") ? vm["step"].as<int>() : 0;
    if (at_step < 0) {
        std::cerr << "plastica: --step takes a step number ≥ 0\n";
        return bad_input;
    }
    std::optional<StepResult> state;
    ModalResult modes;
    try {
        ModesAtStep found = modes_at_step(model, count, at_step);
        modes = std::move(found.modes);
        state = std::move(found.state);
    } catch (const ModalError& e) {
        std::cerr << "plastica: " << scene_file << ": " << e.what() << "\n";
        return stopped_early;
    } catch (const std::runtime_error& e) {
        std::cerr << "plastica: " << scene_file << ": " << e.what() << "\n";
        return bad_input;
    }
    if (std::any_of(state->applied_load.begin(), state->applied_load.end(), [](double f) { return f != 0.0; }))
        render_options.hide.push_back("loads");
    namespace fs = std::filesystem;
    const std::string folder = vm.count("output") ? vm["output"].as<std::string>()
                                                  : (fs::path(default_output_folder(model.name)) / "modes").string();
    try {
        OutputFolderOptions o;
        o.holder = "plastica modes " + scene_file;
        OutputFolder lock(folder, std::move(o));
        write_file_atomically((fs::path(folder) / "modes.csv").string(), modes_table(modes));
        // The shapes as a series: one "step" per mode, its period and frequency as the curve.
        Model shown = model;
        shown.title = "Modes" + std::string(at_step > 0 ? " at step " + std::to_string(at_step) : "") +
                      (model.title.empty() ? "" : ": " + model.title);
        shown.report.load_label = "frequency";
        shown.report.displacement_label = "period";
        shown.report.length_unit.clear(), shown.report.force_unit.clear();
        shown.analysis.scheme = Scheme::load_control;
        shown.stages.clear();
        VtuSeriesWriter writer(shown, folder, {1, SeriesTime::step});
        for (const ModeRow& m : modes.modes) {
            StepResult r = *state;
            r.step = m.mode;
            const double k = shape_scale(model, m.shape);
            for (std::size_t d = 0; d < r.displacement.size(); ++d) r.displacement[d] = k * m.shape[d];
            r.load = m.frequency;
            r.control_displacement = std::isfinite(m.period) ? m.period : 0.0;
            writer(r);
        }
        writer.finish();
    } catch (const std::exception& e) {
        std::cerr << "plastica: " << e.what() << "\n";
        return stopped_early;
    }
    if (!vm.count("quiet"))
        for (const ModeRow& m : modes.modes)
            std::cerr << "mode " << m.mode << ": T = " << m.period << ", f = " << m.frequency << ", M_x = " << m.effective_mass_x
                      << ", M_y = " << m.effective_mass_y << "\n";
#ifdef PLASTICA_DRAWING
    if (draws) return render_and_report(folder, render_options);
#endif
    return ok;
}

} // namespace plastica::cli
