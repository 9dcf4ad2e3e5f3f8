// What every figure shares: its title band and text sizes, and the words it writes about a
// series (the scene's heading, the load axis' title, numbers).
#pragma once

#include "load_chart.hpp"
#include "series_summary.hpp"

#include <string>
#include <vector>

class vtkTextActor;

namespace plastica::render {

// The title band's height, as a fraction of the picture.
inline constexpr double band = 0.11;

// Text and line sizes are set for 1280 × 720 and scale with the picture; a narrower picture
// scales by its width so that the legend column still holds its text.
double text_scale(int width, int height);
void style(vtkTextActor* text, double size, bool bold);

// "title  (scene)", or the scene's name alone.
std::string scene_heading(const SeriesSummary& s);
// The load axis' title, saying where it is cut (see SeriesSummary::load_axis_cut).
std::string load_axis_title(const SeriesSummary& s);
// The first `count` displacements (load = false) or loads of a curve.
std::vector<double> curve_column(const std::vector<CurvePoint>& curve, std::size_t count, bool load);
// What the run's chart plots: the load against the displacement, or for a series in time the
// displacement against time. The first `count` points, and the axes' titles.
std::vector<double> chart_x(const SeriesSummary& s, std::size_t count);
std::vector<double> chart_y(const SeriesSummary& s, std::size_t count);
std::string chart_x_title(const SeriesSummary& s);
std::string chart_y_title(const SeriesSummary& s);
// "%.4g" without trailing noise.
std::string number(double value);
// Labels for values that must stay apart: the fewest significant digits (at least 3) with which
// every two different values read differently, written out in full between 0.001 and 10⁷
// (235000, not 2.35e+05).
std::vector<std::string> distinct_numbers(const std::vector<double>& values);

} // namespace plastica::render
