// Contact between the members' surfaces as a component (contact/self_contact.hpp): each pair
// of a node and a segment that touch presses both, couples DOFs that no member joins, and so
// brings a block of its own: the pairs that have touched since the last commit keep one.
#pragma once

#include "analysis/component.hpp"
#include "contact/self_contact.hpp"
#include "model/model.hpp"

#include <array>
#include <map>
#include <vector>

namespace plastica {

class SurfaceContactComponent final : public Component {
public:
    SurfaceContactComponent(const Model& model, const std::vector<int>& equation);

    bool evaluate(const EvaluationPoint& at, Eigen::VectorXd& internal, Eigen::VectorXd& coupling) override;
    void append_blocks(std::vector<std::vector<int>>& blocks) const override;
    bool blocks_changed() const override { return blocks_changed_; }
    void assemble(BlockAssembler& assembler, std::size_t first) const override;
    // Only the pairs that touch now keep their blocks. A pair that touched only in a wandering
    // iterate would otherwise keep coupling two far nodes of a ring, and its factorisation
    // would stay as wide as that chord made it.
    void commit() override;
    bool settled() const override { return !contact_.active_set_changed() && contact_.active_set_consistent(); }
    void report(const Eigen::VectorXd& u, bool with_sections, StepResult& out) const override;

    const SelfContact& self_contact() const { return contact_; }
    // A gap force below which a contact state is not decided (StructureProblem's band).
    void set_undecided_force(double force) { undecided_force_ = force; }

private:
    bool add_blocks(); // of the pairs that have none yet; whether any was new

    SelfContact contact_;
    const std::vector<int>& equation_;
    double undecided_force_ = 0.0;
    std::vector<std::vector<int>> blocks_;              // one per pair that has touched
    std::map<std::vector<int>, std::size_t> block_of_; // a pair's distinct nodes → its block
    bool blocks_changed_ = false;
};

} // namespace plastica
