// Which element ends carry a plastic hinge's capacity (concentrated plasticity).
//
// Where exactly two hinge elements meet at a node whose rotation nothing else holds (no
// rotational support or spring, no applied moment), their end moments are equal and opposite,
// so one hinge serves the node: two would leave the split of the plastic rotation between them
// arbitrary and the tangent singular. The end whose capacity M_p(N), at its own axial force and
// on the side it bends to, is the lower takes it: its capacity is reached first. That choice is
// made at N = 0 before loading and made again after every converged step, so a column that
// takes axial load becomes the joint's weaker end although its section is the stronger at
// N = 0 (Liew, White & Chen, "Second-order refined plastic-hinge analysis for frame design",
// J. Struct. Eng. 119(11), 1993, check each member end against its own N–M surface). The other
// end keeps only its pseudo-spring, or, where the sections are equal, not even that: the serving
// end's spring stands for both in series (two springs going soft together leave the same split
// nearly arbitrary). Everywhere else, every hinge end carries its own capacity and spring: a
// support or spring that takes moment lets the two ends differ.
#pragma once

#include "element/corotational_beam.hpp"
#include "element/hinge_ends.hpp"
#include "model/model.hpp"

#include <array>
#include <vector>

namespace plastica {

// One entry per element of the model: how many element ends the capacity rows and the
// pseudo-spring at its first and second end serve (0, 1 or 2), as chosen at N = 0.
std::vector<HingeEnds> allocate_hinge_capacity(const Model& model);

// The joints where one hinge serves two element ends, and the choice of that end as the
// members' axial forces change. Two ways of deciding were tried and left out:
// - both ends carrying capacity rows where their capacities are nearly equal (two hinges in
//   series at one node): the catenary beam and the arch on the floor stop where both flow;
// - moving the hinge as soon as the other end passes its own capacity by 5e-4: at a symmetric
//   joint at capacity (the catenary beam's mid-span, the arch's crown) the ends' capacities
//   cross back and forth by a few 1e-4 as the serving end flows, and Newton does not recover
//   from a move there (four catenary beams of study/robustness_cases.cpp stopped).
class JointHinges {
public:
    explicit JointHinges(const Model& model);
    const std::vector<HingeEnds>& ends_served() const { return served_; }
    // After a commit: moves each joint's hinge to the other end where that end's committed
    // capacity has fallen below the serving end's by more than equal_band; tells the elements
    // whose ends changed. Returns how many joints changed.
    int reassign(std::vector<CorotationalBeam>& elements);

    // Capacities within this share of each other count as equal: the end without the hinge
    // may exceed its own capacity by at most this much (measured: 1e-4 on the frames of
    // tests/test_member_end_capacity.cpp, where a column becomes the weaker end by 7–22 %).
    // At 2e-3 and below, catenary beams of study/robustness_cases.cpp stop; at 5e-3 and 1e-2
    // every case completes.
    static constexpr double equal_band = 5e-3;
    // Measured against no less than this share of the weaker section's M_p(0).
    static constexpr double capacity_floor = 0.1;

private:
    struct Joint {
        std::array<std::array<int, 2>, 2> ends; // (element, end) of the two members
        bool equal_sections = false;
        int serving = 0; // which of the two ends serves (and holds the spring of equal sections)
        double capacity_floor = 0.0; // JointHinges::capacity_floor × the weaker M_p(0)
    };
    void apply(const Joint& joint);
    std::vector<HingeEnds> served_;
    std::vector<Joint> joints_;
};

} // namespace plastica
