// What a fibre section can carry, as curves an engineer reads: the N–M capacity (fully plastic
// moment and first yield over the axial range, both bending signs) and moment–curvature curves
// at fixed shares of the squash load. `plastica section` writes and draws them.
#pragma once

#include "section/fibre_section.hpp"

#include <vector>

namespace plastica {

// Moments are signed edges of the domain at N: the largest (positive bending) and the smallest
// (negative bending). Off a symmetric section both can have one sign near a squash load (a
// composite beam's plastic centroid lies off its elastic one, about which M is taken).
struct CapacityRow {
    double axial_force = 0.0;
    double moment_positive = 0.0;     // fully plastic moment, positive bending
    double moment_negative = 0.0;     // and negative bending (below zero for a section that carries both signs)
    double first_yield_moment = 0.0;  // the elastic range's upper edge; NaN where N alone yields a fibre
    // The plastic hinge's capacity: the smooth curve through the polygon's corners
    // (section/capacity_curve.hpp), which the hinges and their utilisation are measured against.
    double hinge_moment_positive = 0.0;
    double hinge_moment_negative = 0.0;
    double first_yield_moment_negative = 0.0; // its lower edge; NaN with the upper one
};

// `points` rows from the compressive to the tensile squash load.
std::vector<CapacityRow> capacity_table(const FibreSection& section, int points);

struct MomentCurvatureCurve {
    double axial_ratio = 0.0; // N / N_y (tension); for a section with concrete −N / N_c (compression)
    bool of_compression = false;
    double axial_force = 0.0;
    std::vector<MomentCurvaturePoint> points;
};

// The section's first-yield curvature without axial force: M_y(0) / EI.
double first_yield_curvature(const FibreSection& section);

// M–κ at N = ratio × N_y for each ratio, from zero to `multiple` × the first-yield curvature;
// for a section with concrete at N = −ratio × N_c (compression), to 1.5 × the curvature at which
// its compressed face reaches εcu2 under that force.
std::vector<MomentCurvatureCurve> moment_curvature_family(const FibreSection& section, const std::vector<double>& ratios,
                                                          double multiple, int points);

} // namespace plastica
