// The structural model: what a scene file describes once it has been read and validated.
// Plain data only; the analysis builds elements, sections and springs from it.
#pragma once

#include "model/dynamics_spec.hpp"

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace plastica {

inline constexpr int dofs_per_node = 3; // ux, uy, rotation (counter-clockwise)

struct Node {
    double x = 0.0;
    double y = 0.0;
};

// Bilinear steel (Silva et al., CS-ASA, eq. 6): elastic inside ±εy, ±fy up to ±εu, failed past εu.
// An inelastic material: its law (material/material_registry.cpp lists them), the parameters
// every law has, and those of its own (by key, as the scene names them).
struct SteelSpec {
    double E = 0.0;
    double fy = 0.0;
    double ultimate_strain = 0.0; // εu; 0 means "never fails"
    std::string law = "bilinear";
    std::map<std::string, double> parameters;
};

// The CS-ASA paper's elastic–perfectly plastic steel.
inline SteelSpec bilinear_steel(double E, double fy, double ultimate_strain = 0.0) {
    SteelSpec s;
    s.E = E;
    s.fy = fy;
    s.ultimate_strain = ultimate_strain;
    return s;
}

struct Fibre {
    double area = 0.0;
    double y = 0.0;                 // distance from the reference axis, local +y side
    double residual_stress = 0.0;   // initial stress (ECCS patterns and the like)
    int material = 0;               // 0: the section's material; k ≥ 1: SectionSpec::other_materials[k − 1]
    double extent = 0.0;            // half the fibre's height in y: where its outer edge lies (first yield, strain limits)
};

// How an inelastic section's plasticity is modelled along a member.
enum class Plasticity {
    none,        // elastic
    hinges,      // refined plastic hinges at element ends (concentrated plasticity)
    distributed, // fibre sections at integration points along the member (plastic zone)
};

// How a distributed-plasticity member relates its sections to its ends: by a displacement
// field (curvature linear along each segment) or by equilibrium (moments linear, exact).
enum class Formulation { displacement, force };

// Gauss–Legendre points per segment, and segments per element, of a displacement-based
// distributed-plasticity member unless the scene says; Gauss–Lobatto points of a force-based one.
inline constexpr int default_integration_points = 3;
inline constexpr int default_force_based_points = 5;
inline constexpr int default_segments = 1;

// Layers through a rectangle's depth unless the scene says. A perfectly plastic law in a plastic
// zone gets more: past `layers`·κ_y every layer has yielded and the section's M–κ is flat, and
// when a plastic zone's sections all reach that, Newton stalls (a ring crushed between plates
// on 50 elements stops at 17 % of its travel with 10 layers and completes with 30).
inline constexpr int default_layers = 10;
inline constexpr int default_perfectly_plastic_zone_layers = 30;

// A section carries elastic properties for the beam interior and, when the scene is
// inelastic, a fibre discretisation used by the plastic hinges (Strain Compatibility Method).
struct SectionSpec {
    std::string name;
    double E = 0.0;
    double area = 0.0;
    double inertia = 0.0;
    std::optional<SteelSpec> steel; // present: inelastic section with fibres (of this material unless they name another)
    std::vector<SteelSpec> other_materials; // the laws of rebars, a tube's core, a slab (Fibre::material ≥ 1)
    std::vector<Fibre> fibres;      // filled when steel is present
    Plasticity plasticity = Plasticity::none; // hinges or distributed when steel is present
    Formulation formulation = Formulation::displacement; // distributed
    int integration_points = 0;     // distributed: Gauss–Legendre points per segment (Lobatto: force-based)
    int segments = 1;               // distributed: segments per element (inner nodes condensed)
    double segment_grading = 1.0;   // distributed: each segment's length over its outer neighbour's
    bool axial_strain_per_segment = false; // distributed segments: each its own axial strain, one N along the member
    double mass_per_length = 0.0;   // density × area: self weight and inertia
    double rotary_inertia_per_length = 0.0; // density × inertia
    // The distance between the section's two surfaces (h, depth, diameter, thickness) where
    // self-contact needs it; 0: that of the rectangle of the same A and I, √(12 I/A).
    double depth = 0.0;
    double surface_depth() const { return depth > 0.0 ? depth : std::sqrt(12.0 * inertia / area); }
};

struct ElementSpec {
    int node_i = 0;
    int node_j = 0;
    int section = 0;
    std::array<bool, 2> released{false, false}; // moment releases at node_i, node_j (a pin in the member)
    int member = -1; // index in Model::member_names; -1 for an element given on its own ([[element]])
};

// [[self_contact]]: the surfaces of these elements, at ± half their section's depth from the
// centre line, do not pass through each other (frictionless, penalty; contact/self_contact.hpp).
struct SelfContactSpec {
    std::vector<int> elements;
    // Force per unit penetration (per unit length too where the surfaces act along the
    // members); 0: SelfContact's default from the members.
    double stiffness = 0.0;
    // Points along each member press (Gauss points), not only its nodes.
    bool along_members = false;
};

struct Support {
    int node = 0;
    std::array<bool, dofs_per_node> fixed{false, false, false};
};

// Loads, pressures, prescribed displacements and moving bases each belong to a load pattern
// (Model::patterns; 0 is "main"). A stage drives one pattern's factor; the others stay at the
// factor they last had (OpenSees' loadConst).
struct NodalLoad {
    int node = 0;
    std::array<double, dofs_per_node> value{0.0, 0.0, 0.0}; // fx, fy, moment; scaled by λ
    int pattern = 0;
};

// Pressure on an element, per unit current length, normal to its deformed chord (a follower
// load): positive along the element's left normal (node i to node j), scaled by λ.
struct ElementPressure {
    int element = 0;
    double value = 0.0;
    int pattern = 0;
};

// A line load in a fixed direction per unit initial length ([[distributed_load]] wx, wy) on an
// element. The analysis takes it as the nodal loads it lumps to (in Model::loads); this record
// is for the outputs, which draw it along the member.
struct ElementLineLoad {
    int element = 0;
    double wx = 0.0, wy = 0.0;
    int pattern = 0;
};

struct PrescribedDisplacement {
    int node = 0;
    int dof = 0;
    double value = 0.0; // reference value, scaled by λ
    int pattern = 0;
};

// A straight rigid base: points x with (x − p)·normal < 0 penetrate it, where p = point + λ·motion
// (a platen driven by the load factor; motion zero for a fixed base).
struct BaseLine {
    std::array<double, 2> point{0.0, 0.0};
    std::array<double, 2> normal{0.0, 1.0};
    std::array<double, 2> motion{0.0, 0.0};
    int pattern = 0; // whose factor moves it

    bool moves() const { return motion[0] != 0.0 || motion[1] != 0.0; }
    // The gap of a point at load factor λ.
    double gap(double x, double y, double load_factor) const {
        return (x - point[0] - load_factor * motion[0]) * normal[0] + (y - point[1] - load_factor * motion[1]) * normal[1];
    }
};

// Discrete foundation spring at a node (Silva et al., CS-ASA, eq. 5): Kb = diag(kx, ky, kθ). A unilateral
// spring pushes along the base normal only, and only while the node touches the base. An
// anchored one (a tensionless Winkler bed) has no base line: it pushes with stiffness ky along
// its own `direction` while the node has moved against it from its initial position.
struct FoundationSpring {
    int node = 0;
    double kx = 0.0;
    double ky = 0.0;
    double krot = 0.0;
    bool unilateral = false;
    bool anchored = false;                       // unilateral, against the node's initial position
    std::array<double, 2> direction{0.0, 1.0};   // anchored: the unit direction the bed pushes
    int base = 0;                                // unilateral, not anchored: its base line in Model::bases
    bool along_members = false;                  // unilateral: the base acts along the members (BaseEdge), not at the node; ky is then the tributary share, for scales only
};

// A member pressed onto a rigid base along its length (contact/member_overlap.hpp): the springs
// of its end nodes on that base carry the forces of the overlap.
struct BaseEdge {
    std::array<int, 2> spring{0, 0};          // indices into Model::springs, along_members
    double stiffness = 0.0;                   // the penalty per unit length
    double length = 0.0;                      // the member's initial length
    std::array<double, 2> tangent_angle{0.0, 0.0}; // the centre line's initial direction at i and j, from i toward j
    bool straight = false;                    // a released end: the chord stands for the member
};

// transient: time integration (engine/dynamics/), the others path following.
enum class Scheme { load_control, displacement_control, arc_length, transient };

struct DofRef {
    int node = 0;
    int dof = 1;
    double sign = 1.0; // reported value = sign * displacement

    // Its reported value in a full displacement vector u (three DOFs a node).
    template <class Vector>
    double value_in(const Vector& u) const {
        return sign * u[dofs_per_node * node + dof];
    }
};

// What the path does at a bifurcation: say so and go on along the fundamental path, or go on
// along the buckled branch (analysis/path_critical.cpp).
enum class BifurcationRule { report, switch_branch };

// The kinematics of the members: co-rotational (large displacements and rotations), or first
// order (small displacements: equilibrium on the initial geometry, no P-Δ, pressure on the
// initial chords), which EN 1993-1-1 §5.2's α_cr = F_cr/F_Ed and design by hand are built on.
enum class Geometry { large_displacement, first_order };

// An imperfection in the shape of a buckling mode of a pattern's loads ([[imperfection]]):
// the perfect geometry plus `amplitude` times the mode scaled to a largest nodal translation of 1
// (analysis/imperfections.hpp).
struct ImperfectionSpec {
    int mode = 1;
    double amplitude = 0.0; // a length, signed
    int pattern = 0;
    double load_factor = 0.0; // the mode's critical factor on the perfect geometry (set when applied)
};

struct AnalysisSpec {
    Scheme scheme = Scheme::arc_length;
    BifurcationRule bifurcation = BifurcationRule::report;
    Geometry geometry = Geometry::large_displacement;
    double initial_increment = 0.01; // Δλ, Δu of the control DOF, or arc length Δl
    double min_increment = 1e-8;
    double max_increment = 0.0;      // 0: no cap
    int desired_iterations = 5;      // adapts increments toward this count
    bool adaptive = true;
    int max_iterations = 30;
    int max_steps = 1000;
    static constexpr double default_residual_tolerance = 1e-6;
    double residual_tolerance = default_residual_tolerance; // ‖R‖ relative to the reference load
    // Not given by the scene: the tolerance then rises to the state's round-off floor where
    // that lies above it (a fine mesh, a stiff penalty), instead of stopping the run.
    bool residual_tolerance_follows_floor = false;
    static constexpr double default_displacement_tolerance = 1e-6;
    double displacement_tolerance = default_displacement_tolerance; // ‖δu‖ relative to ‖Δu‖ of the step
    std::optional<double> target_load_factor;
    std::optional<double> target_displacement; // on the control DOF, signed as reported
    DofRef control;                            // displacement control and reporting
    int pattern = 0;                           // the load pattern λ drives (Model::patterns)
    // Self-contact is not modelled: a structure that passes through itself stops the run,
    // unless the scene allows it (a cantilever rolled into two turns, say).
    bool allow_crossing = false;
    TransientSpec transient; // scheme transient
};

// A further stage of the analysis after [analysis]'s: the path goes on from where the previous
// stage ended, under load or displacement control, toward a target on either side (unloading
// to λ = 0, reloading, reversing).
struct StageSpec {
    Scheme scheme = Scheme::load_control;
    double increment = 0.1;                    // |Δλ| or |Δu| of the control DOF
    bool adaptive = false;
    std::optional<double> target_load_factor;
    std::optional<double> target_displacement; // on the control DOF, signed as reported
    int pattern = 0;                           // the load pattern it drives
    DofRef control;                            // its controlled DOF (the previous stage's unless named)
    TransientSpec transient;                   // scheme transient
};

struct ReportSpec {
    // The reported load: λ times the total of the reference loads along their common direction
    // (forces all parallel, or moments only), or λ itself where they are not parallel (or the
    // scene asks for the factor); times load_scale (2 for a half model).
    // platen: the force the moving bases press with (a scene driven by platens alone).
    enum class Measure { total, factor, platen } measure = Measure::total;
    double load_scale = 1.0;
    std::string load_label = "load";                         // axis and title names in pictures
    std::string displacement_label = "control displacement";
    std::string exact;  // a closed form this scene has ("cantilever_tip_load"), for `plastica study`
    std::optional<double> mirror_x; // a half model symmetric about x = mirror_x: pictures show both halves
    std::string length_unit, force_unit; // names for pictures ("mm", "kN"); empty: none given
    // Control displacements at which run.json gives the load, interpolated along the path (a
    // flattening standard's travel, δ/D = 0.5 as δ = 0.5 D), each where the path first reaches it.
    std::vector<double> load_at;
};

struct Model {
    std::string name;
    std::string title;  // free text for pictures
    std::string source; // the scene file it came from
    std::vector<Node> nodes;
    std::vector<SectionSpec> sections;
    std::vector<ElementSpec> elements;
    std::vector<std::string> member_names; // the [[line]]s and [[arc]]s, in the scene's order
    std::vector<Support> supports;
    std::vector<NodalLoad> loads; // nodal loads, line loads and self weight lumped to nodes
    std::vector<ElementPressure> pressures;
    std::vector<ElementLineLoad> line_loads; // drawn only: their nodal shares are in `loads`
    std::vector<PrescribedDisplacement> prescribed;
    std::vector<FoundationSpring> springs;
    std::vector<SelfContactSpec> self_contact;
    std::vector<BaseLine> bases; // the rigid base lines of unilateral springs (FoundationSpring::base)
    std::vector<BaseEdge> base_edges; // members that bear on a base along their length
    std::vector<std::string> patterns{"main"}; // load pattern names, "main" first
    AnalysisSpec analysis;
    std::vector<StageSpec> stages; // after the first ([analysis]), in order
    std::vector<ImperfectionSpec> imperfections; // applied to the nodes when the scene is read
    DynamicsSpec dynamics;
    ReportSpec report;

    // Whether some stage integrates in time.
    bool transient() const;
    // The path following locates bifurcations and limit points (analysis/path_critical.cpp):
    // every member elastic (a yielding one's pivots turn with its hinges and fibres), and some
    // stage follows a path.
    bool tracks_critical_points() const;
    int dof_count() const { return dofs_per_node * static_cast<int>(nodes.size()); }
    // The larger side of the nodes' bounding box (0 for fewer than two distinct points).
    double size() const;
    bool inelastic() const;
    bool has_plasticity(Plasticity kind) const; // some element's section models it this way
    int integration_points() const;             // most sections along a distributed-plasticity element
    bool has_unilateral_base() const;
    // Whether a base moves with the load factor (a platen).
    bool has_moving_base() const;
    // Whether loads, pressures or prescribed displacements act (scaled by λ).
    bool loaded() const { return !loads.empty() || !pressures.empty() || !prescribed.empty(); }
    // Whether pattern p has loads, pressures or prescribed displacements.
    bool loaded(int pattern) const;
    // Forces (nodal loads, line loads, pressure) in the pattern; without them the pattern only
    // moves supports or bases, and a negative pivot along it is no limit of anything it scales.
    bool has_forces(int pattern) const;
    // Whether a base of pattern p moves.
    bool has_moving_base(int pattern) const;
    // Nothing but moving bases drives pattern p.
    bool driven_by_platens(int pattern) const { return !loaded(pattern) && has_moving_base(pattern); }
    // The same for the reported pattern.
    bool driven_by_platens() const { return driven_by_platens(reported_pattern()); }
    // The pattern the curve reports, and the controlled DOF it reports: the last stage's.
    int reported_pattern() const { return stages.empty() ? analysis.pattern : stages.back().pattern; }
    const DofRef& reported_control() const { return stages.empty() ? analysis.control : stages.back().control; }
    // Whether the reported pattern's loads have one direction (parallel forces, or moments only).
    bool loads_parallel() const;
    // Whether the reported pattern's only load is one pressure, equal on every loaded element
    // (it is then reported).
    bool uniform_pressure_only() const;
    // The reported load per unit factor of the reported pattern (ReportSpec::measure, load_scale included).
    double load_per_factor() const;
    // Whether some member end is released.
    bool has_releases() const;
    // Per node: whether its rotation meets no stiffness at all (every member end there is
    // released, and no support, prescribed rotation or rotational spring holds it). Such a
    // rotation is held at zero: it moves nothing.
    std::vector<bool> rotation_unattached() const;
};

} // namespace plastica
