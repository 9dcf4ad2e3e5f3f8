// plastica render: draw a result series (a folder written by `plastica run`, or its .pvd)
// without solving anything again.
#include "commands.hpp"
#include "options.hpp"
#include "render_stage.hpp"

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
    return render_and_report(vm["series"].as<std::string>(), render_options);
}

} // namespace plastica::cli
