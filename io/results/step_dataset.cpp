#include "step_dataset.hpp"

#include "arrays/output_array.hpp"
#include "result_schema.hpp"

#include <algorithm>

namespace plastica {

namespace {

// force·length, force/length: the compound units of moments and pressures.
std::string compound(const std::string& a, const char* op, const std::string& b) {
    if (a.empty() || b.empty()) return {};
    return a + op + b;
}

} // namespace

std::pair<std::string, std::string> reported_units(const Model& m) {
    const std::string& force = m.report.force_unit;
    const std::string& length = m.report.length_unit;
    std::string load = force;
    if (m.report.measure == ReportSpec::Measure::factor) {
        load.clear();
    } else if (m.uniform_pressure_only()) {
        load = compound(force, "/", length);
    } else {
        bool any = false, moments_only = true;
        for (const NodalLoad& l : m.loads)
            if (l.pattern == m.reported_pattern()) any = true, moments_only = moments_only && l.value[0] == 0.0 && l.value[1] == 0.0;
        if (any && moments_only) load = compound(force, "·", length);
    }
    return {load, m.reported_control().dof == 2 ? "rad" : length};
}


StepDataset::StepDataset(const Model& model) : model_(&model) {
    const auto [load_unit, displacement_unit] = reported_units(model);
    units_ = {load_unit, displacement_unit};
    for (const result::Array& a : result::arrays())
        if (result::present(a, model)) arrays_.emplace(a.name);
}

XmlDataset StepDataset::operator()(const StepResult& r, double time) const {
    const Model& m = *model_;
    const std::size_t n = m.nodes.size(), ne = m.elements.size();
    XmlDataset grid;
    grid.points.resize(3 * n);
    grid.lines.reserve(ne);
    for (const ElementSpec& e : m.elements) grid.lines.push_back({e.node_i, e.node_j});
    for (std::size_t i = 0; i < n; ++i) {
        grid.points[3 * i] = m.nodes[i].x + r.displacement[3 * i];
        grid.points[3 * i + 1] = m.nodes[i].y + r.displacement[3 * i + 1];
    }
    grid.point_data.reserve(arrays_.size()); // at most every array of the scene in one place: no reallocation
    grid.cell_data.reserve(arrays_.size());
    grid.field_data.reserve(arrays_.size());
    const StepView view{m, r, time, units_.load, units_.displacement, arrays_};
    for (const OutputGroup& g : output_groups())
        if (g.fill) g.fill(view, grid);
    return grid;
}

} // namespace plastica
