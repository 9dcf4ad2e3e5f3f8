#include "analysis/support_reactions.hpp"

#include <set>
#include <utility>

namespace plastica {

namespace {

const char* const component_names[dofs_per_node] = {"fx", "fy", "mz"};

// Which DOFs each support reports: those it fixes that no earlier support at its node fixes.
std::vector<std::array<bool, dofs_per_node>> reported_dofs(const Model& model) {
    std::vector<std::array<bool, dofs_per_node>> reported;
    std::set<std::pair<int, int>> taken;
    for (const Support& s : model.supports) {
        std::array<bool, dofs_per_node> mine{};
        for (int d = 0; d < dofs_per_node; ++d)
            mine[d] = s.fixed[d] && taken.insert({s.node, d}).second;
        reported.push_back(mine);
    }
    return reported;
}

} // namespace

std::vector<SupportReaction> support_reactions(const Model& model, const StepResult& step) {
    const auto reported = reported_dofs(model);
    std::vector<SupportReaction> out;
    for (std::size_t k = 0; k < model.supports.size(); ++k) {
        SupportReaction r;
        r.support = static_cast<int>(k);
        r.node = model.supports[k].node;
        r.reported = reported[k];
        for (int d = 0; d < dofs_per_node; ++d)
            if (r.reported[d] && !step.reaction.empty()) r.force[d] = step.reaction[dofs_per_node * r.node + d];
        out.push_back(r);
    }
    return out;
}

std::vector<std::string> reaction_columns(const Model& model) {
    std::vector<std::string> names;
    const auto reported = reported_dofs(model);
    for (std::size_t k = 0; k < reported.size(); ++k)
        for (int d = 0; d < dofs_per_node; ++d)
            if (reported[k][d]) names.push_back("support" + std::to_string(k + 1) + "_" + component_names[d]);
    return names;
}

} // namespace plastica
