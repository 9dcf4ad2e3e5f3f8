// The options the render stage shares between `plastica render` and `plastica run`, and the
// call that reports its outcome on stderr (render_options.cpp: the options, in both programs;
// render_stage.cpp: the drawing, in plastica-draw only).
#pragma once

#include "commands.hpp"
#include "options.hpp"

#include "render_series.hpp"

namespace plastica::cli {

void add_render_options(po::options_description& options);
// Reads the render options; returns an exit code when they are bad.
std::optional<int> read_render_options(const po::variables_map& vm, render::RenderOptions& options);
// The render options given on a command line that draws nothing (run --no-render or
// --curves-only), each as a note saying so; `why` names the option that stops the drawing.
std::vector<std::string> render_options_left_unused(const po::variables_map& vm, const std::string& why);
// The folder a drawing of `series` (a result folder or its .pvd) writes into: -o, or the series'.
std::string pictures_folder(const std::string& series, const render::RenderOptions& options);
// Renders a series and says what was written; returns the exit code. Options that could not act
// are said on stderr (quiet or not) and added to `notes` when given (run.json).
int render_and_report(const std::string& series, const render::RenderOptions& options,
                      std::vector<std::string>* notes = nullptr);

} // namespace plastica::cli
