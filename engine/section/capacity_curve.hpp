// A section's moment capacity M_p(N) for one bending sign, as a smooth concave function of N:
// the C¹ cubic (Hermite) through the breakpoints of the fibres' capacity polygon. Those
// breakpoints are exact fully plastic states (neutral axis on a fibre boundary); the straight
// sides between them are an artefact of the fibre count whose corners would make a hinge's
// axial flow jump with the slope (a continuous section has M_p′(0) = 0, the polygon ±slope).
// Slopes at interior breakpoints are the mean of the adjacent sides, at the squash points the
// side's own.
#pragma once

#include <vector>

namespace plastica {

struct CapacityValue {
    double moment = 0.0; // s·M_p(N) for the curve's bending sign s, at least zero; zero outside the squash range
    double slope = 0.0;  // its derivative in N
    double curvature = 0.0;
};

class CapacityCurve {
public:
    CapacityCurve() = default;
    // Breakpoints (N, s·M) ordered by N, from the compression squash point to the tension one.
    // s·M is below zero where a section whose plastic centroid lies off its elastic one (a
    // composite beam) carries, at that N, only moments of the other sign.
    CapacityCurve(std::vector<double> N, std::vector<double> M);
    CapacityValue at(double N) const;
    // s·M_p(N) as it is, below zero too, at the squash points included; 0 outside them.
    double bound(double N) const;
    double lowest() const { return N_.empty() ? 0.0 : N_.front(); }
    double highest() const { return N_.empty() ? 0.0 : N_.back(); }

private:
    // The cubic through the breakpoints, unclamped, for N strictly inside the squash range.
    CapacityValue hermite(double N) const;

    std::vector<double> N_, M_, slope_;
};

} // namespace plastica
