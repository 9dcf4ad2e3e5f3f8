// plastica stability: the built-in sweep of stiff, extreme and failing cases, each against the
// outcome it must have; a table on stdout and stability.csv. Exit 1 when a case misbehaves.
#include "commands.hpp"
#include "options.hpp"

#include "stability_cases.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace plastica::cli {

int stability_command(const Args& args) {
    po::options_description options("Options");
    options.add_options()("output,o", po::value<std::string>()->default_value("out/stability"), "output folder")(
        "case", po::value<std::string>()->default_value(""), "run only the cases whose name contains this text");
    po::positional_options_description positional;
    po::variables_map vm;
    if (auto code = parse_options(args, "plastica stability [-o DIR] [--case TEXT]", options, positional, vm)) return *code;
    const std::string only = vm["case"].as<std::string>();
    namespace fs = std::filesystem;
    const fs::path folder = vm["output"].as<std::string>();
    fs::create_directories(folder);
    std::ofstream csv(folder / "stability.csv");
    csv << "case,parameter,outcome,expected_met,steps,iterations,cut_steps,max_residual,max_negative_pivots,peak_load,seconds,problem\n";
    std::printf("%-46s %-24s %-15s %6s %6s %5s %9s %4s %8s  %s\n", "case", "parameter", "outcome", "steps", "iters", "cuts",
                "residual", "neg", "seconds", "verdict");
    int failed = 0;
    int ran = 0;
    for (const StabilityCase& c : stability_cases()) {
        if (!only.empty() && c.name.find(only) == std::string::npos) continue;
        ++ran;
        const StabilityRow r = run_stability_case(c);
        failed += !r.passed;
        csv << '"' << r.name << "\",\"" << r.parameter << "\"," << r.outcome << ',' << r.passed << ',' << r.steps << ','
            << r.iterations << ',' << r.cut_steps << ',' << r.max_residual << ',' << r.max_negative_pivots << ',' << r.peak_load
            << ',' << r.seconds << ",\"" << r.problem << "\"\n";
        std::printf("%-46s %-24s %-15s %6d %6d %5d %9.1e %4d %8.3f  %s\n", r.name.c_str(), r.parameter.c_str(), r.outcome.c_str(),
                    r.steps, r.iterations, r.cut_steps, r.max_residual, r.max_negative_pivots, r.seconds,
                    r.passed ? "as expected" : ("UNEXPECTED: " + r.problem).c_str());
    }
    if (ran == 0) {
        std::cerr << "plastica stability: no case name contains '" << only << "'\n";
        return bad_input;
    }
    std::cout << (failed ? std::to_string(failed) + " cases did not behave as expected" : "every case behaved as expected")
              << " -> " << (folder / "stability.csv").string() << "\n";
    return failed ? check_failed : ok;
}

} // namespace plastica::cli
