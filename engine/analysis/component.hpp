// A part of the structural system that couples DOFs with forces (what OpenSees calls an
// element): the members, the foundation springs and bases, the contact between surfaces. The
// system evaluates, assembles, commits, reverts and reports each through this interface, in the
// order they were added (structural_system.cpp: one line each), and asks nothing else of them
// while following the path. A new kind is one file pair here and that one line.
#pragma once

#include "analysis/step_result.hpp"
#include "solver/block_assembler.hpp"

#include <Eigen/Dense>
#include <cstddef>
#include <vector>

namespace plastica {

// The state the system is evaluated at.
struct EvaluationPoint {
    const Eigen::VectorXd& u;    // full displacement vector
    const Eigen::VectorXd& ubar; // the driven pattern's prescribed displacements per unit λ (full)
    double load_factor;
    bool freeze_active;          // contact sets kept as they are
    bool freeze_hinges;          // hinge states kept
    bool freeze_fibres;          // fibre branches kept
};

class Component {
public:
    virtual ~Component() = default;

    // Adds its forces on the nodes to `internal` (full DOF vector), and to `coupling` (free
    // DOFs) what the load factor's prescribed motions exert through it per unit λ. False where
    // a force is not finite.
    virtual bool evaluate(const EvaluationPoint& at, Eigen::VectorXd& internal, Eigen::VectorXd& coupling) = 0;
    // Its blocks of equation numbers (−1: a DOF not assembled), in the order assemble() fills them.
    virtual void append_blocks(std::vector<std::vector<int>>& blocks) const = 0;
    // Whether its blocks changed in the last evaluate() or commit() (contact pairs that appeared
    // or ended): the system then builds its assembler again.
    virtual bool blocks_changed() const { return false; }
    // Adds its tangent at the last evaluation; its blocks are numbered from `first`.
    virtual void assemble(BlockAssembler& assembler, std::size_t first) const = 0;
    // The evaluated state becomes the converged one, or is given up for it.
    virtual void commit() {}
    virtual void revert() {}
    // Whether its contact sets are those the evaluated geometry gives, unchanged from the
    // evaluation before.
    virtual bool settled() const { return true; }
    // Fills its part of a step's result (committed state); a reaction it carries itself is
    // taken out of out.reaction.
    virtual void report(const Eigen::VectorXd& u, bool with_sections, StepResult& out) const = 0;
};

} // namespace plastica
