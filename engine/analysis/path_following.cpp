#include "analysis/path_following.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace plastica {

PathFollowing::PathFollowing(const Model& model) : model_(model), system_(model) {
    const int n = model.dof_count();
    u_ = Eigen::VectorXd::Zero(n);
    force_ = Eigen::VectorXd::Zero(n);
    ubar_ = Eigen::VectorXd::Zero(n);
    for (const NodalLoad& l : model.loads)
        for (int d = 0; d < dofs_per_node; ++d) force_[dofs_per_node * l.node + d] += l.value[d];
    for (const PrescribedDisplacement& p : model.prescribed)
        ubar_[dofs_per_node * p.node + p.dof] = p.value;
    const DofRef& c = model.analysis.control;
    control_equation_ = system_.equation(dofs_per_node * c.node + c.dof);
}

double PathFollowing::control_value(const Eigen::VectorXd& u) const {
    const DofRef& c = model_.analysis.control;
    return c.sign * u[dofs_per_node * c.node + c.dof];
}

StepResult PathFollowing::make_result(int step, int iterations) const {
    StepResult r;
    r.step = step;
    r.load_factor = lambda_;
    const double norm = model_.reference_load_norm();
    r.load = model_.report.load_scale * lambda_ * (norm > 0.0 ? norm : 1.0);
    r.control_displacement = control_value(u_);
    r.arc_length = arc_length_;
    r.iterations = iterations;
    r.negative_pivots = solver_.negative_pivots();
    r.residual = last_residual_;
    system_.report(u_, lambda_ * force_, r);
    return r;
}

PathFollowing::Attempt PathFollowing::attempt_increment(double h, const RunControl& control,
                                                        int& iterations) {
    const AnalysisSpec& a = model_.analysis;
    const Eigen::VectorXd force_free = system_.gather(force_);
    Eigen::VectorXd increment = Eigen::VectorXd::Zero(system_.free_count());
    Eigen::VectorXd u_free = system_.gather(u_);
    double delta_lambda = 0.0;
    double last_step_norm = 0.0;

    for (int it = 0; it <= a.max_iterations; ++it) {
        iterations = it;
        const bool freeze = it >= control.freeze_active_after;
        if (!system_.evaluate(u_, ubar_, freeze)) return Attempt::non_finite;
        const Eigen::VectorXd load_direction = force_free - system_.coupling();
        const Eigen::VectorXd residual = lambda_ * force_free - system_.gather(system_.internal_force());
        // Residual relative to the reference load: the largest converged load level so far
        // (meaningful where λ passes zero after a limit point, and not inflated by a wild
        // iterate); in the first increment, the load level being applied.
        const double level = peak_lambda_ > 0.0 ? peak_lambda_
                                                : std::max(std::abs(lambda_), std::abs(delta_lambda));
        const double reference = std::max(level * load_direction.norm(), 1e-300);
        const double relative = residual.norm() / reference;
        if (!std::isfinite(relative)) return Attempt::non_finite;
        last_residual_ = relative;
        trace_.push_back({step_ + 1, it, relative});
        if (it > 0) {
            const bool residual_ok = relative <= a.residual_tolerance;
            // Relative to the increment, with a floor at round-off of the whole displacement
            // (a tiny last increment that lands on a target would otherwise never pass).
            const bool displacement_ok = last_step_norm <= a.displacement_tolerance * increment.norm() ||
                                         last_step_norm <= 1e-12 * u_free.norm();
            const bool settled = !system_.foundation().active_set_changed() &&
                                 system_.foundation().active_set_consistent();
            // Stagnation at round-off: the correction no longer moves the state and the
            // residual is within a hundred times the tolerance (EA/EI ~ 1e5 at small loads).
            const bool stagnated = last_step_norm <= 1e-12 * u_free.norm() &&
                                   relative <= 100.0 * a.residual_tolerance;
            if ((residual_ok || stagnated) && displacement_ok && settled) {
                previous_increment_ = increment;
                return Attempt::converged;
            }
            if (relative > 1e8) return Attempt::failed; // diverging
        }
        if (it == a.max_iterations) break;

        if (!solver_.factorize(system_.tangent())) return Attempt::failed;
        const Eigen::VectorXd du_r = solver_.solve(residual);
        const Eigen::VectorXd du_f = solver_.solve(load_direction);

        double dl = 0.0;
        switch (a.scheme) {
        case Scheme::load_control:
            dl = it == 0 ? h : 0.0;
            break;
        case Scheme::displacement_control: {
            const double target = it == 0 ? h * model_.analysis.control.sign : 0.0;
            if (std::abs(du_f[control_equation_]) < 1e-300) return Attempt::failed;
            dl = (target - du_r[control_equation_]) / du_f[control_equation_];
            break;
        }
        case Scheme::arc_length: {
            if (it == 0) {
                // Predictor along the tangent; its sign follows the previous increment
                // (Feng's criterion), which passes limit points without tracking the pivots.
                double sign = h >= 0.0 ? 1.0 : -1.0;
                if (previous_increment_.size() == du_f.size() && previous_increment_.norm() > 0.0)
                    sign = previous_increment_.dot(du_f) >= 0.0 ? 1.0 : -1.0;
                dl = sign * std::abs(h) / std::max(du_f.norm(), 1e-300);
            } else {
                const Eigen::VectorXd base = increment + du_r;
                const double qa = du_f.squaredNorm();
                const double qb = 2.0 * base.dot(du_f);
                const double qc = base.squaredNorm() - h * h;
                const double disc = qb * qb - 4.0 * qa * qc;
                if (disc < 0.0) return Attempt::failed; // no point on the arc: cut the step
                const double root = std::sqrt(disc);
                const double l1 = (-qb + root) / (2.0 * qa);
                const double l2 = (-qb - root) / (2.0 * qa);
                // The root whose increment stays closest to the current one.
                const double c1 = (base + l1 * du_f).dot(increment);
                const double c2 = (base + l2 * du_f).dot(increment);
                dl = c1 >= c2 ? l1 : l2;
            }
            break;
        }
        }
        const Eigen::VectorXd du = du_r + dl * du_f;
        if (!du.allFinite() || !std::isfinite(dl)) return Attempt::non_finite;
        increment += du;
        u_free += du;
        delta_lambda += dl;
        lambda_ += dl;
        last_step_norm = du.norm();
        system_.scatter(u_free, u_);
        for (const PrescribedDisplacement& p : model_.prescribed) {
            const int dof = dofs_per_node * p.node + p.dof;
            u_[dof] = lambda_ * ubar_[dof];
        }
    }
    return Attempt::failed;
}

std::string PathFollowing::initial_mechanism() {
    if (system_.free_count() == 0) return {};
    system_.evaluate(u_, ubar_, false);
    const bool ok = solver_.factorize(system_.tangent());
    system_.revert();
    if (ok && solver_.pivot_ratio() > 1e-12) return {};
    const int eq = solver_.weakest_equation();
    for (int dof = 0; dof < system_.dof_count(); ++dof) {
        if (system_.equation(dof) != eq) continue;
        static const char* names[] = {"ux", "uy", "rz"};
        const Node& n = model_.nodes[dof / dofs_per_node];
        std::ostringstream s;
        s << "the structure is a mechanism before loading: DOF " << names[dof % dofs_per_node]
          << " of the node at [" << n.x << ", " << n.y << "] is free (add a support or a spring)";
        return s.str();
    }
    return "the structure is a mechanism before loading (singular stiffness)";
}

RunSummary PathFollowing::run(const std::vector<StepObserver>& observers, const RunControl& control) {
    const auto start = std::chrono::steady_clock::now();
    const AnalysisSpec& a = model_.analysis;
    RunSummary summary;
    auto publish = [&](const StepResult& r) {
        for (const StepObserver& o : observers) o(r);
    };

    // Step 0: the unloaded state (springs evaluated so the contact set is known).
    system_.evaluate(u_, ubar_, false);
    system_.commit();
    publish(make_result(0, 0));

    double h = a.initial_increment;
    const double h_min = a.min_increment;
    summary.status = RunStatus::step_limit;
    summary.reason = "step limit reached";
    while (step_ < a.max_steps) {
        if (control.interrupt && control.interrupt->load()) {
            summary.status = RunStatus::interrupted;
            summary.reason = "interrupted";
            break;
        }
        // Land on the target instead of overshooting it (load and displacement control).
        if (a.scheme == Scheme::load_control && a.target_load_factor) {
            const double remaining = *a.target_load_factor - lambda_;
            if (std::abs(h) > std::abs(remaining)) h = remaining;
        }
        if (a.scheme == Scheme::displacement_control && a.target_displacement) {
            const double remaining = *a.target_displacement - control_value(u_);
            if (std::abs(h) > std::abs(remaining)) h = remaining;
        }
        const Eigen::VectorXd u_saved = u_;
        const double lambda_saved = lambda_;
        int iterations = 0;
        const Attempt outcome = attempt_increment(h, control, iterations);
        summary.iterations += iterations;
        if (outcome != Attempt::converged) {
            u_ = u_saved;
            lambda_ = lambda_saved;
            system_.revert();
            ++summary.cut_steps;
            h *= 0.5;
            if (std::abs(h) >= h_min) continue;
            std::ostringstream why;
            if (outcome == Attempt::non_finite) {
                summary.status = RunStatus::non_finite;
                why << "non-finite state in step " << step_ + 1;
                if (!system_.non_finite_where().empty()) why << " at " << system_.non_finite_where();
            } else if (a.scheme == Scheme::load_control && solver_.negative_pivots() > 0) {
                summary.status = RunStatus::limit_load;
                why << "limit load reached at load factor " << lambda_;
            } else if (a.scheme == Scheme::load_control) {
                summary.status = RunStatus::limit_load;
                why << "limit load reached: no equilibrium beyond load factor " << lambda_;
            } else {
                summary.status = RunStatus::no_convergence;
                why << "no convergence in step " << step_ + 1 << " at load factor " << lambda_;
            }
            summary.reason = why.str();
            system_.evaluate(u_, ubar_, false); // leave the system at the last converged state
            break;
        }
        system_.commit();
        peak_lambda_ = std::max(peak_lambda_, std::abs(lambda_));
        ++step_;
        arc_length_ += previous_increment_.norm();
        publish(make_result(step_, iterations));

        if (a.adaptive) {
            const double factor = std::sqrt(static_cast<double>(a.desired_iterations) /
                                            std::max(iterations, 1));
            h *= std::clamp(factor, 0.5, 2.0);
        } else if (std::abs(h) < std::abs(a.initial_increment)) {
            h = std::copysign(std::min(2.0 * std::abs(h), std::abs(a.initial_increment)), h); // recover after a cut
        }
        if (a.max_increment > 0.0 && std::abs(h) > a.max_increment)
            h = std::copysign(a.max_increment, h);
        // A target counts as reached within round-off of the increment that led to it.
        const double slack = 1e-9 * std::abs(a.initial_increment);
        const bool reached_lambda = a.target_load_factor &&
            std::abs(lambda_) >= std::abs(*a.target_load_factor) - slack;
        const bool reached_displacement = a.target_displacement &&
            control_value(u_) >= *a.target_displacement - slack;
        if (reached_lambda || reached_displacement) {
            summary.status = RunStatus::completed;
            summary.reason = reached_lambda ? "target load factor reached" : "target displacement reached";
            break;
        }
    }
    summary.steps = step_;
    summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return summary;
}

} // namespace plastica
