#include "analysis/path_following.hpp"

#include "analysis/increment_constraints.hpp"
#include "analysis/penetration_check.hpp"
#include "analysis/plastic_sites.hpp"
#include "analysis/stop_diagnosis.hpp"
#include "analysis/structure_problem.hpp"
#include "model/rigid_motions.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <new>
#include <sstream>

namespace plastica {

namespace {
// An arc-length increment within 18° of the reverse of the last one (cosine below minus this)
// retraced the path.
constexpr double max_turn_cosine = 0.95;
// A step that failed after three cuts with a round-off floor this many times the residual
// tolerance stops the run: no smaller increment lowers that floor.
constexpr double hopeless_floor = 1e3;

double dof_value(const DofRef& c, const Eigen::VectorXd& u) {
    return c.sign * u[dofs_per_node * c.node + c.dof];
}
} // namespace

PathFollowing::PathFollowing(const Model& model)
    : model_(model), analysis_(model.analysis), system_(model), factors_(model.patterns.size()) {
    const int n = model.dof_count();
    u_ = Eigen::VectorXd::Zero(n);
    ubar_ = Eigen::VectorXd::Zero(n);
    ubar_held_ = Eigen::VectorXd::Zero(n);
    factors_.driven = model.analysis.pattern;
    for (const PrescribedDisplacement& p : model.prescribed)
        if (p.pattern == factors_.driven) ubar_[dofs_per_node * p.node + p.dof] = p.value;
    const DofRef& c = model.analysis.control;
    control_equation_ = system_.equation(dofs_per_node * c.node + c.dof);
}

double PathFollowing::control_value(const Eigen::VectorXd& u) const {
    return dof_value(analysis_.control, u);
}

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

double PathFollowing::load_flexibility() {
    if (system_.free_count() == 0 || !solver_.factorize(system_.tangent())) return 0.0;
    const Eigen::VectorXd f = system_.gather(system_.load()) - system_.coupling();
    return f.dot(solver_.solve(f));
}

const StepResult& PathFollowing::make_result(int step, int iterations, Acceptance rule, bool with_sections) {
    StepResult& r = result_;
    r.step = step;
    r.load_factor = lambda_;
    r.stage = static_cast<int>(stage_) + 1;
    r.pattern_factors.resize(factors_.held.size());
    for (std::size_t p = 0; p < factors_.held.size(); ++p) r.pattern_factors[p] = factors_.at(static_cast<int>(p), lambda_);
    r.load = r.pattern_factors[static_cast<std::size_t>(model_.reported_pattern())] * model_.load_per_factor();
    r.control_displacement = dof_value(model_.reported_control(), u_);
    r.arc_length = arc_length_;
    r.iterations = iterations;
    r.accepted_by = rule;
    r.negative_pivots = solver_.negative_pivots();
    r.residual = last_residual_;
    system_.report(u_, system_.external_force(lambda_), r, with_sections);
    if (model_.report.measure == ReportSpec::Measure::platen) {
        r.load = 0.0;
        for (std::size_t k = 0; k < r.springs.size(); ++k)
            if (system_.on_moving_base(k)) r.load += std::hypot(r.springs[k].force[0], r.springs[k].force[1]);
        r.load *= model_.report.load_scale;
    }
    return r;
}

bool PathFollowing::extrapolating() const {
    // Not along an arc: its constraint sphere already centres the corrector on the path, and
    // the extrapolated point steers the root choice past a limit point into the wrong branch.
    return analysis_.scheme != Scheme::arc_length && path_.ready();
}

double PathFollowing::path_parameter() const {
    switch (analysis_.scheme) {
    case Scheme::load_control: return lambda_;
    case Scheme::displacement_control: return control_value(u_);
    case Scheme::arc_length: return arc_length_;
    }
    return 0.0;
}

NewtonResult PathFollowing::attempt_increment(double h, const RunControl& control, bool extrapolate) {
    return attempt_increment(h, control, extrapolate, analysis_.scheme);
}

NewtonResult PathFollowing::attempt_increment(double h, const RunControl& control, bool extrapolate, Scheme scheme) {
    const AnalysisSpec& a = analysis_;
    StructureProblem problem(system_, u_, lambda_, ubar_, ubar_held_, control.freeze_active_after,
                             control.freeze_hinges_after, control.freeze_fibres_after);
    problem.set_contact_band(a.residual_tolerance, peak_lambda_);
    NewtonSettings settings;
    settings.max_iterations = a.max_iterations;
    settings.residual_tolerance = a.residual_tolerance;
    settings.tolerance_follows_floor = a.residual_tolerance_follows_floor;
    settings.displacement_tolerance = a.displacement_tolerance;
    settings.reference_level = peak_lambda_;
    // Hinged and fibre members are left out: with them, four variants that complete (the arch
    // with fibre sections, the catenary beam in 40 elements, the arch in three times the
    // elements, the whole ring with I × 3 and adaptive increments) crept into their step limits
    // or stopped, and the inelastic ring saved 1 % of its work. Along an arc the accepted state
    // would lie off the arc by the correction not taken, which moves the adaptive arc's steps
    // (Lee's frame: 95 steps against 104).
    settings.accept_before_correction = system_.all_members_elastic() && scheme != Scheme::arc_length;
    // Where hinges or fibres make the laws piecewise linear; an elastic structure's residual that
    // grows near convergence (a follower pressure's) is Newton's to reduce, not a kink.
    settings.backtrack_at_kinks = !system_.all_members_elastic();
    const int step = step_ + 1;
    const IterationHook hook = [&](int iteration, double relative) {
        trace_.push_back({step, iteration, relative});
        last_residual_ = relative;
    };
    IncrementGuess guess;
    const IncrementGuess* start = nullptr;
    PathPoint ahead;
    if (extrapolate && extrapolating()) {
        ahead = path_.at(path_parameter() + (a.scheme == Scheme::arc_length ? std::abs(h) : h));
        guess.dx = ahead.displacement - system_.gather(u_);
        // Under load control the load factor is the path parameter: its step exactly.
        guess.dlambda = a.scheme == Scheme::load_control ? h : ahead.load_factor - lambda_;
        start = &guess;
        problem.predict_axial_forces(ahead.axial_forces);
        settings.fail_fast = true; // the tangent's predictor is the fallback
    }
    NewtonResult result;
    switch (scheme) {
    case Scheme::load_control: {
        LoadControl c(h);
        result = solve_increment(problem, c, settings, solver_, hook, start);
        break;
    }
    case Scheme::displacement_control: {
        DisplacementControl c(control_equation_, h * a.control.sign);
        result = solve_increment(problem, c, settings, solver_, hook, start);
        break;
    }
    case Scheme::arc_length: {
        // After three cuts of this step a root-less corrector takes the line's point nearest
        // the arc instead of cutting on (before, a cut is what settles most such corrections).
        // So does every step after three in a row that were cut for it: approaching a corner
        // of the path, each step misses at its first try and lands at half of it, the next
        // regrows and misses again, and the increments shrink geometrically: their sum never
        // reaches the corner.
        ArcLength c(h, previous_increment_, failures_in_step_ >= 3 || steps_missing_arc_ >= 3);
        result = solve_increment(problem, c, settings, solver_, hook, start);
        // An increment nearly opposite to the last one went back down the path (the corrector
        // wandered across an active-set change and met the arc behind): taken as a failure, the
        // step is cut. Along a smooth path consecutive increments turn by a few degrees, even
        // through a limit point or a snap-back; a corner where a contact opens may turn the path
        // by well over a right angle (137° where the arch lifts off the floor), but not back on
        // itself.
        if (result.converged() && path_.traced_a_step() && result.increment.size() == previous_increment_.size() &&
            result.increment.dot(previous_increment_) < -max_turn_cosine * result.increment.norm() * previous_increment_.norm()) {
            result.rule = Acceptance::none;
            result.failure = NewtonFailure::turned_back;
        }
        break;
    }
    }
    if (result.converged()) previous_increment_ = result.increment;
    return result;
}

std::string PathFollowing::initial_mechanism() {
    if (system_.free_count() == 0) return {};
    system_.evaluate(u_, ubar_, lambda_, false);
    const bool ok = solver_.factorize(system_.tangent());
    system_.revert();
    // A pivot within ten round-offs of zero, against its own diagonal entry.
    if (ok && solver_.pivot_ratio() > 10 * LinearSolver::zero_pivot) return {};
    std::string where = "an equation";
    const int eq = solver_.weakest_equation();
    for (int dof = 0; dof < system_.dof_count(); ++dof) {
        if (system_.equation(dof) != eq) continue;
        static const char* names[] = {"ux", "uy", "rz"};
        const Node& n = model_.nodes[dof / dofs_per_node];
        std::ostringstream s;
        s << "DOF " << names[dof % dofs_per_node] << " of the node at [" << n.x << ", " << n.y << "]";
        where = s.str();
    }
    // Singular to double precision is not the same as free: the supports decide which.
    if (const std::string motion = unrestrained_rigid_motion(model_); !motion.empty())
        return "the structure is a mechanism before loading: " + where + " is free (add a support or a spring); " + motion;
    // Nor are the releases: the same structure with its member ends held tells.
    if (const std::string released = release_mechanism(); !released.empty())
        return "the structure is a mechanism before loading: " + where + " is free, " + released;
    std::ostringstream s;
    s.precision(2);
    s << "the stiffness matrix is singular to double precision, although the supports hold every rigid-body "
         "motion: the pivot of "
      << where << " is " << solver_.pivot_ratio() << " of its diagonal entry. The stiffnesses of this model span "
      << "more than the 16 digits of a double (very many or very short elements, a spring or a section far "
         "stiffer than the rest, or coordinates far from 1): use fewer elements or stiffnesses closer together";
    return s.str();
}

std::string PathFollowing::release_mechanism() const {
    if (!model_.has_releases()) return {};
    Model held = model_;
    std::vector<std::string> ends;
    for (ElementSpec& e : held.elements) {
        for (int end = 0; end < 2; ++end) {
            if (!e.released[end]) continue;
            const Node& n = model_.nodes[end == 0 ? e.node_i : e.node_j];
            if (ends.size() < 4) ends.push_back(point_text(model_, n.x, n.y));
            else if (ends.size() == 4) ends.push_back("…");
        }
        e.released = {false, false};
    }
    StructuralSystem rigid(held);
    rigid.evaluate(u_, ubar_, lambda_, false);
    LinearSolver solver;
    if (!solver.factorize(rigid.tangent()) || solver.pivot_ratio() <= 10 * LinearSolver::zero_pivot) return {};
    std::string list;
    for (const std::string& e : ends) list += (list.empty() ? "" : ", ") + e;
    return "because of the moment releases (released member ends at " + list +
           "): with those ends held it is stable. A frame of pinned members needs a brace, a support "
           "or a spring to hold it (or release fewer ends)";
}

std::string PathFollowing::probe_contact_mechanism(const Eigen::VectorXd& u_converged, double lambda_converged) {
    if (const std::string m = contact_mechanism(); !m.empty()) return m;
    if (committed_contact_.empty() || system_.free_count() == 0) return {};
    // The failed iterate may have wandered anywhere: look where the load first carries the
    // converged state instead, a small step along the tangent's response to it.
    system_.evaluate(u_converged, ubar_, lambda_converged, false);
    if (!solver_.factorize(system_.tangent())) return {};
    const Eigen::VectorXd response = solver_.solve(system_.gather(system_.load()) - system_.coupling());
    const double largest = response.cwiseAbs().maxCoeff();
    if (!(largest > 0.0) || !std::isfinite(largest)) return {};
    double size = 0.0;
    for (const Node& n : model_.nodes) size = std::max({size, std::abs(n.x), std::abs(n.y)});
    Eigen::VectorXd step = Eigen::VectorXd::Zero(u_converged.size());
    system_.scatter(response * (1e-6 * std::max(size, 1.0) / largest), step);
    system_.evaluate(u_converged + step, ubar_, lambda_converged, false);
    return contact_mechanism();
}

void PathFollowing::roll_back(const Eigen::VectorXd& u_saved, double lambda_saved) {
    u_ = u_saved;
    lambda_ = lambda_saved;
    system_.revert();
}

void PathFollowing::remember_contact() {
    const std::vector<SpringState>& states = system_.foundation().states();
    committed_contact_.resize(states.size());
    for (std::size_t k = 0; k < states.size(); ++k) committed_contact_[k] = states[k].unilateral && states[k].active;
}

std::string PathFollowing::contact_mechanism() const {
    const std::vector<SpringState>& states = system_.foundation().states();
    if (states.size() != model_.springs.size()) return {};
    std::vector<bool> in_contact(states.size());
    std::vector<std::size_t> lost;
    for (std::size_t k = 0; k < states.size(); ++k) {
        in_contact[k] = !states[k].unilateral || states[k].active;
        // Lost since the last converged step: touching then (a closed gap), open now.
        if (states[k].unilateral && !states[k].active && committed_contact_.size() == states.size() && committed_contact_[k])
            lost.push_back(k);
    }
    if (lost.empty()) return {};
    // Surfaces pressed together hold each other's parts along their normal.
    std::vector<SurfaceHold> pressed;
    for (const SurfaceContact& c : system_.self_contact().contacts()) {
        if (c.gap > 0.0) continue;
        pressed.push_back({c.node, {c.normal[0], c.normal[1]}});
        for (int end : c.segment) pressed.push_back({end, {-c.normal[0], -c.normal[1]}});
    }
    const std::string motion = unrestrained_rigid_motion(model_, &in_contact, &pressed);
    if (motion.empty()) return {};
    std::ostringstream s;
    s << "contact with the base was lost at " << lost.size() << (lost.size() == 1 ? " node" : " nodes") << " (";
    for (std::size_t i = 0; i < lost.size() && i < 4; ++i) {
        const Node& n = model_.nodes[model_.springs[lost[i]].node];
        s << (i ? ", " : "") << point_text(model_, n.x, n.y);
    }
    s << (lost.size() > 4 ? ", …" : "") << "), and nothing else holds it: " << motion
      << ". Hold it with a support or a spring, or drive it by a prescribed displacement";
    return s.str();
}

RoundOffFloor PathFollowing::round_off_floor() const {
    return system_.round_off_floor(u_, lambda_);
}

RunSummary PathFollowing::run(const std::vector<StepObserver>& observers, const RunControl& control) {
    RunSummary summary;
    try {
        return run_steps(observers, control, summary);
    } catch (const std::bad_alloc&) {
        summary.status = RunStatus::out_of_memory;
        std::ostringstream why;
        why << "out of memory in step " << step_ + 1 << ": the model's " << system_.free_count()
            << " unknowns need more memory than this process may have";
        summary.reason = why.str();
        summary.steps = step_;
        return summary;
    }
}

RunSummary PathFollowing::run_steps(const std::vector<StepObserver>& observers, const RunControl& control,
                                    RunSummary& summary) {
    const auto start = std::chrono::steady_clock::now();
    const AnalysisSpec& a = analysis_;
    // An observer that cannot take a step (its disk is full) ends the run: the step is not
    // counted, and the run's outputs end with the step before it.
    auto publish = [&](const StepResult& r) {
        try {
            for (const StepObserver& o : observers) o(r);
            return true;
        } catch (const std::exception& e) {
            summary.status = RunStatus::output_failed;
            summary.reason = "the results of step " + std::to_string(r.step) + " could not be written: " + e.what();
            return false;
        }
    };
    auto finish = [&](int steps) {
        summary.steps = steps;
        summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return summary;
    };

    // Step 0: the unloaded state (springs evaluated so the contact set is known).
    system_.evaluate(u_, ubar_, lambda_, false);
    system_.commit();
    remember_contact();
    initial_flexibility_ = load_flexibility();
    if (!publish(make_result(0, 0, Acceptance::none, control.report_sections))) return finish(0);
    path_.add(path_parameter(), system_.gather(u_), lambda_, system_.axial_forces());

    double h = a.initial_increment;
    const double h_min = a.min_increment;
    failures_in_step_ = 0;
    summary.status = RunStatus::step_limit;
    summary.reason = "step limit reached";
    while (step_ < a.max_steps) {
        if (control.interrupt && control.interrupt->load()) {
            summary.status = RunStatus::interrupted;
            summary.reason = "interrupted";
            break;
        }
        // Land on the target instead of overshooting it (load and displacement control).
        double step_h = h;
        if (a.scheme == Scheme::load_control && a.target_load_factor)
            step_h = StepController::landing(step_h, *a.target_load_factor - lambda_);
        if (a.scheme == Scheme::displacement_control && a.target_displacement)
            step_h = StepController::landing(step_h, *a.target_displacement - control_value(u_));
        const Eigen::VectorXd u_saved = u_;
        const double lambda_saved = lambda_;
        NewtonResult outcome = attempt_increment(step_h, control, true);
        if (!outcome.converged() && extrapolating()) {
            // The extrapolation may overshoot a kink of the path (a hinge or contact that
            // appears in this step): try the tangent's predictor before cutting the step.
            summary.iterations += outcome.iterations;
            roll_back(u_saved, lambda_saved);
            outcome = attempt_increment(step_h, control, false);
        }
        // An arc-length step past the stage's target is taken again from where it started, under
        // the control that lands on the target exactly (a step that fails to land is cut).
        if (outcome.converged() && a.scheme == Scheme::arc_length && past_target() > target_slack()) {
            summary.iterations += outcome.iterations;
            roll_back(u_saved, lambda_saved);
            const double remaining = a.target_load_factor ? *a.target_load_factor - lambda_ : *a.target_displacement - control_value(u_);
            outcome = attempt_increment(remaining, control, false, a.target_load_factor ? Scheme::load_control : Scheme::displacement_control);
        }
        summary.iterations += outcome.iterations;
        if (outcome.rule == Acceptance::residual) ++summary.accepted_by_residual;
        if (outcome.rule == Acceptance::stagnation) ++summary.accepted_by_stagnation;
        if (!outcome.converged()) {
            // The failed state's round-off floor. It is relative to the load and set by the
            // total displacements, so a smaller increment leaves it where it is: far above the
            // tolerance after three cuts in a row, cutting on could only spend time (a 100 000-
            // element cantilever cut its first step twenty times for 16 s before saying so). A
            // single failure says little: its last iterate may be far off, and so its floor.
            ++failures_in_step_;
            if (outcome.failure == NewtonFailure::no_constraint_root) missed_arc_in_step_ = true;
            const RoundOffFloor floor_at_failure =
                outcome.failure != NewtonFailure::non_finite ? round_off_floor() : RoundOffFloor{};
            // (A tolerance that follows the floor is never below it.)
            const bool hopeless = !a.residual_tolerance_follows_floor && failures_in_step_ > 3 &&
                                  floor_at_failure.total >= hopeless_floor * a.residual_tolerance;
            const bool giving_up = std::abs(0.5 * step_h) < h_min || hopeless;
            // Under load control, the tangent where the failed increment ended tells whether
            // the structure has passed its limit (a plastic mechanism or buckling); it is read
            // only when the run stops here.
            bool beyond_limit = false;
            // Not before the first step: the unloaded tangent was found positive definite, so a
            // negative pivot there is round-off, not a limit at load factor 0. Nor where the
            // factor only moves supports or bases (a platen's travel): the user prescribes that
            // motion, and a negative pivot along it limits nothing the factor scales.
            const bool can_be_limit = a.scheme == Scheme::load_control && step_ > 0 && model_.has_forces(a.pattern);
            // A base the structure has left holds nothing: if that frees a rigid motion, the
            // failure is a mechanism, named with the contact that released it.
            const std::string mechanism = giving_up ? probe_contact_mechanism(u_saved, lambda_saved) : std::string();
            // Members at capacity (committed sections): with fibre sections along them, a
            // structure left with a hundredth of its stiffness in the load direction is at its
            // plastic limit, as their zones spread and keep a little of it where a hinge's
            // plateau keeps only its regularisation.
            const std::string sites = giving_up && can_be_limit ? plastic_sites(model_, system_) : std::string();
            const double limit_stiffness = !sites.empty() && model_.has_plasticity(Plasticity::distributed)
                                               ? plastic_zone_stiffness : hinge_plateau_stiffness;
            if (giving_up && can_be_limit && outcome.failure != NewtonFailure::non_finite) {
                if (outcome.negative_pivots_seen > 0)
                    limit_evidence_ = "the tangent beyond it has " + std::to_string(outcome.negative_pivots_seen) +
                                      " negative pivot(s)";
                beyond_limit = outcome.negative_pivots_seen > 0 || tangent_shows_limit(limit_stiffness);
            }
            roll_back(u_saved, lambda_saved);
            ++summary.cut_steps;
            h = steps_.after_failure(step_h);
            if (!giving_up) continue;
            system_.evaluate(u_, ubar_, lambda_, false); // leave the system at the last converged state
            FailedStep failed;
            failed.step = step_ + 1;
            failed.load_factor = lambda_;
            failed.failure = outcome.failure;
            failed.non_finite_where = system_.non_finite_where();
            failed.mechanism = mechanism;
            // The tangent is read for a limit only where nothing else explains the failure.
            failed.limit = outcome.failure != NewtonFailure::non_finite && mechanism.empty() &&
                           (beyond_limit || (can_be_limit && tangent_shows_limit()));
            failed.limit_evidence = limit_evidence_;
            if (failed.limit) failed.plastic_sites = sites;
            failed.hopeless = hopeless;
            failed.increment = h;
            failed.residual = outcome.residual;
            failed.tolerance = a.residual_tolerance;
            failed.tolerance_follows_floor = a.residual_tolerance_follows_floor;
            failed.floor = floor_at_failure;
            const StopReason stop = diagnose_failed_step(failed);
            summary.status = stop.status;
            summary.reason = stop.reason;
            break;
        }
        // Adaptive increments also bound the error of the hinges' explicit pseudo-springs (η from
        // the start of the step): a step that carries a section further than max_yield_advance
        // into its yielding range is taken again, smaller in proportion. Unless the last smaller
        // step carried it as far: then the advance is a jump of the section's state (a member
        // reaching its squash load), which no increment makes smaller.
        const double advance = a.adaptive ? system_.trial_yield_advance() : 0.0;
        if (const double smaller = steps_.refined(step_h, advance, h_min); smaller != 0.0) {
            roll_back(u_saved, lambda_saved);
            ++summary.refined_steps;
            h = smaller;
            continue;
        }
        if (outcome.tolerance > summary.largest_residual_tolerance) {
            summary.largest_residual_tolerance = outcome.tolerance;
            summary.largest_tolerance_step = step_ + 1;
        }
        system_.commit();
        remember_contact();
        failures_in_step_ = 0;
        steps_missing_arc_ = missed_arc_in_step_ ? steps_missing_arc_ + 1 : 0;
        missed_arc_in_step_ = false;
        peak_lambda_ = std::max(peak_lambda_, std::abs(lambda_));
        ++step_;
        arc_length_ += previous_increment_.norm();
        path_.add(path_parameter(), system_.gather(u_), lambda_, system_.axial_forces());
        const std::string crossing = check_penetration();
        const StepResult& result = make_result(step_, outcome.iterations, outcome.rule, control.report_sections);
        if (result.negative_pivots > 0) {
            if (summary.negative_pivot_steps++ == 0) summary.first_negative_pivot_step = step_;
        }
        if (!publish(result)) return finish(step_ - 1);
        if (!crossing.empty()) {
            summary.status = RunStatus::penetration;
            summary.reason = crossing;
            break;
        }

        h = steps_.after_success(a, h, step_h, outcome, advance);
        if (target_reached()) {
            if (stage_ < model_.stages.size()) {
                h = begin_stage(stage_);
                continue;
            }
            summary.status = RunStatus::completed;
            summary.reason = a.target_load_factor ? "target load factor reached" : "target displacement reached";
            if (stage_ > 0) summary.reason += " (" + std::to_string(stage_ + 1) + " stages)";
            break;
        }
        // Under load control a mechanism's regularised plateau can be followed in ever smaller
        // load steps (the extrapolated start finds them): once the increment has been cut to
        // a thousandth, a tangent without stiffness in the load direction is the limit load.
        if (a.scheme == Scheme::load_control && model_.has_forces(a.pattern) && std::abs(step_h) < 1e-3 * std::abs(a.initial_increment) &&
            tangent_shows_limit()) {
            FailedStep at_limit;
            at_limit.step = step_;
            at_limit.load_factor = lambda_;
            at_limit.limit = true;
            at_limit.limit_evidence = limit_evidence_;
            at_limit.plastic_sites = plastic_sites(model_, system_);
            const StopReason stop = diagnose_failed_step(at_limit);
            summary.status = stop.status;
            summary.reason = stop.reason;
            break;
        }
    }
    return finish(step_);
}

bool PathFollowing::target_reached() const {
    return past_target() >= -target_slack();
}

double PathFollowing::past_target() const {
    const AnalysisSpec& a = analysis_;
    if (!a.target_load_factor && !a.target_displacement) return -std::numeric_limits<double>::infinity();
    if (stage_ == 0) {
        if (a.target_load_factor) return std::abs(lambda_) - std::abs(*a.target_load_factor);
        return control_value(u_) - *a.target_displacement;
    }
    // Later stages go either way: past once the value has come to the target.
    const double value = a.target_load_factor ? lambda_ : control_value(u_);
    const double target = a.target_load_factor ? *a.target_load_factor : *a.target_displacement;
    return (value - target) * direction_;
}

double PathFollowing::begin_stage(std::size_t k) {
    const StageSpec& s = model_.stages[k];
    ++stage_;
    drive_pattern(s.pattern);
    analysis_.control = s.control;
    control_equation_ = system_.equation(dofs_per_node * s.control.node + s.control.dof);
    analysis_.scheme = s.scheme;
    analysis_.initial_increment = s.increment;
    analysis_.adaptive = s.adaptive;
    analysis_.min_increment = std::min(model_.analysis.min_increment, 1e-6 * s.increment);
    analysis_.max_increment = 10.0 * s.increment;
    analysis_.target_load_factor = s.target_load_factor;
    analysis_.target_displacement = s.target_displacement;
    const double value = s.target_load_factor ? lambda_ : control_value(u_);
    const double target = s.target_load_factor ? *s.target_load_factor : *s.target_displacement;
    const double previous_direction = direction_;
    direction_ = target >= value ? 1.0 : -1.0;
    // A stage that turns back starts from an elastic predictor: continued loading there may be
    // a mechanism's tangent, which throws the first iterate far off.
    if (direction_ != previous_direction) system_.predict_unloading();
    path_.clear();
    path_.add(path_parameter(), system_.gather(u_), lambda_, system_.axial_forces());
    return direction_ * s.increment;
}

std::string PathFollowing::check_penetration() const {
    if (analysis_.allow_crossing) return {};
    const std::string found = find_penetration(model_, u_, lambda_, &factors_);
    if (found.empty()) return found;
    return "step " + std::to_string(step_) + ": " + found;
}

bool PathFollowing::tangent_shows_limit(double below) {
    // The state the system was last evaluated at is at or beyond a limit point when its
    // tangent has a negative pivot, or when its stiffness in the load direction (Bergan's
    // current stiffness parameter, f·K₀⁻¹f / f·K⁻¹f) has fallen below `below` of the initial
    // one: a plastic mechanism, whose only remaining stiffness is the hinges' regularising
    // hardening (or the spread of fibre sections' zones).
    if (!solver_.factorize(system_.tangent())) {
        limit_evidence_ = "singular tangent";
        return true;
    }
    if (solver_.negative_pivots() > 0) {
        limit_evidence_ = std::to_string(solver_.negative_pivots()) + " negative pivot(s)";
        return true;
    }
    const Eigen::VectorXd f = system_.gather(system_.load()) - system_.coupling();
    const double flexibility = f.dot(solver_.solve(f));
    if (initial_flexibility_ > 0.0 && flexibility > 0.0) {
        const double stiffness = initial_flexibility_ / flexibility;
        if (stiffness < below) {
            std::ostringstream s;
            s << "stiffness in the load direction " << stiffness << " of the initial";
            limit_evidence_ = s.str();
            return true;
        }
    }
    return false;
}

} // namespace plastica
