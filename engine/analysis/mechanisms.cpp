#include "analysis/mechanisms.hpp"

#include "model/rigid_motions.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace plastica {

std::string unloaded_mechanism(const Model& model, StructuralSystem& system, LinearSolver& solver,
                               const Eigen::VectorXd& u, const Eigen::VectorXd& ubar, double load_factor) {
    if (system.free_count() == 0) return {};
    system.evaluate(u, ubar, load_factor, false);
    const bool ok = solver.factorize(system.tangent());
    system.revert();
    // A pivot within ten round-offs of zero, against its own diagonal entry.
    if (ok && solver.pivot_ratio() > 10 * LinearSolver::zero_pivot) return {};
    std::string where = "an equation";
    const int eq = solver.weakest_equation();
    for (int dof = 0; dof < system.dof_count(); ++dof) {
        if (system.equation(dof) != eq) continue;
        static const char* names[] = {"ux", "uy", "rz"};
        const Node& n = model.nodes[dof / dofs_per_node];
        std::ostringstream s;
        s << "DOF " << names[dof % dofs_per_node] << " of the node at [" << n.x << ", " << n.y << "]";
        where = s.str();
    }
    // Singular to double precision is not the same as free: the supports decide which.
    if (const std::string motion = unrestrained_rigid_motion(model); !motion.empty())
        return "the structure is a mechanism before loading: " + where + " is free (add a support or a spring); " + motion;
    // Nor are the releases: the same structure with its member ends held tells.
    if (const std::string released = release_mechanism(model, u, ubar, load_factor); !released.empty())
        return "the structure is a mechanism before loading: " + where + " is free, " + released;
    std::ostringstream s;
    s.precision(2);
    s << "the stiffness matrix is singular to double precision, although the supports hold every rigid-body "
         "motion: the pivot of "
      << where << " is " << solver.pivot_ratio() << " of its diagonal entry. The stiffnesses of this model span "
      << "more than the 16 digits of a double (very many or very short elements, a spring or a section far "
         "stiffer than the rest, or coordinates far from 1): use fewer elements or stiffnesses closer together";
    return s.str();
}

std::string release_mechanism(const Model& model, const Eigen::VectorXd& u, const Eigen::VectorXd& ubar,
                              double load_factor) {
    if (!model.has_releases()) return {};
    Model held = model;
    std::vector<std::string> ends;
    for (ElementSpec& e : held.elements) {
        for (int end = 0; end < 2; ++end) {
            if (!e.released[end]) continue;
            const Node& n = model.nodes[end == 0 ? e.node_i : e.node_j];
            if (ends.size() < 4) ends.push_back(point_text(model, n.x, n.y));
            else if (ends.size() == 4) ends.push_back("…");
        }
        e.released = {false, false};
    }
    StructuralSystem rigid(held);
    rigid.evaluate(u, ubar, load_factor, false);
    LinearSolver solver;
    if (!solver.factorize(rigid.tangent()) || solver.pivot_ratio() <= 10 * LinearSolver::zero_pivot) return {};
    std::string list;
    for (const std::string& e : ends) list += (list.empty() ? "" : ", ") + e;
    return "because of the moment releases (released member ends at " + list +
           "): with those ends held it is stable. A frame of pinned members needs a brace, a support "
           "or a spring to hold it (or release fewer ends)";
}

std::vector<bool> touching_bases(const StructuralSystem& system) {
    const std::vector<SpringState>& states = system.foundation().states();
    std::vector<bool> touching(states.size());
    for (std::size_t k = 0; k < states.size(); ++k) touching[k] = states[k].unilateral && states[k].active;
    return touching;
}

std::string lost_contact_mechanism(const Model& model, const StructuralSystem& system,
                                   const std::vector<bool>& touching_before) {
    const std::vector<SpringState>& states = system.foundation().states();
    if (states.size() != model.springs.size()) return {};
    std::vector<bool> in_contact(states.size());
    std::vector<std::size_t> lost;
    for (std::size_t k = 0; k < states.size(); ++k) {
        in_contact[k] = !states[k].unilateral || states[k].active;
        // Lost since the last converged step: touching then (a closed gap), open now.
        if (states[k].unilateral && !states[k].active && touching_before.size() == states.size() && touching_before[k])
            lost.push_back(k);
    }
    if (lost.empty()) return {};
    // Surfaces pressed together hold each other's parts along their normal.
    std::vector<SurfaceHold> pressed;
    for (const SurfaceContact& c : system.self_contact().contacts()) {
        if (c.gap > 0.0) continue;
        pressed.push_back({c.point[0], {c.normal[0], c.normal[1]}});
        if (c.along_member()) pressed.push_back({c.point[1], {c.normal[0], c.normal[1]}});
        for (int end : c.segment) pressed.push_back({end, {-c.normal[0], -c.normal[1]}});
    }
    const std::string motion = unrestrained_rigid_motion(model, &in_contact, &pressed);
    if (motion.empty()) return {};
    std::ostringstream s;
    s << "contact with the base was lost at " << lost.size() << (lost.size() == 1 ? " node" : " nodes") << " (";
    for (std::size_t i = 0; i < lost.size() && i < 4; ++i) {
        const Node& n = model.nodes[model.springs[lost[i]].node];
        s << (i ? ", " : "") << point_text(model, n.x, n.y);
    }
    s << (lost.size() > 4 ? ", …" : "") << "), and nothing else holds it: " << motion
      << ". Hold it with a support or a spring, or drive it by a prescribed displacement";
    return s.str();
}

std::string probe_lost_contact(const Model& model, StructuralSystem& system, LinearSolver& solver,
                               const std::vector<bool>& touching_before, const Eigen::VectorXd& u_converged,
                               const Eigen::VectorXd& ubar, double lambda_converged) {
    if (const std::string m = lost_contact_mechanism(model, system, touching_before); !m.empty()) return m;
    if (touching_before.empty() || system.free_count() == 0) return {};
    // The failed iterate may have wandered anywhere: look where the load first carries the
    // converged state instead, a small step along the tangent's response to it.
    system.evaluate(u_converged, ubar, lambda_converged, false);
    if (!solver.factorize(system.tangent())) return {};
    const Eigen::VectorXd response = solver.solve(system.gather(system.load()) - system.coupling());
    const double largest = response.cwiseAbs().maxCoeff();
    if (!(largest > 0.0) || !std::isfinite(largest)) return {};
    double size = 0.0;
    for (const Node& n : model.nodes) size = std::max({size, std::abs(n.x), std::abs(n.y)});
    Eigen::VectorXd step = Eigen::VectorXd::Zero(u_converged.size());
    system.scatter(response * (1e-6 * std::max(size, 1.0) / largest), step);
    system.evaluate(u_converged + step, ubar, lambda_converged, false);
    return lost_contact_mechanism(model, system, touching_before);
}

} // namespace plastica
