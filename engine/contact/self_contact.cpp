#include "contact/self_contact.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <queue>
#include <tuple>

namespace plastica {

namespace {


// Gauss–Lobatto points on [0, 1] and their weights: exact for the penalty of a gap linear along
// the element (a quadratic); the ends among them, so that a node standing on a surface holds
// from the first touch (inner points alone leave a ring on one node floating).
constexpr int points_per_element = 4;
constexpr double gauss_eta[points_per_element] = {0.0, 0.2763932022500210, 0.7236067977499790, 1.0};
constexpr double gauss_weight[points_per_element] = {1.0 / 12.0, 5.0 / 12.0, 5.0 / 12.0, 1.0 / 12.0};


// The nodes within `radius` of `from` along the elements (undeformed lengths), sorted.
std::vector<int> nodes_within(int from, double radius, const std::vector<std::vector<std::pair<int, double>>>& links) {
    std::map<int, double> reached{{from, 0.0}};
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> open;
    open.push({0.0, from});
    while (!open.empty()) {
        const auto [distance, node] = open.top();
        open.pop();
        if (distance > reached[node]) continue;
        for (const auto& [next, length] : links[static_cast<std::size_t>(node)]) {
            const double further = distance + length;
            if (further > radius) continue;
            auto it = reached.find(next);
            if (it != reached.end() && it->second <= further) continue;
            reached[next] = further;
            open.push({further, next});
        }
    }
    std::vector<int> out;
    for (const auto& entry : reached) out.push_back(entry.first);
    return out;
}

using Key = std::tuple<int, int, int>;

// A pair whose force at its gap is within the band keeps its state; without a band (the first
// evaluation) the geometry alone decides, so surfaces that start touching touch.
bool undecided(const SurfaceContact& c, double band) { return band > 0.0 && c.stiffness * std::abs(c.gap) <= band; }
Key key_of(const SurfaceContact& c) { return {c.point_id, c.segment[0], c.segment[1]}; }

} // namespace

double SelfContact::default_stiffness(const Model& model, const std::vector<int>& elements) {
    double k = 0.0;
    for (int e : elements) {
        const ElementSpec& spec = model.elements[static_cast<std::size_t>(e)];
        const Node &a = model.nodes[static_cast<std::size_t>(spec.node_i)], &b = model.nodes[static_cast<std::size_t>(spec.node_j)];
        const SectionSpec& s = model.sections[static_cast<std::size_t>(spec.section)];
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        k = std::max(k, std::min(s.E * s.area / length, 100.0 * 12.0 * s.E * s.inertia / (length * length * length)));
    }
    return k;
}

SelfContact::SelfContact(const Model& model) {
    int points_so_far = 0;
    for (const Node& n : model.nodes) {
        x0_.push_back(n.x);
        x0_.push_back(n.y);
    }
    for (const SelfContactSpec& spec : model.self_contact) {
        Group g;
        g.along_members = spec.along_members;
        g.stiffness = spec.stiffness > 0.0 ? spec.stiffness : default_stiffness(model, spec.elements);
        std::map<int, double> half_depth; // per node, the deepest section meeting there
        std::vector<std::vector<std::pair<int, double>>> links(model.nodes.size());
        double deepest = 0.0;
        for (int e : spec.elements) {
            const ElementSpec& el = model.elements[static_cast<std::size_t>(e)];
            const double h = 0.5 * model.sections[static_cast<std::size_t>(el.section)].surface_depth();
            const Node &a = model.nodes[static_cast<std::size_t>(el.node_i)], &b = model.nodes[static_cast<std::size_t>(el.node_j)];
            const double length = std::hypot(b.x - a.x, b.y - a.y);
            g.segments.push_back({el.node_i, el.node_j, h, length});
            deepest = std::max(deepest, 2.0 * h);
            for (int node : {el.node_i, el.node_j}) half_depth[node] = std::max(half_depth[node], h);
            links[static_cast<std::size_t>(el.node_i)].push_back({el.node_j, length});
            links[static_cast<std::size_t>(el.node_j)].push_back({el.node_i, length});
        }
        // Two points of one member touch only across a fold: the tightest fold (inner surface
        // of radius 0) puts facing points half a turn of radius c/2 apart along the centre line,
        // π·c/2. Nearer points are neighbours, never contact; twice the reach leaves a margin.
        const double radius = 2.0 * deepest;
        for (const auto& [node, h] : half_depth) {
            g.nodes.push_back(node);
            g.node_half_depth.push_back(h);
            g.near.push_back(nodes_within(node, radius, links));
        }
        for (const Segment& s : g.segments) {
            const auto entry = [&](int node) {
                return static_cast<std::size_t>(std::lower_bound(g.nodes.begin(), g.nodes.end(), node) - g.nodes.begin());
            };
            g.segment_ends.push_back({entry(s.a), entry(s.b)});
        }
        if (g.along_members && spec.stiffness <= 0.0) {
            // The default per pair, spread over the mean element length.
            double total = 0.0;
            for (const Segment& s : g.segments) total += s.length;
            g.stiffness *= static_cast<double>(g.segments.size()) / total;
        }
        g.first_point_id = static_cast<int>(model.nodes.size()) + points_so_far;
        points_so_far += static_cast<int>(g.segments.size()) * points_per_element;
        groups_.push_back(std::move(g));
    }
}

bool SelfContact::reaches(const Eigen::Vector2d& x, double reach, const Segment& s, SurfaceContact& out) const {
    const Eigen::Vector2d a = position(s.a), b = position(s.b);
    // Cheap rejection first: the point is farther than the reach from the segment's box.
    if (x[0] < std::min(a[0], b[0]) - reach || x[0] > std::max(a[0], b[0]) + reach ||
        x[1] < std::min(a[1], b[1]) - reach || x[1] > std::max(a[1], b[1]) + reach)
        return false;
    const Eigen::Vector2d e = b - a;
    const double xi = std::clamp((x - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
    const Eigen::Vector2d toward = x - (a + xi * e);
    const double distance = toward.norm();
    // Centre lines that meet have no normal: the crossing check stops such a run.
    if (distance - reach > 0.0 || distance <= 1e-9 * reach) return false;
    out.segment = xi <= 0.0 ? std::array<int, 2>{s.a, s.a} : xi >= 1.0 ? std::array<int, 2>{s.b, s.b} : std::array<int, 2>{s.a, s.b};
    out.xi = xi;
    out.reach = reach;
    out.gap = distance - reach;
    out.normal = toward / distance;
    return true;
}

bool SelfContact::touch(const Group& group, std::size_t p, const Segment& s, SurfaceContact& out) const {
    const int node = group.nodes[p];
    const std::vector<int>& near = group.near[p];
    if (std::binary_search(near.begin(), near.end(), s.a) || std::binary_search(near.begin(), near.end(), s.b)) return false;
    if (!reaches(position(node), group.node_half_depth[p] + s.half_depth, s, out)) return false;
    out.node = node;
    out.point = {node, node};
    out.eta = 0.0;
    out.point_id = node;
    out.stiffness = group.stiffness;
    return true;
}

bool SelfContact::touch_along(const Group& group, std::size_t own, int g, const Segment& s, SurfaceContact& out) const {
    const Segment& mine = group.segments[own];
    const double eta = gauss_eta[g];
    // The box (in reaches) first, then the neighbours along the members.
    if (!reaches((1.0 - eta) * position(mine.a) + eta * position(mine.b), mine.half_depth + s.half_depth, s, out)) return false;
    for (std::size_t end : group.segment_ends[own]) {
        const std::vector<int>& near = group.near[end];
        if (std::binary_search(near.begin(), near.end(), s.a) || std::binary_search(near.begin(), near.end(), s.b)) return false;
    }
    out.node = eta < 0.5 ? mine.a : mine.b;
    out.point = {mine.a, mine.b};
    out.eta = eta;
    out.point_id = group.first_point_id + static_cast<int>(own) * points_per_element + g;
    // Half the point's share of the element: the other surface's points make up the rest.
    out.stiffness = 0.5 * group.stiffness * gauss_weight[g] * mine.length;
    return true;
}

void SelfContact::serve_ends_once(std::vector<SurfaceContact>& found, std::size_t first) {
    // One contact per segment end, and none at an end where the point touches the interior of
    // a segment that ends there (that one is nearer or as near).
    auto end_is_served = [&](std::size_t k) {
        const SurfaceContact& ck = found[k];
        if (ck.segment[0] != ck.segment[1]) return false;
        for (std::size_t m = first; m < found.size(); ++m) {
            if (m == k) continue;
            const SurfaceContact& cm = found[m];
            if (cm.segment[0] != cm.segment[1] && (cm.segment[0] == ck.segment[0] || cm.segment[1] == ck.segment[0])) return true;
            if (cm.segment[0] == cm.segment[1] && cm.segment[0] == ck.segment[0] && m < k) return true;
        }
        return false;
    };
    std::vector<SurfaceContact> kept;
    for (std::size_t k = first; k < found.size(); ++k)
        if (!end_is_served(k)) kept.push_back(found[k]);
    found.resize(first);
    found.insert(found.end(), kept.begin(), kept.end());
}

void SelfContact::evaluate(const Eigen::VectorXd& u, bool freeze_active, double undecided_force) {
    u_ = u.data();
    std::vector<SurfaceContact> found;
    SurfaceContact c;
    for (const Group& g : groups_) {
        if (g.along_members) {
            // Each segment's box grown by its half depth: a point of one segment can touch
            // another only where their boxes overlap.
            std::vector<Eigen::Vector4d> boxes; // x_min, x_max, y_min, y_max
            for (const Segment& s : g.segments) {
                const Eigen::Vector2d a = position(s.a), b = position(s.b);
                const double h = s.half_depth;
                boxes.emplace_back(std::min(a[0], b[0]) - h, std::max(a[0], b[0]) + h, std::min(a[1], b[1]) - h, std::max(a[1], b[1]) + h);
            }
            const auto apart = [&](std::size_t i, std::size_t j) {
                return boxes[i][1] < boxes[j][0] || boxes[j][1] < boxes[i][0] || boxes[i][3] < boxes[j][2] || boxes[j][3] < boxes[i][2];
            };
            for (std::size_t own = 0; own < g.segments.size(); ++own)
                for (int p = 0; p < points_per_element; ++p) {
                    const std::size_t first = found.size();
                    for (std::size_t s = 0; s < g.segments.size(); ++s)
                        if (!apart(own, s) && touch_along(g, own, p, g.segments[s], c)) found.push_back(c);
                    serve_ends_once(found, first);
                }
            continue;
        }
        for (std::size_t p = 0; p < g.nodes.size(); ++p) {
            const std::size_t first = found.size();
            for (const Segment& s : g.segments)
                if (touch(g, p, s, c)) found.push_back(c);
            serve_ends_once(found, first);
        }
    }

    // Two segment ends that touch each other are one contact, though each pass finds it.
    {
        std::set<Key> ends;
        for (const SurfaceContact& f : found)
            if (f.nodes() == 2) ends.insert(key_of(f));
        found.erase(std::remove_if(found.begin(), found.end(),
                                   [&](const SurfaceContact& f) {
                                       return f.nodes() == 2 && f.node > f.segment[0] &&
                                              ends.count({f.segment[0], f.node, f.node});
                                   }),
                    found.end());
    }
    std::set<Key> now, before;
    for (const SurfaceContact& f : found) now.insert(key_of(f));
    for (const SurfaceContact& f : contacts_) before.insert(key_of(f));

    // A pair whose force at its gap is within the undecided band keeps its previous state.
    std::vector<SurfaceContact> acting;
    consistent_ = true;
    for (const SurfaceContact& f : found) {
        const bool was = before.count(key_of(f)) > 0;
        const bool small = undecided(f, undecided_force);
        if (freeze_active ? was : (was || !small)) {
            acting.push_back(f);
            evaluate_pair(acting.back());
        } else if (!small) {
            consistent_ = false; // a new touch the frozen set leaves out
        }
    }
    // Previous pairs that opened: kept while frozen, or while undecided, at their old kind.
    for (const SurfaceContact& f : contacts_) {
        if (now.count(key_of(f))) continue;
        SurfaceContact kept = f;
        evaluate_pair(kept);
        const bool small = undecided(kept, undecided_force);
        if (freeze_active || small) acting.push_back(kept);
        if (freeze_active && !small) consistent_ = false;
    }
    std::set<Key> after;
    for (const SurfaceContact& a : acting) after.insert(key_of(a));
    changed_ = after != before;
    contacts_ = std::move(acting);
}

} // namespace plastica
