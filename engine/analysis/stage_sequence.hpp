// The stages of a run: [analysis] first, then each [[stage]] from where the one before ended.
// It keeps the settings the current stage runs under and the direction toward its target, and
// says where a state lies against that target: short of it, on it (within the round-off of an
// increment) or past it. path_following.cpp asks it; the pattern a stage drives is set in path_state.cpp.
#pragma once

#include "model/model.hpp"

#include <Eigen/Dense>
#include <cstddef>
#include <vector>

namespace plastica {

class StageSequence {
public:
    explicit StageSequence(const Model& model);

    // The settings of the current stage: [analysis], or a [[stage]] over it.
    const AnalysisSpec& current() const { return current_; }
    int number() const { return static_cast<int>(index_) + 1; } // 1: [analysis]
    bool has_next() const { return index_ < stages_.size(); }
    // The stage after the current one (has_next()).
    const StageSpec& next() const { return stages_[index_]; }
    // Makes the next stage current, from the state at load factor λ and displacements u, and
    // returns its first increment, signed toward its target.
    double begin_next(double load_factor, const Eigen::VectorXd& u);
    // Whether the current stage travels the other way than the one before it.
    bool turned_back() const { return turned_back_; }
    // The sign of travel in λ or in the controlled displacement toward the current target.
    double direction() const { return direction_; }

    // The current stage's controlled displacement at u, signed as reported.
    double control_value(const Eigen::VectorXd& u) const;
    // How far the state lies past the target, toward it positive (in load factor or controlled
    // displacement); −∞ without a target. [analysis]'s target of a load factor counts in |λ|.
    double past_target(double load_factor, const Eigen::VectorXd& u) const;
    // On or past the target, within target_slack().
    bool target_reached(double load_factor, const Eigen::VectorXd& u) const {
        return past_target(load_factor, u) >= -target_slack();
    }
    // Round-off of the increment that led to the target: nearer than this counts as on it.
    double target_slack() const { return 1e-9 * std::abs(current_.initial_increment); }
    // What remains to the target in its own quantity, and the scheme that lands on it exactly.
    double remaining(double load_factor, const Eigen::VectorXd& u) const;
    Scheme landing_scheme() const {
        return current_.target_load_factor ? Scheme::load_control : Scheme::displacement_control;
    }

private:
    AnalysisSpec first_;
    std::vector<StageSpec> stages_;
    AnalysisSpec current_;
    std::size_t index_ = 0;  // 0: [analysis]; k: stages_[k − 1]
    double direction_ = 1.0; // the sign of travel toward the current stage's target
    bool turned_back_ = false;
};

} // namespace plastica
