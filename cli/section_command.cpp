// plastica section: for each inelastic section of a scene, the N–M capacity curve and the
// moment–curvature curves at several axial force levels, as CSV.
#include "commands.hpp"
#include "options.hpp"
#include "output_folder.hpp"

#include "scene_reader.hpp"
#include "section/fibre_section.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>

namespace plastica::cli {

int section_command(const Args& args) {
    po::options_description options("Options");
    options.add_options()
        ("scene", po::value<std::string>()->required(), "scene file (TOML)")
        ("section", po::value<std::string>(), "only this section (default: every inelastic one)")
        ("output,o", po::value<std::string>(), "output folder (default out/<scene>/sections)")
        ("points", po::value<int>()->default_value(101), "points per curve");
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
    int written = 0;
    for (const SectionSpec& spec : model.sections) {
        if (vm.count("section") && spec.name != vm["section"].as<std::string>()) continue;
        if (!spec.steel) continue;
        FibreSection section(spec);
        const double Ny = section.axial_capacity_tension();
        {
            std::ofstream out(folder / (spec.name + "_capacity.csv"));
            out.precision(12);
            out << "axial_force,moment_positive,moment_negative,first_yield_moment\n";
            for (int k = 0; k < points; ++k) {
                const double N = -Ny + 2.0 * Ny * k / (points - 1);
                out << N << ',' << section.moment_capacity(N, 1.0) << ',' << -section.moment_capacity(N, -1.0)
                    << ',' << std::max(0.0, section.first_yield_moment(N)) << '\n';
            }
        }
        {
            std::ofstream out(folder / (spec.name + "_moment_curvature.csv"));
            out.precision(12);
            out << "axial_ratio,axial_force,curvature,moment\n";
            const double kappa_y = spec.steel->fy / spec.E / std::sqrt(spec.inertia / spec.area) / std::sqrt(3.0);
            for (double ratio : {0.0, 0.2, 0.4, 0.6, 0.8}) {
                for (const MomentCurvaturePoint& p : section.moment_curvature(ratio * Ny, 10.0 * kappa_y, points - 1))
                    out << ratio << ',' << ratio * Ny << ',' << p.curvature << ',' << p.moment << '\n';
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
