#include "render_stage.hpp"

#include "render_error.hpp"

#include <iostream>

namespace plastica::cli {

void add_render_options(po::options_description& options) {
    options.add_options()
        ("size", po::value<std::string>()->default_value("1280x720"), "picture size WIDTHxHEIGHT in pixels")
        ("field", po::value<std::string>()->default_value("bending_moment"), "point or cell array that colours the structure")
        ("overlay", po::value<std::vector<std::string>>()->composing(), "another result folder whose curve joins chart.png (repeatable)")
        ("no-animation", "PNG frames only, no GIF");
}

std::optional<int> read_render_options(const po::variables_map& vm, render::RenderOptions& options) {
    const std::string size = vm["size"].as<std::string>();
    const auto x = size.find('x');
    try {
        std::size_t used_w = 0, used_h = 0;
        if (x == std::string::npos) throw std::invalid_argument("no x");
        options.width = std::stoi(size.substr(0, x), &used_w);
        options.height = std::stoi(size.substr(x + 1), &used_h);
        if (used_w != x || used_h != size.size() - x - 1) throw std::invalid_argument("trailing text");
    } catch (const std::exception&) {
        std::cerr << "plastica: --size takes WIDTHxHEIGHT in pixels, e.g. 1280x720 (got '" << size << "')\n";
        return bad_input;
    }
    options.field = vm["field"].as<std::string>();
    if (vm.count("overlay")) options.overlays = vm["overlay"].as<std::vector<std::string>>();
    options.animation = vm.count("no-animation") == 0;
    return std::nullopt;
}

int render_and_report(const std::string& series, const render::RenderOptions& options) {
    try {
        const render::RenderReport r = render::render_series(series, options);
        if (!options.quiet) {
            std::cerr << "rendered " << r.frames << " frames in " << r.seconds << " s (" << r.frames_per_second
                      << " frames per second, " << r.gl_renderer << ") into " << r.output << "/frames\n";
            std::cerr << r.output << "/chart.png, " << r.output << "/contact_sheet.png; " << r.animation << "\n";
        }
    } catch (const render::RenderError& e) {
        std::cerr << "plastica: cannot render: " << e.what() << "\n";
        return bad_input;
    } catch (const std::exception& e) {
        std::cerr << "plastica: cannot render " << series << ": " << e.what() << "\n";
        return bad_input;
    }
    return ok;
}

} // namespace plastica::cli
