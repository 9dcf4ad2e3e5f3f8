// The robustness matrix of the inelastic engine: the shipped inelastic ring varied the way an
// engineer would vary it (whole ring, yield stress, thickness, how far, mesh, fibres, step,
// adaptive or not, arc length) and the gallery's frame, arch and beams; each must complete to
// its target with the scene's own settings.
#pragma once

#include "stability_cases.hpp"

#include <string>
#include <utility>
#include <vector>

namespace plastica {

// The scene text with each `from` replaced by `to` (each must occur, else std::logic_error).
std::string edited(std::string text, const std::vector<std::pair<std::string, std::string>>& edits);

std::vector<StabilityCase> robustness_cases();

} // namespace plastica
