// The three ways an increment is constrained (each an IncrementConstraint for Newton):
// load control (Δλ given), displacement control of one equation (Batoz & Dhatt), and
// Crisfield's cylindrical arc length ‖Δx‖ = Δl with the root nearest the current increment.
#pragma once

#include "solver/newton_solver.hpp"

namespace plastica {

class LoadControl final : public IncrementConstraint {
public:
    explicit LoadControl(double delta_lambda) : h_(delta_lambda) {}
    double load_change(int iteration, const Eigen::VectorXd&, const Eigen::VectorXd&, const Eigen::VectorXd&,
                       int) override {
        return iteration == 0 ? h_ : 0.0;
    }

private:
    double h_;
};

class DisplacementControl final : public IncrementConstraint {
public:
    // Moves equation `equation` by `delta` (already signed) in the increment.
    DisplacementControl(int equation, double delta) : equation_(equation), h_(delta) {}
    double load_change(int iteration, const Eigen::VectorXd& increment, const Eigen::VectorXd& du_residual,
                       const Eigen::VectorXd& du_load, int negative_pivots) override;

private:
    int equation_;
    double h_;
};

// What the last converged arc-length step leaves for the next one's predictor.
struct ArcLengthMemory {
    Eigen::VectorXd increment;  // free DOFs (empty at the start)
    double load_change = 0.0;
    int negative_pivots = -1;   // of the tangent the step started from (-1: unknown)
};

class ArcLength final : public IncrementConstraint {
public:
    // The predictor's sign follows the last increment's direction (Feng's criterion), which
    // passes limit points without pivot tracking. Where the tangent has turned by more than 60°
    // from that increment (a contact closing, a plastic zone spreading: the arch pressed into its
    // floor) the dot product no longer tells forward from back, and the load keeps the last
    // step's sense unless the tangent's inertia changed parity since that step began (a limit
    // point passed).
    ArcLength(double length, const ArcLengthMemory& last) : h_(length), last_(last) {}
    double load_change(int iteration, const Eigen::VectorXd& increment, const Eigen::VectorXd& du_residual,
                       const Eigen::VectorXd& du_load, int negative_pivots) override;
    // The tangent's negative pivots at this step's start, for the next step's memory.
    int start_negative_pivots() const { return start_negative_pivots_; }

private:
    double h_;
    const ArcLengthMemory& last_;
    int start_negative_pivots_ = -1;
};

} // namespace plastica
