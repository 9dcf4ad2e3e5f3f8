#include "analysis/path_following.hpp"

#include "analysis/mechanisms.hpp"
#include "analysis/penetration_check.hpp"
#include "analysis/plastic_sites.hpp"
#include "analysis/stop_diagnosis.hpp"
#include "analysis/structure_problem.hpp"
#include "dynamics/modal_analysis.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <new>
#include <sstream>

namespace plastica {

namespace {
// A step that failed after three cuts with a round-off floor this many times the residual
// tolerance stops the run: no smaller increment lowers that floor.
constexpr double hopeless_floor = 1e3;

} // namespace

PathFollowing::PathFollowing(const Model& model)
    : model_(model), stages_(model), constraint_(make_path_constraint(model.analysis.scheme)), system_(model),
      factors_(model.patterns.size()) {
    const int n = model.dof_count();
    u_ = Eigen::VectorXd::Zero(n);
    ubar_ = Eigen::VectorXd::Zero(n);
    ubar_held_ = Eigen::VectorXd::Zero(n);
    factors_.driven = model.analysis.pattern;
    for (const PrescribedDisplacement& p : model.prescribed)
        if (p.pattern == factors_.driven) ubar_[dofs_per_node * p.node + p.dof] = p.value;
    const DofRef& c = model.analysis.control;
    control_equation_ = system_.equation(dofs_per_node * c.node + c.dof);
    if (model.transient()) stepper_ = std::make_unique<TimeStepper>(model_, system_);
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

bool PathFollowing::extrapolating() const {
    return constraint_->starts_from_extrapolation() && path_.ready();
}

PathPosition PathFollowing::position() const {
    return {lambda_, stages_.control_value(u_), arc_length_};
}

double PathFollowing::path_parameter() const {
    return constraint_->parameter(position());
}

NewtonResult PathFollowing::attempt_increment(double h, const RunControl& control, bool extrapolate,
                                              const PathConstraint& constraint, std::optional<double> extrapolate_to) {
    const AnalysisSpec& a = stages_.current();
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
    settings.accept_before_correction = system_.all_members_elastic() && constraint.scheme() != Scheme::arc_length;
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
    if (extrapolate && constraint.starts_from_extrapolation() && path_.ready()) {
        ahead = path_.at(extrapolate_to.value_or(path_parameter() + h));
        guess.dx = ahead.displacement - system_.gather(u_);
        guess.dlambda = constraint.extrapolated_load_change(h, ahead.load_factor - lambda_);
        start = &guess;
        problem.predict_axial_forces(ahead.axial_forces);
        settings.fail_fast = true; // the tangent's predictor is the fallback
    }
    // After three cuts of this step a root-less arc-length corrector takes the line's point
    // nearest the arc instead of cutting on (before, a cut is what settles most such
    // corrections). So does every step after three in a row that were cut for it: approaching a
    // corner of the path, each step misses at its first try and lands at half of it, the next
    // regrows and misses again, and the increments shrink geometrically: their sum never
    // reaches the corner.
    CorrectorContext context;
    context.control_equation = control_equation_;
    context.control_sign = a.control.sign;
    context.previous = &previous_increment_;
    context.nearest_when_no_root = failures_in_step_ >= 3 || steps_missing_arc_ >= 3;
    const std::unique_ptr<IncrementConstraint> corrector = constraint.corrector(h, context);
    NewtonResult result = solve_increment(problem, *corrector, settings, solver_, hook, start);
    // Refused, the increment counts as a failure and the step is cut.
    if (result.converged() && path_.traced_a_step() && constraint.turned_back(result.increment, previous_increment_)) {
        result.rule = Acceptance::none;
        result.failure = NewtonFailure::turned_back;
    }
    if (result.converged()) previous_increment_ = result.increment;
    return result;
}

NewtonResult PathFollowing::attempt_step(double h, const RunControl& control, const Eigen::VectorXd& u_saved,
                                         double lambda_saved, RunSummary& summary) {
    NewtonResult outcome = attempt_increment(h, control, true, *constraint_);
    if (!outcome.converged() && extrapolating()) {
        // The extrapolation may overshoot a kink of the path (a hinge or contact that appears
        // in this step): try the tangent's predictor before cutting the step.
        summary.iterations += outcome.iterations;
        roll_back(u_saved, lambda_saved);
        outcome = attempt_increment(h, control, false, *constraint_);
    }
    // Where the load factor moves plates or prescribed displacements alone it measures no load,
    // and the path rarely folds in it: an arc-length step that finds no point on its arc is
    // taken under load control of the travel the path extrapolates to that arc length. Fibres
    // yielding and unloading as λ swings within the corrector's iterations make it cycle
    // (a crushed ring's walls); with λ held, the same step converges.
    if (!outcome.converged() && constraint_->scheme() == Scheme::arc_length && !model_.has_forces(factors_.driven) &&
        path_.traced_a_step() && !stages_.turned_back()) {
        const double travel = path_.at(path_parameter() + h).load_factor - lambda_saved;
        if (travel != 0.0) {
            summary.iterations += outcome.iterations;
            roll_back(u_saved, lambda_saved);
            outcome = attempt_increment(travel, control, true, *make_path_constraint(Scheme::load_control), path_parameter() + h);
        }
    }
    // A step past the stage's target that the scheme could not shorten beforehand is taken
    // again from where it started, under the control that lands on the target exactly (a step
    // that fails to land is cut).
    if (outcome.converged() && constraint_->retakes_past_target() &&
        stages_.past_target(lambda_, u_) > stages_.target_slack()) {
        summary.iterations += outcome.iterations;
        roll_back(u_saved, lambda_saved);
        const double remaining = stages_.remaining(lambda_, u_);
        outcome = attempt_increment(remaining, control, false, *make_path_constraint(stages_.landing_scheme()));
    }
    return outcome;
}

std::string PathFollowing::initial_mechanism() {
    // A structure in motion from the start is held by its inertia: a free body may fly.
    if (model_.analysis.scheme == Scheme::transient) return {};
    return unloaded_mechanism(model_, system_, solver_, u_, ubar_, lambda_);
}

void PathFollowing::roll_back(const Eigen::VectorXd& u_saved, double lambda_saved) {
    u_ = u_saved;
    lambda_ = lambda_saved;
    system_.revert();
}

RoundOffFloor PathFollowing::round_off_floor() const {
    return system_.round_off_floor(u_, lambda_);
}

RunSummary PathFollowing::run(const std::vector<StepObserver>& observers, const RunControl& control) {
    RunSummary summary;
    try {
        return run_steps(observers, control, summary);
    } catch (const ModalError& e) {
        // Damping by modal ratios needs the modes where the first transient stage starts.
        summary.status = RunStatus::no_convergence;
        summary.reason = std::string("the damping's modes: ") + e.what();
        summary.steps = step_;
        return summary;
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
        if (stepper_) {
            summary.time = stepper_->time();
            summary.rayleigh_alpha_m = stepper_->alpha_m();
            summary.rayleigh_beta_k = stepper_->beta_k();
        }
        summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return summary;
    };
    auto stop = [&](const StopReason& why) {
        summary.status = why.status;
        summary.reason = why.reason;
    };

    // Step 0: the unloaded state (springs evaluated so the contact set is known).
    if (stepper_) {
        system_.evaluate(u_, ubar_, lambda_, false);
        stepper_->note_initial_tangent();
        if (model_.analysis.scheme == Scheme::transient) set_factors_at(0.0);
    }
    system_.evaluate(u_, ubar_, lambda_, false);
    system_.commit();
    committed_contact_ = touching_bases(system_);
    initial_flexibility_ = load_flexibility();
    // A scene in motion from the start: step 0 is its state at t = 0, velocities and energies too.
    const bool starts_in_time = stepper_ && model_.analysis.scheme == Scheme::transient;
    if (starts_in_time) stepper_->begin_stage(model_.analysis.transient, u_, lambda_, solver_);
    make_result(0, 0, Acceptance::none, control.report_sections);
    if (starts_in_time) stepper_->fill(u_, result_);
    if (!publish(result_)) return finish(0);
    path_.add(path_parameter(), system_.gather(u_), lambda_, system_.axial_forces());

    // The current stage's settings (the sequence updates them in place at each new stage).
    const AnalysisSpec& stage = stages_.current();
    double h = stage.initial_increment;
    failures_in_step_ = 0;
    summary.status = RunStatus::step_limit;
    summary.reason = "step limit reached";
    while (step_ < stage.max_steps) {
        if (control.interrupt && control.interrupt->load()) {
            stop({RunStatus::interrupted, "interrupted"});
            break;
        }
        if (stage.scheme == Scheme::transient) {
            const bool begun = starts_in_time && stages_.number() == 1;
            if (const std::optional<StopReason> stopped = run_transient_stage(publish, control, summary, begun)) {
                if (stopped->status == RunStatus::output_failed) return finish(step_ - 1);
                stop(*stopped);
                break;
            }
            if (stages_.has_next()) {
                h = begin_next_stage();
                continue;
            }
            std::ostringstream reason;
            reason << "duration reached (t = " << stepper_->time() << ")";
            if (stages_.number() > 1) reason << " (" << stages_.number() << " stages)";
            stop({RunStatus::completed, reason.str()});
            break;
        }
        const double step_h = constraint_->landing(h, position(), stage);
        const Eigen::VectorXd u_saved = u_;
        const double lambda_saved = lambda_;
        const NewtonResult outcome = attempt_step(step_h, control, u_saved, lambda_saved, summary);
        summary.iterations += outcome.iterations;
        if (outcome.rule == Acceptance::residual) ++summary.accepted_by_residual;
        if (outcome.rule == Acceptance::stagnation) ++summary.accepted_by_stagnation;
        if (!outcome.converged()) {
            const std::optional<StopReason> failed = after_failure(outcome, step_h, u_saved, lambda_saved, h);
            ++summary.cut_steps;
            if (!failed) continue;
            stop(*failed);
            break;
        }
        // Adaptive increments also bound the error of the hinges' explicit pseudo-springs (η from
        // the start of the step): a step that carries a section further than max_yield_advance
        // into its yielding range is taken again, smaller in proportion (StepController::refined).
        const double advance = stage.adaptive ? system_.trial_yield_advance() : 0.0;
        if (const double smaller = steps_.refined(step_h, advance, stage.min_increment); smaller != 0.0) {
            roll_back(u_saved, lambda_saved);
            ++summary.refined_steps;
            h = smaller;
            continue;
        }
        commit_step(outcome, summary);
        const std::string crossing = check_penetration();
        const StepResult& result = make_result(step_, outcome.iterations, outcome.rule, control.report_sections);
        if (result.negative_pivots > 0) {
            if (summary.negative_pivot_steps++ == 0) summary.first_negative_pivot_step = step_;
        }
        if (!publish(result)) return finish(step_ - 1);
        if (!crossing.empty()) {
            stop({RunStatus::penetration, crossing});
            break;
        }

        h = steps_.after_success(stage, h, step_h, outcome, advance);
        if (stages_.target_reached(lambda_, u_)) {
            if (stages_.has_next()) {
                h = begin_next_stage();
                continue;
            }
            std::string reason = stage.target_load_factor ? "target load factor reached" : "target displacement reached";
            if (stages_.number() > 1) reason += " (" + std::to_string(stages_.number()) + " stages)";
            stop({RunStatus::completed, reason});
            break;
        }
        if (const std::optional<StopReason> limit = limit_on_plateau(step_h)) {
            stop(*limit);
            break;
        }
    }
    return finish(step_);
}

std::optional<StopReason> PathFollowing::after_failure(const NewtonResult& outcome, double step_h,
                                                       const Eigen::VectorXd& u_saved, double lambda_saved,
                                                       double& h) {
    const AnalysisSpec& a = stages_.current();
    // The failed state's round-off floor. It is relative to the load and set by the total
    // displacements, so a smaller increment leaves it where it is: far above the tolerance
    // after three cuts in a row, cutting on could only spend time (a 100 000-element
    // cantilever cut its first step twenty times for 16 s before saying so). A single failure
    // says little: its last iterate may be far off, and so its floor.
    ++failures_in_step_;
    if (outcome.failure == NewtonFailure::no_constraint_root) missed_arc_in_step_ = true;
    const RoundOffFloor floor_at_failure = outcome.failure != NewtonFailure::non_finite ? round_off_floor() : RoundOffFloor{};
    // (A tolerance that follows the floor is never below it.)
    const bool hopeless = !a.residual_tolerance_follows_floor && failures_in_step_ > 3 &&
                          floor_at_failure.total >= hopeless_floor * a.residual_tolerance;
    const bool giving_up = std::abs(0.5 * step_h) < a.min_increment || hopeless;
    // Under load control, the tangent where the failed increment ended tells whether the
    // structure has passed its limit (a plastic mechanism or buckling); it is read only when
    // the run stops here.
    bool beyond_limit = false;
    // Not before the first step: the unloaded tangent was found positive definite, so a
    // negative pivot there is round-off, not a limit at load factor 0. Nor where the factor
    // only moves supports or bases (a platen's travel): the user prescribes that motion, and a
    // negative pivot along it limits nothing the factor scales.
    const bool can_be_limit = constraint_->prescribes_load_factor() && step_ > 0 && model_.has_forces(factors_.driven);
    // A base the structure has left holds nothing: if that frees a rigid motion, the failure is
    // a mechanism, named with the contact that released it.
    const std::string mechanism =
        giving_up ? probe_lost_contact(model_, system_, solver_, committed_contact_, u_saved, ubar_, lambda_saved) : std::string();
    // Members at capacity (committed sections): with fibre sections along them, a structure
    // left with a hundredth of its stiffness in the load direction is at its plastic limit, as
    // their zones spread and keep a little of it where a hinge's plateau keeps only its
    // regularisation.
    const std::string sites = giving_up && can_be_limit ? plastic_sites(model_, system_) : std::string();
    const double limit_stiffness =
        !sites.empty() && model_.has_plasticity(Plasticity::distributed) ? plastic_zone_stiffness : hinge_plateau_stiffness;
    if (giving_up && can_be_limit && outcome.failure != NewtonFailure::non_finite) {
        if (outcome.negative_pivots_seen > 0)
            limit_evidence_ = "the tangent beyond it has " + std::to_string(outcome.negative_pivots_seen) + " negative pivot(s)";
        beyond_limit = outcome.negative_pivots_seen > 0 || tangent_shows_limit(limit_stiffness);
    }
    roll_back(u_saved, lambda_saved);
    h = steps_.after_failure(step_h);
    if (!giving_up) return std::nullopt;
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
    return diagnose_failed_step(failed);
}

void PathFollowing::commit_step(const NewtonResult& outcome, RunSummary& summary) {
    if (outcome.tolerance > summary.largest_residual_tolerance) {
        summary.largest_residual_tolerance = outcome.tolerance;
        summary.largest_tolerance_step = step_ + 1;
    }
    system_.commit();
    committed_contact_ = touching_bases(system_);
    failures_in_step_ = 0;
    steps_missing_arc_ = missed_arc_in_step_ ? steps_missing_arc_ + 1 : 0;
    missed_arc_in_step_ = false;
    peak_lambda_ = std::max(peak_lambda_, std::abs(lambda_));
    ++step_;
    arc_length_ += previous_increment_.norm();
    path_.add(path_parameter(), system_.gather(u_), lambda_, system_.axial_forces());
}

std::optional<StopReason> PathFollowing::limit_on_plateau(double step_h) {
    // Under load control a mechanism's regularised plateau can be followed in ever smaller load
    // steps (the extrapolated start finds them): once the increment has been cut to a
    // thousandth, a tangent without stiffness in the load direction is the limit load.
    if (!constraint_->prescribes_load_factor() || !model_.has_forces(factors_.driven) ||
        std::abs(step_h) >= 1e-3 * std::abs(stages_.current().initial_increment) || !tangent_shows_limit())
        return std::nullopt;
    FailedStep at_limit;
    at_limit.step = step_;
    at_limit.load_factor = lambda_;
    at_limit.limit = true;
    at_limit.limit_evidence = limit_evidence_;
    at_limit.plastic_sites = plastic_sites(model_, system_);
    return diagnose_failed_step(at_limit);
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
    return h;
}

std::string PathFollowing::check_penetration() const {
    if (stages_.current().allow_crossing) return {};
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
