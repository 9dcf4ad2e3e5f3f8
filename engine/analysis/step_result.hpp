// What the analysis reports for every converged step: the state the observers (VTU writer,
// curve writer, progress) read. Nothing here refers to solver internals.
#pragma once

#include "element/basic_law.hpp"
#include "element/corotational_beam.hpp"
#include "solver/newton_solver.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace plastica {

struct ElementResult {
    BeamForces forces;
    bool hinged = false;
    std::array<HingeReport, 2> hinge{};
    std::vector<SectionReport> sections; // distributed plasticity: its integration points
};

struct SpringResult {
    int node = 0;
    bool unilateral = false;
    bool active = false;
    double gap = 0.0;
    std::array<double, 3> force{0.0, 0.0, 0.0}; // on the node, from the spring or the base
};

// Two surfaces pressed together ([[self_contact]]): a node against a segment (or a segment end).
struct SurfaceContactResult {
    int node = 0;
    std::array<int, 2> segment{0, 0}; // the segment's ends; the same twice for a segment end
    double xi = 0.0;                  // where along the segment
    double gap = 0.0;                 // negative: the penetration
    std::array<double, 2> force{0.0, 0.0}; // on the node; its segment takes the opposite
    // The point that touches: (1 − eta)·point[0] + eta·point[1] (a node: both the node).
    std::array<int, 2> point{0, 0};
    double eta = 0.0;
};

// A transient step's energy accounts since the first transient stage began (Hughes, The
// Finite Element Method, 1987, ch. 9): each work is the trapezoidal sum of its force over the
// displacement increments. strain: the elastic energy the members would give back unloading
// (½ qᵀ f_elastic q of their end forces); plastic: the members' work less the change of it.
struct EnergyTerms {
    double kinetic = 0.0, strain = 0.0, plastic = 0.0, damping = 0.0, contact = 0.0, external = 0.0, ground = 0.0;
    double error = 0.0; // |kinetic + strain + plastic + damping + contact − external − ground − initial| over the largest term
};

// A point of the path where the tangent loses its positive definiteness (one more negative
// pivot): a bifurcation, where the critical mode is orthogonal to the load (φ·f ≈ 0) and the
// path may branch, or a limit point, where it is not and the load passes a maximum. Located by
// the tangent eigenvalue problem about the last stable state (analysis/linear_buckling.hpp).
enum class CriticalKind { bifurcation, limit };

struct CriticalPoint {
    CriticalKind kind = CriticalKind::bifurcation;
    int step = 0;              // the first step past it
    double load_factor = 0.0;  // where the lowest eigenvalue of the tangent passes zero
    double load = 0.0;         // the same as the reported load
    double load_alignment = 0.0; // |φ·f| / (‖φ‖ ‖f‖) over the free DOFs
    std::vector<double> mode;  // full DOF vector, its largest nodal translation 1
    bool followed = false;     // the path switched to the branch along the mode
};

const char* to_string(CriticalKind kind);

struct StepResult {
    int step = 0;                   // 0 is the unloaded state
    double load_factor = 0.0;       // λ, the factor of the pattern the step's stage drives
    double load = 0.0;              // reported load: the reported pattern's factor · Model::load_per_factor()
    double control_displacement = 0.0; // of Model::reported_control()
    int stage = 1;                  // 1 for [analysis], then 2, 3, … for each [[stage]]
    std::vector<double> pattern_factors; // per load pattern (Model::patterns), λ for the driven one
    double arc_length = 0.0;        // cumulative path length, monotone
    int iterations = 0;
    Acceptance accepted_by = Acceptance::none; // which rule accepted the step
    int negative_pivots = 0;
    double residual = 0.0;          // relative residual at convergence
    std::vector<double> displacement; // 3 per node: ux, uy, rotation
    std::vector<double> reaction;     // 3 per node, at supported and prescribed DOFs (zero elsewhere):
                                      // the force the support exerts on the structure
    std::vector<double> applied_load; // 3 per node: each pattern's factor × its reference loads (pressure as it follows)
    std::vector<ElementResult> elements;
    std::vector<SpringResult> springs;
    int contact_count = 0;
    std::vector<SurfaceContactResult> surface_contacts;
    double base_reaction = 0.0;     // total normal force of the base
    double contact_length = 0.0;    // length of the deformed structure along active nodes
    int hinge_count = 0;            // element ends yielding or plastic
    int plastic_hinge_count = 0;    // element ends at capacity
    // Transient steps: model time, the free DOFs' velocity and acceleration (3 per node, relative
    // to a moving ground), and the energies; a static step's time is where time stands (0 before
    // the first transient stage).
    double time = 0.0;
    std::vector<double> velocity, acceleration;
    EnergyTerms energy;
    // The critical point passed in this step, if any.
    std::optional<CriticalPoint> critical;
    // The path has passed its first limit point (analysis/path_watch.hpp): a higher load from
    // here on is not the structure's capacity.
    bool past_first_limit = false;
};

// output_failed: an observer could not take a step (a full disk); the steps before it stand.
enum class RunStatus { completed, no_convergence, limit_load, non_finite, interrupted, step_limit, penetration, output_failed, out_of_memory };

struct RunSummary {
    RunStatus status = RunStatus::completed;
    std::string reason;
    int steps = 0;
    // Transient stages: the model time reached, the largest energy error and its step.
    double time = 0.0;
    double largest_energy_error = 0.0;
    int largest_energy_error_step = 0;
    double rayleigh_alpha_m = 0.0, rayleigh_beta_k = 0.0; // the damping's coefficients as used
    int iterations = 0;
    int cut_steps = 0;
    // Converged steps of adaptive increments taken again smaller because they carried a hinge
    // section too far into its yielding range (not counted as cut).
    int refined_steps = 0;
    // Steps taken with the hinges' capacity rows or the fibre members stiffened, where a perfectly
    // plastic mechanism let no increment converge (PathFollowing::after_failure).
    int stiffened_steps = 0;
    int accepted_by_residual = 0;
    int accepted_by_stagnation = 0;
    // Converged steps whose tangent had a negative pivot (past a limit or a bifurcation), and the
    // first of them (−1: none).
    // The largest residual tolerance a step was accepted with, and that step: above the
    // analysis' own where the tolerance followed the round-off floor.
    double largest_residual_tolerance = 0.0;
    int largest_tolerance_step = 0;
    int negative_pivot_steps = 0;
    int first_negative_pivot_step = -1;
    // Every critical point the path passed, in order (the modes included).
    std::vector<CriticalPoint> critical_points;
    // The run ended on a branch that is not stable: past a bifurcation it did not follow.
    bool ends_unstable = false;
    double seconds = 0.0;
};

const char* to_string(RunStatus status);

} // namespace plastica
