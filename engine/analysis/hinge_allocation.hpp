// Which element ends carry a plastic hinge's capacity (concentrated plasticity).
//
// Where exactly two hinge elements meet at a node whose rotation nothing else holds (no
// rotational support or spring, no applied moment), their end moments are equal and opposite,
// so one hinge serves the node: two would leave the split of the plastic rotation between them
// arbitrary and the tangent singular. The weaker section's end takes it (its capacity is
// reached first); the other keeps only its pseudo-spring, or, where the sections are equal,
// not even that: the serving end's spring stands for both in series (two springs going soft
// together leave the same split nearly arbitrary). Everywhere else, every hinge end carries its
// own capacity and spring: a support or spring that takes moment lets the two ends differ.
#pragma once

#include "element/hinge_ends.hpp"
#include "model/model.hpp"

#include <vector>

namespace plastica {

// One entry per element of the model: how many element ends the capacity rows and the
// pseudo-spring at its first and second end serve (0, 1 or 2).
std::vector<HingeEnds> allocate_hinge_capacity(const Model& model);

} // namespace plastica
