// [[imperfection]]: the initial geometry as the perfect one plus scaled buckling modes
// (engine/analysis/imperfections.hpp), each located at its table when it cannot be made.
#include "scene_builder.hpp"

#include "analysis/imperfections.hpp"

namespace plastica::detail {

void SceneBuilder::read_imperfections(TomlTableReader& top) {
    const Tables list = array_of_tables(top, "imperfection");
    if (list.empty()) return;
    std::vector<int> lines;
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, file_, indexed("imperfection", i), scene_table("imperfection"), units());
        ImperfectionSpec spec;
        spec.mode = r.integer("mode");
        spec.amplitude = r.number("amplitude", dimension::length);
        if (spec.amplitude == 0.0) r.fail("amplitude", "an imperfection of zero amplitude is none: give a length, signed");
        spec.pattern = r.has("pattern") ? driven_pattern(r) : model_.analysis.pattern;
        r.finish();
        model_.imperfections.push_back(spec);
        lines.push_back(list[i].second);
    }
    try {
        add_imperfections(model_);
    } catch (const ImperfectionError& e) {
        throw SceneError(file_, lines[e.index()], indexed("imperfection", e.index()), e.what());
    }
}

} // namespace plastica::detail
