// plastica: co-rotational beam-columns with plastic hinges and unilateral foundations.
// This file only dispatches to the subcommands.
#include "commands.hpp"
#include "drawing_program.hpp"

#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <malloc.h>
#include <iostream>
#include <map>

namespace {

const char* usage = R"(Usage: plastica COMMAND [options]

Commands:
  run SCENE        solve a scene: curve.csv, run.json, VTU/PVD series, and pictures
  render SERIES    draw a result folder: frames, chart, contact sheet, animation
  compare A REF    rendered pictures against stored references (exit 1 when they differ)
  study SCENE      error against run time over element, fibre and increment ladders
  stability        the sweep of stiff and extreme cases, each against its expected outcome
  modes SCENE      natural periods, frequencies, effective masses and shapes (at a step: --step K)
  buckling SCENE   critical load factors and buckling modes of the loads (about a step: --step K)
  section SCENE    moment-curvature and N-M capacity curves of a scene's sections
  sweep SCENE      many runs of a scene with keys varied (grid or Monte Carlo); sweep.csv
  merge DIR        sweep.csv from the runs a sweep folder holds (after GNU Parallel or Slurm)
  report OUT_DIR   one self-contained HTML page of a result folder (CI artifacts)
  schema           the arrays a result series may hold (--scene: a scene's keys), as Markdown tables

Run 'plastica COMMAND --help' for the options of a command.
Exit codes: 0 success, 1 comparison failed, 2 bad input, 3 analysis stopped early,
130 interrupted.
)";

} // namespace

int main(int argc, char** argv) {
    using namespace plastica::cli;
    // VTK's XML writer allocates and frees large buffers for every file, and Eigen's LDLᵀ its
    // workspace for every factorisation; without this glibc maps them fresh (or hands them back
    // to the kernel) each time, and a run spends much of its time in page faults.
    mallopt(M_MMAP_THRESHOLD, 256 << 20);
    mallopt(M_TRIM_THRESHOLD, 512 << 20);
    mallopt(M_TOP_PAD, 64 << 20);
    // Commands that draw are compiled into plastica-draw only; plastica hands them over.
    const std::map<std::string, int (*)(const Args&)> commands{
        {"run", run_command}, {"modes", modes_command}, {"buckling", buckling_command}, {"stability", stability_command}, {"report", report_command}, {"schema", schema_command},
#ifdef PLASTICA_DRAWING
        {"render", render_command}, {"compare", compare_command}, {"study", study_command},
        {"section", section_command}, {"sweep", sweep_command}, {"merge", merge_command},
#endif
    };
    const char* drawing_commands[] = {"render", "compare", "study", "section", "sweep", "merge"};
    if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
        std::cout << usage;
        return argc < 2 ? bad_input : ok;
    }
    if (!std::strcmp(argv[1], "--version")) {
        std::cout << "plastica " << PLASTICA_VERSION << "\n";
        return ok;
    }
    const auto command = commands.find(argv[1]);
    if (command == commands.end() && !can_draw())
        for (const char* name : drawing_commands)
            if (!std::strcmp(argv[1], name)) return hand_over_to_drawing(name, Args(argv + 2, argv + argc));
    if (command == commands.end()) {
        std::cerr << "plastica: unknown command '" << argv[1] << "'\n" << usage;
        return bad_input;
    }
    // Each command turns the errors it knows into located messages; whatever else escapes
    // (a library's own exception) still ends with a message and an exit code, never an abort.
    try {
        return command->second(Args(argv + 2, argv + argc));
    } catch (const std::bad_alloc&) {
        std::cerr << "plastica " << argv[1] << (argc > 2 ? std::string(" ") + argv[2] : std::string()) << ": out of memory\n";
        return stopped_early;
    } catch (const std::exception& e) {
        std::cerr << "plastica " << argv[1] << (argc > 2 ? std::string(" ") + argv[2] : std::string()) << ": " << e.what() << "\n";
        return bad_input;
    }
}
