// The capacity of a section with concrete by the strain-limit method of EN 1992-1-1 §6.1: every
// plane strain distribution that reaches a design limit (εcu2 at the compressed face, εc2 at
// (1 − εc2/εcu2)·h from it when the whole section is compressed, εud of steel that has
// `ultimate_strain`, none otherwise), each fibre at its law's stress for its strain from the
// unstressed state. The capacity is the N–M region those states enclose.
#pragma once

#include "section/section_capacity.hpp"

#include <memory>

namespace plastica {

class FibreSection;

// One strain distribution at the limits: ε(y) = eps0 − y·curvature, and what it carries.
struct LimitState {
    double eps0 = 0.0, curvature = 0.0;
    double N = 0.0, M = 0.0;
};

// The limit states of both bending signs (index 0 positive), each ordered from the tensile end
// to uniform compression. Empty for a section without a compressive strain limit.
std::array<std::vector<LimitState>, 2> strain_limit_states(const FibreSection& section, int points_per_region = 64);

// The hinge's curves through those states (null for a section without strain limits).
std::shared_ptr<const SectionCapacity> strain_limit_capacity(const FibreSection& section);

} // namespace plastica
