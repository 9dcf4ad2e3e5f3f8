// What each scheme of path following fixes along the path, and what it means for the loop that
// follows it: the quantity a state's place along the path is measured in (its path parameter),
// how an increment lands on a stage's target, whether a step may start from the path's
// extrapolation, and the constraint Newton's corrector meets (increment_constraints.hpp).
// A new scheme is one more PathConstraint here and one case in make_path_constraint.
#pragma once

#include "model/model.hpp"
#include "solver/newton_solver.hpp"

#include <Eigen/Dense>
#include <memory>
#include <optional>

namespace plastica {

// Where a state lies: its load factor, the displacement of the stage's controlled DOF (signed
// as reported) and the arc length travelled.
struct PathPosition {
    double load_factor = 0.0;
    double control = 0.0;
    double arc_length = 0.0;
};

// What the corrector of one increment needs beyond its size.
struct CorrectorContext {
    int control_equation = -1;          // the controlled DOF's equation
    double control_sign = 1.0;          // reported value = sign · displacement
    const Eigen::VectorXd* previous = nullptr; // the last converged increment (free DOFs; empty at the start)
    bool nearest_when_no_root = false;  // an arc missed by the corrector's line: its nearest point
};

class PathConstraint {
public:
    virtual ~PathConstraint() = default;
    virtual Scheme scheme() const = 0;
    // A state's place along the path, in the quantity increments are measured in.
    virtual double parameter(const PathPosition& at) const = 0;
    // The increment to try: h, or what lands on the stage's target where h would pass it.
    virtual double landing(double h, const PathPosition& at, const AnalysisSpec& stage) const = 0;
    // Whether a converged step that passed the target is taken again under the control that
    // lands on it (a scheme whose increments cannot be shortened to the target beforehand).
    virtual bool retakes_past_target() const { return false; }
    // Whether a step starts from the path's quadratic extrapolation (when there is one).
    virtual bool starts_from_extrapolation() const { return true; }
    // The load factor's change a step extrapolated by h starts with, the extrapolation's being `extrapolated`.
    virtual double extrapolated_load_change(double /*h*/, double extrapolated) const { return extrapolated; }
    // The constraint on one increment of size h (signed) for Newton's corrector.
    virtual std::unique_ptr<IncrementConstraint> corrector(double h, const CorrectorContext& context) const = 0;
    // Whether a converged increment is refused, given the last converged one.
    virtual bool turned_back(const Eigen::VectorXd& /*increment*/, const Eigen::VectorXd& /*previous*/) const {
        return false;
    }
    // Whether the user's factor is the load itself (and a tangent without stiffness against it a limit).
    virtual bool prescribes_load_factor() const { return false; }
};

std::unique_ptr<PathConstraint> make_path_constraint(Scheme scheme);

} // namespace plastica
