// The foundation springs and rigid bases as a component (contact/foundation.hpp): each spring's
// force and tangent on its node, what a moving base exerts per unit λ, and in a step's result
// the springs' forces, the contact with the bases and its length along the members.
#pragma once

#include "analysis/component.hpp"
#include "contact/foundation.hpp"
#include "model/model.hpp"

#include <vector>

namespace plastica {

class FoundationComponent final : public Component {
public:
    FoundationComponent(const Model& model, const std::vector<int>& equation);

    bool evaluate(const EvaluationPoint& at, Eigen::VectorXd& internal, Eigen::VectorXd& coupling) override;
    void append_blocks(std::vector<std::vector<int>>& blocks) const override;
    void assemble(BlockAssembler& assembler, std::size_t first) const override;
    bool settled() const override { return !foundation_.active_set_changed() && foundation_.active_set_consistent(); }
    void report(const Eigen::VectorXd& u, bool with_sections, StepResult& out) const override;

    const Foundation& foundation() const { return foundation_; }
    Foundation& foundation() { return foundation_; }
    bool on_moving_base(std::size_t spring) const { return on_moving_base_[spring]; }
    // The forces the moving bases exert at the last evaluation (free DOFs, `size` of them).
    Eigen::VectorXd platen_force(int size) const;

private:
    Foundation foundation_;
    const std::vector<int>& equation_;
    std::vector<ElementSpec> elements_; // for the contact length along them
    std::vector<Node> nodes_;
    std::vector<bool> on_moving_base_; // per spring
};

} // namespace plastica
