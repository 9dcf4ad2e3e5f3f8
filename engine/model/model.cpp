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

bool Model::transient() const {
    if (analysis.scheme == Scheme::transient) return true;
    for (const StageSpec& s : stages)
        if (s.scheme == Scheme::transient) return true;
    return false;
}

bool Model::has_moving_base() const {
    for (const BaseLine& b : bases)
        if (b.moves()) return true;
    return false;
}

bool Model::has_moving_base(int pattern) const {
    for (const BaseLine& b : bases)
        if (b.moves() && b.pattern == pattern) return true;
    return false;
}

bool Model::loaded(int pattern) const {
    auto in = [pattern](const auto& item) { return item.pattern == pattern; };
    return std::any_of(loads.begin(), loads.end(), in) || std::any_of(pressures.begin(), pressures.end(), in) ||
           std::any_of(prescribed.begin(), prescribed.end(), in);
}

bool Model::has_forces(int pattern) const {
    auto in = [pattern](const auto& item) { return item.pattern == pattern; };
    return std::any_of(loads.begin(), loads.end(), in) || std::any_of(pressures.begin(), pressures.end(), in);
}

bool Model::has_unilateral_base() const {
    for (const auto& s : springs)
        if (s.unilateral) return true;
    return false;
}

namespace {
// The first non-zero load of a pattern as a direction in (fx, fy, moment) space.
std::array<double, 3> first_direction(const std::vector<NodalLoad>& loads, int pattern) {
    for (const NodalLoad& l : loads) {
        if (l.pattern != pattern) continue;
        const double n = std::sqrt(l.value[0] * l.value[0] + l.value[1] * l.value[1] + l.value[2] * l.value[2]);
        if (n > 0.0) return {l.value[0] / n, l.value[1] / n, l.value[2] / n};
    }
    return {0.0, 0.0, 0.0};
}
} // namespace

bool Model::uniform_pressure_only() const {
    const int pattern = reported_pattern();
    const ElementPressure* first = nullptr;
    for (const NodalLoad& l : loads)
        if (l.pattern == pattern) return false;
    for (const ElementPressure& p : pressures) {
        if (p.pattern != pattern) continue;
        if (!first) first = &p;
        if (p.value != first->value) return false;
    }
    return first != nullptr;
}

bool Model::loads_parallel() const {
    const int pattern = reported_pattern();
    for (const ElementPressure& p : pressures)
        if (p.pattern == pattern) return uniform_pressure_only(); // a pressure has no one direction
    const std::array<double, 3> d = first_direction(loads, pattern);
    for (const NodalLoad& l : loads) {
        if (l.pattern != pattern) continue;
        // Parallel to d: no component across it (a force with a moment is not parallel to a force).
        const double along = l.value[0] * d[0] + l.value[1] * d[1] + l.value[2] * d[2];
        double across = 0.0;
        for (int k = 0; k < 3; ++k) across += (l.value[k] - along * d[k]) * (l.value[k] - along * d[k]);
        if (std::sqrt(across) > 1e-12 * std::abs(along) + 1e-300) return false;
    }
    return true;
}

bool Model::has_releases() const {
    return std::any_of(elements.begin(), elements.end(), [](const ElementSpec& e) { return e.released[0] || e.released[1]; });
}

std::vector<bool> Model::rotation_unattached() const {
    std::vector<bool> unattached(nodes.size(), false);
    if (!has_releases()) return unattached;
    std::vector<int> held_ends(nodes.size(), 0), ends(nodes.size(), 0);
    for (const ElementSpec& e : elements) {
        ++ends[static_cast<std::size_t>(e.node_i)], ++ends[static_cast<std::size_t>(e.node_j)];
        if (!e.released[0]) ++held_ends[static_cast<std::size_t>(e.node_i)];
        if (!e.released[1]) ++held_ends[static_cast<std::size_t>(e.node_j)];
    }
    for (std::size_t n = 0; n < nodes.size(); ++n) unattached[n] = ends[n] > 0 && held_ends[n] == 0;
    for (const Support& s : supports)
        if (s.fixed[2]) unattached[static_cast<std::size_t>(s.node)] = false;
    for (const PrescribedDisplacement& p : prescribed)
        if (p.dof == 2) unattached[static_cast<std::size_t>(p.node)] = false;
    for (const FoundationSpring& s : springs)
        if (s.krot != 0.0) unattached[static_cast<std::size_t>(s.node)] = false;
    return unattached;
}

double Model::load_per_factor() const {
    if (report.measure == ReportSpec::Measure::factor) return report.load_scale;
    const int pattern = reported_pattern();
    if (uniform_pressure_only())
        for (const ElementPressure& p : pressures)
            if (p.pattern == pattern) return report.load_scale * std::abs(p.value);
    const std::array<double, 3> d = first_direction(loads, pattern);
    double total = 0.0;
    bool any = false;
    for (const NodalLoad& l : loads)
        if (l.pattern == pattern) total += l.value[0] * d[0] + l.value[1] * d[1] + l.value[2] * d[2], any = true;
    if (!any) return report.load_scale;
    return report.load_scale * std::abs(total);
}

bool Model::tracks_critical_points() const {
    if (has_plasticity(Plasticity::hinges) || has_plasticity(Plasticity::distributed)) return false;
    if (analysis.scheme != Scheme::transient) return true;
    for (const StageSpec& s : stages)
        if (s.scheme != Scheme::transient) return true;
    return false;
}

double Model::size() const {
    if (nodes.empty()) return 0.0;
    double x0 = nodes.front().x, x1 = x0, y0 = nodes.front().y, y1 = y0;
    for (const Node& n : nodes) {
        x0 = std::min(x0, n.x), x1 = std::max(x1, n.x);
        y0 = std::min(y0, n.y), y1 = std::max(y1, n.y);
    }
    return std::max(x1 - x0, y1 - y0);
}

} // namespace plastica
