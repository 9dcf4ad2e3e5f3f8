#include "contact/foundation.hpp"

#include <algorithm>

namespace plastica {

Foundation::Foundation(const Model& model)
    : springs_(model.springs), edges_(model.base_edges), overlaps_(model.base_edges.size()),
      edge_rates_(model.springs.size(), Eigen::Vector3d::Zero()), nodes_(model.nodes), bases_(model.bases) {
    for (BaseLine& b : bases_) {
        const double n = std::hypot(b.normal[0], b.normal[1]);
        b.normal = {b.normal[0] / n, b.normal[1] / n};
    }
    reference_bases_ = bases_;
    states_.resize(springs_.size());
    for (std::size_t k = 0; k < springs_.size(); ++k) {
        states_[k].node = springs_[k].node;
        states_[k].unilateral = springs_[k].unilateral;
    }
}

void Foundation::set_pattern_factors(const PatternFactors& factors) {
    for (std::size_t b = 0; b < bases_.size(); ++b) bases_[b] = base_in_stage(reference_bases_[b], factors);
}

void Foundation::evaluate(const Eigen::VectorXd& u, double load_factor, bool freeze_active) {
    changed_ = false;
    for (std::size_t k = 0; k < springs_.size(); ++k) {
        const FoundationSpring& sp = springs_[k];
        SpringState& st = states_[k];
        const Eigen::Vector3d d = u.segment<3>(dofs_per_node * sp.node);
        if (!sp.unilateral) {
            st.force = -Eigen::Vector3d(sp.kx * d[0], sp.ky * d[1], sp.krot * d[2]);
            continue;
        }
        const Eigen::Vector2d n = normal_of(sp);
        if (sp.anchored) {
            st.gap = d.head<2>().dot(n); // the bed is where the node started
        } else {
            const Node& n0 = nodes_[sp.node];
            st.gap = bases_[static_cast<std::size_t>(sp.base)].gap(n0.x + d[0], n0.y + d[1], load_factor);
        }
        st.force.setZero();
        if (sp.along_members) continue; // evaluate_edges() presses it
        const bool touching = undecided(st, sp) ? st.active : st.gap <= 0.0;
        if (!freeze_active) {
            changed_ = changed_ || touching != st.active;
            st.active = touching;
        }
        if (st.active) st.force.head<2>() = -sp.ky * st.gap * n;
    }
    evaluate_edges(u, load_factor);
}

void Foundation::evaluate_edges(const Eigen::VectorXd& u, double load_factor) {
    for (Eigen::Vector3d& r : edge_rates_) r.setZero();
    for (std::size_t e = 0; e < edges_.size(); ++e) {
        const BaseEdge& edge = edges_[e];
        const BaseLine& b = bases_[static_cast<std::size_t>(springs_[edge.spring[0]].base)];
        MemberCurve curve;
        for (int end = 0; end < 2; ++end) {
            const int node = springs_[edge.spring[end]].node;
            const Eigen::Vector3d d = u.segment<3>(dofs_per_node * node);
            curve.position[end] = Eigen::Vector2d(nodes_[node].x + d[0], nodes_[node].y + d[1]);
            curve.tangent_angle[end] = edge.tangent_angle[end] + d[2];
        }
        curve.length = edge.length;
        curve.straight = edge.straight;
        overlaps_[e] = member_overlap(curve, Eigen::Vector2d(b.point[0] + load_factor * b.motion[0], b.point[1] + load_factor * b.motion[1]),
                                      Eigen::Vector2d(b.normal[0], b.normal[1]), edge.stiffness);
        // A moving base is the member moving back by λ·motion: ∂(internal force)/∂λ = −K·motion.
        Eigen::Matrix<double, 6, 1> motion;
        motion << b.motion[0], b.motion[1], 0.0, b.motion[0], b.motion[1], 0.0;
        const Eigen::Matrix<double, 6, 1> rate = -edge_tangent(e) * motion;
        for (int end = 0; end < 2; ++end) {
            states_[edge.spring[end]].force -= overlaps_[e].internal_force.segment<3>(3 * end);
            edge_rates_[edge.spring[end]] += rate.segment<3>(3 * end);
        }
    }
    for (std::size_t k = 0; k < springs_.size(); ++k)
        if (springs_[k].along_members) states_[k].active = states_[k].gap <= 0.0 || states_[k].force.head<2>().norm() > 0.0;
}

Eigen::Matrix<double, 6, 6> Foundation::edge_tangent(std::size_t e) const {
    Eigen::Matrix<double, 6, 6> t = overlaps_[e].stiffness;
    // A node that touches where the overlap has not begun to bear (a ring standing on the base
    // at one node, a platen about to press) has no stiffness yet, and nothing else may hold it:
    // it takes 1e-3 of what a member lying flat on the base gives its node.
    const BaseEdge& edge = edges_[e];
    const Eigen::Vector2d n = normal_of(springs_[edge.spring[0]]);
    const double onset = 1e-3 * edge.stiffness * edge.length / 3.0;
    for (int end = 0; end < 2; ++end) {
        if (states_[edge.spring[end]].gap > 0.0) continue;
        const double has = n.dot(t.block<2, 2>(3 * end, 3 * end) * n);
        if (has <= 0.0) t.block<2, 2>(3 * end, 3 * end) += (onset - has) * n * n.transpose();
    }
    return t;
}

Eigen::Vector2d Foundation::normal_of(const FoundationSpring& spring) const {
    if (spring.anchored) return Eigen::Vector2d(spring.direction[0], spring.direction[1]);
    const BaseLine& b = bases_[static_cast<std::size_t>(spring.base)];
    return Eigen::Vector2d(b.normal[0], b.normal[1]);
}

Eigen::Vector3d Foundation::load_rate(std::size_t k) const {
    const FoundationSpring& sp = springs_[k];
    if (sp.along_members) return edge_rates_[k];
    Eigen::Vector3d rate = Eigen::Vector3d::Zero();
    if (!sp.unilateral || sp.anchored || !states_[k].active) return rate;
    const BaseLine& b = bases_[static_cast<std::size_t>(sp.base)];
    if (!b.moves()) return rate;
    // Internal force k·g·n with ∂g/∂λ = −motion·n.
    const Eigen::Vector2d n = normal_of(sp);
    rate.head<2>() = -sp.ky * (b.motion[0] * n[0] + b.motion[1] * n[1]) * n;
    return rate;
}

bool Foundation::active_set_consistent() const {
    for (std::size_t k = 0; k < states_.size(); ++k) {
        const SpringState& st = states_[k];
        if (switches(springs_[k]) && st.active != (st.gap <= 0.0) && !undecided(st, springs_[k])) return false;
    }
    return true;
}

Eigen::Matrix3d Foundation::tangent(std::size_t k) const {
    const FoundationSpring& sp = springs_[k];
    Eigen::Matrix3d t = Eigen::Matrix3d::Zero();
    if (!sp.unilateral) {
        t.diagonal() << sp.kx, sp.ky, sp.krot;
    } else if (states_[k].active && !sp.along_members) {
        const Eigen::Vector2d n = normal_of(sp);
        t.topLeftCorner<2, 2>() = sp.ky * n * n.transpose();
    }
    return t;
}

int Foundation::active_contacts() const {
    int count = 0;
    for (const SpringState& st : states_)
        if (st.unilateral && st.active) ++count;
    return count;
}

} // namespace plastica
