// Which element ends the rows at each end of a plastic-hinge element stand for
// (analysis/hinge_allocation.hpp): 0, none; 1, its own; 2, its own and the other element's at
// the node, where one hinge serves both.
#pragma once

#include <array>

namespace plastica {

struct HingeEnds {
    std::array<int, 2> capacity{1, 1}; // the ends the capacity rows serve
    std::array<int, 2> spring{1, 1};   // the ends whose pseudo-springs the end's spring stands for
    bool operator==(const HingeEnds& o) const { return capacity == o.capacity && spring == o.spring; }
    bool operator!=(const HingeEnds& o) const { return !(*this == o); }
};

} // namespace plastica
