// Path following's state as the outside sees it: the pattern a stage drives, a converged step's
// result, and what passed through what.
#include "analysis/path_following.hpp"

#include "analysis/mechanisms.hpp"
#include "analysis/penetration_check.hpp"
#include "analysis/plastic_sites.hpp"
#include "analysis/stop_diagnosis.hpp"
#include "analysis/structure_problem.hpp"

#include <cmath>
#include <sstream>

namespace plastica {

void PathFollowing::drive_pattern(int pattern) {
    if (pattern == factors_.driven) return;
    factors_.held[static_cast<std::size_t>(factors_.driven)] = lambda_;
    factors_.driven = pattern;
    lambda_ = factors_.held[static_cast<std::size_t>(pattern)];
    factors_.held[static_cast<std::size_t>(pattern)] = 0.0;
    ubar_.setZero();
    ubar_held_.setZero();
    for (const PrescribedDisplacement& p : model_.prescribed) {
        const int dof = dofs_per_node * p.node + p.dof;
        ubar_[dof] += factors_.rate(p.pattern) * p.value;
        ubar_held_[dof] += factors_.constant(p.pattern) * p.value;
    }
    system_.set_pattern_factors(factors_);
    // The new pattern's residual is measured against its own loads and the held ones, and its
    // limit against the stiffness the structure has where the stage starts.
    peak_lambda_ = std::abs(lambda_);
    system_.evaluate(u_, ubar_, lambda_, false);
    initial_flexibility_ = load_flexibility();
}

StepResult& PathFollowing::make_result(int step, int iterations, Acceptance rule, bool with_sections) {
    StepResult& r = result_;
    r.step = step;
    r.load_factor = lambda_;
    r.stage = stages_.number();
    r.pattern_factors.resize(factors_.held.size());
    for (std::size_t p = 0; p < factors_.held.size(); ++p) r.pattern_factors[p] = factors_.at(static_cast<int>(p), lambda_);
    r.load = r.pattern_factors[static_cast<std::size_t>(model_.reported_pattern())] * model_.load_per_factor();
    r.control_displacement = model_.reported_control().value_in(u_);
    r.arc_length = arc_length_;
    r.iterations = iterations;
    r.accepted_by = rule;
    r.negative_pivots = solver_.negative_pivots();
    r.residual = last_residual_;
    r.critical.reset();
    // A scene in time reports every step's time; a static step's motion is none.
    if (stepper_) {
        r.time = stepper_->time();
        r.velocity.assign(u_.size(), 0.0);
        r.acceleration.assign(u_.size(), 0.0);
        r.energy = {};
    }
    system_.report(u_, system_.external_force(lambda_), r, with_sections);
    if (model_.report.measure == ReportSpec::Measure::platen) {
        r.load = 0.0;
        for (std::size_t k = 0; k < r.springs.size(); ++k)
            if (system_.on_moving_base(k)) r.load += std::hypot(r.springs[k].force[0], r.springs[k].force[1]);
        r.load *= model_.report.load_scale;
    }
    return r;
}

std::string PathFollowing::check_penetration() const {
    if (stages_.current().allow_crossing) return {};
    const std::string found = find_penetration(model_, u_, lambda_, &factors_);
    if (found.empty()) return found;
    return "step " + std::to_string(step_) + ": " + found;
}

} // namespace plastica
