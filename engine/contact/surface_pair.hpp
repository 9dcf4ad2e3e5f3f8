// One pair of touching member surfaces ([[self_contact]], contact/self_contact.hpp): a point (a
// node, or a point along an element) against a segment (an element chord) or its end, with the
// penalty potential ½·k·g² of the gap g = d − reach, its force and its tangent.
#pragma once

#include <Eigen/Dense>
#include <array>

namespace plastica {

struct SurfaceContact {
    int node = 0;               // the node that touches; along the members, the point's nearer element end
    // The point that touches: (1 − eta)·point[0] + eta·point[1]; a node is point = {node, node}.
    std::array<int, 2> point{0, 0};
    double eta = 0.0;
    int point_id = 0;           // the node, or a number past the nodes for a point along a member
    std::array<int, 2> segment; // the ends of the segment it touches; both the same for an end
    double xi = 0.0;            // where along the segment, 0 … 1
    double reach = 0.0;         // the sum of the two half depths
    double gap = 0.0;           // distance − reach: negative, the penetration
    double stiffness = 0.0;
    Eigen::Vector2d normal;     // unit, from the segment toward the node
    // Internal force on the translations (x, y) of node (point[0]), segment[0], segment[1] and
    // point[1] (a node's contact with an end uses the first four entries, with a segment the
    // first six; a point along a member all eight, the same node twice where it touches an
    // end), and its tangent.
    Eigen::Matrix<double, 8, 1> force;
    Eigen::Matrix<double, 8, 8> tangent;
    bool along_member() const { return point[0] != point[1]; } // a point of an element, not a node
    int nodes() const { return along_member() ? 4 : segment[0] == segment[1] ? 2 : 3; }
    // The nodes the force and tangent act on, in their order.
    std::array<int, 4> node_list() const { return {point[0], segment[0], segment[1], point[1]}; }
    Eigen::Vector2d point_force() const { return force.head<2>() + force.tail<2>(); }
};

// The pair's gap, normal, force and tangent with the point at x and the segment's ends at
// a_end and b_end (b_end unused for a segment end), its kind and stiffness kept.
void press(SurfaceContact& c, const Eigen::Vector2d& x, const Eigen::Vector2d& a_end, const Eigen::Vector2d& b_end);

} // namespace plastica
