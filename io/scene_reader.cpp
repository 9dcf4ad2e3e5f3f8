#include "scene_reader.hpp"

#include "dynamics_reader.hpp"

#include "bounded_file.hpp"
#include "member_geometry.hpp"
#include "mesh_builder.hpp"
#include "model_building.hpp"
#include "section_shapes.hpp"

#include "toml_table_reader.hpp"

#include "material/material_registry.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace plastica {

namespace {

struct Material {
    double E = 0.0;
    double density = 0.0; // mass per unit volume, for self weight
    std::optional<SteelSpec> steel;
};

class SceneBuilder {
public:
    SceneBuilder(const toml::table& root, std::string file) : root_(root), file_(std::move(file)) {}

    Model build() {
        TomlTableReader top(root_, file_, "", scene_root_table());
        read_scene_table(top);
        read_units(top);
        read_materials(top);
        read_sections(top);
        read_nodes(top);
        read_lines(top);
        read_arcs(top);
        read_elements(top);
        check_nodes(top);
        read_supports(top);
        read_loads(top);
        read_distributed_loads(top);
        read_prescribed(top);
        read_foundations(top);
        read_self_contact(top);
        read_dynamics(top, dynamics_context(), model_);
        check_released_moments();
        read_analysis(top);
        read_stages(top);
        read_report(top);
        top.finish();
        if (!model_.loaded() && !model_.has_moving_base() && !(model_.transient() && model_.dynamics.excites()))
            throw SceneError(file_, 1, "load",
                             "the scene has no [[load]], no [[distributed_load]], no [[prescribed]] displacement, no moving base "
                             "(base_motion), and no [[ground_motion]] or [[initial_velocity]] for a transient stage");
        check_patterns_driven(top);
        return std::move(model_);
    }

private:
    using Tables = std::vector<std::pair<const toml::table*, int>>;

    Tables array_of_tables(TomlTableReader& top, const std::string& key) {
        Tables out;
        const toml::node* n = top.node(key);
        if (!n) return out;
        const toml::array* a = n->as_array();
        if (!a || !a->is_array_of_tables())
            top.fail(key, "expected an array of tables, written [[" + key + "]]");
        for (const toml::node& item : *a) out.emplace_back(item.as_table(), line_of(item));
        return out;
    }

    std::string indexed(const std::string& key, std::size_t i) const {
        return key + "[" + std::to_string(i + 1) + "]";
    }

    void read_scene_table(TomlTableReader& top) {
        const toml::table* t = top.table("scene");
        if (!t) top.fail("", "missing required table [scene] (with a 'name')");
        TomlTableReader r(*t, file_, "scene", scene_table("scene"), units());
        model_.name = r.string("name");
        if (model_.name.empty() || model_.name.size() > 64 ||
            !std::all_of(model_.name.begin(), model_.name.end(), [](char c) {
                return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
            }))
            r.fail("name", "expected 1 to 64 letters, digits, '_' or '-' (it names the output folder)");
        model_.title = r.string("title");
        r.finish();
    }

    // [units]: the scene's length and force; numbers may then be written with units.
    void read_units(TomlTableReader& top) {
        const toml::table* t = top.table("units");
        if (!t) return;
        TomlTableReader r(*t, file_, "units", scene_table("units"));
        const std::string length = r.string("length"), force = r.string("force");
        try {
            units_.emplace(length, force);
        } catch (const UnitError& e) {
            r.fail(std::string(e.what()).find("length") != std::string::npos ? "length" : "force", e.what());
        }
        r.finish();
        model_.report.length_unit = length;
        model_.report.force_unit = force;
    }
    const UnitSystem* units() const { return units_ ? &*units_ : nullptr; }

    void read_materials(TomlTableReader& top) {
        const Tables list = array_of_tables(top, "material");
        for (std::size_t i = 0; i < list.size(); ++i) {
            TomlTableReader r(*list[i].first, file_, indexed("material", i), scene_table("material"), units());
            const std::string name = r.string("name");
            if (materials_.count(name)) r.fail("name", "a material named '" + name + "' exists already");
            Material m;
            m.E = r.number("E");
            m.density = r.number("density");
            if (r.has("fy")) {
                SteelSpec s;
                s.E = m.E;
                s.fy = r.number("fy");
                s.ultimate_strain = r.number("ultimate_strain");
                if (s.ultimate_strain > 0.0 && s.ultimate_strain <= s.fy / s.E)
                    r.fail("ultimate_strain", "expected 0 (never fails) or a strain above fy/E");
                // The law and the keys of its own, as the registry lists them.
                s.law = r.choice("law");
                r.choose_group(s.law);
                for (const LawParameter& p : find_material_law(s.law)->parameters) s.parameters[p.name] = r.number(p.name);
                try {
                    make_material(s, 0.0);
                } catch (const MaterialParameterError& e) {
                    r.fail(e.key, e.what());
                }
                m.steel = s;
            } else if (r.has("law")) {
                r.fail("law", "a material law needs a yield stress 'fy'");
            }
            r.finish();
            materials_[name] = m;
        }
    }

    // A key of another shape ('diameter' on a rectangle) would be read by nothing: say whose it is.
    void read_sections(TomlTableReader& top) {
        const Tables list = array_of_tables(top, "section");
        for (std::size_t i = 0; i < list.size(); ++i) {
            TomlTableReader r(*list[i].first, file_, indexed("section", i), scene_table("section"), units());
            const std::string name = r.string("name");
            if (section_index_.count(name)) r.fail("name", "a section named '" + name + "' exists already");
            const std::string material = r.string("material");
            auto m = materials_.find(material);
            if (m == materials_.end()) r.fail("material", "no [[material]] named '" + material + "'");
            const SectionShape& shape = read_section_shape(r);
            SectionSpec s = shape.build(r, {m->second.E, m->second.steel});
            if (r.has("plastic"))
                r.fail("plastic", "replaced by plasticity = \"none\" | \"hinges\" | \"distributed\"");
            // Hinges by default for an inelastic material, unless its law hardens: a plastic
            // zone follows the hardening along the member, a hinge lumps it at the end.
            const bool hardens = m->second.steel && !find_material_law(m->second.steel->law)->perfectly_plastic;
            const std::string plasticity =
                r.choice_or("plasticity", !m->second.steel ? "none" : hardens ? "distributed" : "hinges");
            if (plasticity != "none" && !m->second.steel)
                r.fail("plasticity", "an inelastic section needs a material with 'fy'");
            if (plasticity == "distributed") {
                s.plasticity = Plasticity::distributed;
                s.formulation = r.choice("formulation") == "force" ? Formulation::force : Formulation::displacement;
                if (s.formulation == Formulation::force) {
                    // Lobatto points: three integrate the elastic flexibility exactly.
                    s.integration_points = r.integer_or("integration_points", default_force_based_points);
                    if (s.integration_points < 3)
                        r.fail("integration_points", "expected a whole number from 3 to 10 for formulation = \"force\" (Gauss–Lobatto points include both ends)");
                    for (const char* key : {"segments", "segment_grading", "axial_strain"})
                        if (r.has(key)) r.fail(key, "a force-based member has no segments: its sections take the curvature their exact moments need");
                }
                else s.integration_points = r.integer_or("integration_points", default_integration_points); // one point leaves a mode without stiffness
                s.segments = r.integer("segments");
                if (r.has("segment_grading")) {
                    if (s.segments < 3) r.fail("segment_grading", "grading needs segments = 3 or more");
                    s.segment_grading = r.number("segment_grading");
                }
                if (r.has("axial_strain")) {
                    if (s.segments < 2) r.fail("axial_strain", "an axial strain per segment needs segments = 2 or more");
                    s.axial_strain_per_segment = r.choice("axial_strain") == "per_segment";
                }
            } else {
                if (r.has("integration_points"))
                    r.fail("integration_points", "only a section with plasticity = \"distributed\" has integration points");
                if (r.has("formulation"))
                    r.fail("formulation", "only a section with plasticity = \"distributed\" has a formulation");
                for (const char* key : {"segments", "segment_grading", "axial_strain"})
                    if (r.has(key)) r.fail(key, "only a section with plasticity = \"distributed\" has segments");
                s.plasticity = plasticity == "hinges" ? Plasticity::hinges : Plasticity::none;
            }
            if (s.plasticity != Plasticity::none) s.steel = m->second.steel;
            else s.fibres.clear();
            s.name = name;
            s.mass_per_length = m->second.density * s.area;
            s.rotary_inertia_per_length = m->second.density * s.inertia;
            r.finish();
            section_index_[name] = static_cast<int>(model_.sections.size());
            model_.sections.push_back(s);
        }
    }

    int section_of(TomlTableReader& r) {
        const std::string name = r.string("section");
        auto it = section_index_.find(name);
        if (it == section_index_.end()) r.fail("section", "no [[section]] named '" + name + "'");
        return it->second;
    }

    // A mesh step's refusal, located at the key that asked for it.
    template <class Step>
    auto meshed(TomlTableReader& r, const std::string& key, Step step) {
        try {
            return step();
        } catch (const MeshError& e) {
            r.fail(key, e.what());
        }
    }

    void read_nodes(TomlTableReader& top) {
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
    void read_releases(TomlTableReader& r, int first_element, int last_element) {
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

    void read_lines(TomlTableReader& top) {
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

    void read_arcs(TomlTableReader& top) {
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

    int node_by_id(TomlTableReader& r, const std::string& key, int64_t id) {
        const int* node = mesh_.node_of_id(static_cast<int>(id));
        if (!node) r.fail(key, "no [[node]] with id " + std::to_string(id));
        return *node;
    }

    void read_elements(TomlTableReader& top) {
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
    void read_self_contact(TomlTableReader& top) {
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
            if (r.has("stiffness")) spec.stiffness = r.number("stiffness");
            model_.self_contact.push_back(std::move(spec));
            r.finish();
        }
    }

    void check_nodes(TomlTableReader& top) {
        if (model_.elements.empty()) top.fail("", "the scene has no elements ([[line]], [[arc]] or [[element]])");
        meshed(top, "node", [&] { mesh_.finish(); });
    }

    // A node named by 'node = id' or by 'at = [x, y]'.
    int node_ref(TomlTableReader& r, const std::string& id_key = "node", const std::string& at_key = "at") {
        if (r.has(id_key) && r.has(at_key)) r.fail(at_key, "give either '" + id_key + "' or '" + at_key + "', not both");
        if (r.has(id_key)) return node_by_id(r, id_key, r.integer(id_key));
        if (!r.has(at_key)) r.fail("", "missing '" + at_key + "' (a point [x, y]) or '" + id_key + "' (a node id)");
        const auto p = r.point(at_key);
        return node_at(r, at_key, p);
    }
    int node_at(TomlTableReader& r, const std::string& key, const std::array<double, 2>& p) {
        if (const int k = mesh_.node_near(p); k >= 0) return k;
        std::ostringstream s;
        s << "no node at [" << p[0] << ", " << p[1] << "]";
        r.fail(key, s.str());
    }

    // The load pattern a load, pressure, prescribed displacement or moving base belongs to
    // ('pattern', default "main"), registered in Model::patterns on first use.
    int pattern_of(TomlTableReader& r) {
        const std::string name = r.string("pattern");
        if (name.empty() || name.size() > 32 ||
            !std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; }))
            r.fail("pattern", "expected 1 to 32 letters, digits, '_' or '-' (it names a curve column)");
        const auto known = std::find(model_.patterns.begin(), model_.patterns.end(), name);
        if (known != model_.patterns.end()) return static_cast<int>(known - model_.patterns.begin());
        model_.patterns.push_back(name);
        return static_cast<int>(model_.patterns.size() - 1);
    }

    // The pattern a stage drives: one with loads, pressures, prescribed displacements or a moving base.
    int driven_pattern(TomlTableReader& r) {
        const std::string name = r.string("pattern");
        const auto known = std::find(model_.patterns.begin(), model_.patterns.end(), name);
        const int p = static_cast<int>(known - model_.patterns.begin());
        // A scene with nothing to drive at all is told so once it is read (build()).
        if (!model_.loaded() && !model_.has_moving_base()) return 0;
        if (known == model_.patterns.end() || (!model_.loaded(p) && !model_.has_moving_base(p))) {
            std::string names;
            for (std::size_t k = 0; k < model_.patterns.size(); ++k)
                if (model_.loaded(static_cast<int>(k)) || model_.has_moving_base(static_cast<int>(k)))
                    names += (names.empty() ? "'" : ", '") + model_.patterns[k] + "'";
            r.fail("pattern", "no load, pressure, prescribed displacement or moving base belongs to pattern '" + name +
                                  "'" + (r.has("pattern") ? "" : " (the default)") + "; the scene's patterns: " + names);
        }
        return p;
    }

    bool supported(int node, int dof) const {
        for (const Support& s : model_.supports)
            if (s.node == node && s.fixed[dof]) return true;
        return false;
    }

    static int dof_index(TomlTableReader& r, const std::string& key, const std::string& name) {
        if (name == "ux") return 0;
        if (name == "uy") return 1;
        if (name == "rz") return 2;
        r.fail(key, "expected 'ux', 'uy' or 'rz', got '" + name + "'");
    }

    // A controlled displacement is a length, or a rotation in radians (a pure number).
    static Dimension control_dimension(const DofRef& c) { return c.dof == 2 ? dimension::none : dimension::length; }

    void read_supports(TomlTableReader& top) {
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

    void read_loads(TomlTableReader& top) {
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
    void read_distributed_loads(TomlTableReader& top) {
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
            }
            const std::map<int, std::array<double, 2>> lumped = lumped_line_load(model_, elements, {wx, wy}, gravity);
            if (!moves) r.fail("on", "every node of '" + on + "' is held: the load moves nothing");
            for (const auto& [node, f] : lumped)
                if (f[0] != 0.0 || f[1] != 0.0) model_.loads.push_back({node, {f[0], f[1], 0.0}, pattern});
            r.finish();
        }
    }

    void read_prescribed(TomlTableReader& top) {
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

    void read_foundations(TomlTableReader& top) {
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
            const bool per_length = r.boolean("per_length");
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
            for (std::size_t k = 0; k < nodes.size(); ++k) {
                const int n = nodes[k];
                FoundationSpring s;
                s.node = n;
                const double f = scale[n] * tributary[n];
                s.kx = kx * f; s.ky = ky * f; s.krot = kr * f;
                s.unilateral = unilateral || tensionless;
                s.anchored = tensionless;
                if (tensionless) s.direction = directions[k];
                s.base = base_index;
                model_.springs.push_back(s);
            }
            r.finish();
        }
    }

    // The direction a tensionless bed pushes at each node: a fixed vector, or the members' left
    // or right normal there (the mean of the adjacent elements' normals: toward the centre of a
    // counter-clockwise arc for "left_normal").
    std::vector<std::array<double, 2>> bed_directions(TomlTableReader& r, const std::vector<int>& nodes) {
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

    // Stages after [analysis]'s, each under load or displacement control toward a target on
    // either side of where the previous one ended (unload to λ = 0, reload, reverse).
    void read_stages(TomlTableReader& top) {
        const Tables list = array_of_tables(top, "stage");
        const AnalysisSpec& a = model_.analysis;
        for (std::size_t i = 0; i < list.size(); ++i) {
            TomlTableReader r(*list[i].first, file_, indexed("stage", i), scene_table("stage"), units());
            StageSpec s;
            const bool transient = r.choice("scheme") == "transient";
            // Patterns with a [[time_series]] follow it in a transient stage; the rest hold.
            s.pattern = transient && !r.has("pattern") ? (model_.stages.empty() ? a.pattern : model_.stages.back().pattern)
                                                       : driven_pattern(r);
            s.control = model_.stages.empty() ? a.control : model_.stages.back().control;
            if (r.has("control_at") || r.has("control_node")) {
                s.control = read_control(r, s.pattern);
            } else {
                for (const char* key : {"control_dof", "control_sign"})
                    if (r.has(key)) r.fail(key, "name the controlled point as well ('control_at' or 'control_node')");
            }
            const std::string scheme = r.choice("scheme");
            s.scheme = scheme == "load_control" ? Scheme::load_control
                     : scheme == "transient" ? Scheme::transient : Scheme::displacement_control;
            if (s.scheme == Scheme::transient) {
                s.transient = read_transient(r);
                check_transient_step(r, s.transient, model_);
                r.finish();
                model_.stages.push_back(s);
                continue;
            }
            for (const char* key : {"time_step", "duration", "integrator", "alpha"})
                if (r.has(key)) r.fail(key, "a key of scheme = \"transient\"");
            const Dimension controlled = control_dimension(s.control);
            s.increment = r.number("increment", s.scheme == Scheme::displacement_control ? controlled : dimension::none);
            s.adaptive = r.boolean("adaptive");
            if (r.has("target_load_factor") && r.has("target_displacement"))
                r.fail("target_displacement", "give one stop, 'target_load_factor' or 'target_displacement', not both");
            if (r.has("target_load_factor")) s.target_load_factor = r.number("target_load_factor");
            if (r.has("target_displacement")) s.target_displacement = r.number("target_displacement", controlled);
            if (!s.target_load_factor && !s.target_displacement)
                r.fail("", "missing a stop: 'target_load_factor' or 'target_displacement'");
            if (s.scheme == Scheme::load_control && s.target_displacement)
                r.fail("target_displacement", "a load-controlled stage stops at a 'target_load_factor'");
            if (s.scheme == Scheme::displacement_control && s.target_load_factor)
                r.fail("target_load_factor", "a displacement-controlled stage stops at a 'target_displacement'");
            if (s.scheme == Scheme::displacement_control) {
                const std::string named = r.has("control_at") || r.has("control_node") ? "" : " (an earlier stage or [analysis] names it)";
                for (const Support& sup : model_.supports)
                    if (sup.node == s.control.node && sup.fixed[s.control.dof])
                        r.fail("scheme", "the controlled DOF is supported" + named);
                for (const PrescribedDisplacement& p : model_.prescribed)
                    if (p.node == s.control.node && p.dof == s.control.dof)
                        r.fail("scheme", "the controlled DOF has a prescribed displacement" + named);
            }
            r.finish();
            model_.stages.push_back(s);
        }
    }

    // A moment on a node where every member end is released has nothing to carry it.
    void check_released_moments() const {
        const std::vector<bool> unattached = model_.rotation_unattached();
        for (std::size_t i = 0; i < load_lines_.size(); ++i) {
            const NodalLoad& l = model_.loads[i];
            if (l.value[2] != 0.0 && unattached[static_cast<std::size_t>(l.node)])
                throw SceneError(file_, load_lines_[i], "load[" + std::to_string(i + 1) + "].moment",
                                 "every member end at " + describe_node(l.node) +
                                     " is released, so nothing carries a moment there (hold the rotation with a support or a 'krot' spring, or release fewer ends)");
        }
    }

    // A pattern no stage drives would never act: most likely a misspelt name.
    void check_patterns_driven(TomlTableReader& top) {
        std::vector<bool> driven(model_.patterns.size(), false);
        driven[static_cast<std::size_t>(model_.analysis.pattern)] = true;
        for (const StageSpec& st : model_.stages) driven[static_cast<std::size_t>(st.pattern)] = true;
        // In time, a pattern follows its series; from t = 0, every pattern acts.
        if (model_.transient())
            for (const TimeSeriesSpec& ts : model_.dynamics.series) driven[static_cast<std::size_t>(ts.pattern)] = true;
        if (model_.analysis.scheme == Scheme::transient) std::fill(driven.begin(), driven.end(), true);
        for (std::size_t p = 0; p < driven.size(); ++p)
            if (!driven[p] && (model_.loaded(static_cast<int>(p)) || model_.has_moving_base(static_cast<int>(p))))
                top.fail("stage", "load pattern '" + model_.patterns[p] +
                                      "' is driven by neither [analysis] nor a [[stage]] ('pattern = \"" + model_.patterns[p] +
                                      "\"'), so its loads would never act");
    }

    std::string describe_node(int n) const { return mesh_.describe(n); }

    SceneContext dynamics_context() {
        SceneContext c;
        c.file = file_;
        c.units = units();
        c.node_ref = [this](TomlTableReader& r) { return node_ref(r); };
        c.members = &mesh_.member_elements();
        return c;
    }

    void read_analysis(TomlTableReader& top) {
        const toml::table* t = top.table("analysis");
        if (!t) top.fail("", "missing required table [analysis]");
        TomlTableReader r(*t, file_, "analysis", scene_table("analysis"), units());
        AnalysisSpec& a = model_.analysis;
        const std::string scheme = r.choice("scheme");
        a.scheme = scheme == "arc_length" ? Scheme::arc_length
                 : scheme == "load_control" ? Scheme::load_control
                 : scheme == "transient" ? Scheme::transient : Scheme::displacement_control;
        model_.dynamics.mass = r.choice("mass") == "lumped" ? MassKind::lumped : MassKind::consistent;
        if (a.scheme == Scheme::transient) {
            read_transient_analysis(r);
            return;
        }
        for (const char* key : {"time_step", "duration", "integrator", "alpha"})
            if (r.has(key)) r.fail(key, "a key of scheme = \"transient\"");
        // Displacement control steps the controlled DOF; load control and arc length step λ.
        const Dimension controlled = r.choice("control_dof") == "rz" ? dimension::none : dimension::length;
        const Dimension step = a.scheme == Scheme::displacement_control ? controlled : dimension::none;
        a.initial_increment = r.number("increment", step);
        a.min_increment = r.number_or("min_increment", a.initial_increment * 1e-6, step);
        a.max_increment = r.number_or("max_increment", 0.0 + a.initial_increment * 10.0, step);
        a.adaptive = r.boolean_or("adaptive", a.scheme != Scheme::load_control);
        // Fibre branches along a member settle in about three extra iterations at any step
        // size (Newton freezes them from its third iteration): a plastic zone asks for more.
        a.desired_iterations = r.integer_or("desired_iterations", model_.has_plasticity(Plasticity::distributed) ? 8 : 5);
        a.max_iterations = r.integer("max_iterations");
        if (a.max_increment > 0.0 && a.min_increment > a.max_increment)
            r.fail("min_increment", "must not exceed max_increment");
        if (a.min_increment > a.initial_increment) r.fail("min_increment", "must not exceed the first increment");
        if (r.has("max_increment") && a.max_increment < a.initial_increment)
            r.fail("max_increment", "must not be below the first increment");
        a.max_steps = r.integer("max_steps");
        a.residual_tolerance_follows_floor = !r.has("residual_tolerance");
        a.residual_tolerance = r.number_or("residual_tolerance", AnalysisSpec::default_residual_tolerance);
        a.displacement_tolerance = r.number("displacement_tolerance");
        a.allow_crossing = r.boolean("allow_crossing");
        if (r.has("target_load_factor") && r.has("target_displacement"))
            r.fail("target_displacement", "give one stop, 'target_load_factor' or 'target_displacement', not both");
        if (r.has("target_load_factor"))
            a.target_load_factor = r.number("target_load_factor"); // a load the other way: reverse the [[load]]
        if (r.has("target_displacement")) a.target_displacement = r.number("target_displacement", controlled);
        a.pattern = driven_pattern(r);
        if (r.has("control_at") || r.has("control_node")) {
            a.control = read_control(r, a.pattern);
        } else if (a.scheme == Scheme::displacement_control || a.target_displacement) {
            r.fail("", "missing 'control_at' (the point whose displacement controls or stops the analysis)");
        } else if (const auto first = std::find_if(model_.loads.begin(), model_.loads.begin() + nodal_loads_,
                                                   [&](const NodalLoad& l) { return l.pattern == a.pattern; });
                   first != model_.loads.begin() + nodal_loads_) {
            a.control.node = first->node; // report the first load's point
            a.control.dof = 1;
        } else if (model_.prescribed.empty() && (!model_.loads.empty() || !model_.pressures.empty())) {
            r.fail("", "missing 'control_at': a scene loaded only by [[distributed_load]]s names the point whose displacement it reports");
        }
        if (!a.target_load_factor && !a.target_displacement)
            r.fail("", "missing a stop: 'target_load_factor' or 'target_displacement'");
        for (const Support& s : model_.supports)
            if (a.scheme == Scheme::displacement_control && s.node == a.control.node && s.fixed[a.control.dof])
                r.fail("control_dof", "the controlled DOF is supported");
        for (const PrescribedDisplacement& p : model_.prescribed)
            if (a.scheme == Scheme::displacement_control && p.node == a.control.node && p.dof == a.control.dof)
                r.fail("control_dof", "the controlled DOF has a prescribed displacement");
        // Nothing to solve when every DOF is held.
        std::vector<bool> held(static_cast<std::size_t>(model_.dof_count()), false);
        for (const Support& s : model_.supports)
            for (int d = 0; d < dofs_per_node; ++d)
                if (s.fixed[d]) held[static_cast<std::size_t>(dofs_per_node * s.node + d)] = true;
        for (const PrescribedDisplacement& p : model_.prescribed)
            held[static_cast<std::size_t>(dofs_per_node * p.node + p.dof)] = true;
        if (std::all_of(held.begin(), held.end(), [](bool h) { return h; }))
            r.fail("", "every degree of freedom is supported or prescribed: nothing can move (see the [[support]] tables)");
        r.finish();
    }

    // [analysis] scheme = "transient": the structure moves from rest (or its initial
    // velocities) at t = 0; patterns with a [[time_series]] follow it, the others act at factor 1.
    void read_transient_analysis(TomlTableReader& r) {
        AnalysisSpec& a = model_.analysis;
        a.transient = read_transient(r);
        check_transient_step(r, a.transient, model_);
        a.max_iterations = r.integer("max_iterations");
        a.max_steps = std::max(r.integer("max_steps"), static_cast<int>(std::ceil(a.transient.duration / a.transient.time_step - 1e-9)) + 1);
        a.residual_tolerance_follows_floor = !r.has("residual_tolerance");
        a.residual_tolerance = r.number_or("residual_tolerance", AnalysisSpec::default_residual_tolerance);
        a.displacement_tolerance = r.number("displacement_tolerance");
        a.allow_crossing = r.boolean("allow_crossing");
        a.pattern = r.has("pattern") ? driven_pattern(r) : 0;
        if (r.has("control_at") || r.has("control_node")) {
            a.control = read_control(r, a.pattern);
        } else if (!model_.loads.empty()) {
            a.control.node = model_.loads.front().node;
        } else if (!model_.dynamics.initial_velocities.empty()) {
            a.control.node = model_.dynamics.initial_velocities.front().node;
        }
        r.finish();
    }

    // A controlled (and reported) DOF: 'control_at' or 'control_node', 'control_dof' (default
    // "uy") and 'control_sign'. The displacement runs with the driven pattern's load on that DOF:
    // by default its sign is the load's, and a sign against the load is refused.
    DofRef read_control(TomlTableReader& r, int pattern) {
        DofRef c;
        c.node = node_ref(r, "control_node", "control_at");
        c.dof = dof_index(r, "control_dof", r.choice("control_dof"));
        double load_on_control = 0.0;
        for (const NodalLoad& l : model_.loads)
            if (l.node == c.node && l.pattern == pattern) load_on_control += l.value[c.dof];
        const double along_load = load_on_control < 0.0 ? -1.0 : 1.0;
        c.sign = along_load;
        if (r.has("control_sign")) {
            const double sign = r.number("control_sign");
            if (sign != 1.0 && sign != -1.0) r.fail("control_sign", "expected 1 or -1");
            if (load_on_control != 0.0 && sign != along_load)
                r.fail("control_sign", "the load on the controlled DOF points the other way: with control_sign = " +
                                           std::string(sign > 0 ? "1" : "-1") + " the structure would be pushed against it; use " +
                                           std::string(along_load > 0 ? "1" : "-1") + " (or leave it out)");
            c.sign = sign;
        }
        return c;
    }

    void read_report(TomlTableReader& top) {
        const toml::table* t = top.table("report");
        // Loads in more than one direction have no total an engineer would call the load:
        // then the load factor is reported, and labelled so.
        const bool parallel = model_.loads_parallel();
        infer_report_measure(model_);
        if (!t) return;
        TomlTableReader r(*t, file_, "report", scene_table("report"), units());
        if (r.has("load")) {
            const std::string measure = r.choice("load");
            if (measure == "total" && !parallel)
                r.fail("load", "the loads are not parallel, so their total has no direction: report the load factor (load = \"factor\")");
            if (measure == "factor") {
                model_.report.measure = ReportSpec::Measure::factor;
                model_.report.load_label = "load factor";
            } else if (model_.report.measure != ReportSpec::Measure::platen) {
                model_.report.measure = ReportSpec::Measure::total;
            }
        }
        model_.report.load_scale = r.number("load_scale");
        model_.report.load_label = r.string_or("load_label", model_.report.load_label);
        model_.report.displacement_label = r.string_or("displacement_label", model_.report.displacement_label);
        model_.report.exact = r.choice_or("exact", "");
        if (r.has("mirror_x")) model_.report.mirror_x = r.number("mirror_x");
        for (const auto& [key, unit] : {std::pair{"length_unit", &model_.report.length_unit}, std::pair{"force_unit", &model_.report.force_unit}}) {
            *unit = r.string_or(key, *unit); // [units] names them unless [report] relabels
            if (unit->size() > 16 || unit->find_first_of("\n\r\t") != std::string::npos)
                r.fail(key, "expected a short unit name such as \"mm\" or \"kN\"");
        }
        if (model_.report.exact == "cantilever_tip_load" && !is_cantilever_with_tip_load(model_))
            r.fail("exact", "cantilever_tip_load is the closed form of a straight elastic cantilever, clamped at one end, "
                            "with one transverse load at the other and nothing else; this scene is not one");
        if (model_.report.mirror_x) {
            // A half model lies on one side of its symmetry line.
            const double x0 = *model_.report.mirror_x, tol = 1e-9 * mesh_.size_scale();
            bool left = false, right = false;
            for (const Node& n : model_.nodes) left = left || n.x < x0 - tol, right = right || n.x > x0 + tol;
            if (left && right) r.fail("mirror_x", "the structure lies on both sides of this line: a half model lies on one side");
        }
        r.finish();
    }

    const toml::table& root_;
    std::string file_;
    Model model_;
    std::optional<UnitSystem> units_;
    std::map<std::string, Material> materials_;
    std::map<std::string, int> section_index_;
    MeshBuilder mesh_{model_, max_elements};
    std::vector<int> load_lines_; // of each [[load]], in order
    int nodal_loads_ = 0;                                     // [[load]]s, ahead of the lumped ones
};

} // namespace

Model read_scene_text(const std::string& text, const std::string& name_for_errors) {
    toml::table root;
    try {
        root = toml::parse(text, name_for_errors);
    } catch (const toml::parse_error& e) {
        throw SceneError(name_for_errors, static_cast<int>(e.source().begin.line), "",
                         std::string(e.description()));
    }
    return read_scene_table(root, name_for_errors);
}

Model read_scene_table(const toml::table& root, const std::string& name_for_errors) {
    Model m = SceneBuilder(root, name_for_errors).build();
    m.source = name_for_errors;
    return m;
}

Model read_scene(const std::string& path) {
    std::string text;
    try {
        text = read_bounded_file(path, scene_file_limit);
    } catch (const FileReadError& e) {
        throw SceneError(path, 0, "", std::string("cannot read the scene file: ") + e.what());
    }
    return read_scene_text(text, path);
}

} // namespace plastica
