// plastica compare: rendered pictures against stored references, for CI. Exit 0 when every
// image is within tolerance, 1 when one differs (or is missing or extra), 2 on bad input.
#include "commands.hpp"
#include "options.hpp"

#include "image_compare.hpp"
#include "render_error.hpp"

#include <cstdio>
#include <iostream>

namespace plastica::cli {

int compare_command(const Args& args) {
    render::CompareOptions defaults;
    po::options_description options("Options");
    options.add_options()
        ("actual", po::value<std::string>()->required(), "PNG or folder of PNGs just rendered")
        ("reference", po::value<std::string>()->required(), "PNG or folder of stored references")
        ("threshold", po::value<int>()->default_value(defaults.threshold), "per-channel difference (0-255) below which pixels count as equal")
        ("max-fraction", po::value<double>()->default_value(defaults.max_fraction), "share of differing pixels an image may have")
        ("diff", po::value<std::string>(), "folder for <name>_diff.png of the images that fail")
        ("quiet,q", "print failures only");
    po::positional_options_description positional;
    positional.add("actual", 1).add("reference", 1);
    po::variables_map vm;
    if (auto code = parse_options(args, "plastica compare ACTUAL REFERENCE [--threshold T] [--max-fraction F] [--diff DIR]",
                                  options, positional, vm))
        return *code;
    render::CompareOptions o;
    o.threshold = vm["threshold"].as<int>();
    o.max_fraction = vm["max-fraction"].as<double>();
    if (vm.count("diff")) o.diff_folder = vm["diff"].as<std::string>();
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
    std::cout << (failed ? std::to_string(failed) + " of " + std::to_string(verdicts.size()) + " images differ"
                         : "all " + std::to_string(verdicts.size()) + " images match")
              << " (threshold " << o.threshold << ", max fraction " << o.max_fraction << ")\n";
    return failed ? check_failed : ok;
}

} // namespace plastica::cli
