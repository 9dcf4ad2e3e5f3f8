// The charts of a parameter sweep, from its results: the family of load–displacement curves
// coloured by the first parameter, the peak load against each parameter, and for a sampled
// sweep the empirical distribution of the peak load (histogram and CDF, sample size shown).
#pragma once

#include <string>
#include <vector>

namespace plastica::render {

struct SweepChartRun {
    std::vector<double> values; // one per key (NaN where a value is not a number)
    double peak_load = 0.0;
    std::vector<double> displacement, load;
};

struct SweepCharts {
    std::string scene, load_label = "load", displacement_label = "control displacement";
    std::string load_unit, displacement_unit; // from the scene's [units] or [report]; empty: none
    std::vector<std::string> keys;
    std::vector<SweepChartRun> runs; // finished runs only
    bool sampled = false;
};

// Writes curves.png, peak_<n>.png per key (n from 1) and, when sampled, peak_distribution.png
// into `folder`; returns the files written.
std::vector<std::string> draw_sweep_charts(const SweepCharts& charts, const std::string& folder);

} // namespace plastica::render
