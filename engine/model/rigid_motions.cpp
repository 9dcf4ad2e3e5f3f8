#include "model/rigid_motions.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace plastica {

namespace {

// Union–find of the nodes joined by elements.
class Parts {
public:
    explicit Parts(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
    int find(int a) {
        while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
        return a;
    }
    void join(int a, int b) { parent_[find(a)] = find(b); }

private:
    std::vector<int> parent_;
};

} // namespace

std::string point_text(const Model& model, double x, double y) {
    double size = 0.0;
    for (const Node& n : model.nodes) size = std::max({size, std::abs(n.x), std::abs(n.y)});
    const auto clean = [&](double v) { return std::abs(v) <= 1e-9 * size ? 0.0 : v; };
    std::ostringstream s;
    s.precision(6);
    s << "[" << clean(x) << ", " << clean(y) << "]";
    return s.str();
}

std::string unrestrained_rigid_motion(const Model& model, const std::vector<bool>* in_contact,
                                      const std::vector<SurfaceHold>* surface_holds) {
    const int n = static_cast<int>(model.nodes.size());
    Parts parts(n);
    for (const ElementSpec& e : model.elements) parts.join(e.node_i, e.node_j);
    // Each part's nodes, centre and size, so that the rotation's columns are of order one.
    std::vector<std::vector<int>> members(n);
    for (int i = 0; i < n; ++i) members[parts.find(i)].push_back(i);
    for (const std::vector<int>& nodes : members) {
        if (nodes.empty()) continue;
        double cx = 0.0, cy = 0.0;
        for (int i : nodes) {
            cx += model.nodes[i].x;
            cy += model.nodes[i].y;
        }
        cx /= nodes.size();
        cy /= nodes.size();
        double size = 0.0;
        for (int i : nodes) size = std::max(size, std::hypot(model.nodes[i].x - cx, model.nodes[i].y - cy));
        if (!(size > 0.0) || !std::isfinite(size)) size = 1.0;
        // The three rigid motions at a node's DOF d: translations along x and y, and a rotation
        // by 1/size about the centre.
        auto mode = [&](int node, int d) -> Eigen::RowVector3d {
            const double rx = (model.nodes[node].x - cx) / size, ry = (model.nodes[node].y - cy) / size;
            if (d == 0) return {1.0, 0.0, -ry};
            if (d == 1) return {0.0, 1.0, rx};
            return {0.0, 0.0, 1.0}; // 1/size, scaled to one: only its direction counts
        };
        auto in_part = [&](int node) { return parts.find(node) == parts.find(nodes.front()); };
        // What holds the part: each restraint is a row of the rigid motions it resists.
        Eigen::Matrix3d held = Eigen::Matrix3d::Zero();
        auto hold = [&](const Eigen::RowVector3d& row) { held += row.transpose() * row / std::max(row.squaredNorm(), 1e-300); };
        for (const Support& s : model.supports)
            if (in_part(s.node))
                for (int d = 0; d < dofs_per_node; ++d)
                    if (s.fixed[d]) hold(mode(s.node, d));
        for (const PrescribedDisplacement& p : model.prescribed)
            if (in_part(p.node)) hold(mode(p.node, p.dof));
        for (std::size_t k = 0; k < model.springs.size(); ++k) {
            const FoundationSpring& s = model.springs[k];
            if (!in_part(s.node)) continue;
            if (s.unilateral && in_contact && !(*in_contact)[k]) continue;
            if (s.unilateral) {
                // A compression-only spring holds along its normal (it is what rests the
                // structure on its base).
                const std::array<double, 2> d = s.anchored ? s.direction : model.bases.at(static_cast<std::size_t>(s.base)).normal;
                hold(d[0] * mode(s.node, 0) + d[1] * mode(s.node, 1));
                continue;
            }
            if (s.kx > 0.0) hold(mode(s.node, 0));
            if (s.ky > 0.0) hold(mode(s.node, 1));
            if (s.krot > 0.0) hold(mode(s.node, 2));
        }
        if (surface_holds)
            for (const SurfaceHold& h : *surface_holds)
                if (in_part(h.node)) hold(h.direction[0] * mode(h.node, 0) + h.direction[1] * mode(h.node, 1));
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(held);
        if (eig.eigenvalues()[0] > 1e-9 * std::max(eig.eigenvalues()[2], 1e-300)) continue;
        const Eigen::Vector3d free = eig.eigenvectors().col(0);
        const Node& at = model.nodes[nodes.front()];
        std::ostringstream s;
        s << "the part of the structure with the node at " << point_text(model, at.x, at.y) << " (" << nodes.size()
          << (nodes.size() == 1 ? " node" : " nodes") << ") can move as a rigid body: ";
        if (std::abs(free[2]) < 1e-6)
            s << "a translation along [" << free[0] / free.head<2>().norm() << ", " << free[1] / free.head<2>().norm() << "]";
        else // the point that does not move: u = t + ω × (x − c) vanishes there
            s << "a rotation about " << point_text(model, cx - size * free[1] / free[2], cy + size * free[0] / free[2]);
        return s.str();
    }
    return {};
}

} // namespace plastica
