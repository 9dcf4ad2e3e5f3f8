#include "render_stage.hpp"

#include <cmath>
#include <iostream>
#include <sstream>

namespace plastica::cli {

void add_render_options(po::options_description& options) {
    options.add_options()
        ("size", po::value<std::string>()->default_value("1280x720"), "picture size WIDTHxHEIGHT in pixels")
        ("field", po::value<std::string>()->default_value(""), "point or cell array that colours the structure (default: yielded_share with distributed plasticity, else bending_moment)")
        ("overlay", po::value<std::vector<std::string>>()->composing(), "another result folder whose curve joins chart.png (repeatable)")
        ("shapes", po::value<std::string>(), "displacements d1,d2,…: shapes.png, the deformed shapes there drawn over each other (an --overlay run beside)")
        ("overlay-csv", po::value<std::vector<std::string>>()->composing(), "FILE:label, points (displacement, load per line) drawn over chart.png, e.g. digitised from a paper (repeatable)")
        ("steps", po::value<std::string>(), "draw only these step numbers, e.g. 0,104,200")
        ("hide", po::value<std::string>(), "leave out layers: initial,base,hinges,releases,contact,surface_contact,supports,loads (point and line loads)")
        ("show", po::value<std::string>(), "draw layers left out by default: reactions (the supports' forces and moments)")
        ("magnify", po::value<std::string>()->default_value("1"), "draw displacements × k: a factor, or auto (about 10 % of the size for a stiff structure without a rigid base)")
        ("no-animation", "PNG frames only, no GIF")
        ("speed", po::value<double>(), "a series in time: model seconds per second of animation, frames sampled by model time at 12 a second (default: the run in 10 s)")
        ("jobs,j", po::value<int>()->default_value(0), "drawing processes (0: one per core)");
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
    const std::string magnify = vm["magnify"].as<std::string>();
    if (magnify == "auto") {
        options.magnify = 0.0;
    } else {
        std::size_t used = 0;
        double k = 0.0;
        try {
            k = std::stod(magnify, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != magnify.size() || !(k > 0.0) || !std::isfinite(k)) {
            std::cerr << "plastica: --magnify takes auto or a positive factor, e.g. 20 (got '" << magnify << "')\n";
            return bad_input;
        }
        options.magnify = k;
    }
    if (vm.count("overlay")) options.overlays = vm["overlay"].as<std::vector<std::string>>();
    if (vm.count("overlay-csv")) options.reference_points = vm["overlay-csv"].as<std::vector<std::string>>();
    options.animation = vm.count("no-animation") == 0;
    if (vm.count("speed")) {
        options.speed = vm["speed"].as<double>();
        if (!(options.speed > 0.0) || !std::isfinite(options.speed)) {
            std::cerr << "plastica: --speed takes a positive number of model seconds per second of animation\n";
            return bad_input;
        }
    }
    options.workers = vm["jobs"].as<int>();
    if (options.workers < 0) {
        std::cerr << "plastica: --jobs takes a whole number ≥ 0 (0: one drawing process per core)\n";
        return bad_input;
    }
    auto split = [](const std::string& text) {
        std::vector<std::string> items;
        std::stringstream in(text);
        for (std::string item; std::getline(in, item, ',');)
            if (!item.empty()) items.push_back(item);
        return items;
    };
    if (vm.count("hide")) options.hide = split(vm["hide"].as<std::string>());
    if (vm.count("show")) options.show = split(vm["show"].as<std::string>());
    // A comma-separated list of numbers, each read whole by `convert` (std::stod, std::stoi).
    auto numbers = [&](const char* key, auto convert, auto& out, const char* what) {
        if (!vm.count(key)) return true;
        try {
            for (const std::string& item : split(vm[key].as<std::string>())) {
                std::size_t used = 0;
                out.push_back(convert(item, &used));
                if (used != item.size()) throw std::invalid_argument(item);
            }
        } catch (const std::exception&) {
            std::cerr << "plastica: --" << key << " takes " << what << "\n";
            return false;
        }
        return true;
    };
    const auto real = [](const std::string& s, std::size_t* used) { return std::stod(s, used); };
    const auto whole = [](const std::string& s, std::size_t* used) { return std::stoi(s, used); };
    if (!numbers("shapes", real, options.shapes, "displacements separated by commas, e.g. 25,50,75,100") ||
        !numbers("steps", whole, options.steps, "step numbers separated by commas, e.g. 0,104,200"))
        return bad_input;
    return std::nullopt;
}

std::vector<std::string> render_options_left_unused(const po::variables_map& vm, const std::string& why) {
    po::options_description render("render");
    add_render_options(render);
    std::vector<std::string> notes;
    for (const auto& option : render.options()) {
        const std::string& name = option->long_name();
        if (vm.count(name) && !vm[name].defaulted()) notes.push_back("--" + name + " changes nothing: " + why + " draws nothing");
    }
    return notes;
}

} // namespace plastica::cli
