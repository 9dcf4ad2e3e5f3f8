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
    u_published_ = u_;
    lambda_published_ = lambda_;
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
    std::string found = element_beyond_reach(model_, u_);
    if (found.empty()) found = find_penetration(model_, u_, lambda_, &factors_);
    if (found.empty()) return found;
    return "step " + std::to_string(step_) + ": " + found;
}

void PathFollowing::commit_step(const NewtonResult& outcome, RunSummary& summary) {
    if (outcome.tolerance > summary.largest_residual_tolerance) {
        summary.largest_residual_tolerance = outcome.tolerance;
        summary.largest_tolerance_step = step_ + 1;
    }
    system_.commit();
    if (stiffened_step_) {
        ++summary.stiffened_steps;
        stiffened_step_ = false;
        system_.stiffen_capacity(0.0);
    }
    committed_contact_ = touching_bases(system_);
    failures_in_step_ = 0;
    steps_missing_arc_ = missed_arc_in_step_ ? steps_missing_arc_ + 1 : 0;
    missed_arc_in_step_ = false;
    peak_lambda_ = std::max(peak_lambda_, std::abs(lambda_));
    ++step_;
    arc_length_ += previous_increment_.norm();
    path_.add(path_parameter(), system_.gather(u_), lambda_, system_.axial_forces());
}

double PathFollowing::begin_next_stage() {
    const StageSpec& s = stages_.next();
    drive_pattern(s.pattern);
    const double h = stages_.begin_next(lambda_, u_);
    constraint_ = make_path_constraint(s.scheme);
    control_equation_ = system_.equation(dofs_per_node * s.control.node + s.control.dof);
    // A stage that turns back starts from an elastic predictor: continued loading there may be
    // a mechanism's tangent, which throws the first iterate far off.
    if (stages_.turned_back()) system_.predict_unloading();
    path_.clear();
    path_.add(path_parameter(), system_.gather(u_), lambda_, system_.axial_forces());
    watch_stage();
    return h;
}

void PathFollowing::watch_stage() {
    // λ is a load where the driven pattern has forces (not a plate's travel alone); a stage that
    // unloads falls by design.
    const bool watched = stages_.current().scheme != Scheme::transient && model_.has_forces(factors_.driven) && !stages_.turned_back();
    watch_.begin_stage(watched, lambda_ < 0.0 ? -1.0 : 1.0, lambda_);
}

bool PathFollowing::extrapolating() const {
    return constraint_->starts_from_extrapolation() && path_.ready();
}

PathPosition PathFollowing::position() const {
    return {lambda_, stages_.control_value(u_), arc_length_};
}

double PathFollowing::path_parameter() const {
    return constraint_->parameter(position());
}

Eigen::VectorXd PathFollowing::load_direction() const {
    return system_.gather(system_.load()) - system_.coupling();
}

} // namespace plastica
