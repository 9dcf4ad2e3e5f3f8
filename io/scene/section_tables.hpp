// The section curves (section/section_curves.hpp) as CSV files.
#pragma once

#include "section/section_curves.hpp"

#include <ostream>
#include <vector>

namespace plastica {

// axial_force, moment_positive, moment_negative, first_yield_moment, hinge_moment_positive,
// hinge_moment_negative, first_yield_moment_negative (section/section_curves.hpp)
void write_capacity_csv(std::ostream& out, const std::vector<CapacityRow>& rows);
// axial_ratio, axial_force, curvature, moment
void write_moment_curvature_csv(std::ostream& out, const std::vector<MomentCurvatureCurve>& curves);

} // namespace plastica
