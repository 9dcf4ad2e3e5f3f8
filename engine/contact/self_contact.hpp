// Frictionless contact between the surfaces of members (a ring flattened until its walls meet,
// a pipe pressed onto a pipe), by the penalty method. Each surface lies half its section's depth
// from the centre line, so two centre lines may come no nearer than the sum of their half depths,
// the reach c. Every node is tested against every segment (element chord) of its group that is
// not its neighbour along the members: with d the distance from the node to the segment (to its
// nearest point, interior or end), the gap is g = d − c and a pair with g ≤ 0 carries the
// potential ½·k·g². Its gradient is the internal force, its Hessian (including the term from the
// turning normal) the tangent, on the translations of the node and the segment's ends
// (Wriggers, Computational Contact Mechanics, 2006, ch. 4: node-to-segment contact; here the
// two-pass form, each node against the other surface). A node whose nearest point is a segment
// end touches that end once, however many segments end there.
// Along the members (acts_on = "members"), the points that press are 4 Gauss–Lobatto points of
// each element (its ends and two inside), on its chord; each carries the penalty per unit
// length times half its weight (the two passes make up the whole), so the surfaces press with
// k·penetration per unit length and a contact zone grows a third of an element at a time
// instead of node by node (the Gauss-point-to-segment form: Fischer & Wriggers, "Frictionless
// 2D contact formulations for finite deformations based on the mortar method", 2005). One
// pair's force and tangent: contact/surface_pair.hpp.
#pragma once

#include "contact/surface_pair.hpp"
#include "model/model.hpp"

#include <Eigen/Dense>
#include <array>
#include <vector>

namespace plastica {

class SelfContact {
public:
    explicit SelfContact(const Model& model);

    bool empty() const { return groups_.empty(); }

    // Finds the touching pairs at the full displacement vector u and evaluates them. With
    // freeze_active the pairs of the previous evaluation act (even where they opened) and no
    // new pair is taken. A pair whose force at its gap would be at most undecided_force keeps
    // its state (the foundation's rule: no flipping on round-off).
    void evaluate(const Eigen::VectorXd& u, bool freeze_active, double undecided_force);
    const std::vector<SurfaceContact>& contacts() const { return contacts_; }
    bool active_set_changed() const { return changed_; }
    // Whether the acting pairs are those the geometry gives (they are unless frozen and stale).
    bool active_set_consistent() const { return consistent_; }

    // A group's penalty unless the scene names one: over its elements the largest of the
    // smaller of E·A/ℓ and 100·12·E·I/ℓ³. A node pressed by it sinks into the surface no more
    // than an element end shortens under the same force, nor more than a hundredth of what an
    // element bends under it: contact adds little stiffness beyond what the members have (the
    // tangent's conditioning is kept, also for a slender member whose E·A/ℓ dwarfs its bending),
    // while the penetration stays below the members' own local deformation.
    static double default_stiffness(const Model& model, const std::vector<int>& elements);

private:
    struct Segment {
        int a = 0, b = 0;
        double half_depth = 0.0;
        double length = 0.0; // undeformed
    };
    struct Group {
        std::vector<Segment> segments;
        std::vector<int> nodes;
        std::vector<double> node_half_depth; // per entry of nodes: the deepest section there
        // Per entry of nodes: the nodes nearer along the members than they could ever touch.
        std::vector<std::vector<int>> near;
        double stiffness = 0.0;
        bool along_members = false;
        int first_point_id = 0; // of its points along the members
        std::vector<std::array<std::size_t, 2>> segment_ends; // per segment: its ends' entries in nodes
    };
    // Whether a point at x comes within `reach` of segment s: then the pair's segment (or end),
    // xi, reach, gap and normal.
    bool reaches(const Eigen::Vector2d& x, double reach, const Segment& s, SurfaceContact& out) const;
    // The nearest point of segment s to node p; false if the pair does not touch.
    bool touch(const Group& group, std::size_t p, const Segment& s, SurfaceContact& out) const;
    // The same for Gauss point g of segment `own`.
    bool touch_along(const Group& group, std::size_t own, int g, const Segment& s, SurfaceContact& out) const;
    // Keeps one contact per segment end among found[first …] (a point's contacts).
    static void serve_ends_once(std::vector<SurfaceContact>& found, std::size_t first);
    Eigen::Vector2d point_position(const SurfaceContact& c) const {
        return (1.0 - c.eta) * position(c.point[0]) + c.eta * position(c.point[1]);
    }
    // Its gap, normal, force and tangent at the current positions (the pair's kind kept).
    void evaluate_pair(SurfaceContact& c) const {
        press(c, point_position(c), position(c.segment[0]), position(c.segment[1]));
    }
    Eigen::Vector2d position(int node) const { return {x0_[2 * node] + u_[3 * node], x0_[2 * node + 1] + u_[3 * node + 1]}; }

    std::vector<Group> groups_;
    std::vector<double> x0_; // initial positions, x y per node
    const double* u_ = nullptr;
    std::vector<SurfaceContact> contacts_;
    bool changed_ = false, consistent_ = true;
};

} // namespace plastica
