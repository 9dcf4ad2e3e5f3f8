// The discrete structure: elements and foundation springs over the model's DOFs. It evaluates
// internal forces and the tangent on the free DOFs for a given full displacement vector, and
// the coupling ∂f/∂λ that prescribed displacements (K_fp·ū) and moving platens exert on the
// free DOFs.
#pragma once

#include "analysis/hinge_allocation.hpp"
#include "analysis/step_result.hpp"
#include "contact/foundation.hpp"
#include "contact/self_contact.hpp"
#include "element/corotational_beam.hpp"
#include "load/follower_pressure.hpp"
#include "model/model.hpp"
#include "solver/block_assembler.hpp"

#include <Eigen/Dense>
#include <array>
#include <map>
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
    // Whether that tangent is finite; if not, non_finite_where() names the element.
    bool tangent_finite() const;
    const std::string& non_finite_where() const { return non_finite_where_; }
    const Foundation& foundation() const { return foundation_; }
    const SelfContact& self_contact() const { return self_contact_; }
    void set_contact_undecided_force(double force) {
        foundation_.set_undecided_force(force);
        undecided_force_ = force;
    }
    // Whether the bases' and the surfaces' contact sets of the last evaluation are those its
    // geometry gives, unchanged from the evaluation before.
    bool contact_settled() const;
    // No load, no prescribed displacement: moving bases drive the structure.
    bool driven_by_platens() const { return driven_by_platens_; }
    // The forces the moving bases exert at the last evaluation (free DOFs).
    Eigen::VectorXd platen_force() const;
    bool on_moving_base(std::size_t spring) const { return on_moving_base_[spring]; }
    // Whether every element's hinge states (frozen or not) agree with the evaluated state.
    bool hinge_states_consistent() const;
    // No member has hinges or fibre sections: every law is smooth.
    bool all_members_elastic() const;
    // The reference load moves with the structure (follower pressure); else it is fixed.
    bool load_follows_deformation() const { return !pressure_.empty(); }
    // The largest advance of a section into its yielding range over the trial step, among
    // laws that integrate their stiffness explicitly (BasicLaw::trial_yield_advance).
    double trial_yield_advance() const;

    // The residual, relative to the load at λ, that the rounding of the displacements u alone
    // leaves at the last evaluation, and the part of it the foundation springs' penalties cause.
    RoundOffFloor round_off_floor(const Eigen::VectorXd& u, double load_factor) const;
    // Its force alone, eps·‖|K|·|u|‖ (no load or springs to gather): Newton asks every iteration.
    double round_off_force(const Eigen::VectorXd& u) const;

    Eigen::VectorXd gather(const Eigen::VectorXd& full) const;
    void gather(const Eigen::VectorXd& full, Eigen::VectorXd& free) const; // no allocation once sized
    void scatter(const Eigen::VectorXd& free, Eigen::VectorXd& full) const;

    // Commits every element and spring, then gives each joint's hinge to its weaker end at the
    // committed axial forces (analysis/hinge_allocation.hpp).
    void commit();
    // The next increment turns the load back: its predictor unloads elastically.
    void predict_unloading();
    void revert();

    // Fills the element, spring and reaction parts of a step result (committed state), the
    // sections along the members if asked.
    void report(const Eigen::VectorXd& u, const Eigen::VectorXd& external, StepResult& out,
                bool with_sections = true) const;

    const std::vector<CorotationalBeam>& elements() const { return elements_; }

private:
    std::vector<ElementSpec> element_specs_;
    std::vector<Node> nodes_;
    std::vector<CorotationalBeam> elements_;
    std::vector<bool> distributed_; // per element: fibre sections along it (else hinges or elastic)
    std::vector<double> elastic_ea_; // per element: EA if neither hinges nor fibre sections, else 0
    std::vector<std::vector<int>> held_dofs_; // per element: its local DOFs that are supported or prescribed
    Foundation foundation_;
    SelfContact self_contact_;
    double undecided_force_ = 0.0;
    // The assembler's blocks: elements, springs, then each pair of surfaces that has touched
    // (node, segment ends), found by its nodes. A new pair widens the pattern once.
    std::vector<std::vector<int>> blocks_;
    std::size_t member_blocks_ = 0; // elements and springs: the blocks that are always there
    std::map<std::array<int, 3>, std::size_t> surface_block_;
    bool add_surface_blocks(); // whether a pair was new (the assembler is then built again)
    // At a commit: only the pairs that touch now keep their blocks. A pair that touched only in
    // a wandering iterate would otherwise keep coupling two far nodes of a ring, and its
    // factorisation would stay as wide as that chord made it.
    void keep_touching_surface_blocks();
    FollowerPressure pressure_;
    JointHinges joint_hinges_;
    std::vector<Eigen::VectorXd> pattern_loads_; // per pattern, the nodal loads
    std::vector<bool> platens_only_;            // per pattern: driven by moving bases alone
    Eigen::VectorXd fixed_load_;                // the driven pattern's
    Eigen::VectorXd held_fixed_load_;           // the held patterns' at their factors
    Eigen::VectorXd load_;
    Eigen::VectorXd held_load_;
    int free_count_ = 0;
    std::vector<int> equation_;
    std::vector<int> dof_of_equation_; // the inverse of equation_ on the free DOFs
    // Assembled on demand from the elements' and springs' trial states (tangent()).
    void assemble_tangent() const;
    void element_stiffness(std::size_t e, Matrix6& k) const; // the member's tangent and its pressure's
    bool element_tangent(std::size_t e, Matrix6& k) const; // the same; false (and names it) if not finite
    void name_non_finite(std::size_t e) const;

    mutable BlockAssembler assembler_;
    mutable bool tangent_assembled_ = false;
    mutable bool tangent_finite_ = true;
    Eigen::VectorXd tangent_axial_forces_;
    bool tangent_takes_axial_forces_ = false; // for the last evaluation's tangent
    double evaluated_load_factor_ = 0.0; // of the last evaluation: follower pressure's stiffness
    Eigen::VectorXd internal_;
    Eigen::VectorXd coupling_;
    mutable std::string non_finite_where_;
    std::vector<bool> on_moving_base_; // per foundation spring
    bool driven_by_platens_ = false;
};

} // namespace plastica
