// Discrete foundation springs (Silva et al., CS-ASA, eq. 5: Kb = diag(kx, ky, kθ)) and frictionless unilateral
// contact with a straight rigid base by the penalty method. A bilateral spring always acts:
// f = Kb·u. A unilateral spring acts along the base normal n only while the node touches or
// penetrates the base, gap g = (x − p)·n ≤ 0 (equality included, so a ring that starts on the
// base is held): f = k·g·n, tangent k·n nᵀ. An anchored unilateral spring (a tensionless
// Winkler bed) measures g = u·n from the node's initial position along its own direction n.
// The active set is re-read from the current positions at every evaluation; the driver
// decides when it has settled. A base that acts along the members (BaseEdge) presses each
// member by its exact overlap with the line (contact/line_overlap.hpp) and hands the shares to
// the springs of its end nodes: a force continuous in the positions, with no active set.
#pragma once

#include <cmath>

#include "contact/member_overlap.hpp"
#include "load/pattern_factors.hpp"
#include "model/model.hpp"

#include <Eigen/Dense>
#include <vector>

namespace plastica {

struct SpringState {
    int node = 0;
    bool unilateral = false;
    bool active = true;
    double gap = 0.0;                                  // unilateral only
    Eigen::Vector3d force = Eigen::Vector3d::Zero();   // force the spring exerts on the node
};

class Foundation {
public:
    explicit Foundation(const Model& model);

    bool empty() const { return springs_.empty(); }
    std::size_t size() const { return springs_.size(); }
    const FoundationSpring& spring(std::size_t k) const { return springs_[k]; }

    // Evaluates every spring at the full displacement vector and load factor (which moves
    // platens). With freeze_active the unilateral springs keep the active flags of the
    // previous evaluation.
    void evaluate(const Eigen::VectorXd& u, double load_factor, bool freeze_active);
    // Whether the active set used matches the geometry (it does unless frozen and stale).
    bool active_set_consistent() const;
    // A unilateral spring whose force at its gap would be at most this keeps its state: open
    // or closed, the residual differs by less than that force. A node on the base within
    // round-off of touching would otherwise flip at every re-decision, and Newton cycle.
    void set_undecided_force(double force) { undecided_force_ = force; }
    // Whether the last evaluation changed the active set compared with the one before.
    bool active_set_changed() const { return changed_; }

    const std::vector<SpringState>& states() const { return states_; }
    // Internal force (3 entries) and tangent (3×3) of spring k at the last evaluation.
    Eigen::Vector3d internal_force(std::size_t k) const { return -states_[k].force; }
    Eigen::Matrix3d tangent(std::size_t k) const;
    // ∂(internal force of spring k)/∂λ: nonzero where an active spring's base moves.
    Eigen::Vector3d load_rate(std::size_t k) const;

    // The members bearing along their length: their springs' indices, and the tangent (6×6,
    // the two nodes' DOFs) and the overlapping share of the length at the last evaluation.
    std::size_t edge_count() const { return edges_.size(); }
    const BaseEdge& edge(std::size_t e) const { return edges_[e]; }
    Eigen::Matrix<double, 6, 6> edge_tangent(std::size_t e) const;
    double edge_fraction(std::size_t e) const { return overlaps_[e].fraction; }
    double edge_force(std::size_t e) const { return overlaps_[e].resultant; }

    int active_contacts() const;

    // A new stage: each base moves with λ if its pattern is driven, else stays where its held
    // factor put it.
    void set_pattern_factors(const PatternFactors& factors);

private:
    // The unit direction a unilateral spring pushes: its own (anchored) or the base's normal.
    Eigen::Vector2d normal_of(const FoundationSpring& spring) const;

    void evaluate_edges(const Eigen::VectorXd& u, double load_factor);

    std::vector<FoundationSpring> springs_;
    std::vector<BaseEdge> edges_;
    std::vector<MemberOverlap> overlaps_;     // per edge, at the last evaluation
    std::vector<Eigen::Vector3d> edge_rates_; // per spring: its edges' ∂(internal force)/∂λ
    std::vector<Node> nodes_;
    std::vector<BaseLine> reference_bases_; // as the model gives them (normals of unit length)
    std::vector<BaseLine> bases_;           // in the current stage (base_in_stage)
    std::vector<SpringState> states_;
    bool changed_ = false;
    double undecided_force_ = 0.0;
    bool undecided(const SpringState& st, const FoundationSpring& sp) const { return sp.ky * std::abs(st.gap) <= undecided_force_; }
    // Whether a spring switches on and off by itself (at its node, not along members).
    static bool switches(const FoundationSpring& sp) { return sp.unilateral && !sp.along_members; }
};

} // namespace plastica
