#include "analysis/path_watch.hpp"

namespace plastica {

void PathWatch::begin_stage(bool watched, double direction, double lambda) {
    watched_ = watched;
    direction_ = direction < 0.0 ? -1.0 : 1.0;
    lambda_start_ = lambda;
    rise_ = 0.0;
    rise_step_ = 0;
    rise_lambda_ = lambda;
}

void PathWatch::note(int step, double lambda) {
    if (!watched_ || past_first_limit()) return;
    const double rise = direction_ * (lambda - lambda_start_);
    if (rise > rise_) {
        rise_ = rise;
        rise_step_ = step;
        rise_lambda_ = lambda;
    } else if (rise < (1.0 - limit_drop) * rise_) {
        limit_step_ = rise_step_;
        limit_lambda_ = rise_lambda_;
    }
}

} // namespace plastica
