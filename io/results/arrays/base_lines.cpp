#include "arrays/base_lines.hpp"

#include <algorithm>

namespace plastica {

using namespace result;

XmlDataset base_lines_dataset(const Model& m, const std::set<std::string>& present) {
    XmlDataset poly;
    XmlArray kind = integer_array(name::base_kind, 0);
    auto add_point = [&poly](double x, double y) {
        poly.points.insert(poly.points.end(), {x, y, 0.0});
        return static_cast<std::int64_t>(poly.point_count() - 1);
    };
    for (const FoundationSpring& s : m.springs) {
        if (s.unilateral) continue; // a base line holds these (drawn below); a tensionless bed shows by its contact forces
        poly.vertices.push_back(add_point(m.nodes[s.node].x, m.nodes[s.node].y));
        integer(kind).push_back(static_cast<int>(BaseKind::spring_anchor));
    }
    // Each rigid line, long enough for a structure that spreads over it: twice the structure's
    // extent on either side of its centre. A platen's line is drawn where it is at λ = 0 and
    // moves by λ·motion (cell array "motion"; λ is each step's load_factor, or with several load
    // patterns the factor of the line's "pattern" in the step's pattern_factors).
    XmlArray motion = real_array(name::base_motion, poly.vertices.size(), 3);
    XmlArray pattern = integer_array(name::base_pattern, poly.vertices.size());
    const std::vector<int> patterns = active_patterns(m);
    for (const BaseLine& base : m.bases) {
        double lo = 1e300, hi = -1e300;
        const double tx = -base.normal[1], ty = base.normal[0];
        for (const Node& nd : m.nodes) {
            const double t = (nd.x - base.point[0]) * tx + (nd.y - base.point[1]) * ty;
            lo = std::min(lo, t);
            hi = std::max(hi, t);
        }
        const double mid = 0.5 * (lo + hi), half = std::max(hi - lo, 1e-12);
        const std::int64_t a = add_point(base.point[0] + (mid - 2 * half) * tx, base.point[1] + (mid - 2 * half) * ty);
        const std::int64_t b = add_point(base.point[0] + (mid + 2 * half) * tx, base.point[1] + (mid + 2 * half) * ty);
        poly.lines.push_back({a, b});
        integer(kind).push_back(static_cast<int>(BaseKind::rigid_line));
        for (double v : {base.motion[0], base.motion[1], 0.0}) real(motion).push_back(v);
        integer(pattern).push_back(static_cast<int>(std::find(patterns.begin(), patterns.end(), base.pattern) - patterns.begin()));
    }
    poly.cell_data.push_back(std::move(kind));
    if (present.count(name::base_motion)) poly.cell_data.push_back(std::move(motion));
    if (present.count(name::base_pattern)) poly.cell_data.push_back(std::move(pattern));
    return poly;
}

OutputGroup base_line_arrays() {
    return {{
                {name::base_kind, Where::base, Type::int32, 1, Quantity::none, When::spring_anchors, "0 spring anchor (vertex), 1 rigid base line"},
                {name::base_motion, Where::base, Type::float64, 3, Quantity::length, When::moving_base, "a platen's travel per unit factor of its pattern (lines only)"},
                {name::base_pattern, Where::base, Type::int32, 1, Quantity::none, When::moving_base_patterns, "the line's load pattern: its index in pattern_factors"},
            },
            nullptr};
}

} // namespace plastica
