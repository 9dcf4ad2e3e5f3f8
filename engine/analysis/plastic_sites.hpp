// Where a structure of plastic hinges yields as a mechanism, in words for a stop message: the
// nodes at which hinges are at capacity. A limit load with such sites is a plastic mechanism,
// and the user wants to know which one. (Fibre sections along a member yield gradually; where
// their zones stand at a limit is left to the pictures.)
#pragma once

#include "analysis/structural_system.hpp"
#include "model/model.hpp"

#include <string>

namespace plastica {

// The committed state's hinges at capacity, as "[x, y], [x, y], …" (scene coordinates, at most
// eight); empty where none is.
std::string plastic_sites(const Model& model, const StructuralSystem& system);

} // namespace plastica
