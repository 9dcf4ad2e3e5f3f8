// plastica study: error against run time over ladders of elements, fibres, integration points and
// increments, optionally for two ways of modelling plasticity; study.csv, a table on stdout and study.png.
#include "commands.hpp"
#include "options.hpp"
#include "output_folder.hpp"

#include "frame_composer.hpp"
#include "png_file.hpp"
#include "render_error.hpp"
#include "scene_error.hpp"
#include "scene_reader.hpp"
#include "study.hpp"
#include "study_error.hpp"

#include <vtkImageData.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace plastica::cli {

namespace {

std::vector<double> numbers(const std::string& text, const std::string& what) {
    std::vector<double> values;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        std::size_t used = 0;
        try {
            values.push_back(std::stod(item, &used));
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != item.size() || !(values.empty() || std::isfinite(values.back())))
            throw StudyError(what + ": '" + item + "' is not a number");
    }
    return values;
}

Ladder ladder(const std::string& text) {
    const auto eq = text.find('=');
    if (eq == std::string::npos) throw StudyError("--vary takes NAME=v1,v2,… (got '" + text + "')");
    Ladder l{text.substr(0, eq), numbers(text.substr(eq + 1), "--vary " + text.substr(0, eq))};
    for (double v : l.levels)
        if (!(v > 0)) throw StudyError("--vary " + l.parameter + ": levels must be positive");
    return l;
}

std::string percent(double relative) {
    char b[32];
    if (std::isnan(relative)) return "-";
    std::snprintf(b, sizeof b, "%.3g %%", 100.0 * relative);
    return b;
}

} // namespace

int study_command(const Args& args) {
    po::options_description options("Options");
    options.add_options()
        ("scene", po::value<std::string>()->required(), "scene file (TOML)")
        ("vary", po::value<std::vector<std::string>>()->composing(),
         "NAME=v1,v2,… with NAME elements, fibres, integration_points or increment (repeatable); plasticity=hinges,distributed runs every ladder with each method against the last method's finest level")
        ("reference", po::value<std::string>(), "exact, finest, or a CSV file of displacement,load (default: exact when the scene has a closed form)")
        ("at", po::value<std::string>(), "displacements where the error is reported, e.g. 20,40,60")
        ("output,o", po::value<std::string>(), "output folder (default out/<scene>/study)");
    po::positional_options_description positional;
    positional.add("scene", 1);
    po::variables_map vm;
    if (auto code = parse_options(args, "plastica study SCENE --vary elements=10,20,50 [--vary …] [--reference exact|finest|FILE]",
                                  options, positional, vm))
        return *code;
    StudyOptions o;
    o.scene = vm["scene"].as<std::string>();
    StudyReport report;
    Model model;
    try {
        model = read_scene(o.scene);
        if (!vm.count("vary")) throw StudyError("give at least one --vary NAME=v1,v2,…");
        for (const std::string& v : vm["vary"].as<std::vector<std::string>>()) {
            if (v.rfind("plasticity=", 0) == 0) {
                std::stringstream in(v.substr(11));
                for (std::string method; std::getline(in, method, ',');) {
                    if (method != "hinges" && method != "distributed")
                        throw StudyError("--vary plasticity: expected hinges or distributed, got '" + method + "'");
                    o.methods.push_back(method);
                }
                if (o.methods.size() < 2) throw StudyError("--vary plasticity needs two methods, e.g. plasticity=hinges,distributed");
                continue;
            }
            o.ladders.push_back(ladder(v));
        }
        if (o.ladders.empty()) throw StudyError("--vary plasticity=… compares methods over a ladder: add --vary elements=… (or fibres, increment)");
        o.reference = vm.count("reference") ? vm["reference"].as<std::string>() : (model.report.exact.empty() ? "finest" : "exact");
        if (vm.count("at")) o.at = numbers(vm["at"].as<std::string>(), "--at");
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

    std::ofstream csv(folder / "study.csv");
    csv.precision(10);
    csv << "method,parameter,level,seconds,repeats,steps,iterations,status,is_reference,max_error,rms_error";
    for (double d : report.at) csv << ",error_at_" << d;
    csv << "\n";
    std::cout << model.name << ": errors against " << report.reference << " (relative to the peak load)\n";
    const bool compared = !o.methods.empty();
    if (compared) std::printf("%-12s ", "plasticity");
    std::printf("%-10s %8s %10s %6s %7s %10s %10s", "parameter", "level", "seconds", "steps", "iters", "max", "rms");
    for (double d : report.at) std::printf("   at %-6g", d);
    std::printf("\n");
    for (const StudyLevel& l : report.levels) {
        csv << l.method << ',' << l.parameter << ',' << l.level << ',' << l.seconds << ',' << l.repeats << ',' << l.steps << ',' << l.iterations
            << ",\"" << l.status << "\"," << l.is_reference << ',' << l.error.max << ',' << l.error.rms;
        for (double e : l.error.at) csv << ',' << e;
        csv << "\n";
        if (compared) std::printf("%-12s ", l.method.c_str());
        std::printf("%-10s %8g %10.4g %6d %7d %10s %10s", l.parameter.c_str(), l.level, l.seconds, l.steps, l.iterations,
                    l.is_reference ? "reference" : percent(l.error.max).c_str(), l.is_reference ? "" : percent(l.error.rms).c_str());
        for (double e : l.error.at) std::printf("   %-9s", l.is_reference ? "" : percent(e).c_str());
        std::printf("\n");
    }
    for (const StudyReport::Order& o : report.observed_order)
        std::printf("observed order of convergence in %s%s: %.2f\n", o.parameter.c_str(),
                    o.method.empty() ? "" : (" with " + o.method).c_str(), o.order);

    render::ChartFigure chart{model.name + (compared ? ": error against " + report.reference : ": error of the load-displacement curve against run time"), "wall time of the analysis [s]",
                              "max error of the load / peak load", {}, true};
    chart.log_scale = true;
    const render::Rgb colours[] = {{31, 90, 180}, {230, 120, 20}, {40, 150, 70}, {170, 40, 150}, {120, 120, 120}, {200, 50, 50}};
    // One line per method and parameter, in the order of the observed orders.
    int k = 0;
    for (const StudyReport::Order& order : report.observed_order) {
        const std::string name = (order.method.empty() ? "" : order.method + ", ") + order.parameter + " ";
        render::ChartSeries line{name, {}, {}, colours[k % 6], 2.5f};
        render::ChartSeries dots{"", {}, {}, colours[k % 6], 9.0f, true};
        for (const StudyLevel& l : report.levels)
            if (l.parameter == order.parameter && l.method == order.method && !l.is_reference && l.error.max > 0) {
                line.x.push_back(l.seconds);
                line.y.push_back(l.error.max);
                line.label += (line.x.size() == 1 ? "" : ", ") + render::number(l.level);
            }
        if (std::isfinite(order.order)) line.label += "  (order " + render::number(order.order) + ")";
        dots.x = line.x;
        dots.y = line.y;
        chart.series.push_back(line);
        chart.series.push_back(dots);
        ++k;
    }
    try {
        render::write_png(render::draw_chart(chart), (folder / "study.png").string());
    } catch (const render::RenderError& e) {
        std::cerr << "plastica: cannot draw study.png: " << e.what() << "\n";
        return bad_input;
    }
    std::cout << "-> " << (folder / "study.csv").string() << ", " << (folder / "study.png").string() << "\n";
    return ok;
}

} // namespace plastica::cli
