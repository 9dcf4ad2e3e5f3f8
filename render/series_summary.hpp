// What the whole series holds, gathered in one pass over its steps before any frame is drawn:
// the bounds of the motion (so the camera never jumps), the load–displacement curve, the range
// of the coloured field (so one colour means one value in every frame), and which layers the
// scene needs at all (a base, contact arrows, plastic hinges). Only these summaries are kept,
// so memory does not grow with the number of steps.
#pragma once

#include "result_series.hpp"

#include <vtkSmartPointer.h>

#include <array>
#include <string>
#include <vector>

class vtkDataArray;
class vtkUnstructuredGrid;

namespace plastica::render {

struct CurvePoint {
    int step = 0;
    double time = 0.0;       // model time (a series in time)
    double base_shear = 0.0; // the horizontal force on the supports (−Σ of their reactions along x)
    // The energy accounts of a series in time (the VTU's `energy`): kinetic, strain, plastic,
    // damping, contact, external, ground motion, and the balance's error.
    std::array<double, 8> energy{};
    double displacement = 0.0;
    double load = 0.0;
    int contact_count = 0;
    int hinge_count = 0;
    // The critical point this step passed (the VTU's critical_point): 0 none, 1 a bifurcation,
    // 2 a limit point; and where it lies.
    int critical = 0;
    double critical_load_factor = 0.0;
};

struct ColourField {
    std::string name;
    bool on_cells = false; // a cell array (per element) rather than a point array
    int components = 1;    // vectors are coloured by their magnitude
    // A signed quantity (a force, moment, length, rotation or curvature, one component): coloured
    // on a scale diverging about zero, so that a sign is a colour in every frame and every run.
    // Otherwise (shares, ratios, magnitudes) a sequential scale from zero.
    bool is_signed = false;
};

struct SeriesSummary {
    std::string scene, title, load_label, displacement_label;
    double bounds[4] = {0, 0, 0, 0}; // x min, x max, y min, y max of every deformed and initial point
    std::vector<CurvePoint> curve;   // one point per step of the series
    ColourField field;
    double field_range[2] = {0, 0};
    bool unilateral = false;         // the scene has a unilateral base (contact arrays)
    bool any_contact = false;        // some step has a node in contact
    double max_contact_force = 0.0;
    double max_surface_contact_force = 0.0; // largest push between surfaces ([[self_contact]]) at a node
    bool inelastic = false;          // the scene has plastic hinges (hinge arrays)
    // A series in time (its VTUs carry model_time): charts plot against time, frames say t.
    bool in_time = false;
    bool mirrored = false;           // a half model drawn with its mirror image about x = mirror_x
    double mirror_x = 0.0;
    bool any_yielding = false, any_plastic = false, any_failed = false;
    // Arrows at nodes (applied loads, support reactions): the largest force and moment at a
    // node over the run, and which sides of their nodes the arrows' tails lie on.
    struct NodalArrows {
        double max_force = 0.0, max_moment = 0.0;
        int sides = 0; // bits: 1 left, 2 right, 4 below, 8 above
        // Every node's force keeps its direction through the run (loads given as fx and fy, line
        // loads): drawn as its components, as the user gave them. A pressure that follows the
        // structure turns: drawn as one arrow along the force.
        bool by_components = false;
    };
    NodalArrows loads, reactions; // loads: point loads, line loads' nodal shares taken off
    struct LineLoads {
        double max_intensity = 0.0; // the largest |w| of an element in the run
        int sides = 0;              // as NodalArrows::sides
    } line_loads;
    double magnify = 1.0;         // displacements are drawn × this (positions x0 + k·u)
    // Options that could not act, each saying why (--magnify auto on a structure resting on a
    // base): told on stderr and kept in run.json.
    std::vector<std::string> notes;
    // A structure that lands on a base after its own response (an arch snapping onto a floor)
    // is then held by the base's penalty, and its load climbs by orders of magnitude; charts
    // show the load axis over this range (both 0: the whole run) so that the structure's own
    // response stays in view.
    double load_axis_cut[2] = {0.0, 0.0};
    double largest_load = 0.0;    // the largest |load| of the run, said where the axis is cut
    // The force drawn at full length by the arrows of applied loads: the largest in the run, or,
    // where the load axis is cut, the largest while the load is in view (a base's penalty taking
    // over the load would otherwise shrink the arrow to a stub for the structure's own response).
    double load_arrow_reference = 0.0;
    // The same for the arrows of contact forces: the largest contact force in the run, or, where
    // the load axis is cut, the largest while the load is in view (after landing, the base's
    // penalty holds the load and its contact forces would set the scale).
    double contact_arrow_reference = 0.0;
    // Units the scene names (empty: none): of lengths and forces, and of the reported load and
    // displacement.
    std::string length_unit, force_unit, load_unit, displacement_unit;
};

// "label (unit)", or the label alone without a unit.
std::string with_unit(const std::string& label, const std::string& unit);
// The unit of a result array by what it holds (moments force·length, forces, lengths, rotations
// in rad); empty for shares and ratios or when the scene names no units.
std::string array_unit(const SeriesSummary& summary, const std::string& array);
// The unit, or where the scene names none, what the value is in the scene's own consistent units
// ("force·length", "length"); empty for shares and ratios.
std::string array_unit_or_dimension(const SeriesSummary& summary, const std::string& array);

// Throws RenderError naming the step file, or listing the arrays when `field` is not one of them.
// magnify: the factor displacements are drawn with; 0 chooses one: 1 when the largest
// displacement is at least 2 % of the structure's size or the structure meets a rigid base
// (magnified, it would seem to pass through it), else a round number that makes it about 10 %.
SeriesSummary summarise(const ResultSeries& series, const std::string& field, double magnify = 1.0);

// The step's grid with its points at x0 + k·u (the step itself when k = 1).
vtkSmartPointer<vtkUnstructuredGrid> magnified(vtkUnstructuredGrid* step, double k);

// Whether a point of a half model lies on its mirror line: a support there states symmetry,
// and a load there is half of the whole structure's.
bool on_mirror_line(const SeriesSummary& summary, const double* initial_position);

// The magnitude of tuple i of an array (its value when it has one component).
double tuple_magnitude(vtkDataArray* array, long long i);

} // namespace plastica::render
