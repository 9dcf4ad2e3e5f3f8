// Whether supports, prescribed displacements and springs hold every rigid-body motion of every
// connected part of the structure. Beam elements join their nodes rigidly (three DOFs shared),
// so a part is a mechanism exactly when one of its three rigid motions is free: a test of
// geometry and supports alone, free of the stiffness values and of round-off. It tells a real
// mechanism from a stiffness matrix that is singular only to double precision.
#pragma once

#include "model/model.hpp"

#include <string>
#include <vector>

namespace plastica {

// Empty when every part is held; else which part moves and how, in words (a translation's
// direction, a rotation's centre). in_contact: per foundation spring, whether a unilateral one
// touches its base (those that do not hold nothing); null: every spring holds. surface_holds:
// nodes pressed by another surface ([[self_contact]]) and the direction they are pushed along;
// each holds its part along that direction (as a base would: the other part is taken as held).
struct SurfaceHold {
    int node = 0;
    std::array<double, 2> direction{0.0, 1.0};
};
std::string unrestrained_rigid_motion(const Model& model, const std::vector<bool>* in_contact = nullptr,
                                      const std::vector<SurfaceHold>* surface_holds = nullptr);

// "[x, y]" of a point for messages: six digits, round-off against the model's size shown as 0.
std::string point_text(const Model& model, double x, double y);

} // namespace plastica
