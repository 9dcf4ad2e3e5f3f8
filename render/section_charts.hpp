// Charts of a fibre section's curves (section/section_curves.hpp): the N–M capacity with first
// yield (and, when a run is at hand, the path of its most loaded element end), and the
// moment–curvature family.
#pragma once

#include "charts.hpp"
#include "section/section_curves.hpp"
#include "section_path.hpp"

#include <optional>
#include <string>
#include <vector>

namespace plastica::render {

// The scene's units label the axes ("" when it names none).
struct SectionUnits {
    std::string length, force;
};

// With `strain_limits` (a section with concrete) the hinges' capacity by strain limits is drawn
// beside the fully plastic one.
ChartFigure capacity_chart(const std::string& section_name, const std::vector<CapacityRow>& rows, const SectionUnits& units,
                           const std::optional<SectionPath>& path = std::nullopt, bool strain_limits = false);
ChartFigure moment_curvature_chart(const std::string& section_name, const std::vector<MomentCurvatureCurve>& curves,
                                   const SectionUnits& units);

} // namespace plastica::render
