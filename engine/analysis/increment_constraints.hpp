// The three ways an increment is constrained (each an IncrementConstraint for Newton):
// load control (Δλ given), displacement control of one equation (Batoz & Dhatt), and
// Crisfield's cylindrical arc length ‖Δx‖ = Δl with the root nearest the current increment.
#pragma once

#include "solver/newton_solver.hpp"

namespace plastica {

class LoadControl final : public IncrementConstraint {
public:
    explicit LoadControl(double delta_lambda) : h_(delta_lambda) {}
    double load_change(int iteration, const Eigen::VectorXd&, const Eigen::VectorXd&,
                       const Eigen::VectorXd&) override {
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
                       const Eigen::VectorXd& du_load) override;

private:
    int equation_;
    double h_;
};

class ArcLength final : public IncrementConstraint {
public:
    // previous: the last converged increment (empty at the start); its direction chooses the
    // predictor's sign (Feng's criterion), which passes limit points without pivot tracking.
    // nearest_when_no_root: a correction whose line misses the arc takes the line's point
    // nearest to it, instead of failing (which cuts the step).
    ArcLength(double length, const Eigen::VectorXd& previous, bool nearest_when_no_root = false)
        : h_(length), previous_(previous), nearest_when_no_root_(nearest_when_no_root) {}
    double load_change(int iteration, const Eigen::VectorXd& increment, const Eigen::VectorXd& du_residual,
                       const Eigen::VectorXd& du_load) override;

private:
    double h_;
    const Eigen::VectorXd& previous_;
    bool nearest_when_no_root_;
};

} // namespace plastica
