// The predictor of an increment from the path already traced: the last three converged states
// (free displacements, load factor and the members' axial forces against a path parameter: the
// controlled displacement, the load factor or the arc length) extrapolated by the quadratic
// through them.
//
// Why not the tangent alone: a tangent step moves every node along a straight line, and a
// member that turns by φ in the step then stretches by about φ²/2 of its length; in a thin
// member (EA·L²/EI of 1e9 in the ring) that strain puts a residual of a thousand times the
// load on the first iterate, and plastic hinges and contacts decide their states at that wild
// state. The quadratic's error is one order higher in the step, so the first iterate is close
// to the path and Newton starts inside its basin.
//
// Its residual is still mostly the membrane's (the ring's: 50 times the load), and so are the
// axial forces at that point, far from those on the path. A tangent whose geometric stiffness
// came from them would steer the first correction's bending part off (the ring then needed a
// second correction for that and a third for the membrane strain the second one made): the
// first tangent takes the extrapolated axial forces in its elastic members instead (644 → 472
// iterations in the elastic ring's 200 steps, the converged states the same to round-off), where
// they differ from the start's by a stretch below 1e-4 (StructuralSystem::element_stiffness). Not
// in members that may yield: there the law's return map bounds the trial's axial force, and the
// quadratic through a kink of the path (a hinge forming) overshoots; measured on the variants
// of the inelastic rings and the catenary beam, seven that complete stopped early with it.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <optional>

namespace plastica {

struct PathPoint {
    double parameter = 0.0;
    Eigen::VectorXd displacement; // free DOFs
    double load_factor = 0.0;
    Eigen::VectorXd axial_forces; // per member
};

class PathExtrapolation {
public:
    void add(double parameter, const Eigen::VectorXd& displacement, double load_factor,
             const Eigen::VectorXd& axial_forces);
    // Forget the path (a new stage may turn back: the old points do not lie ahead of it).
    void clear() { count_ = 0; }
    bool ready() const { return count_ >= 3; }
    // A step traced since the start or the last clear().
    bool traced_a_step() const { return count_ >= 2; }
    // The state at `parameter`; only when ready().
    PathPoint at(double parameter) const;
    // The largest |λ| of the quadratic through the last two points and a new one (parameter,
    // load factor), where its vertex lies between the last point and the new one: a limit point
    // between samples. Empty with fewer than two points or no such vertex.
    // vertex: where it lies, in the path parameter.
    std::optional<double> peak_with(double parameter, double load_factor, double* vertex = nullptr) const;

private:
    std::array<PathPoint, 3> points_; // oldest first
    int count_ = 0;
};

} // namespace plastica
