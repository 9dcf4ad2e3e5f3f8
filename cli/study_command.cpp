// plastica study: error against run time over ladders of elements, fibres, integration points and
// increments, optionally for two ways of modelling plasticity; study.csv, a table on stdout and study.png.
#include "commands.hpp"
#include "options.hpp"
#include "default_folder.hpp"

#include "atomic_file.hpp"

#include "png_file.hpp"
#include "render_error.hpp"
#include "scene_error.hpp"
#include "scene_reader.hpp"
#include "scene_schema.hpp"
#include "study.hpp"
#include "study_chart.hpp"
#include "study_table.hpp"
#include "study_error.hpp"

#include <vtkImageData.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace plastica::cli {

int study_command(const Args& args) {
    std::string names;
    for (const std::string& key : studied_keys()) names += (names.empty() ? "" : ", ") + key;
    const std::string vary_help = "NAME=v1,v2,… with NAME one of " + names +
                                  " (repeatable); plasticity=hinges,distributed runs every ladder with each method, each against its own reference";
    po::options_description options("Options");
    options.add_options()
        ("scene", po::value<std::string>()->required(), "scene file (TOML)")
        ("vary", po::value<std::vector<std::string>>()->composing(),
         vary_help.c_str())
        ("reference", po::value<std::string>(), "exact, extrapolated, finest, or a CSV file of displacement,load (default: exact when the scene has a closed form; else extrapolated when methods are compared over three levels or more, finest otherwise)")
        ("at", po::value<std::string>(), "displacements where the error is reported, e.g. 20,40,60")
        ("output,o", po::value<std::string>(), "output folder (default out/<scene>/study)");
    po::positional_options_description positional;
    positional.add("scene", 1);
    po::variables_map vm;
    if (auto code = parse_options(args, "plastica study SCENE --vary elements=10,20,50 [--vary …] [--reference exact|extrapolated|finest|FILE]",
                                  options, positional, vm))
        return *code;
    StudyOptions o;
    o.scene = vm["scene"].as<std::string>();
    StudyReport report;
    Model model;
    try {
        model = read_scene(o.scene);
        if (!vm.count("vary")) throw StudyError("give at least one --vary NAME=v1,v2,…");
        for (const std::string& v : vm["vary"].as<std::vector<std::string>>()) add_variation(o, v);
        if (o.ladders.empty()) throw StudyError("--vary plasticity=… compares methods over a ladder: add --vary elements=… (or fibres, increment)");
        const bool three_levels = std::all_of(o.ladders.begin(), o.ladders.end(), [](const Ladder& l) { return l.levels.size() >= 3; });
        o.reference = vm.count("reference")             ? vm["reference"].as<std::string>()
                      : !model.report.exact.empty()     ? "exact"
                      : !o.methods.empty() && three_levels ? "extrapolated"
                                                        : "finest";
        if (vm.count("at")) o.at = parse_numbers(vm["at"].as<std::string>(), "--at");
        report = run_study(o);
    } catch (const SceneError& e) {
        std::cerr << "plastica: " << e.what() << "\n";
        return bad_input;
    } catch (const StudyError& e) {
        std::cerr << "plastica: " << o.scene << ": " << e.what() << "\n";
        return bad_input;
    }
    namespace fs = std::filesystem;
    const fs::path folder = vm.count("output") ? fs::path(vm["output"].as<std::string>()) : fs::path(default_output_folder(model.name)) / "study";
    fs::create_directories(folder);

    std::ostringstream csv;
    write_study_csv(csv, report);
    write_file_atomically((folder / "study.csv").string(), csv.str());
    print_study_table(std::cout, model.name, report, !o.methods.empty());
    try {
        render::write_png(render::draw_chart(render::study_chart(model.name, report)), (folder / "study.png").string());
    } catch (const render::RenderError& e) {
        std::cerr << "plastica: cannot draw study.png: " << e.what() << "\n";
        return bad_input;
    }
    std::cout << "-> " << (folder / "study.csv").string() << ", " << (folder / "study.png").string();
    if (!report.limits.empty()) {
        std::ostringstream limits;
        write_limits_csv(limits, report);
        write_file_atomically((folder / "limits.csv").string(), limits.str());
        std::cout << ", " << (folder / "limits.csv").string();
    }
    std::cout << "\n";
    return ok;
}

} // namespace plastica::cli
