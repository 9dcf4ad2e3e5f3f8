#include "model/model.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

bool Model::inelastic() const {
    for (const auto& s : sections)
        if (s.steel) return true;
    return false;
}

bool Model::has_plasticity(Plasticity kind) const {
    for (const ElementSpec& e : elements)
        if (sections[e.section].plasticity == kind) return true;
    return false;
}

int Model::integration_points() const {
    int most = 0;
    for (const ElementSpec& e : elements)
        if (sections[e.section].plasticity == Plasticity::distributed)
            most = std::max(most, sections[e.section].segments * sections[e.section].integration_points);
    return most;
}

bool Model::has_moving_base() const {
    for (const BaseLine& b : bases)
        if (b.moves()) return true;
    return false;
}

bool Model::has_unilateral_base() const {
    for (const auto& s : springs)
        if (s.unilateral) return true;
    return false;
}

namespace {
// The first non-zero load as a direction in (fx, fy, moment) space.
std::array<double, 3> first_direction(const std::vector<NodalLoad>& loads) {
    for (const NodalLoad& l : loads) {
        const double n = std::sqrt(l.value[0] * l.value[0] + l.value[1] * l.value[1] + l.value[2] * l.value[2]);
        if (n > 0.0) return {l.value[0] / n, l.value[1] / n, l.value[2] / n};
    }
    return {0.0, 0.0, 0.0};
}
} // namespace

bool Model::uniform_pressure_only() const {
    if (pressures.empty() || !loads.empty()) return false;
    for (const ElementPressure& p : pressures)
        if (p.value != pressures.front().value) return false;
    return true;
}

bool Model::loads_parallel() const {
    if (!pressures.empty()) return uniform_pressure_only(); // a pressure has no one direction
    const std::array<double, 3> d = first_direction(loads);
    for (const NodalLoad& l : loads) {
        // Parallel to d: no component across it (a force with a moment is not parallel to a force).
        const double along = l.value[0] * d[0] + l.value[1] * d[1] + l.value[2] * d[2];
        double across = 0.0;
        for (int k = 0; k < 3; ++k) across += (l.value[k] - along * d[k]) * (l.value[k] - along * d[k]);
        if (std::sqrt(across) > 1e-12 * std::abs(along) + 1e-300) return false;
    }
    return true;
}

double Model::load_per_factor() const {
    if (report.measure == ReportSpec::Measure::factor) return report.load_scale;
    if (uniform_pressure_only()) return report.load_scale * std::abs(pressures.front().value);
    if (loads.empty()) return report.load_scale;
    const std::array<double, 3> d = first_direction(loads);
    double total = 0.0;
    for (const NodalLoad& l : loads) total += l.value[0] * d[0] + l.value[1] * d[1] + l.value[2] * d[2];
    return report.load_scale * std::abs(total);
}

} // namespace plastica
