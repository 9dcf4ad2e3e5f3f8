// The scene's supports, loads, prescribed displacements and foundations (io/scene/scene_builder.hpp).
#include "scene_builder.hpp"

#include "dynamics_reader.hpp"
#include "member_geometry.hpp"
#include "model_building.hpp"
#include "section_shapes.hpp"

#include "material/material_registry.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace plastica::detail {

bool SceneBuilder::supported(int node, int dof) const {
    for (const Support& s : model_.supports)
        if (s.node == node && s.fixed[dof]) return true;
    return false;
}

int SceneBuilder::dof_index(TomlTableReader& r, const std::string& key, const std::string& name) {
    if (name == "ux") return 0;
    if (name == "uy") return 1;
    if (name == "rz") return 2;
    r.fail(key, "expected 'ux', 'uy' or 'rz', got '" + name + "'");
}

void SceneBuilder::read_supports(TomlTableReader& top) {
    const Tables list = array_of_tables(top, "support");
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, file_, indexed("support", i), scene_table("support"), units());
        Support s;
        s.node = node_ref(r);
        const toml::array* fix = r.array("fix");
        if (!fix || fix->empty()) r.fail("fix", "expected a list of DOFs, e.g. fix = [\"ux\", \"uy\"]");
        for (const toml::node& f : *fix) {
            if (!f.is_string()) r.fail("fix", "expected DOF names 'ux', 'uy', 'rz'");
            s.fixed[dof_index(r, "fix", *f.value<std::string>())] = true;
        }
        r.finish();
        model_.supports.push_back(s);
    }
}

void SceneBuilder::read_loads(TomlTableReader& top) {
    const Tables list = array_of_tables(top, "load");
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, file_, indexed("load", i), scene_table("load"), units());
        NodalLoad l;
        l.node = node_ref(r);
        l.value = {r.number("fx"), r.number("fy"), r.number("moment")};
        l.pattern = pattern_of(r);
        if (l.value[0] == 0.0 && l.value[1] == 0.0 && l.value[2] == 0.0)
            r.fail("", "a load needs a non-zero 'fx', 'fy' or 'moment'");
        bool moves = false;
        for (int d = 0; d < dofs_per_node; ++d) moves = moves || (l.value[d] != 0.0 && !supported(l.node, d));
        if (!moves) r.fail("", "the load acts only on supported DOFs of the node at " + describe_node(l.node) + ": it moves nothing");
        load_lines_.push_back(list[i].second);
        r.finish();
        model_.loads.push_back(l);
    }
}

// Line loads per unit initial length in a fixed direction (and self weight, ρA·g) are lumped
// half to each end of every element; pressure follows the deformed members (FollowerPressure).
void SceneBuilder::read_distributed_loads(TomlTableReader& top) {
    nodal_loads_ = static_cast<int>(model_.loads.size());
    const Tables list = array_of_tables(top, "distributed_load");
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, file_, indexed("distributed_load", i), scene_table("distributed_load"), units());
        const std::string on = r.string("on");
        std::vector<int> elements;
        if (on == "all") {
            for (std::size_t e = 0; e < model_.elements.size(); ++e) elements.push_back(static_cast<int>(e));
        } else {
            auto g = mesh_.member_elements().find(on);
            if (g == mesh_.member_elements().end()) r.fail("on", "expected 'all' or the name of a [[line]] or [[arc]], got '" + on + "'");
            elements = g->second;
        }
        const double wx = r.number("wx"), wy = r.number("wy");
        const double pressure = r.number("pressure"); // per unit length of member
        std::array<double, 2> gravity{0.0, 0.0};
        if (r.has("gravity")) {
            gravity = r.point("gravity");
            for (int e : elements)
                if (model_.sections[model_.elements[e].section].mass_per_length <= 0.0)
                    r.fail("gravity", "self weight needs the material's 'density' (section '" +
                                          model_.sections[model_.elements[e].section].name + "' has none)");
        }
        if (wx == 0.0 && wy == 0.0 && pressure == 0.0 && gravity[0] == 0.0 && gravity[1] == 0.0)
            r.fail("", "a distributed load needs a non-zero 'wx', 'wy', 'pressure' or 'gravity'");
        const int pattern = pattern_of(r);
        bool moves = false;
        for (int e : elements) {
            const ElementSpec& el = model_.elements[e];
            for (int node : {el.node_i, el.node_j}) moves = moves || !supported(node, 0) || !supported(node, 1);
            if (pressure != 0.0) model_.pressures.push_back({e, pressure, pattern});
            if (wx != 0.0 || wy != 0.0) model_.line_loads.push_back({e, wx, wy, pattern});
        }
        const std::map<int, std::array<double, 2>> lumped = lumped_line_load(model_, elements, {wx, wy}, gravity);
        if (!moves) r.fail("on", "every node of '" + on + "' is held: the load moves nothing");
        for (const auto& [node, f] : lumped)
            if (f[0] != 0.0 || f[1] != 0.0) model_.loads.push_back({node, {f[0], f[1], 0.0}, pattern});
        r.finish();
    }
}

void SceneBuilder::read_prescribed(TomlTableReader& top) {
    const Tables list = array_of_tables(top, "prescribed");
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, file_, indexed("prescribed", i), scene_table("prescribed"), units());
        PrescribedDisplacement p;
        p.node = node_ref(r);
        p.dof = dof_index(r, "dof", r.choice("dof"));
        p.value = r.number("value", p.dof == 2 ? dimension::none : dimension::length); // a rotation in radians
        p.pattern = pattern_of(r);
        if (supported(p.node, p.dof))
            r.fail("dof", "this DOF is also supported ([[support]] fix): a prescribed displacement replaces the support there; remove it from 'fix'");
        r.finish();
        model_.prescribed.push_back(p);
    }
}

void SceneBuilder::read_foundations(TomlTableReader& top) {
    const Tables list = array_of_tables(top, "foundation");
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, file_, indexed("foundation", i), scene_table("foundation"), units());
        const std::string kind = r.choice("kind");
        const bool unilateral = kind == "unilateral", tensionless = kind == "tensionless";
        std::vector<int> nodes;
        const std::string on = r.string_or("on", "");
        if (!on.empty()) {
            if (on == "all") {
                for (std::size_t k = 0; k < model_.nodes.size(); ++k) nodes.push_back(static_cast<int>(k));
            } else {
                auto g = mesh_.member_nodes().find(on);
                if (g == mesh_.member_nodes().end()) r.fail("on", "expected 'all' or the name of a [[line]] or [[arc]], got '" + on + "'");
                nodes = g->second;
            }
        }
        if (const toml::array* a = r.array("at")) {
            for (const toml::node& p : *a) {
                const toml::array* xy = p.as_array();
                if (!xy) r.fail("at", "expected a list of points [[x, y], …]");
                nodes.push_back(node_at(r, "at", r.point_in(p, "at", dimension::length)));
            }
        }
        if (r.has("below")) {
            // Keeps only the selected nodes whose initial height is at most this value.
            const double limit = r.number("below");
            if (nodes.empty()) r.fail("below", "'below' filters the nodes chosen by 'on' or 'at'");
            std::vector<int> kept;
            for (int n : nodes)
                if (model_.nodes[n].y <= limit) kept.push_back(n);
            nodes = kept;
            if (nodes.empty()) r.fail("below", "no selected node lies at or below this height");
        }
        if (nodes.empty()) r.fail("on", "a foundation needs nodes: 'on' (\"all\" or a generator name) or 'at'");
        std::vector<double> scale(model_.nodes.size(), 1.0);
        if (const toml::array* a = r.array("halve_at")) {
            for (const toml::node& p : *a) {
                const toml::array* xy = p.as_array();
                if (!xy) r.fail("halve_at", "expected a list of points [[x, y], …]");
                scale[node_at(r, "halve_at", r.point_in(p, "halve_at", dimension::length))] = 0.5;
            }
        }
        // Springs at nodes (force per length, moment per radian) or per unit length of member.
        const bool along_members = r.choice("acts_on") == "members";
        if (along_members) {
            if (!unilateral) r.fail("acts_on", "only a unilateral base acts along the members (kind = \"unilateral\")");
            for (const char* key : {"halve_at", "kx", "krot", "per_length"})
                if (r.has(key))
                    r.fail(key, std::string("a base acting along the members takes 'ky' per unit length alone; '") + key +
                                    "' belongs to springs at nodes (acts_on = \"nodes\")");
        }
        const bool per_length = along_members || r.boolean("per_length");
        const Dimension k_dimension = per_length ? dimension::stress : dimension::force_per_length;
        const Dimension krot_dimension = per_length ? dimension::force : dimension::moment;
        const double kx = r.number("kx", k_dimension), ky = r.number("ky", k_dimension);
        const double kr = r.number("krot", krot_dimension);
        if (unilateral && !(ky > 0.0)) r.fail("ky", "a unilateral base needs a positive normal stiffness 'ky'");
        if (tensionless && !(ky > 0.0)) r.fail("ky", "a tensionless bed needs a positive stiffness 'ky' along its 'direction'");
        if (tensionless && (kx != 0.0 || kr != 0.0))
            r.fail(kx != 0.0 ? "kx" : "krot", "a tensionless bed pushes along its 'direction' only, with stiffness 'ky'");
        if (!tensionless && r.has("direction"))
            r.fail("direction", "a direction belongs to a tensionless bed (kind = \"tensionless\")");
        if (!unilateral && kx == 0.0 && ky == 0.0 && kr == 0.0) r.fail("ky", "a foundation needs a positive kx, ky or krot");
        const std::vector<double> tributary = per_length ? tributary_lengths(model_) : std::vector<double>(model_.nodes.size(), 1.0);
        int base_index = 0;
        if (unilateral) {
            BaseLine base;
            double lowest = 1e300;
            for (int n : nodes) lowest = std::min(lowest, model_.nodes[n].y);
            base.point = r.has("base_point") ? r.point("base_point") : std::array<double, 2>{0.0, lowest};
            base.normal = r.has("base_normal") ? r.point("base_normal") : std::array<double, 2>{0.0, 1.0};
            const double nn = std::hypot(base.normal[0], base.normal[1]);
            if (!(nn > 0.0)) r.fail("base_normal", "expected a non-zero vector");
            base.normal = {base.normal[0] / nn, base.normal[1] / nn};
            // A platen: the base moves by λ·base_motion (the load factor drives it).
            if (r.has("base_motion")) base.motion = r.point("base_motion");
            if (r.has("pattern") && !base.moves()) r.fail("pattern", "a pattern drives a moving base ('base_motion')");
            if (base.moves()) base.pattern = pattern_of(r);
            // Foundations on the same line share it; another line is another base.
            const auto same = std::find_if(model_.bases.begin(), model_.bases.end(), [&](const BaseLine& b) {
                return b.point == base.point && b.normal == base.normal && b.motion == base.motion && b.pattern == base.pattern;
            });
            base_index = static_cast<int>(same - model_.bases.begin());
            if (same == model_.bases.end()) model_.bases.push_back(base);
            std::string inside;
            for (int n : nodes)
                if (base.gap(model_.nodes[n].x, model_.nodes[n].y, 0.0) < -1e-9 * mesh_.size_scale())
                    inside += (inside.empty() ? "" : ", ") + describe_node(n);
            if (!inside.empty()) r.fail("base_point", "the structure already penetrates the base at " + inside);
        } else {
            for (const char* key : {"base_point", "base_normal", "base_motion", "pattern"})
                if (r.has(key)) r.fail(key, "a base line belongs to a unilateral foundation (kind = \"unilateral\")");
        }
        const std::vector<std::array<double, 2>> directions = tensionless ? bed_directions(r, nodes) : std::vector<std::array<double, 2>>{};
        std::map<int, int> spring_of; // node → its spring of this foundation
        for (std::size_t k = 0; k < nodes.size(); ++k) {
            const int n = nodes[k];
            if (along_members && spring_of.count(n)) continue; // selected twice ('on' and 'at')
            spring_of[n] = static_cast<int>(model_.springs.size());
            FoundationSpring s;
            s.node = n;
            const double f = scale[n] * tributary[n];
            s.kx = kx * f; s.ky = ky * f; s.krot = kr * f;
            s.unilateral = unilateral || tensionless;
            s.anchored = tensionless;
            if (tensionless) s.direction = directions[k];
            s.base = base_index;
            s.along_members = along_members;
            model_.springs.push_back(s);
        }
        if (along_members) add_base_edges(r, spring_of, ky);
        r.finish();
    }
}

// The members whose both ends a base acting along the members holds, each with its penalty per
// unit length and the initial direction of its centre line at both nodes: where a neighbour in
// the selection continues it within 30° (the chords of an arc), the mean of the two chords, so
// the curve the contact sees is the arc's; else its own chord.
void SceneBuilder::add_base_edges(TomlTableReader& r, const std::map<int, int>& spring_of, double ky) {
    std::vector<std::size_t> bearing;
    std::vector<std::vector<std::size_t>> at_node(model_.nodes.size());
    for (std::size_t e = 0; e < model_.elements.size(); ++e) {
        const ElementSpec& el = model_.elements[e];
        if (!spring_of.count(el.node_i) || !spring_of.count(el.node_j)) continue;
        bearing.push_back(e);
        at_node[el.node_i].push_back(e);
        at_node[el.node_j].push_back(e);
    }
    if (bearing.empty()) r.fail("acts_on", "no member has both its ends among the selected nodes");
    auto chord = [&](std::size_t e) {
        const ElementSpec& el = model_.elements[e];
        const Node &a = model_.nodes[el.node_i], &b = model_.nodes[el.node_j];
        return Eigen::Vector2d(b.x - a.x, b.y - a.y);
    };
    // The direction at `node` of member e (pointing from i to j), continued by its neighbour.
    auto tangent_at = [&](std::size_t e, int node) {
        const Eigen::Vector2d own = chord(e).normalized();
        if (at_node[node].size() != 2) return own;
        const std::size_t other = at_node[node][0] == e ? at_node[node][1] : at_node[node][0];
        const ElementSpec& o = model_.elements[other];
        const ElementSpec& el = model_.elements[e];
        // The neighbour runs on through the node in e's direction where it ends where e starts.
        const bool same_sense = (o.node_j == node) == (el.node_i == node);
        const Eigen::Vector2d continued = (same_sense ? 1.0 : -1.0) * chord(other).normalized();
        if (own.dot(continued) < std::cos(M_PI / 6.0)) return own;
        return Eigen::Vector2d((own + continued).normalized());
    };
    for (std::size_t e : bearing) {
        const ElementSpec& el = model_.elements[e];
        BaseEdge edge;
        edge.spring = {spring_of.at(el.node_i), spring_of.at(el.node_j)};
        edge.stiffness = ky;
        edge.length = chord(e).norm();
        for (int end = 0; end < 2; ++end) {
            const Eigen::Vector2d t = tangent_at(e, end == 0 ? el.node_i : el.node_j);
            edge.tangent_angle[static_cast<std::size_t>(end)] = std::atan2(t[1], t[0]);
        }
        edge.straight = el.released[0] || el.released[1];
        model_.base_edges.push_back(edge);
    }
}

// The direction a tensionless bed pushes at each node: a fixed vector, or the members' left
// or right normal there (the mean of the adjacent elements' normals: toward the centre of a
// counter-clockwise arc for "left_normal").
std::vector<std::array<double, 2>> SceneBuilder::bed_directions(TomlTableReader& r, const std::vector<int>& nodes) {
    std::vector<std::array<double, 2>> out(nodes.size(), {0.0, 1.0});
    const toml::node* given = r.has("direction") ? r.node("direction") : nullptr;
    if (given && given->is_array()) {
        std::array<double, 2> d = r.point("direction");
        const double length = std::hypot(d[0], d[1]);
        if (!(length > 0.0)) r.fail("direction", "expected a non-zero vector");
        std::fill(out.begin(), out.end(), std::array<double, 2>{d[0] / length, d[1] / length});
        return out;
    }
    if (!given) return out;
    const std::string side = r.choice("direction");
    const double sign = side == "left_normal" ? 1.0 : -1.0;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        const std::optional<std::array<double, 2>> normal = member_normal(model_, nodes[k]);
        if (!normal) r.fail("direction", "the members at " + describe_node(nodes[k]) + " have no one normal");
        out[k] = {sign * (*normal)[0], sign * (*normal)[1]};
    }
    return out;
}

// A moment on a node where every member end is released has nothing to carry it.
void SceneBuilder::check_released_moments() const {
    const std::vector<bool> unattached = model_.rotation_unattached();
    for (std::size_t i = 0; i < load_lines_.size(); ++i) {
        const NodalLoad& l = model_.loads[i];
        if (l.value[2] != 0.0 && unattached[static_cast<std::size_t>(l.node)])
            throw SceneError(file_, load_lines_[i], "load[" + std::to_string(i + 1) + "].moment",
                             "every member end at " + describe_node(l.node) +
                                 " is released, so nothing carries a moment there (hold the rotation with a support or a 'krot' spring, or release fewer ends)");
    }
}

} // namespace plastica::detail
