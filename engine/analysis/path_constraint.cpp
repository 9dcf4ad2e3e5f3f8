#include "analysis/path_constraint.hpp"

#include "analysis/increment_constraints.hpp"
#include "analysis/step_controller.hpp"

#include <cmath>

namespace plastica {

namespace {

class LoadControlPath final : public PathConstraint {
public:
    Scheme scheme() const override { return Scheme::load_control; }
    double parameter(const PathPosition& at) const override { return at.load_factor; }
    double landing(double h, const PathPosition& at, const AnalysisSpec& stage) const override {
        return stage.target_load_factor ? StepController::landing(h, *stage.target_load_factor - at.load_factor) : h;
    }
    // The load factor is the path parameter: its step exactly.
    double extrapolated_load_change(double h, double) const override { return h; }
    std::unique_ptr<IncrementConstraint> corrector(double h, const CorrectorContext&) const override {
        return std::make_unique<LoadControl>(h);
    }
    bool prescribes_load_factor() const override { return true; }
};

class DisplacementControlPath final : public PathConstraint {
public:
    Scheme scheme() const override { return Scheme::displacement_control; }
    double parameter(const PathPosition& at) const override { return at.control; }
    double landing(double h, const PathPosition& at, const AnalysisSpec& stage) const override {
        return stage.target_displacement ? StepController::landing(h, *stage.target_displacement - at.control) : h;
    }
    std::unique_ptr<IncrementConstraint> corrector(double h, const CorrectorContext& c) const override {
        return std::make_unique<DisplacementControl>(c.control_equation, h * c.control_sign);
    }
};

// An arc-length increment within 18° of the reverse of the last one (cosine below minus this)
// retraced the path.
constexpr double max_turn_cosine = 0.95;

class ArcLengthPath final : public PathConstraint {
public:
    Scheme scheme() const override { return Scheme::arc_length; }
    double parameter(const PathPosition& at) const override { return at.arc_length; }
    // An arc's increment cannot be shortened to a target in λ or u beforehand: the step that
    // passes it is taken again under the control that lands on it.
    double landing(double h, const PathPosition&, const AnalysisSpec&) const override { return h; }
    bool retakes_past_target() const override { return true; }
    // Its constraint sphere already centres the corrector on the path, and the extrapolated
    // point steers the root choice past a limit point into the wrong branch.
    bool starts_from_extrapolation() const override { return false; }
    std::unique_ptr<IncrementConstraint> corrector(double h, const CorrectorContext& c) const override {
        return std::make_unique<ArcLength>(h, *c.previous, c.nearest_when_no_root);
    }
    // An increment nearly opposite to the last one went back down the path (the corrector
    // wandered across an active-set change and met the arc behind). Along a smooth path
    // consecutive increments turn by a few degrees, even through a limit point or a snap-back;
    // a corner where a contact opens may turn the path by well over a right angle (137° where
    // the arch lifts off the floor), but not back on itself.
    bool turned_back(const Eigen::VectorXd& increment, const Eigen::VectorXd& previous) const override {
        return increment.size() == previous.size() &&
               increment.dot(previous) < -max_turn_cosine * increment.norm() * previous.norm();
    }
};

} // namespace

std::unique_ptr<PathConstraint> make_path_constraint(Scheme scheme) {
    switch (scheme) {
    case Scheme::load_control: return std::make_unique<LoadControlPath>();
    case Scheme::displacement_control: return std::make_unique<DisplacementControlPath>();
    case Scheme::arc_length: return std::make_unique<ArcLengthPath>();
    case Scheme::transient: break; // time integration follows no path (engine/dynamics/)
    }
    return std::make_unique<LoadControlPath>();
}

} // namespace plastica
