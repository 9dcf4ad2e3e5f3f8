// plastica section: for each inelastic section of a scene, the N–M capacity curve and the
// moment–curvature curves at several axial force levels, as CSV and as charts; the N–M chart
// carries the path of the most loaded element end when the scene's results are at hand.
#include "commands.hpp"
#include "progress.hpp"
#include "options.hpp"
#include "default_folder.hpp"

#include "atomic_file.hpp"
#include "output_folder.hpp"
#include "safe_names.hpp"

#include "png_file.hpp"
#include "render_error.hpp"
#include "scene_reader.hpp"
#include "section/section_curves.hpp"
#include "section_charts.hpp"
#include "section_tables.hpp"

#include <vtkImageData.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <set>
#include <sstream>

namespace plastica::cli {

namespace {
// Measured on an HEB 300 of 2 million fibres, 101 points: 90 s for its capacity and five M–κ curves.
constexpr double seconds_per_fibre_point = 4.5e-7;
} // namespace

int section_command(const Args& args) {
    po::options_description options("Options");
    options.add_options()
        ("scene", po::value<std::string>()->required(), "scene file (TOML)")
        ("section", po::value<std::string>(), "only this section (default: every inelastic one)")
        ("output,o", po::value<std::string>(), "output folder (default out/<scene>/sections)")
        ("points", po::value<int>()->default_value(101), "points per curve")
        ("series", po::value<std::string>(), "results whose most loaded end is drawn on the N-M chart (default out/<scene> when present)")
        ("no-charts", "CSV only")
        ("quiet,q", "no progress on stderr");
    po::positional_options_description positional;
    positional.add("scene", 1);
    po::variables_map vm;
    if (auto code = parse_options(args, "plastica section SCENE [--section NAME] [-o DIR]", options, positional, vm))
        return *code;
    Model model;
    try {
        model = read_scene(vm["scene"].as<std::string>());
    } catch (const SceneError& e) {
        std::cerr << "plastica: " << e.what() << "\n";
        return bad_input;
    }
    const int points = vm["points"].as<int>();
    if (points < 3 || points > 100000) {
        std::cerr << "plastica: --points takes a whole number from 3 to 100000\n";
        return bad_input;
    }
    namespace fs = std::filesystem;
    const fs::path folder = vm.count("output") ? fs::path(vm["output"].as<std::string>())
                                               : fs::path(default_output_folder(model.name)) / "sections";
    // The folder is this command's own while it writes (a lock; no links where files go).
    std::optional<OutputFolder> lock;
    try {
        OutputFolderOptions o;
        o.clear_results = false;
        o.holder = "plastica section " + vm["scene"].as<std::string>();
        lock.emplace(folder.string(), std::move(o));
    } catch (const OutputFolderError& e) {
        std::cerr << "plastica: " << e.what() << "\n";
        return bad_input;
    }
    // The results of this scene, when they are at hand, give the N-M chart its load path.
    std::optional<render::ResultSeries> series;
    const std::string results = vm.count("series") ? vm["series"].as<std::string>() : default_output_folder(model.name);
    try {
        if (vm.count("series") || fs::exists(fs::path(results) / (model.name + ".pvd"))) series = render::open_series(results);
    } catch (const render::RenderError& e) {
        std::cerr << "plastica: " << e.what() << "\n";
        return bad_input;
    }
    int written = 0;
    std::set<std::string> stems;
    for (const SectionSpec& spec : model.sections) {
        if (vm.count("section") && spec.name != vm["section"].as<std::string>()) continue;
        if (!spec.steel) continue;
        // The curves' work grows with fibres × points: refused beyond what would take many
        // minutes, announced beyond a few seconds, with progress per curve.
        const double seconds = seconds_per_fibre_point * static_cast<double>(spec.fibres.size()) * points;
        if (seconds > 600.0) {
            std::cerr << "plastica: section '" << spec.name << "': " << spec.fibres.size() << " fibres × " << points
                      << " points would take about " << std::lround(seconds / 60.0)
                      << " min; use fewer fibres, or fewer --points\n";
            return bad_input;
        }
        const bool announce = seconds > 5.0 && !vm.count("quiet");
        if (announce)
            std::cerr << "plastica: section '" << spec.name << "': " << spec.fibres.size() << " fibres × " << points
                      << " points, about " << duration_text(seconds) << "\n";
        const FibreSection section(spec);
        const std::vector<CapacityRow> capacity = capacity_table(section, points);
        std::vector<MomentCurvatureCurve> curvature;
        Progress progress("section " + spec.name, 1);
        const std::vector<double> ratios{0.0, 0.2, 0.4, 0.6, 0.8};
        for (std::size_t k = 0; k < ratios.size(); ++k) {
            if (announce)
                progress.update(static_cast<int>(k), static_cast<double>(k) / ratios.size(),
                                "M-κ at N/Ny = " + std::to_string(ratios[k]).substr(0, 3));
            curvature.push_back(moment_curvature_family(section, {ratios[k]}, 10.0, points - 1).front());
        }
        progress.finish();
        // A section's name is the user's text: its files take a safe stem of it, inside the folder.
        std::string stem = file_stem_for(spec.name);
        // Two names of one stem ("HEB 200", "HEB_200") keep files of their own.
        for (int k = 2; !stems.insert(stem).second; ++k) stem = file_stem_for(spec.name) + "_" + std::to_string(k);
        try {
            std::ostringstream out, curves;
            write_capacity_csv(out, capacity);
            write_moment_curvature_csv(curves, curvature);
            write_file_atomically((folder / (stem + "_capacity.csv")).string(), out.str());
            write_file_atomically((folder / (stem + "_moment_curvature.csv")).string(), curves.str());
        } catch (const WriteError& e) {
            std::cerr << "plastica: " << e.what() << "\n";
            return stopped_early;
        }
        if (!vm.count("no-charts")) {
            try {
                std::optional<render::SectionPath> path;
                if (series) path = render::most_loaded_end(*series);
                const render::SectionUnits units{model.report.length_unit, model.report.force_unit};
                render::write_png(render::draw_chart(render::capacity_chart(spec.name, capacity, units, path, section.has_strain_limits())),
                                  (folder / (stem + "_capacity.png")).string());
                render::write_png(render::draw_chart(render::moment_curvature_chart(spec.name, curvature, units)),
                                  (folder / (stem + "_moment_curvature.png")).string());
            } catch (const render::RenderError& e) {
                std::cerr << "plastica: cannot draw the section charts: " << e.what() << "\n";
                return bad_input;
            }
        }
        std::cout << spec.name << ": Ny = " << section.axial_capacity_tension() << ", Mp(0) = " << section.moment_capacity(0.0, 1.0)
                  << ", My(0) = " << section.first_yield_moment(0.0) << "  -> " << (folder / stem).string()
                  << "_{capacity,moment_curvature}.csv\n";
        ++written;
    }
    if (written == 0) {
        std::cerr << "plastica: " << vm["scene"].as<std::string>() << ": no inelastic section"
                  << (vm.count("section") ? " named '" + vm["section"].as<std::string>() + "'" : std::string()) << "\n";
        return bad_input;
    }
    return ok;
}

} // namespace plastica::cli
