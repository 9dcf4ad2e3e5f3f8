// Path following's failures and limits: what a failed step means (cut again, or stop and why),
// and whether a tangent shows a limit load (a negative pivot, or no stiffness left in the load
// direction, Bergan's current stiffness parameter).
#include "analysis/path_following.hpp"

#include "analysis/mechanisms.hpp"
#include "analysis/penetration_check.hpp"
#include "analysis/plastic_sites.hpp"
#include "analysis/stop_diagnosis.hpp"
#include "analysis/structure_problem.hpp"

#include <cmath>
#include <sstream>

namespace plastica {

namespace {
// A step that failed after three cuts with a round-off floor this many times the residual
// tolerance stops the run: no smaller increment lowers that floor.
constexpr double hopeless_floor = 1e3;
// Where perfectly plastic hinges or fibres let no increment of a step converge, the step is
// taken again from the stage's increment with the hinges' capacity rows hardening by this share
// of the elastic stiffness, and the fibre members stiffened by it on the step's increment (a
// step's worth of either is remembered). The hinges' own regularising 1e-6 leaves a mechanism
// that Newton's first correction runs off along; so does a fully plastic crown that has left
// the plate. Measured over the crushed rings with hinges (R/h 10, 20, 40, three schemes): 1e-5
// and 3e-5 leave two arc-length runs stopped or turned back, 1e-4 completes all nine with 0-9
// such steps of 500-900; tried at every failed attempt instead, 1e-4 left one run at its step
// limit and 1e-3 raised the loads by up to 12 %.
constexpr double stiffened_step_hardening = 1e-4;

} // namespace

double PathFollowing::load_flexibility() {
    if (system_.free_count() == 0 || !solver_.factorize(system_.tangent())) return 0.0;
    const Eigen::VectorXd f = load_direction();
    return f.dot(solver_.solve(f));
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
    // Only where λ moves plates or prescribed displacements alone: the travel the user drives
    // is followed past a plastic mechanism, where under forces the same mechanism is the limit
    // load and a stiffened member would carry the load past it.
    const bool plastic = model_.has_plasticity(Plasticity::hinges) || model_.has_plasticity(Plasticity::distributed);
    if (giving_up && !stiffened_step_ && plastic && !model_.has_forces(factors_.driven)) {
        roll_back(u_saved, lambda_saved);
        system_.stiffen_capacity(stiffened_step_hardening);
        stiffened_step_ = true;
        failures_in_step_ = 0;
        h = std::copysign(std::abs(a.initial_increment), step_h);
        return std::nullopt;
    }
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
    failed.correction_ratio = outcome.correction_ratio;
    failed.displacement_tolerance = a.displacement_tolerance;
    failed.settled = outcome.settled;
    failed.tolerance_follows_floor = a.residual_tolerance_follows_floor;
    failed.floor = floor_at_failure;
    failed.controlled_through_contact = a.scheme == Scheme::displacement_control && !system_.self_contact().contacts().empty();
    return diagnose_failed_step(failed);
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

bool PathFollowing::ended_past_limit_load() const {
    // A state the load cannot hold (a column straight again, or crushed): more negative pivots
    // than where the step started, under load control of forces.
    return constraint_->prescribes_load_factor() && model_.has_forces(factors_.driven) && !stages_.turned_back() &&
           solver_.negative_pivots() > committed_pivots_;
}

StopReason PathFollowing::limit_beyond(double step_h) {
    FailedStep at_limit;
    at_limit.step = step_;
    at_limit.load_factor = lambda_;
    at_limit.limit = true;
    std::ostringstream evidence;
    evidence << "a load step of " << step_h << " beyond it turned the tangent's pivot negative";
    at_limit.limit_evidence = evidence.str();
    at_limit.plastic_sites = plastic_sites(model_, system_);
    return diagnose_failed_step(at_limit);
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
    const Eigen::VectorXd f = load_direction();
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
