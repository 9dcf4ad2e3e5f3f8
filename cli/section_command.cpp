// plastica section: for each inelastic section of a scene, the N–M capacity curve and the
// moment–curvature curves at several axial force levels, as CSV and as charts; the N–M chart
// carries the path of the most loaded element end when the scene's results are at hand.
#include "commands.hpp"
#include "options.hpp"
#include "output_folder.hpp"

#include "frame_composer.hpp"
#include "png_file.hpp"
#include "render_error.hpp"
#include "scene_reader.hpp"
#include "section/fibre_section.hpp"
#include "section_path.hpp"

#include <vtkImageData.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

namespace plastica::cli {

int section_command(const Args& args) {
    po::options_description options("Options");
    options.add_options()
        ("scene", po::value<std::string>()->required(), "scene file (TOML)")
        ("section", po::value<std::string>(), "only this section (default: every inelastic one)")
        ("output,o", po::value<std::string>(), "output folder (default out/<scene>/sections)")
        ("points", po::value<int>()->default_value(101), "points per curve")
        ("series", po::value<std::string>(), "results whose most loaded end is drawn on the N-M chart (default out/<scene> when present)")
        ("no-charts", "CSV only");
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
    fs::create_directories(folder);
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
    for (const SectionSpec& spec : model.sections) {
        if (vm.count("section") && spec.name != vm["section"].as<std::string>()) continue;
        if (!spec.steel) continue;
        FibreSection section(spec);
        const double Ny = section.axial_capacity_tension();
        render::ChartFigure capacity{spec.name + ": N-M capacity of the fibre section", "bending moment M", "axial force N", {}, true};
        render::ChartFigure curvature{spec.name + ": moment-curvature at constant axial force", "curvature", "bending moment M", {}, true};
        // Both signs of the capacity and of first yield; one legend entry each.
        capacity.series = {{"fully plastic Mp(N)", {}, {}, render::colour::curve_progress, 3.0f},
                           {"", {}, {}, render::colour::curve_progress, 3.0f},
                           {"first yield", {}, {}, render::colour::hinge_yielding_high, 2.0f},
                           {"", {}, {}, render::colour::hinge_yielding_high, 2.0f}};
        {
            std::ofstream out(folder / (spec.name + "_capacity.csv"));
            out.precision(12);
            out << "axial_force,moment_positive,moment_negative,first_yield_moment\n";
            for (int k = 0; k < points; ++k) {
                const double N = -Ny + 2.0 * Ny * k / (points - 1);
                const double plus = section.moment_capacity(N, 1.0), minus = -section.moment_capacity(N, -1.0);
                const double yield = std::max(0.0, section.first_yield_moment(N));
                out << N << ',' << plus << ',' << minus << ',' << yield << '\n';
                capacity.series[0].x.push_back(plus);
                capacity.series[1].x.push_back(minus);
                capacity.series[2].x.push_back(yield);
                capacity.series[3].x.push_back(-yield);
                for (auto& c : capacity.series) c.y.push_back(N);
            }
        }
        {
            std::ofstream out(folder / (spec.name + "_moment_curvature.csv"));
            out.precision(12);
            out << "axial_ratio,axial_force,curvature,moment\n";
            const double kappa_y = spec.steel->fy / spec.E / std::sqrt(spec.inertia / spec.area) / std::sqrt(3.0);
            const render::Rgb shades[] = {{31, 90, 180}, {40, 150, 70}, {230, 120, 20}, {150, 30, 170}, {90, 90, 90}};
            int shade = 0;
            for (double ratio : {0.0, 0.2, 0.4, 0.6, 0.8}) {
                render::ChartSeries line{"N/Ny = " + render::number(ratio), {}, {}, shades[shade++], 2.5f};
                for (const MomentCurvaturePoint& p : section.moment_curvature(ratio * Ny, 10.0 * kappa_y, points - 1)) {
                    out << ratio << ',' << ratio * Ny << ',' << p.curvature << ',' << p.moment << '\n';
                    line.x.push_back(p.curvature);
                    line.y.push_back(p.moment);
                }
                curvature.series.push_back(line);
            }
        }
        if (!vm.count("no-charts")) {
            try {
                if (series) {
                    const render::SectionPath path = render::most_loaded_end(*series);
                    capacity.series.push_back({"path of " + path.where, path.moment, path.axial_force, render::colour::current_point, 2.0f});
                }
                render::write_png(render::draw_chart(capacity), (folder / (spec.name + "_capacity.png")).string());
                render::write_png(render::draw_chart(curvature), (folder / (spec.name + "_moment_curvature.png")).string());
            } catch (const render::RenderError& e) {
                std::cerr << "plastica: cannot draw the section charts: " << e.what() << "\n";
                return bad_input;
            }
        }
        std::cout << spec.name << ": Ny = " << Ny << ", Mp(0) = " << section.moment_capacity(0.0, 1.0)
                  << ", My(0) = " << section.first_yield_moment(0.0) << "  -> " << (folder / spec.name).string()
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
