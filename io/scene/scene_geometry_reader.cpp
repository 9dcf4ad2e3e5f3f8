// The scene's geometry: [[node]]s, [[line]]s, [[arc]]s, [[element]]s, member-end releases,
// [[self_contact]], and the nodes the other tables name (io/scene/scene_builder.hpp).
#include "scene_builder.hpp"

#include "dynamics_reader.hpp"
#include "member_geometry.hpp"
#include "model_building.hpp"
#include "section_shapes.hpp"

#include "material/material_registry.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace plastica::detail {

void SceneBuilder::read_nodes(TomlTableReader& top) {
    const Tables list = array_of_tables(top, "node");
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, file_, indexed("node", i), scene_table("node"), units());
        const int id = r.integer("id");
        const double x = r.number("x"), y = r.number("y");
        meshed(r, "id", [&] { return mesh_.explicit_node(id, x, y); });
        r.finish();
    }
}

// 'releases = ["start", "end"]': moment releases at the member's first and last node.
void SceneBuilder::read_releases(TomlTableReader& r, int first_element, int last_element) {
    const toml::array* list = r.array("releases");
    if (!list) return;
    for (const toml::node& item : *list) {
        const std::optional<std::string> end = item.value<std::string>();
        if (!end || (*end != "start" && *end != "end"))
            r.fail("releases", "expected a list of \"start\" and \"end\" (the member's first and last node)");
        if (*end == "start") model_.elements[static_cast<std::size_t>(first_element)].released[0] = true;
        else model_.elements[static_cast<std::size_t>(last_element)].released[1] = true;
    }
}

void SceneBuilder::read_lines(TomlTableReader& top) {
    const Tables list = array_of_tables(top, "line");
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, file_, indexed("line", i), scene_table("line"), units());
        const std::string name = r.string_or("name", "line" + std::to_string(i + 1));
        const auto a = r.point("start");
        const auto b = r.point("end");
        const int n = r.integer("elements");
        const int section = section_of(r);
        if (std::hypot(b[0] - a[0], b[1] - a[1]) <= 0.0) r.fail("end", "a line needs a positive length (start and end coincide)");
        mesh_.enlarge(std::max({std::abs(a[0]), std::abs(a[1]), std::abs(b[0]), std::abs(b[1])}));
        const auto [first, last] = meshed(r, "elements", [&] { return mesh_.add_member(name, line_points(a, b, n), section); });
        read_releases(r, first, last);
        r.finish();
    }
}

void SceneBuilder::read_arcs(TomlTableReader& top) {
    const Tables list = array_of_tables(top, "arc");
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, file_, indexed("arc", i), scene_table("arc"), units());
        const std::string name = r.string_or("name", "arc" + std::to_string(i + 1));
        const auto c = r.point("center");
        const double R = r.number("radius");
        const double a0 = r.number("start_angle");
        const double a1 = r.number("end_angle");
        const int n = r.integer("elements");
        const int section = section_of(r);
        if (std::abs(a1 - a0) <= 0.0 || std::abs(a1 - a0) > 360.0)
            r.fail("end_angle", "expected an arc of more than 0 and at most 360 degrees");
        mesh_.enlarge(std::max(std::abs(c[0]) + R, std::abs(c[1]) + R));
        const auto [first, last] = meshed(r, "elements", [&] { return mesh_.add_member(name, arc_points(c, R, a0, a1, n), section); });
        read_releases(r, first, last);
        r.finish();
    }
}

int SceneBuilder::node_by_id(TomlTableReader& r, const std::string& key, int64_t id) {
    const int* node = mesh_.node_of_id(static_cast<int>(id));
    if (!node) r.fail(key, "no [[node]] with id " + std::to_string(id));
    return *node;
}

void SceneBuilder::read_elements(TomlTableReader& top) {
    const Tables list = array_of_tables(top, "element");
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, file_, indexed("element", i), scene_table("element"), units());
        const toml::array* a = r.array("nodes");
        if (!a || a->size() != 2 || !(*a)[0].is_integer() || !(*a)[1].is_integer())
            r.fail("nodes", "expected two node ids, e.g. nodes = [1, 2]");
        const int n0 = node_by_id(r, "nodes", *(*a)[0].value<int64_t>());
        const int n1 = node_by_id(r, "nodes", *(*a)[1].value<int64_t>());
        const int section = section_of(r);
        meshed(r, "nodes", [&] { mesh_.add_element(n0, n1, section); });
        const int added = static_cast<int>(model_.elements.size()) - 1;
        read_releases(r, added, added);
        r.finish();
    }
}

// [[self_contact]]: on = "all", a member's name or a list of them; stiffness optional.
void SceneBuilder::read_self_contact(TomlTableReader& top) {
    const Tables list = array_of_tables(top, "self_contact");
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, file_, indexed("self_contact", i), scene_table("self_contact"), units());
        std::vector<std::string> names;
        const toml::node* on = r.node("on");
        if (const toml::array* a = on ? on->as_array() : nullptr) {
            for (const toml::node& n : *a) {
                if (!n.is_string()) r.fail("on", "expected \"all\", a member's name or a list of names");
                names.push_back(*n.value<std::string>());
            }
            if (names.empty()) r.fail("on", "expected at least one member's name");
        } else {
            if (on && !on->is_string()) r.fail("on", "expected \"all\", a member's name or a list of names");
            names.push_back(on ? *on->value<std::string>() : "all");
        }
        SelfContactSpec spec;
        std::vector<bool> taken(model_.elements.size(), false);
        for (const std::string& name : names) {
            if (name == "all") {
                std::fill(taken.begin(), taken.end(), true);
                continue;
            }
            auto g = mesh_.member_elements().find(name);
            if (g == mesh_.member_elements().end()) {
                std::string known;
                for (const auto& m : mesh_.member_elements()) known += (known.empty() ? "'" : ", '") + m.first + "'";
                r.fail("on", "expected \"all\" or the name of a [[line]] or [[arc]], got '" + name + "'" +
                                 (known.empty() ? "" : "; the members: " + known));
            }
            for (int e : g->second) taken[static_cast<std::size_t>(e)] = true;
        }
        for (std::size_t e = 0; e < taken.size(); ++e)
            if (taken[e]) spec.elements.push_back(static_cast<int>(e));
        spec.along_members = r.choice("acts_on") == "members";
        if (r.has("stiffness")) spec.stiffness = r.number("stiffness", spec.along_members ? dimension::stress : dimension::force_per_length);
        model_.self_contact.push_back(std::move(spec));
        r.finish();
    }
}

void SceneBuilder::check_nodes(TomlTableReader& top) {
    if (model_.elements.empty()) top.fail("", "the scene has no elements ([[line]], [[arc]] or [[element]])");
    meshed(top, "node", [&] { mesh_.finish(); });
}

// A node named by 'node = id' or by 'at = [x, y]'.
int SceneBuilder::node_ref(TomlTableReader& r, const std::string& id_key, const std::string& at_key) {
    if (r.has(id_key) && r.has(at_key)) r.fail(at_key, "give either '" + id_key + "' or '" + at_key + "', not both");
    if (r.has(id_key)) return node_by_id(r, id_key, r.integer(id_key));
    if (!r.has(at_key)) r.fail("", "missing '" + at_key + "' (a point [x, y]) or '" + id_key + "' (a node id)");
    const auto p = r.point(at_key);
    return node_at(r, at_key, p);
}

int SceneBuilder::node_at(TomlTableReader& r, const std::string& key, const std::array<double, 2>& p) {
    if (const int k = mesh_.node_near(p); k >= 0) return k;
    std::ostringstream s;
    s << "no node at [" << p[0] << ", " << p[1] << "]";
    r.fail(key, s.str());
}

} // namespace plastica::detail
