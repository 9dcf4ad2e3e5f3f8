// Path following's critical points: a converged step whose tangent has more negative pivots
// than the state it started from (Sylvester's law of inertia: an eigenvalue of the tangent
// passed zero within the step) has passed a bifurcation or a limit point. Steps are cut until
// they pass one at a time, and classified by the load past it: still rising, a bifurcation
// (its mode orthogonal to the load), located where the tangent's eigenvalue passes zero; else a
// limit point, located at the load's maximum (Wriggers, Nonlinear Finite Element Methods, 2008,
// §7.4). A step that passed one far from its ends is taken again to end near it.
#include "analysis/path_following.hpp"

#include "analysis/linear_buckling.hpp"
#include "solver/tangent_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

namespace plastica {

namespace {
// Cuts of one step to pass its pivots one at a time (a step may leap over many modes where the
// path is straight: a column's shortening is a millionth of its length), down to the stage's
// least increment: repeated eigenvalues (a ring's two ovals) turn negative together.
constexpr int most_pivot_cuts = 40;
// A critical point is landed on (its step taken again shorter) up to this many times, until the
// step that passes it spans less than PathFollowing::landing_band of its load.
constexpr int most_landings = 4;
// Factors within this share of each other are one repeated eigenvalue.
constexpr double repeated_share = 1e-5;
} // namespace

namespace {

// The tangent's eigenpair nearest zero on one side: the smallest positive (sign +1) or the
// largest negative (sign −1, the last to have passed zero).
const TangentEigenpair* nearest_on_side(const std::vector<TangentEigenpair>& pairs, double sign) {
    const TangentEigenpair* found = nullptr;
    for (const TangentEigenpair& p : pairs)
        if (p.value * sign > 0.0 && (!found || std::abs(p.value) < std::abs(found->value))) found = &p;
    return found;
}

} // namespace

SparseMatrix PathFollowing::tangent_at(const Eigen::VectorXd& u, double lambda) {
    const Eigen::VectorXd u_now = u_;
    const double lambda_now = lambda_;
    u_ = u;
    lambda_ = lambda;
    // The trial state taken again from the committed one, as the step's iterations took it.
    system_.evaluate(u_, ubar_, lambda_, true, true, true);
    SparseMatrix K = system_.tangent();
    u_ = u_now;
    lambda_ = lambda_now;
    system_.evaluate(u_, ubar_, lambda_, true, true, true);
    return K;
}

bool PathFollowing::left_the_path(const Eigen::VectorXd& u_saved, double lambda_saved) {
    // The path's tangent where the step started, K₀⁻¹f: a step along the path turns from it by
    // its curvature over one step, a few degrees; one that ran onto another branch moves along
    // that branch's mode, orthogonal to it. Past a stable symmetric bifurcation the buckled
    // branch is stable, so the pivots at both ends agree and only the direction tells.
    const Eigen::VectorXd du = system_.gather(u_ - u_saved);
    const double length = du.norm();
    if (!(length > 0.0)) return false;
    const SparseMatrix K0 = tangent_at(u_saved, lambda_saved);
    if (!check_solver_.factorize(K0)) return false;
    const Eigen::VectorXd f = load_direction();
    const Eigen::VectorXd t = check_solver_.solve(f);
    const double t_norm = t.norm();
    if (!(t_norm > 0.0) || !t.allFinite()) return false;
    // Under load control the tangent's sense is the load's: a step against it went over to
    // another branch as well (an imperfect column's complementary one, its bow reversed).
    const double along = du.dot(t) / t_norm;
    const double dlambda = lambda_ - lambda_saved;
    if (constraint_->prescribes_load_factor() && dlambda != 0.0) return (dlambda > 0.0 ? along : -along) < branch_alignment * length;
    return std::abs(along) < branch_alignment * length;
}

bool PathFollowing::leapt_past_limit(double step_h) {
    const int passed = solver_.negative_pivots() - committed_pivots_;
    if (passed <= 1 || pivot_cuts_in_step_ >= most_pivot_cuts || std::abs(0.5 * step_h) < stages_.current().min_increment) return false;
    ++pivot_cuts_in_step_;
    return true;
}

bool PathFollowing::cut_for_pivots(double step_h) {
    const AnalysisSpec& stage = stages_.current();
    const int passed = solver_.negative_pivots() - committed_pivots_;
    if (passed <= 1 || pivot_cuts_in_step_ >= most_pivot_cuts) return false;
    if (std::abs(0.5 * step_h) < stage.min_increment) return false;
    // Pivots that turn within a thousandth of the load are met together (a ring's two ovals,
    // nearly repeated where its supports break the symmetry).
    if (std::abs(lambda_ - committed_lambda_) <= landing_band * std::abs(lambda_)) return false;
    // A repeated eigenvalue (a ring's two ovals, a symmetric frame's pair) turns its pivots
    // negative at one load whatever the step: the negative eigenvalues nearest zero tell.
    const std::vector<TangentEigenpair> pairs = eigenpairs_nearest_zero(system_.tangent(), solver_.negative_pivots() + 12);
    std::vector<double> negative;
    for (const TangentEigenpair& p : pairs)
        if (p.value < 0.0) negative.push_back(p.value);
    std::sort(negative.begin(), negative.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
    const bool repeated = negative.size() >= static_cast<std::size_t>(passed) &&
                          std::abs(negative[static_cast<std::size_t>(passed) - 1] - negative.front()) <=
                              repeated_share * std::abs(negative[static_cast<std::size_t>(passed) - 1]);
    if (repeated) return false;
    ++pivot_cuts_in_step_;
    return true;
}

CriticalPoint PathFollowing::locate_critical_point(const Eigen::VectorXd& u_saved, double lambda_saved,
                                                  std::optional<double>& land_at) {
    land_at.reset();
    CriticalPoint found;
    found.step = step_ + 1;
    const double lambda_past = lambda_;
    // Does the load still rise past it? The path's tangent at the new state, oriented along
    // the step taken (as the arc-length predictor is: Feng's criterion): a load that turned
    // back has passed its maximum, a limit point; one that rises on past a pivot turned
    // negative has met a bifurcation.
    const Eigen::VectorXd f = load_direction();
    const double along = previous_increment_.size() == f.size() ? previous_increment_.dot(solver_.solve(f)) : 1.0;
    found.kind = along * (lambda_past >= 0.0 ? 1.0 : -1.0) > 0.0 ? CriticalKind::bifurcation : CriticalKind::limit;
    // The eigenvalue of the tangent that passed zero, followed along the step: the tangent
    // interpolated linearly between the step's ends, K(s) = (1 − s) K₀ + s K₁, is singular where
    // its mode's Rayleigh quotients at the ends, a > 0 and b < 0, give s = a/(a − b); the mode is
    // that of K(s) nearest zero, and three rounds settle both (exact where K is linear in λ, as
    // on a column's straight path; the lowest eigenvalue at the start may be another mode's, one
    // that never crosses).
    const SparseMatrix K1 = system_.tangent();
    const SparseMatrix K0 = tangent_at(u_saved, lambda_saved);
    // Small positive eigenvalues may lie nearer zero than the one that crossed: a dozen more.
    const std::vector<TangentEigenpair> after = eigenpairs_nearest_zero(K1, committed_pivots_ + 12);
    const TangentEigenpair* below = nearest_on_side(after, -1.0);
    std::optional<double> share; // of the step, where the eigenvalue passes zero
    if (below) {
        Eigen::VectorXd phi = below->vector;
        for (int round = 0; round < 3; ++round) {
            const double a = phi.dot(K0 * phi), b = phi.dot(K1 * phi);
            if (!(a > 0.0 && b < 0.0)) break;
            share = a / (a - b);
            const SparseMatrix between = (1.0 - *share) * K0 + *share * K1;
            // The same mode followed: of the few nearest zero, the one most like it (another
            // mode may lie nearer zero there, one about to cross after it).
            const std::vector<TangentEigenpair> there = eigenpairs_nearest_zero(between, 3);
            const TangentEigenpair* same = nullptr;
            for (const TangentEigenpair& t : there)
                if (!same || std::abs(t.vector.dot(phi)) > std::abs(same->vector.dot(phi))) same = &t;
            if (!same) break;
            phi = same->vector;
        }
        found.load_alignment = std::abs(phi.dot(f)) / std::max(phi.norm() * f.norm(), 1e-300);
        Eigen::VectorXd full = Eigen::VectorXd::Zero(u_.size());
        system_.scatter(phi, full);
        found.mode.assign(full.data(), full.data() + full.size());
        scale_to_unit_translation(found.mode);
    }
    const bool landing_left = landings_ < most_landings;
    if (found.kind == CriticalKind::bifurcation) {
        // On the step, where the eigenvalue passes zero: exact as the step shrinks (the
        // eigenvalue is smooth in λ), so a step that spans more than a thousandth of the load is
        // taken again, under load control, to end just short of it.
        // Not under arc length: a state that close to the singular tangent, left with an arc
        // far longer than the fundamental path's own motion (a column's shortening), finds
        // the arc's roots off that path.
        found.load_factor = lambda_saved + share.value_or(1.0) * (lambda_past - lambda_saved);
        // With "switch" the branch is taken from the interpolated bifurcation itself: a path led
        // up to it in small steps would follow a slight imperfection's side instead.
        const bool switching = stages_.current().bifurcation == BifurcationRule::switch_branch && !branch_switched_;
        // A step that starts within the band of it has landed already: taken again, it would
        // publish the same load factor once more.
        const bool landed = std::abs(found.load_factor - lambda_saved) <= landing_band * std::abs(found.load_factor);
        if (landing_left && share && !switching && !landed && std::abs(lambda_past - lambda_saved) > landing_band * std::abs(found.load_factor))
            land_at = std::clamp(*share, 0.05, 0.95);
    } else {
        // The load's maximum: the quadratic through the last two states and this one, else the
        // larger end of the step. Where neither end lies within 1e-4 of it, the step is taken
        // again to end at the quadratic's vertex.
        PathPosition at = position();
        const double s_saved = constraint_->parameter(at);
        at.arc_length += previous_increment_.norm();
        const double s_past = constraint_->parameter(at);
        double vertex = 0.0;
        const std::optional<double> peak = path_.peak_with(s_past, lambda_past, &vertex);
        found.load_factor = peak ? *peak : (std::abs(lambda_past) >= std::abs(lambda_saved) ? lambda_past : lambda_saved);
        const double nearest_end = std::min(std::abs(found.load_factor - lambda_saved), std::abs(found.load_factor - lambda_past));
        if (peak && landing_left && s_past != s_saved && nearest_end > 0.1 * landing_band * std::abs(found.load_factor)) {
            const double vertex_share = (vertex - s_saved) / (s_past - s_saved);
            if (vertex_share > 0.02 && vertex_share < 0.98) land_at = vertex_share;
        } else if (!peak && share && landing_left) {
            // Too few states for the quadratic (the first step passed it): the step is taken
            // again to end where the eigenvalue passes zero, and the states then bracket it.
            land_at = std::clamp(*share, 0.05, 0.95);
        }
    }
    found.load = factors_.at(model_.reported_pattern(), found.load_factor) * model_.load_per_factor();
    return found;
}

NewtonResult PathFollowing::switch_branch(const CriticalPoint& at, const Eigen::VectorXd& u_saved, double lambda_saved,
                                          const Eigen::VectorXd& u_past, double lambda_past, const RunControl& control,
                                          RunSummary& summary) {
    // The bifurcation on the fundamental path, interpolated along the step that passed it, and
    // the mode's amplitude there: its largest translation a thousandth of the structure's size
    // (Wagner & Wriggers, "A simple method for the calculation of postcritical branches",
    // Eng. Comput. 5, 1988: a perturbation along the mode, then the arc's corrector).
    const double share = lambda_past != lambda_saved ? (at.load_factor - lambda_saved) / (lambda_past - lambda_saved) : 1.0;
    const Eigen::VectorXd to_bifurcation = system_.gather(u_past - u_saved) * share;
    const Eigen::VectorXd mode = system_.gather(Eigen::Map<const Eigen::VectorXd>(at.mode.data(), u_.size()));
    const double amplitude = 1e-3 * model_.size();
    NewtonResult best;
    double best_lambda = 0.0;
    Eigen::VectorXd best_u;
    for (const double side : {1.0, -1.0}) {
        const Eigen::VectorXd start = to_bifurcation + side * amplitude * mode;
        NewtonResult outcome = attempt_increment(0.0, control, false, *constraint_, std::nullopt, &start,
                                                 at.load_factor - lambda_saved);
        summary.iterations += outcome.iterations;
        if (outcome.converged() && (!best.converged() || lambda_ > best_lambda)) {
            best = outcome;
            best_lambda = lambda_;
            best_u = u_;
        }
        // The load rises along this side: the branch to follow (an asymmetric bifurcation's
        // other side falls; a symmetric one's sides are alike).
        if (outcome.converged() && lambda_ >= at.load_factor) break;
        roll_back(u_saved, lambda_saved);
    }
    if (best.converged() && u_ != best_u) {
        // The better side was the first: take it again (the elements' trial states follow u).
        const Eigen::VectorXd start = to_bifurcation + amplitude * mode;
        best = attempt_increment(0.0, control, false, *constraint_, std::nullopt, &start, at.load_factor - lambda_saved);
        summary.iterations += best.iterations;
    }
    return best;
}

std::string PathFollowing::unstable_ending(RunSummary& summary) const {
    if (committed_pivots_ == 0) return {};
    for (const CriticalPoint& c : summary.critical_points)
        if (c.kind == CriticalKind::bifurcation && !c.followed) {
            summary.ends_unstable = true;
            std::ostringstream s;
            s << "; past a bifurcation at load factor " << c.load_factor << " (step " << c.step
              << ") on an unstable branch: [analysis] bifurcation = \"switch\" follows the buckled one";
            return s.str();
        }
    return {};
}

} // namespace plastica
