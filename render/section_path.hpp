// The path in the N–M plane of the most loaded element end of a result series: the end with the
// largest utilisation M/Mp(N) at the last step, its axial force and moment at every step.
#pragma once

#include "result_series.hpp"

#include <string>
#include <vector>

namespace plastica::render {

struct SectionPath {
    std::string where; // "element 37 (from 0), end j, member 'beam'"
    std::vector<double> axial_force, moment;
};

// Throws RenderError when the series has no hinge arrays (an elastic scene).
SectionPath most_loaded_end(const ResultSeries& series);

} // namespace plastica::render
