// plastica render: draw a result series (a folder written by `plastica run`, or its .pvd)
// without solving anything again.
#include "commands.hpp"
#include "options.hpp"
#include "render_stage.hpp"

#include "output_folder.hpp"

#include <iostream>
#include <optional>

namespace plastica::cli {

int render_command(const Args& args) {
    po::options_description options("Options");
    options.add_options()
        ("series", po::value<std::string>()->required(), "result folder or .pvd file")
        ("output,o", po::value<std::string>(), "folder for the pictures (default: the result folder)")
        ("every", po::value<int>()->default_value(1), "draw every k-th step (the first, the first yield, the peak and the last always)")
        ("quiet,q", "no progress on stderr");
    add_render_options(options);
    po::positional_options_description positional;
    positional.add("series", 1);
    po::variables_map vm;
    if (auto code = parse_options(args, "plastica render OUT_DIR_OR_PVD [-o DIR] [options]", options, positional, vm))
        return *code;
    render::RenderOptions render_options;
    if (auto code = read_render_options(vm, render_options)) return *code;
    if (vm.count("output")) render_options.output = vm["output"].as<std::string>();
    render_options.every = vm["every"].as<int>();
    render_options.quiet = vm.count("quiet") > 0;
    const std::string series = vm["series"].as<std::string>();
    // The pictures' folder is this drawing's own while it draws: a run or another drawing into
    // it is refused, and links where pictures go are too.
    std::optional<OutputFolder> lock;
    try {
        OutputFolderOptions o;
        o.clear_results = false;
        o.holder = "plastica render " + series;
        lock.emplace(pictures_folder(series, render_options), std::move(o));
    } catch (const OutputFolderError& e) {
        std::cerr << "plastica: " << e.what() << "\n";
        return bad_input;
    }
    return render_and_report(series, render_options);
}

} // namespace plastica::cli
