// The result schema: the one list of what a result series holds. Every array of a
// step's VTU and of base.vtp, with where it lives, its type and components, what it measures and
// which scenes have it, and the codes of the integer states. Each row is declared beside the code
// that fills it (io/results/arrays/); this header gathers them. The VTU writer, the render stage,
// docs/output.md's table (`plastica schema` prints it; a test compares) and the tests read it, so a
// name is spelled in one place.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace plastica {
struct Model;
}

namespace plastica::result {

enum class Where { point, cell, field, base };
enum class Type { float64, int32, text };
// What an array's values measure, for their unit.
enum class Quantity { none, length, rotation, force, moment, curvature, reported_load, reported_displacement, velocity, acceleration, force_per_length };
// Which scenes write an array: only what a scene needs (no empty arrays).
enum class When {
    always,
    supported_or_prescribed, // a support or a prescribed displacement
    supported,
    loaded,                  // nodal loads or pressure
    bilateral_springs,
    unilateral_base,         // a rigid base or a tensionless bed
    hinges,
    distributed,
    half_model,              // [report] mirror_x
    units,                   // [report] names its units
    spring_anchors,          // base.vtp: bilateral springs or rigid lines
    moving_base,
    staged,                  // [[stage]]s after [analysis]
    patterns,                // more than one load pattern
    moving_base_patterns,    // base.vtp: a moving base, and more than one load pattern
    releases,                // a member end is released
    self_contact,            // [[self_contact]]
    members,                 // [[line]]s or [[arc]]s (not only [[element]]s given one by one)
    transient,               // a stage integrates in time
    critical_step,           // an elastic path's step that passes a bifurcation or limit point (that step only)
    line_loads,              // [[distributed_load]] wx or wy
};

struct Array {
    std::string_view name;
    Where where;
    Type type;
    int components;          // 0: one per integration point along the member
    Quantity quantity;
    When when;
    std::string_view meaning;
};

// Every array, in the order the writer lays them out.
const std::vector<Array>& arrays();
// The schema's entry of a name; throws std::out_of_range for a name it does not hold.
const Array& find(std::string_view name);
// Whether a scene writes the array.
bool present(const Array& array, const Model& model);
// The load patterns that hold something (loads, pressures, prescribed displacements or a moving
// base), when there are two or more; else none.
std::vector<int> active_patterns(const Model& model);
// The names a scene writes at one place, in the schema's order.
std::vector<std::string> names(Where where, const Model& model);
// The unit of an array's values from the scene's length and force units ("" when unnamed).
std::string unit(const Array& array, const std::string& length_unit, const std::string& force_unit);
// The schema as docs/output.md's Markdown table.
std::string markdown_table();

// Names, so that a misspelt one does not compile instead of drawing nothing.
namespace name {
inline constexpr const char* displacement = "displacement";
inline constexpr const char* velocity = "velocity";
inline constexpr const char* critical_mode = "critical_mode";
inline constexpr const char* critical_point = "critical_point";
inline constexpr const char* critical_load_factor = "critical_load_factor";
inline constexpr const char* model_time = "model_time";
inline constexpr const char* energy = "energy";
inline constexpr const char* acceleration = "acceleration";
inline constexpr const char* node_id = "node_id";
inline constexpr const char* element_id = "element_id";
inline constexpr const char* member = "member";
inline constexpr const char* member_names = "member_names";
inline constexpr const char* rotation = "rotation";
inline constexpr const char* initial_position = "initial_position";
inline constexpr const char* bending_moment = "bending_moment";
inline constexpr const char* reaction = "reaction";
inline constexpr const char* reaction_moment = "reaction_moment";
inline constexpr const char* support = "support";
inline constexpr const char* applied_load = "applied_load";
inline constexpr const char* applied_moment = "applied_moment";
inline constexpr const char* line_load = "line_load";
inline constexpr const char* spring_force = "spring_force";
inline constexpr const char* spring_moment = "spring_moment";
inline constexpr const char* contact_force = "contact_force";
inline constexpr const char* surface_contact_force = "surface_contact_force";
inline constexpr const char* gap = "gap";
inline constexpr const char* contact = "contact";
inline constexpr const char* plastic_utilisation = "plastic_utilisation";
inline constexpr const char* hinge_state = "hinge_state";
inline constexpr const char* axial_force = "axial_force";
inline constexpr const char* moment_i = "moment_i";
inline constexpr const char* moment_j = "moment_j";
inline constexpr const char* shear = "shear";
inline constexpr const char* end_forces = "end_forces";
inline constexpr const char* yielded_share = "yielded_share";
inline constexpr const char* section_yielded_share = "section_yielded_share";
inline constexpr const char* section_curvature = "section_curvature";
inline constexpr const char* section_moment = "section_moment";
inline constexpr const char* ei_ratio = "ei_ratio";
inline constexpr const char* utilisation_i = "utilisation_i";
inline constexpr const char* utilisation_j = "utilisation_j";
inline constexpr const char* hinge_state_i = "hinge_state_i";
inline constexpr const char* hinge_state_j = "hinge_state_j";
inline constexpr const char* time_value = "TimeValue";
inline constexpr const char* load_factor = "load_factor";
inline constexpr const char* load = "load";
inline constexpr const char* control_displacement = "control_displacement";
inline constexpr const char* step = "step";
inline constexpr const char* iterations = "iterations";
inline constexpr const char* contact_count = "contact_count";
inline constexpr const char* surface_contact_count = "surface_contact_count";
inline constexpr const char* hinge_count = "hinge_count";
inline constexpr const char* mirror_x = "mirror_x";
inline constexpr const char* scene = "scene";
inline constexpr const char* title = "title";
inline constexpr const char* load_label = "load_label";
inline constexpr const char* displacement_label = "displacement_label";
inline constexpr const char* length_unit = "length_unit";
inline constexpr const char* force_unit = "force_unit";
inline constexpr const char* load_unit = "load_unit";
inline constexpr const char* displacement_unit = "displacement_unit";
inline constexpr const char* base_kind = "kind";
inline constexpr const char* base_motion = "motion";
inline constexpr const char* released = "released";
inline constexpr const char* stage = "stage";
inline constexpr const char* pattern_factors = "pattern_factors";
inline constexpr const char* pattern_names = "pattern_names";
inline constexpr const char* base_pattern = "pattern";
} // namespace name

// Codes of the Int32 states.
enum class HingeCode : int { elastic = 0, yielding = 1, plastic = 2, failed = 3 };
enum class ContactCode : int { open = 0, closed = 1 };
enum class CriticalCode : int { bifurcation = 1, limit_point = 2 };
enum class BaseKind : int { spring_anchor = 0, rigid_line = 1 };
// `support`: the sum of the DOFs a node's support fixes.
inline constexpr int fixes_ux = 1, fixes_uy = 2, fixes_rz = 4;

} // namespace plastica::result
