// The capacity of a fibre section at its fibres' limit stresses: M_p(N) as an exact polyline per
// bending sign, and the plastic hinge's smooth curves through the corners of the fibres' capacity
// polygon. It depends on the fibres alone, so every section of the same fibres (the two ends of
// each element of a member, every element of a mesh) shares one, built once.
#pragma once

#include "section/capacity_curve.hpp"

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace plastica {

struct CapacityFibre {
    double area = 0.0, y = 0.0;
    double limit_tension = 0.0, limit_compression = 0.0; // limit stresses, both positive
};

struct CapacityPoint {
    double N = 0.0;
    double M = 0.0;
};

struct SectionCapacity {
    // M_p(N) per bending sign (index 0 positive), ordered by N; exact for fibres.
    std::array<std::vector<CapacityPoint>, 2> polyline;
    // The hinge's smooth capacity per bending sign.
    std::array<CapacityCurve, 2> hinge;
};

// Up to this many fibres the polyline's breakpoints are summed whole, each on its own (the results
// every verification was made with: the hinge's curve keeps the breakpoints that round-off leaves
// off a straight line, so another order of summation moves results by up to 0.15 % on a portal);
// above it by prefix sums, which cost O(n) instead of O(n²).
inline constexpr std::size_t direct_capacity_sum_limit = 2048;

// The capacity of these fibres: the one already built for equal fibres while any section still
// holds it, else built now. Safe to call from several threads.
std::shared_ptr<const SectionCapacity> section_capacity(const std::vector<CapacityFibre>& fibres);

// A capacity through given states (N, M) per bending sign: the polylines ordered by N, the
// hinge's curves through the corners of their convex hull.
std::shared_ptr<const SectionCapacity> capacity_through_points(std::array<std::vector<CapacityPoint>, 2> polylines);

} // namespace plastica
