// The discrete structure: its components (component.hpp: the members, the foundation springs
// and bases, the contact between surfaces) over the model's DOFs. It evaluates internal forces
// and the tangent on the free DOFs for a given full displacement vector, and the coupling ∂f/∂λ
// that prescribed displacements (K_fp·ū) and moving platens exert on the free DOFs.
#pragma once

#include "analysis/component.hpp"
#include "analysis/foundation_component.hpp"
#include "analysis/member_set.hpp"
#include "analysis/step_result.hpp"
#include "analysis/surface_contact_component.hpp"
#include "load/follower_pressure.hpp"
#include "model/model.hpp"
#include "solver/block_assembler.hpp"

#include <Eigen/Dense>
#include <array>
#include <memory>
#include <utility>
#include <string>
#include <vector>

namespace plastica {

struct RoundOffFloor {
    double total = 0.0, from_springs = 0.0; // relative to the load at the state's λ
    double force = 0.0;                     // the whole, as a force (whatever the load)
};

class StructuralSystem {
public:
    // The model's nodal loads, pattern by pattern, are the reference loads that do not follow
    // the structure; [analysis]'s pattern is driven first.
    explicit StructuralSystem(const Model& model);
    // Its components keep references into it.
    StructuralSystem(const StructuralSystem&) = delete;
    StructuralSystem& operator=(const StructuralSystem&) = delete;
    // A new stage: the driven pattern's loads, pressures and moving bases scale with λ; the
    // others keep their factors (PatternFactors).
    void set_pattern_factors(const PatternFactors& factors);

    int dof_count() const { return static_cast<int>(equation_.size()); }
    int free_count() const { return free_count_; }
    // Equation number of a DOF, or −1 when it is supported or prescribed.
    int equation(int dof) const { return equation_[dof]; }

    // Evaluates at the full displacement vector u and load factor λ (which scales the load
    // stiffness of follower pressure); ubar is the prescribed-displacement direction. Returns
    // false (and names the element) when a force is not finite. The tangent is assembled when
    // first asked for: a converged state's is mostly not needed (the next step starts elsewhere).
    bool evaluate(const Eigen::VectorXd& u, const Eigen::VectorXd& ubar, double load_factor, bool freeze_active,
                  bool freeze_hinges = false, bool freeze_fibres = false);

    const Eigen::VectorXd& internal_force() const { return internal_; } // full DOF vector
    // The members' part of internal_force() (the rest is the springs' and contacts'), kept from
    // each evaluation once asked for (a transient run's energy accounts).
    void keep_member_forces() { keep_member_forces_ = true; }
    const Eigen::VectorXd& member_internal_force() const { return member_internal_; }
    const Eigen::VectorXd& coupling() const { return coupling_; }       // K_fp·ū + platens, free DOFs
    // Reference loads at the evaluated state, per unit λ: the fixed ones plus follower pressure.
    const Eigen::VectorXd& load() const { return load_; }
    // The held patterns' loads at the evaluated state (full DOF vector): constant in λ.
    const Eigen::VectorXd& held_load() const { return held_load_; }
    // The external force at the evaluated state and λ: held + λ·load.
    Eigen::VectorXd external_force(double load_factor) const { return held_load_ + load_factor * load_; }
    // The tangent at the last evaluation, assembled on first use.
    const SparseMatrix& tangent() const;
    // The tangent of the last evaluation takes these axial forces (one per member) into the
    // geometric stiffness of its elastic members instead of the evaluated ones, where the two
    // differ by a stretch below 1e-4 (path_extrapolation.hpp says why, and why not elsewhere).
    void take_axial_forces_in_tangent(const Eigen::VectorXd& forces);
    // The members' axial forces at the committed state.
    Eigen::VectorXd axial_forces() const;
    // Linear buckling (linear_buckling.hpp), at the last evaluation: each member's axial force
    // rate along a displacement rate (full DOF vector), and the geometric stiffness of given
    // axial forces (one per member) with follower pressure's per unit of its factor; cubic:
    // the members' Hermitian one, else the chord's the tangent carries (corotational_beam.hpp).
    Eigen::VectorXd axial_force_rates(const Eigen::VectorXd& displacement_rate) const {
        return members_->axial_force_rates(displacement_rate);
    }
    SparseMatrix geometric_stiffness(const Eigen::VectorXd& axial_forces, bool cubic) const {
        return members_->geometric_stiffness(axial_forces, free_count_, cubic);
    }
    // Whether that tangent is finite; if not, non_finite_where() names the element.
    bool tangent_finite() const;
    const std::string& non_finite_where() const { return members_->non_finite_where(); }
    const Foundation& foundation() const { return foundation_->foundation(); }
    const SelfContact& self_contact() const { return surfaces_->self_contact(); }
    void set_contact_undecided_force(double force) {
        foundation_->foundation().set_undecided_force(force);
        surfaces_->set_undecided_force(force);
    }
    // Whether the bases' and the surfaces' contact sets of the last evaluation are those its
    // geometry gives, unchanged from the evaluation before.
    bool contact_settled() const;
    // No load, no prescribed displacement: moving bases drive the structure.
    bool driven_by_platens() const { return driven_by_platens_; }
    // The forces the moving bases exert at the last evaluation (free DOFs).
    Eigen::VectorXd platen_force() const { return foundation_->platen_force(free_count_); }
    bool on_moving_base(std::size_t spring) const { return foundation_->on_moving_base(spring); }
    // Whether every element's hinge states (frozen or not) agree with the evaluated state.
    bool hinge_states_consistent() const { return members_->hinge_states_consistent(); }
    // No member has hinges or fibre sections: every law is smooth.
    bool all_members_elastic() const { return members_->all_elastic(); }
    // The reference load moves with the structure (follower pressure); else it is fixed.
    bool load_follows_deformation() const { return pressure_.follows_deformation(); }
    // The largest advance of a section into its yielding range over the trial step, among
    // laws that integrate their stiffness explicitly (BasicLaw::trial_yield_advance).
    double trial_yield_advance() const { return members_->trial_yield_advance(); }

    // The residual, relative to the load at λ, that the rounding of the displacements u alone
    // leaves at the last evaluation, and the part of it the foundation springs' penalties cause.
    RoundOffFloor round_off_floor(const Eigen::VectorXd& u, double load_factor) const;
    // Its force alone, eps·‖|K|·|u|‖ (no load or springs to gather): Newton asks every iteration.
    double round_off_force(const Eigen::VectorXd& u) const;

    Eigen::VectorXd gather(const Eigen::VectorXd& full) const;
    void gather(const Eigen::VectorXd& full, Eigen::VectorXd& free) const; // no allocation once sized
    void scatter(const Eigen::VectorXd& free, Eigen::VectorXd& full) const;

    // Commits every component: the members then give each joint's hinge to its weaker end at
    // the committed axial forces (analysis/hinge_allocation.hpp).
    void commit();
    // The next increment turns the load back: its predictor unloads elastically.
    void predict_unloading() { members_->predict_unloading(); }
    void stiffen_capacity(double ratio) { members_->stiffen_capacity(ratio); }
    void revert();

    // Fills the element, spring and reaction parts of a step result (committed state), the
    // sections along the members if asked.
    void report(const Eigen::VectorXd& u, const Eigen::VectorXd& external, StepResult& out,
                bool with_sections = true) const;

    const std::vector<CorotationalBeam>& elements() const { return members_->elements(); }

private:
    int free_count_ = 0;
    std::vector<int> equation_;
    std::vector<int> dof_of_equation_; // the inverse of equation_ on the free DOFs
    FollowerPressure pressure_;
    // Every component, in the order they are evaluated and assembled (added in the
    // constructor, one line each), and the first of each one's blocks in the assembler.
    std::vector<std::unique_ptr<Component>> components_;
    std::vector<std::size_t> first_block_;
    template <class Kind, class... Arguments>
    Kind* add(Arguments&&... arguments) {
        components_.push_back(std::make_unique<Kind>(std::forward<Arguments>(arguments)...));
        return static_cast<Kind*>(components_.back().get());
    }
    // Those the path following asks more of than the interface.
    MemberSet* members_ = nullptr;
    FoundationComponent* foundation_ = nullptr;
    SurfaceContactComponent* surfaces_ = nullptr;
    void build_assembler();

    std::vector<Eigen::VectorXd> pattern_loads_; // per pattern, the nodal loads
    std::vector<bool> platens_only_;            // per pattern: driven by moving bases alone
    Eigen::VectorXd fixed_load_;                // the driven pattern's
    Eigen::VectorXd held_fixed_load_;           // the held patterns' at their factors
    Eigen::VectorXd load_;
    Eigen::VectorXd held_load_;
    // Assembled on demand from the components' trial states (tangent()).
    void assemble_tangent() const;

    mutable BlockAssembler assembler_;
    mutable bool tangent_assembled_ = false;
    mutable bool tangent_finite_ = true;
    Eigen::VectorXd internal_;
    Eigen::VectorXd member_internal_;
    bool keep_member_forces_ = false;
    Eigen::VectorXd coupling_;
    bool driven_by_platens_ = false;
};

} // namespace plastica
