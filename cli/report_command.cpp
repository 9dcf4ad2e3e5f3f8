// plastica report: one self-contained HTML page of a result folder, for CI artifacts.
#include "commands.hpp"
#include "options.hpp"

#include "atomic_file.hpp"
#include "report_page.hpp"

#include <filesystem>
#include <iostream>

namespace plastica::cli {

int report_command(const Args& args) {
    po::options_description options("Options");
    options.add_options()
        ("folder", po::value<std::string>()->required(), "result folder of plastica run")
        ("output,o", po::value<std::string>(), "the page (default FOLDER/report.html)");
    po::positional_options_description positional;
    positional.add("folder", 1);
    po::variables_map vm;
    if (auto code = parse_options(args, "plastica report OUT_DIR [-o FILE]", options, positional, vm)) return *code;
    const std::string folder = vm["folder"].as<std::string>();
    const std::string page = vm.count("output") ? vm["output"].as<std::string>()
                                                : (std::filesystem::path(folder) / "report.html").string();
    try {
        write_file_atomically(page, run_page(folder));
    } catch (const std::exception& e) {
        std::cerr << "plastica: " << e.what() << "\n";
        return bad_input;
    }
    std::cout << "-> " << page << "\n";
    return ok;
}

} // namespace plastica::cli
