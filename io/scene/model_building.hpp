// What a scene's model is built with beside what the scene file says, as functions of the model
// alone (no TOML, testable on their own): line loads lumped to nodes, the tributary lengths of
// springs given per unit length, the members' normal at a node, and what the reported load
// measures. The scene reader reads and validates, and calls these.
#pragma once

#include "model/model.hpp"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace plastica {

// A load per unit initial length w, and self weight ρA·g where gravity is given, on the listed
// elements, lumped half to each end of every element: the force at each node they reach.
std::map<int, std::array<double, 2>> lumped_line_load(const Model& model, const std::vector<int>& elements,
                                                      const std::array<double, 2>& w, const std::array<double, 2>& gravity);
// Per node: half the length of every element that meets it (a spring per unit length there
// stands for this much of the member).
std::vector<double> tributary_lengths(const Model& model);
// The unit mean of the left normals of the elements that meet the node (toward the centre of a
// counter-clockwise arc); none where there are no elements or their normals cancel.
std::optional<std::array<double, 2>> member_normal(const Model& model, int node);
// What the reported load measures and is labelled, before [report] says otherwise: the force
// moving bases press with where they alone drive the scene, the load factor where the loads are
// not parallel (no total has a direction), "pressure" for a uniform pressure, else the total.
void infer_report_measure(Model& model);
// A straight elastic cantilever clamped at one end with one transverse load at the other and
// nothing else (the closed form `exact = "cantilever_tip_load"` describes).
bool is_cantilever_with_tip_load(const Model& model);
// The fibre states the analysis will hold: every inelastic section's fibres at each of its
// elements' sections (two hinge ends, or the integration points along a fibre member).
double fibre_states(const Model& model);
// Bytes of memory the analysis's fibre states take, measured on rings of 10³–10⁵ fibres a section.
inline constexpr double bytes_per_fibre_state = 300.0;
// Why the model is refused before its set-up starts (its fibre states would not fit in this
// machine's memory), with the estimate; nothing when it fits.
std::optional<std::string> setup_too_large(const Model& model);

} // namespace plastica
