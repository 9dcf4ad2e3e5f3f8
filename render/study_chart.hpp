// The chart of a study (study/study.hpp): the error of each ladder against the analysis' wall
// time, log–log, one line per method and parameter with its levels and observed order.
#pragma once

#include "charts.hpp"
#include "study.hpp"

#include <string>

namespace plastica::render {

ChartFigure study_chart(const std::string& scene, const StudyReport& report);

} // namespace plastica::render
