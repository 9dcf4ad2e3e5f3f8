#include "model_building.hpp"

#include <unistd.h>

#include <sstream>

#include <cmath>

namespace plastica {

namespace {
double element_length(const Model& m, const ElementSpec& e) {
    return std::hypot(m.nodes[e.node_j].x - m.nodes[e.node_i].x, m.nodes[e.node_j].y - m.nodes[e.node_i].y);
}
} // namespace

std::map<int, std::array<double, 2>> lumped_line_load(const Model& model, const std::vector<int>& elements,
                                                      const std::array<double, 2>& w, const std::array<double, 2>& gravity) {
    std::map<int, std::array<double, 2>> lumped;
    for (int e : elements) {
        const ElementSpec& el = model.elements[static_cast<std::size_t>(e)];
        const Node &a = model.nodes[el.node_i], &b = model.nodes[el.node_j];
        const double half = 0.5 * std::hypot(b.x - a.x, b.y - a.y);
        const double m = model.sections[el.section].mass_per_length;
        for (int node : {el.node_i, el.node_j}) {
            lumped[node][0] += half * (w[0] + m * gravity[0]);
            lumped[node][1] += half * (w[1] + m * gravity[1]);
        }
    }
    return lumped;
}

std::vector<double> tributary_lengths(const Model& model) {
    std::vector<double> tributary(model.nodes.size(), 0.0);
    for (const ElementSpec& e : model.elements) {
        const double L = element_length(model, e);
        tributary[e.node_i] += L / 2.0;
        tributary[e.node_j] += L / 2.0;
    }
    return tributary;
}

std::optional<std::array<double, 2>> member_normal(const Model& model, int node) {
    double nx = 0.0, ny = 0.0;
    for (const ElementSpec& e : model.elements) {
        if (e.node_i != node && e.node_j != node) continue;
        const Node &a = model.nodes[e.node_i], &b = model.nodes[e.node_j];
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        nx += -(b.y - a.y) / length, ny += (b.x - a.x) / length;
    }
    const double length = std::hypot(nx, ny);
    if (!(length > 1e-12)) return std::nullopt;
    return std::array<double, 2>{nx / length, ny / length};
}

void infer_report_measure(Model& model) {
    if (model.driven_by_platens()) {
        model.report.measure = ReportSpec::Measure::platen;
        model.report.load_label = "platen force";
    } else if (!model.loads_parallel()) {
        model.report.measure = ReportSpec::Measure::factor;
        model.report.load_label = "load factor";
    } else if (model.uniform_pressure_only()) {
        model.report.load_label = "pressure";
    }
}

bool is_cantilever_with_tip_load(const Model& m) {
    if (m.inelastic() || !m.springs.empty() || !m.prescribed.empty() || !m.pressures.empty() || m.supports.size() != 1 || m.loads.size() != 1)
        return false;
    const Support& s = m.supports.front();
    if (!(s.fixed[0] && s.fixed[1] && s.fixed[2])) return false;
    // A chain of elements from the clamp: every node on the line through the clamp and the
    // loaded node, each node in at most two elements, the clamp and the load at the ends.
    const Node& a = m.nodes[s.node];
    const Node& b = m.nodes[m.loads.front().node];
    const double L = std::hypot(b.x - a.x, b.y - a.y);
    if (!(L > 0.0)) return false;
    const double c = (b.x - a.x) / L, sn = (b.y - a.y) / L;
    std::vector<int> degree(m.nodes.size(), 0);
    for (const ElementSpec& e : m.elements) ++degree[e.node_i], ++degree[e.node_j];
    for (std::size_t k = 0; k < m.nodes.size(); ++k) {
        const double along = (m.nodes[k].x - a.x) * c + (m.nodes[k].y - a.y) * sn;
        const double across = -(m.nodes[k].x - a.x) * sn + (m.nodes[k].y - a.y) * c;
        if (std::abs(across) > 1e-9 * L || along < -1e-9 * L || along > L * (1 + 1e-9) || degree[k] > 2) return false;
    }
    if (degree[s.node] != 1 || degree[m.loads.front().node] != 1) return false;
    const auto& f = m.loads.front().value;
    return f[2] == 0.0 && std::abs(f[0] * c + f[1] * sn) <= 1e-12 * std::hypot(f[0], f[1]);
}

double fibre_states(const Model& model) {
    double states = 0.0;
    for (const ElementSpec& e : model.elements) {
        const SectionSpec& s = model.sections[static_cast<std::size_t>(e.section)];
        if (!s.steel || s.plasticity == Plasticity::none) continue;
        const double sections = s.plasticity == Plasticity::hinges ? 2.0 : (s.integration_points > 0 ? s.integration_points : 5);
        states += static_cast<double>(s.fibres.size()) * sections;
    }
    return states;
}

std::optional<std::string> setup_too_large(const Model& model) {
    const double bytes = fibre_states(model) * bytes_per_fibre_state;
    const double memory = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGESIZE));
    if (!(memory > 0.0) || bytes < 0.8 * memory) return std::nullopt;
    std::ostringstream why;
    why.precision(3);
    why << "the sections' fibres would take about " << bytes / 1e9 << " GB (" << fibre_states(model) << " fibre states: fibres × "
        << "sections along each element × elements), more than the " << 0.8 * memory / 1e9
        << " GB this machine can give it; use fewer fibres or elements";
    return why.str();
}

} // namespace plastica
