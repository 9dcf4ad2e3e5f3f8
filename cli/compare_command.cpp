// plastica compare: rendered pictures against stored references, for CI. Exit 0 when every
// image is within tolerance, 1 when one differs (or is missing or extra), 2 on bad input.
#include "commands.hpp"
#include "options.hpp"

#include "atomic_file.hpp"
#include "image_compare.hpp"
#include "render_error.hpp"
#include "report_page.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace plastica::cli {

namespace fs = std::filesystem;

namespace {

// A CSV field: quoted, its quotes doubled (a picture's name is the folder's to choose).
std::string csv_field(const std::string& text) {
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string verdict_table(const std::vector<render::ImageVerdict>& verdicts) {
    std::ostringstream t;
    t.precision(17);
    t << "name,passed,differing_fraction,rms,vtk_error,problem\n";
    for (const render::ImageVerdict& v : verdicts)
        t << csv_field(v.name) << "," << (v.passed ? 1 : 0) << "," << v.differing_fraction << "," << v.rms << "," << v.vtk_error << ","
          << csv_field(v.problem) << "\n";
    return t.str();
}

} // namespace

int compare_command(const Args& args) {
    render::CompareOptions defaults;
    po::options_description options("Options");
    options.add_options()
        ("actual", po::value<std::string>()->required(), "PNG or folder of PNGs just rendered")
        ("reference", po::value<std::string>()->required(), "PNG or folder of stored references")
        ("threshold", po::value<int>()->default_value(defaults.threshold), "per-channel difference (0-255) below which pixels count as equal")
        ("max-fraction", po::value<double>()->default_value(defaults.max_fraction), "share of differing pixels an image may have")
        ("region", po::value<std::string>(), "compare only x0,y0,x1,y1 of each picture (fractions of width and height, y from the top)")
        ("diff", po::value<std::string>(), "folder for <name>_diff.png of the images that fail")
        ("report", po::value<std::string>(), "an HTML page with every failing picture beside its reference and its difference (diff images in --diff, or beside the page)")
        ("table", po::value<std::string>(), "a CSV of every picture: name, passed, differing_fraction, rms, vtk_error, problem")
        ("quiet,q", "print failures only");
    po::positional_options_description positional;
    positional.add("actual", 1).add("reference", 1);
    po::variables_map vm;
    if (auto code = parse_options(args, "plastica compare ACTUAL REFERENCE [--threshold T] [--max-fraction F] [--region X0,Y0,X1,Y1] [--diff DIR] [--report FILE] [--table FILE]",
                                  options, positional, vm))
        return *code;
    render::CompareOptions o;
    o.threshold = vm["threshold"].as<int>();
    o.max_fraction = vm["max-fraction"].as<double>();
    if (vm.count("diff")) o.diff_folder = vm["diff"].as<std::string>();
    if (vm.count("region")) {
        const std::string text = vm["region"].as<std::string>();
        double* g = o.region;
        char tail = 0;
        if (std::sscanf(text.c_str(), "%lf,%lf,%lf,%lf%c", &g[0], &g[1], &g[2], &g[3], &tail) != 4) {
            std::cerr << "plastica: --region takes x0,y0,x1,y1 (got '" << text << "')\n";
            return bad_input;
        }
    }
    if (vm.count("report") && o.diff_folder.empty())
        o.diff_folder = (fs::path(vm["report"].as<std::string>()).parent_path() / "diff").string();
    std::vector<render::ImageVerdict> verdicts;
    try {
        verdicts = render::compare_pictures(vm["actual"].as<std::string>(), vm["reference"].as<std::string>(), o);
    } catch (const render::RenderError& e) {
        std::cerr << "plastica: " << e.what() << "\n";
        return bad_input;
    }
    int failed = 0;
    for (const render::ImageVerdict& v : verdicts) {
        failed += !v.passed;
        if (vm.count("quiet") && v.passed) continue;
        char line[256];
        if (v.problem.empty())
            std::snprintf(line, sizeof line, "%-4s %-40s differing %.5f%%  rms %.3f  vtk error %.3f", v.passed ? "ok" : "FAIL",
                          v.name.c_str(), 100.0 * v.differing_fraction, v.rms, v.vtk_error);
        else
            std::snprintf(line, sizeof line, "FAIL %-40s %s", v.name.c_str(), v.problem.c_str());
        std::cout << line << "\n";
    }
    if (vm.count("table")) {
        try {
            write_file_atomically(vm["table"].as<std::string>(), verdict_table(verdicts));
        } catch (const std::exception& e) {
            std::cerr << "plastica: " << e.what() << "\n";
            return bad_input;
        }
    }
    std::ostringstream summary;
    summary << (failed ? std::to_string(failed) + " of " + std::to_string(verdicts.size()) + " images differ"
                       : "all " + std::to_string(verdicts.size()) + " images match")
            << " (threshold " << o.threshold << ", max fraction " << o.max_fraction << ")";
    std::cout << summary.str() << "\n";
    if (vm.count("report")) {
        const fs::path actual(vm["actual"].as<std::string>()), reference(vm["reference"].as<std::string>());
        const bool folders = fs::is_directory(actual);
        std::vector<FailedPicture> pictures;
        for (const render::ImageVerdict& v : verdicts) {
            if (v.passed) continue;
            char why[160];
            std::snprintf(why, sizeof why, "%.3f %% of the pixels differ (rms %.2f)", 100.0 * v.differing_fraction, v.rms);
            const fs::path name(v.name);
            pictures.push_back({v.name, v.problem.empty() ? why : v.problem, (folders ? actual / name : actual).string(),
                                (folders ? reference / name : reference).string(),
                                (fs::path(o.diff_folder) / (name.parent_path() / (name.stem().string() + "_diff.png"))).string()});
        }
        try {
            write_file_atomically(vm["report"].as<std::string>(),
                                  comparison_page("Pictures against their references", summary.str(), pictures));
        } catch (const std::exception& e) {
            std::cerr << "plastica: " << e.what() << "\n";
            return bad_input;
        }
        std::cout << "-> " << vm["report"].as<std::string>() << "\n";
    }
    return failed ? check_failed : ok;
}

} // namespace plastica::cli
