#include "analysis/stage_sequence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace plastica {

StageSequence::StageSequence(const Model& model)
    : first_(model.analysis), stages_(model.stages), current_(model.analysis) {}

double StageSequence::control_value(const Eigen::VectorXd& u) const {
    return current_.control.value_in(u);
}

double StageSequence::begin_next(double load_factor, const Eigen::VectorXd& u) {
    const StageSpec& s = stages_[index_];
    ++index_;
    current_.control = s.control;
    current_.scheme = s.scheme;
    current_.initial_increment = s.increment;
    current_.adaptive = s.adaptive;
    current_.min_increment = std::min(first_.min_increment, 1e-6 * s.increment);
    current_.max_increment = 10.0 * s.increment;
    current_.target_load_factor = s.target_load_factor;
    current_.target_displacement = s.target_displacement;
    current_.pattern = s.pattern;
    current_.transient = s.transient;
    if (s.scheme == Scheme::transient) {
        current_.target_load_factor.reset();
        current_.target_displacement.reset();
        return 0.0;
    }
    const double value = s.target_load_factor ? load_factor : control_value(u);
    const double target = s.target_load_factor ? *s.target_load_factor : *s.target_displacement;
    const double previous_direction = direction_;
    direction_ = target >= value ? 1.0 : -1.0;
    turned_back_ = direction_ != previous_direction;
    return direction_ * s.increment;
}

double StageSequence::past_target(double load_factor, const Eigen::VectorXd& u) const {
    const AnalysisSpec& a = current_;
    if (!a.target_load_factor && !a.target_displacement) return -std::numeric_limits<double>::infinity();
    if (index_ == 0) {
        if (a.target_load_factor) return std::abs(load_factor) - std::abs(*a.target_load_factor);
        return control_value(u) - *a.target_displacement;
    }
    // Later stages go either way: past once the value has come to the target.
    const double value = a.target_load_factor ? load_factor : control_value(u);
    const double target = a.target_load_factor ? *a.target_load_factor : *a.target_displacement;
    return (value - target) * direction_;
}

double StageSequence::remaining(double load_factor, const Eigen::VectorXd& u) const {
    return current_.target_load_factor ? *current_.target_load_factor - load_factor
                                       : *current_.target_displacement - control_value(u);
}

} // namespace plastica
