#include "contact/foundation.hpp"

namespace plastica {

Foundation::Foundation(const Model& model)
    : springs_(model.springs), nodes_(model.nodes), bases_(model.bases) {
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
        const bool touching = undecided(st, sp) ? st.active : st.gap <= 0.0;
        if (!freeze_active) {
            changed_ = changed_ || touching != st.active;
            st.active = touching;
        }
        st.force.setZero();
        if (st.active) st.force.head<2>() = -sp.ky * st.gap * n;
    }
}

Eigen::Vector2d Foundation::normal_of(const FoundationSpring& spring) const {
    if (spring.anchored) return Eigen::Vector2d(spring.direction[0], spring.direction[1]);
    const BaseLine& b = bases_[static_cast<std::size_t>(spring.base)];
    return Eigen::Vector2d(b.normal[0], b.normal[1]);
}

Eigen::Vector3d Foundation::load_rate(std::size_t k) const {
    const FoundationSpring& sp = springs_[k];
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
        if (st.unilateral && st.active != (st.gap <= 0.0) && !undecided(st, springs_[k])) return false;
    }
    return true;
}

Eigen::Matrix3d Foundation::tangent(std::size_t k) const {
    const FoundationSpring& sp = springs_[k];
    Eigen::Matrix3d t = Eigen::Matrix3d::Zero();
    if (!sp.unilateral) {
        t.diagonal() << sp.kx, sp.ky, sp.krot;
    } else if (states_[k].active) {
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
