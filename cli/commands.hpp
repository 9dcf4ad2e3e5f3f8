// The subcommands. Each parses its own options and returns the process exit code:
// 0 success, 1 a comparison failed, 2 bad input, 3 the analysis stopped early, 130 interrupted.
#pragma once

#include <string>
#include <vector>

namespace plastica::cli {

enum ExitCode { ok = 0, check_failed = 1, bad_input = 2, stopped_early = 3, interrupted = 130 };

using Args = std::vector<std::string>;

int run_command(const Args& args);
int section_command(const Args& args);
int render_command(const Args& args);
int compare_command(const Args& args);
int study_command(const Args& args);
int stability_command(const Args& args);
int sweep_command(const Args& args);
int merge_command(const Args& args);
int report_command(const Args& args);
int schema_command(const Args& args);
int modes_command(const Args& args);
int buckling_command(const Args& args);

} // namespace plastica::cli
