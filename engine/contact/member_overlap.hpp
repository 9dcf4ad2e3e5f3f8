// A member pressed onto a rigid line by a penalty per unit length: a Winkler bed that only
// pushes, acting over the exact part of the member that overlaps the line. The member's centre
// line between its nodes i and j is the cubic Hermite curve through the nodes' positions with
// the nodes' tangents (their initial directions turned by the nodes' rotations), so a ring's
// wall stays round between nodes and its contact point rolls along it; a straight member (one
// with a released end) is the chord. Its gap g(s) to the line is a cubic in s ∈ [0, 1], and the
// bed presses with q(s) = k·max(0, −g(s)). Force and tangent derive from the energy
// W = ½·k·L·∫ max(0, −g)² ds, integrated exactly (Gauss–Legendre on each overlapping interval):
// the force is continuous, grows from first touch without a jump, and its tangent is symmetric.
#pragma once

#include <Eigen/Dense>

#include <array>

namespace plastica {

// The member's geometry for its contact: where its nodes are and where they point.
struct MemberCurve {
    std::array<Eigen::Vector2d, 2> position;       // the nodes' current positions
    std::array<double, 2> tangent_angle{0.0, 0.0}; // the curve's direction at each node, from i toward j
    double length = 0.0;                           // the member's initial length
    bool straight = false;                         // the chord, ignoring the rotations
};

struct MemberOverlap {
    Eigen::Matrix<double, 6, 1> internal_force = Eigen::Matrix<double, 6, 1>::Zero(); // ∂W/∂(ux, uy, θ at i, j)
    Eigen::Matrix<double, 6, 6> stiffness = Eigen::Matrix<double, 6, 6>::Zero();      // ∂²W: symmetric
    double fraction = 0.0;                         // the share of the length that penetrates
    double resultant = 0.0;                        // ∫ q along the length: the force the bed presses with
};

// The overlap with the line through `point` with unit `normal` (toward the member's side), for
// the bed's stiffness per unit length k.
MemberOverlap member_overlap(const MemberCurve& member, const Eigen::Vector2d& point, const Eigen::Vector2d& normal, double k);

} // namespace plastica
