// The limit of a ladder of load–displacement curves as the discretisation is refined:
// Richardson extrapolation of the three finest curves, sampled at common displacements, with the
// order of convergence observed from the same three (Roache, "Verification and Validation in
// Computational Science and Engineering", 1998, ch. 5). A method compared with another is
// measured against its own limit, never against the other method's coarse run.
#pragma once

#include "curve_error.hpp"

#include <cstddef>
#include <vector>

namespace plastica {

// Ladders converging more slowly than this are not extrapolated.
constexpr double minimum_order = 0.5;

struct CurveLimit {
    Curve curve;                  // over the displacements the three curves share
    bool extrapolated = false;    // false: the changes do not shrink at order ½ or more; the limit is the finest curve
    double order = 0.0;           // the observed order (NaN when the changes do not shrink at all)
    std::size_t used[3] = {};     // indices of the coarse, middle and fine curve
    double change[2] = {};        // RMS of ΔP from coarse to middle and from middle to fine, over the fine peak |P|
};

// `curves` and their step sizes `h` (any order, at least three); the three smallest h are used.
// When the changes do not shrink at order ½ or more (not yet in the asymptotic range) the limit
// is the finest curve, marked not extrapolated. Throws StudyError for fewer than three curves.
CurveLimit extrapolated_limit(const std::vector<Curve>& curves, const std::vector<double>& h, int samples = 400);

} // namespace plastica
