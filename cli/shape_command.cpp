#include "shape_command.hpp"

#include "default_folder.hpp"
#include "drawing_program.hpp"
#include "options.hpp"
#include "render_stage.hpp"

#include "atomic_file.hpp"
#include "output_folder.hpp"
#include "scene_reader.hpp"
#include "vtu_series_writer.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

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

void write_shapes(const Model& model, const ShapeCommand& command, const ShapesFound& found, int at_step,
                  const std::string& folder, const std::string& holder) {
    namespace fs = std::filesystem;
    OutputFolderOptions o;
    o.holder = holder;
    OutputFolder lock(folder, std::move(o));
    write_file_atomically((fs::path(folder) / command.table_file).string(), found.table);
    Model shown = model;
    shown.title = command.title + std::string(at_step > 0 ? " at step " + std::to_string(at_step) : "") +
                  (model.title.empty() ? "" : ": " + model.title);
    shown.report.load_label = command.load_label;
    shown.report.displacement_label = command.displacement_label;
    shown.report.length_unit.clear(), shown.report.force_unit.clear();
    shown.analysis.scheme = Scheme::load_control;
    shown.stages.clear();
    VtuSeriesWriter writer(shown, folder, {1, SeriesTime::step});
    for (const Shape& s : found.shapes) {
        StepResult r = found.state;
        r.step = s.number;
        const double k = shape_scale(model, s.displacement);
        for (std::size_t d = 0; d < r.displacement.size(); ++d) r.displacement[d] = k * s.displacement[d];
        r.load = s.load;
        r.control_displacement = s.control;
        writer(r);
    }
    writer.finish();
}

} // namespace

int shape_command(const Args& args, const ShapeCommand& command) {
    po::options_description options("Options");
    options.add_options()
        ("scene", po::value<std::string>()->required(), "scene file (TOML)")
        ("count,n", po::value<int>()->default_value(6), command.what.c_str())
        ("step", po::value<int>(), "at this step of the scene's run (default: the unloaded structure)")
        ("output,o", po::value<std::string>(), ("output folder (default out/<scene>/" + command.name + ")").c_str())
        ("no-render", (command.table_file + " and the VTU series only").c_str())
        ("quiet,q", "no progress on stderr");
    add_render_options(options);
    po::positional_options_description positional;
    positional.add("scene", 1);
    po::variables_map vm;
    if (auto code = parse_options(args, command.usage, options, positional, vm)) return *code;
    const bool draws = !vm.count("no-render");
    if (draws && !can_draw()) return hand_over_to_drawing(command.name, args);
    render::RenderOptions render_options;
    if (auto code = read_render_options(vm, render_options)) return *code;
    // A shape's forces are those of the state it is taken at, not the shape's: coloured by how
    // far each point moves, and without the state's loads.
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
    ShapesFound found;
    try {
        found = command.find(model, count, at_step);
    } catch (const std::runtime_error& e) {
        std::cerr << "plastica: " << scene_file << ": " << e.what() << "\n";
        // The run ended before the step asked for: the step is the user's to change.
        return std::string(e.what()).rfind("the run ends at step", 0) == 0 ? bad_input : stopped_early;
    }
    if (std::any_of(found.state.applied_load.begin(), found.state.applied_load.end(), [](double f) { return f != 0.0; }))
        render_options.hide.push_back("loads");
    namespace fs = std::filesystem;
    const std::string folder = vm.count("output") ? vm["output"].as<std::string>()
                                                  : (fs::path(default_output_folder(model.name)) / command.name).string();
    try {
        write_shapes(model, command, found, at_step, folder, "plastica " + command.name + " " + scene_file);
    } catch (const std::exception& e) {
        std::cerr << "plastica: " << e.what() << "\n";
        return stopped_early;
    }
    if (!vm.count("quiet")) {
        for (const std::string& note : found.notes) std::cerr << "plastica: " << note << "\n";
        for (const Shape& s : found.shapes) std::cerr << s.line << "\n";
    }
#ifdef PLASTICA_DRAWING
    if (draws) return render_and_report(folder, render_options);
#endif
    return ok;
}

} // namespace plastica::cli
