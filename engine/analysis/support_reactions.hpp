// The reactions of a step gathered per [[support]]: the force each support exerts on the
// structure along the DOFs it fixes. A DOF fixed by two supports at one node is reported once,
// by the first of them.
#pragma once

#include "analysis/step_result.hpp"
#include "model/model.hpp"

#include <array>
#include <string>
#include <vector>

namespace plastica {

struct SupportReaction {
    int support = 0;                                 // index into Model::supports
    int node = 0;
    std::array<bool, dofs_per_node> reported{};      // the DOFs this support reports
    std::array<double, dofs_per_node> force{};       // fx, fy, moment (zero where not reported)
};

std::vector<SupportReaction> support_reactions(const Model& model, const StepResult& step);

// Column names of the reported DOFs, in order: "support1_fx", "support1_fy", "support2_mz", …
std::vector<std::string> reaction_columns(const Model& model);

} // namespace plastica
