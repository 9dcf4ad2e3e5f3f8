#include "analysis/penetration_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <vector>

namespace plastica {

namespace {

struct Point {
    double x, y;
};

double orientation(const Point& a, const Point& b, const Point& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Proper crossing: each segment's ends lie strictly on both sides of the other's line,
// beyond a round-off band (segments that merely touch are not a penetration).
bool cross(const Point& a, const Point& b, const Point& c, const Point& d, double band) {
    const double o1 = orientation(a, b, c), o2 = orientation(a, b, d);
    const double o3 = orientation(c, d, a), o4 = orientation(c, d, b);
    return ((o1 > band && o2 < -band) || (o1 < -band && o2 > band)) &&
           ((o3 > band && o4 < -band) || (o3 < -band && o4 > band));
}

std::string where(const Point& p) {
    std::ostringstream s;
    s << "[" << p.x << ", " << p.y << "]";
    return s.str();
}

} // namespace

std::string element_beyond_reach(const Model& model, const Eigen::VectorXd& u) {
    // An element whose chord has shortened to half its length has passed the reach of beam
    // theory (a column crushed through its own length, or stretched out beyond it, inverted);
    // one stretched to three times its length has too (a plastic string's steel breaks at a
    // fraction of that). Neither is a state of the structure. First-order geometry moves no chord.
    if (model.analysis.geometry == Geometry::first_order) return {};
    for (std::size_t e = 0; e < model.elements.size(); ++e) {
        const ElementSpec& element = model.elements[e];
        const std::size_t i = static_cast<std::size_t>(element.node_i), j = static_cast<std::size_t>(element.node_j);
        const Node &ni = model.nodes[i], &nj = model.nodes[j];
        const Point a{ni.x + u[dofs_per_node * i], ni.y + u[dofs_per_node * i + 1]};
        const Point b{nj.x + u[dofs_per_node * j], nj.y + u[dofs_per_node * j + 1]};
        const double initial = std::hypot(nj.x - ni.x, nj.y - ni.y);
        const double stretch = initial > 0.0 ? std::hypot(b.x - a.x, b.y - a.y) / initial : 1.0;
        if (stretch < 0.5 || stretch > 3.0) {
            std::ostringstream s;
            s << "element " << e << " between " << where(a) << " and " << where(b) << " is " << 100.0 * stretch
              << " % of its length: it has passed through its own length or stretched beyond any beam's reach";
            return s.str();
        }
    }
    return {};
}

std::string find_penetration(const Model& model, const Eigen::VectorXd& u, double load_factor,
                             const PatternFactors* factors) {
    const std::size_t n = model.nodes.size();
    std::vector<Point> at(n);
    for (std::size_t i = 0; i < n; ++i)
        at[i] = {model.nodes[i].x + u[dofs_per_node * i], model.nodes[i].y + u[dofs_per_node * i + 1]};

    // Element chords, swept along the axis on which they overlap less (x for a beam, y for a
    // half ring, whose upper and lower arcs share their x range): only pairs whose ranges on it
    // overlap are tested.
    const std::vector<ElementSpec>& elements = model.elements;
    constexpr double inf = std::numeric_limits<double>::infinity();
    double spread[2] = {0.0, 0.0}, low_box[2] = {inf, inf}, high_box[2] = {-inf, -inf};
    for (const ElementSpec& element : elements) {
        const Point &a = at[element.node_i], &b = at[element.node_j];
        spread[0] += std::abs(b.x - a.x);
        spread[1] += std::abs(b.y - a.y);
        low_box[0] = std::min({low_box[0], a.x, b.x});
        low_box[1] = std::min({low_box[1], a.y, b.y});
        high_box[0] = std::max({high_box[0], a.x, b.x});
        high_box[1] = std::max({high_box[1], a.y, b.y});
    }
    // Overlap on an axis: the chords' summed extent over the structure's (∞ when it is flat).
    auto overlap = [&](int axis) {
        const double box = high_box[axis] - low_box[axis];
        return box > 0.0 ? spread[axis] / box : inf;
    };
    const bool along_y = overlap(1) < overlap(0);
    auto coordinate = [along_y](const Point& p) { return along_y ? p.y : p.x; };
    std::vector<std::size_t> order(elements.size());
    std::iota(order.begin(), order.end(), 0);
    std::vector<double> lows(elements.size()), highs(elements.size()), lengths(elements.size());
    for (std::size_t e = 0; e < elements.size(); ++e) {
        const Point &a = at[elements[e].node_i], &b = at[elements[e].node_j];
        lows[e] = std::min(coordinate(a), coordinate(b));
        highs[e] = std::max(coordinate(a), coordinate(b));
        lengths[e] = std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
    }
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return lows[a] < lows[b]; });
    for (std::size_t k = 0; k < order.size(); ++k) {
        const ElementSpec& e = elements[order[k]];
        const Point &a = at[e.node_i], &b = at[e.node_j];
        for (std::size_t m = k + 1; m < order.size() && lows[order[m]] <= highs[order[k]]; ++m) {
            const ElementSpec& f = elements[order[m]];
            if (f.node_i == e.node_i || f.node_i == e.node_j || f.node_j == e.node_i || f.node_j == e.node_j) continue;
            const Point &c = at[f.node_i], &d = at[f.node_j];
            const double band = 1e-9 * lengths[order[k]] * lengths[order[m]];
            if (cross(a, b, c, d, band))
                return "the structure passes through itself: element " + std::to_string(order[k] + 1) +
                       " crosses element " + std::to_string(order[m] + 1) + " near " + where(a) +
                       (model.self_contact.empty() ? " (a [[self_contact]] table keeps the members' surfaces apart)" : "");
        }
    }

    // A half model may not cross its symmetry line (it would pass through its mirror image).
    if (model.report.mirror_x) {
        const double line = *model.report.mirror_x;
        double side = 0.0;
        for (const Node& node : model.nodes) side += node.x - line;
        const double sign = side >= 0.0 ? 1.0 : -1.0;
        double size = 0.0;
        for (const Node& node : model.nodes) size = std::max(size, std::abs(node.x - line));
        for (std::size_t i = 0; i < n; ++i)
            if (sign * (at[i].x - line) < -1e-6 * size)
                return "the structure passes through its mirror image: node " + std::to_string(i + 1) +
                       " crossed the symmetry line x = " + std::to_string(line) + " at " + where(at[i]);
    }

    // A node a base does not hold may not pass through it (where it started on its free side).
    for (std::size_t b = 0; b < model.bases.size(); ++b) {
        std::vector<bool> held(n, false);
        for (const FoundationSpring& s : model.springs)
            if (s.unilateral && !s.anchored && s.base == static_cast<int>(b)) held[s.node] = true;
        const BaseLine base = factors ? base_in_stage(model.bases[b], *factors) : model.bases[b];
        for (std::size_t i = 0; i < n; ++i) {
            if (held[i] || model.bases[b].gap(model.nodes[i].x, model.nodes[i].y, 0.0) < 0.0) continue;
            if (base.gap(at[i].x, at[i].y, load_factor) < 0.0)
                return "node " + std::to_string(i + 1) + " passed through the rigid base at " + where(at[i]) +
                       " (the base holds only the nodes its springs are on)";
        }
    }
    return {};
}

} // namespace plastica
