// Where a structure yields as a mechanism, in words for a stop message: the nodes at which
// hinges are at capacity, or next to which fibre sections along a member are nearly fully
// plastic. A limit load with such sites is a plastic mechanism, and the user wants to know
// which one.
#pragma once

#include "analysis/structural_system.hpp"
#include "model/model.hpp"

#include <string>

namespace plastica {

// The committed state's hinges at capacity, and the nodes nearest to nearly fully plastic
// sections (mid-member: the section's own place), as "[x, y], [x, y], …" (scene coordinates, at
// most eight, ordered along the members); empty where none is.
std::string plastic_sites(const Model& model, const StructuralSystem& system);

} // namespace plastica
