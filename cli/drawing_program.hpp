// Drawing lives in a second executable, plastica-draw, beside plastica: the rendering stack
// (VTK, OSMesa, LLVM: about ninety shared libraries) is loaded only by commands that draw, so
// `plastica --help` and runs that draw nothing start in a few milliseconds. plastica-draw
// understands every command; plastica hands a command over by replacing itself with it.
#pragma once

#include "commands.hpp"

#include <string>

namespace plastica::cli {

// Where plastica-draw is: the folder of this executable.
std::string drawing_program();
// Replaces this process with `plastica-draw COMMAND ARGS…`; returns only when that fails (after
// saying why), with the exit code for bad input.
int hand_over_to_drawing(const std::string& command, const Args& args);
// The lean plastica (no rendering linked in) or plastica-draw.
bool can_draw();

} // namespace plastica::cli
