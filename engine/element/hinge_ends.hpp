// How many element ends the capacity rows at each end of a plastic-hinge element serve: 0, 1,
// or 2 where one hinge serves both ends meeting at a node (analysis/hinge_allocation.hpp).
#pragma once

#include <array>

namespace plastica {

using HingeEnds = std::array<int, 2>;

} // namespace plastica
