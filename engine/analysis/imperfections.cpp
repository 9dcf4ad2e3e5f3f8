#include "analysis/imperfections.hpp"

#include "analysis/path_following.hpp"

#include <algorithm>
#include <map>
#include <vector>

namespace plastica {

void add_imperfections(Model& model) {
    if (model.imperfections.empty()) return;
    // The modes of each pattern, as many as the highest asked of it, on the perfect geometry.
    std::map<int, int> modes_of_pattern;
    for (const ImperfectionSpec& i : model.imperfections) modes_of_pattern[i.pattern] = std::max(modes_of_pattern[i.pattern], i.mode);
    std::map<int, BucklingResult> modes;
    for (const auto& entry : modes_of_pattern) {
        // Named, not a structured binding: the lambda below captures it (C++17).
        const int pattern = entry.first, count = entry.second;
        Model perfect = model;
        perfect.imperfections.clear();
        perfect.stages.clear();
        perfect.analysis.pattern = pattern;
        perfect.analysis.scheme = Scheme::load_control;
        const std::size_t first = static_cast<std::size_t>(
            std::find_if(model.imperfections.begin(), model.imperfections.end(), [&](const ImperfectionSpec& i) { return i.pattern == pattern; }) -
            model.imperfections.begin());
        try {
            PathFollowing analysis(perfect);
            modes[pattern] = analysis.buckling(count);
        } catch (const BucklingError& e) {
            throw ImperfectionError(first, std::string("the buckling modes of pattern '") + model.patterns[static_cast<std::size_t>(pattern)] +
                                               "': " + e.what());
        }
    }
    std::vector<Node> moved = model.nodes;
    for (std::size_t k = 0; k < model.imperfections.size(); ++k) {
        ImperfectionSpec& i = model.imperfections[k];
        const BucklingResult& found = modes.at(i.pattern);
        if (i.mode > static_cast<int>(found.modes.size()))
            throw ImperfectionError(k, "mode " + std::to_string(i.mode) + " asked, but the loads of pattern '" +
                                           model.patterns[static_cast<std::size_t>(i.pattern)] + "' have only " +
                                           std::to_string(found.modes.size()) + " buckling mode(s) with a positive factor");
        const BucklingMode& m = found.modes[static_cast<std::size_t>(i.mode - 1)];
        i.load_factor = m.load_factor;
        for (std::size_t n = 0; n < moved.size(); ++n) {
            moved[n].x += i.amplitude * m.shape[dofs_per_node * n];
            moved[n].y += i.amplitude * m.shape[dofs_per_node * n + 1];
        }
    }
    model.nodes = std::move(moved);
}

} // namespace plastica
