// The predictor of an increment from the path already traced: the last three converged states
// (free displacements and load factor against a path parameter: the controlled displacement,
// the load factor or the arc length) extrapolated by the quadratic through them.
//
// Why not the tangent alone: a tangent step moves every node along a straight line, and a
// member that turns by φ in the step then stretches by about φ²/2 of its length; in a thin
// member (EA·L²/EI of 1e9 in the ring) that strain puts a residual of a thousand times the
// load on the first iterate, and plastic hinges and contacts decide their states at that wild
// state. The quadratic's error is one order higher in the step, so the first iterate is close
// to the path and Newton starts inside its basin.
#pragma once

#include <Eigen/Dense>
#include <array>

namespace plastica {

struct PathPoint {
    double parameter = 0.0;
    Eigen::VectorXd displacement; // free DOFs
    double load_factor = 0.0;
};

class PathExtrapolation {
public:
    void add(double parameter, const Eigen::VectorXd& displacement, double load_factor);
    // Forget the path (a new stage may turn back: the old points do not lie ahead of it).
    void clear() { count_ = 0; }
    bool ready() const { return count_ >= 3; }
    // A step traced since the start or the last clear().
    bool traced_a_step() const { return count_ >= 2; }
    // The state at `parameter`; only when ready().
    PathPoint at(double parameter) const;

private:
    std::array<PathPoint, 3> points_; // oldest first
    int count_ = 0;
};

} // namespace plastica
