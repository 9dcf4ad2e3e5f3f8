// Plausibility checks of a scene that was read without error, for the unit mistakes that
// otherwise run silently: E and fy in different units (MPa beside kN/m²), a section given in
// millimetres on members in metres, a spring far stiffer than the structure. Each is a warning
// (stderr and run.json, exit 0): an unusual scene may mean it.
#pragma once

#include "model/model.hpp"

#include <string>
#include <vector>

namespace plastica {

std::vector<std::string> scene_warnings(const Model& model);

} // namespace plastica
