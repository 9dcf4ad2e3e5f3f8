// The members as a component: one co-rotational beam per element with its basic law (elastic,
// plastic hinges, fibre sections along it, released ends), follower pressure's stiffness on the
// elements it loads, the coupling of prescribed displacements through the members, and the
// joints' hinges moved to the weaker end at each commit (hinge_allocation.hpp).
#pragma once

#include "analysis/component.hpp"
#include "analysis/hinge_allocation.hpp"
#include "element/corotational_beam.hpp"
#include "load/follower_pressure.hpp"
#include "model/model.hpp"

#include <array>
#include <string>
#include <vector>

namespace plastica {

class MemberSet final : public Component {
public:
    // equation: per DOF, its equation or −1; pressure: the loads that follow the members.
    MemberSet(const Model& model, const std::vector<int>& equation, const FollowerPressure& pressure);

    bool evaluate(const EvaluationPoint& at, Eigen::VectorXd& internal, Eigen::VectorXd& coupling) override;
    void append_blocks(std::vector<std::vector<int>>& blocks) const override;
    void assemble(BlockAssembler& assembler, std::size_t first) const override;
    void commit() override;
    void revert() override;
    void report(const Eigen::VectorXd& u, bool with_sections, StepResult& out) const override;

    const std::vector<CorotationalBeam>& elements() const { return elements_; }
    // The first member whose tangent is not finite, named (non_finite_where()); false if none.
    bool find_non_finite_tangent() const;
    const std::string& non_finite_where() const { return non_finite_where_; }
    // The tangent of the last evaluation takes these axial forces (one per member) into the
    // geometric stiffness of its elastic members instead of the evaluated ones, where the two
    // differ by a stretch below 1e-4 (path_extrapolation.hpp says why).
    void take_axial_forces_in_tangent(const Eigen::VectorXd& forces);
    Eigen::VectorXd axial_forces() const; // committed
    // Linear buckling (linear_buckling.hpp), at the last evaluation: each member's axial force
    // rate along a rate of the displacements (full DOF vector), and the geometric stiffness of
    // given axial forces (the members' Hermitian one) with follower pressure's load stiffness
    // per unit of its factor, on the free DOFs.
    Eigen::VectorXd axial_force_rates(const Eigen::VectorXd& displacement_rate) const;
    SparseMatrix geometric_stiffness(const Eigen::VectorXd& axial_forces, int free_count, bool cubic) const;
    bool hinge_states_consistent() const;
    bool all_elastic() const;
    double trial_yield_advance() const;
    void predict_unloading();
    void stiffen_capacity(double ratio);

private:
    std::array<int, 6> dofs(std::size_t e) const; // the element's DOFs in the full vector
    void element_stiffness(std::size_t e, Matrix6& k) const; // the member's tangent and its pressure's
    bool element_tangent(std::size_t e, Matrix6& k) const;   // the same; false (and names it) if not finite
    void name_non_finite(std::size_t e) const;

    std::vector<ElementSpec> specs_;
    const std::vector<int>& equation_;
    const FollowerPressure& pressure_;
    std::vector<CorotationalBeam> elements_;
    std::vector<bool> distributed_;           // per element: fibre sections along it (else hinges or elastic)
    std::vector<double> elastic_ea_;          // per element: EA if neither hinges nor fibre sections, else 0
    std::vector<std::vector<int>> held_dofs_; // per element: its local DOFs that are supported or prescribed
    JointHinges joint_hinges_;
    Eigen::VectorXd tangent_axial_forces_;
    bool tangent_takes_axial_forces_ = false; // for the last evaluation's tangent
    double evaluated_load_factor_ = 0.0;      // of the last evaluation: follower pressure's stiffness
    mutable std::string non_finite_where_;
};

} // namespace plastica
