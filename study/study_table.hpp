// A study's results for people and programs: study.csv, and the table printed after a run. And
// the ladders a user writes ("elements=10,20,50", "plasticity=hinges,distributed").
#pragma once

#include "study.hpp"

#include <ostream>
#include <string>

namespace plastica {

// One row per level: method, parameter, level, seconds, repeats, steps, iterations, status,
// is_reference, max_error, rms_error, then error_at_<d> for each reported displacement.
void write_study_csv(std::ostream& out, const StudyReport& report);
// The table of levels with errors in per cent, then the observed orders, the limits and how far
// the methods' limits lie apart.
void print_study_table(std::ostream& out, const std::string& scene, const StudyReport& report, bool methods_compared);
// "limit of hinges in elements: extrapolated from elements = 16, 32, 64 at observed order 1.02".
std::string limit_text(const StudyReport::Limit& limit);
// The limit curves: method, parameter, extrapolated, order, displacement, load (one row a point);
// a method's rows can be given back to `--reference`.
void write_limits_csv(std::ostream& out, const StudyReport& report);

// Numbers separated by commas; throws StudyError naming `what` for anything else.
std::vector<double> parse_numbers(const std::string& text, const std::string& what);
// Adds one "--vary NAME=v1,v2,…" to the options: a ladder, or the methods to compare.
// Throws StudyError for a bad name, level or method.
void add_variation(StudyOptions& options, const std::string& text);

} // namespace plastica
