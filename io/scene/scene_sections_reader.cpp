// The scene's [units], [[material]]s and [[section]]s (io/scene/scene_builder.hpp).
#include "scene_builder.hpp"

#include "dynamics_reader.hpp"
#include "member_geometry.hpp"
#include "model_building.hpp"
#include "section_shapes.hpp"

#include "material/material_registry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace plastica::detail {

namespace {
// Keys that only a displacement-based member has: giving one chooses that formulation.
constexpr std::array<const char*, 3> displacement_only_keys{"segments", "segment_grading", "axial_strain"};
} // namespace

// [units]: the scene's length and force; numbers may then be written with units.
void SceneBuilder::read_units(TomlTableReader& top) {
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

void SceneBuilder::read_materials(TomlTableReader& top) {
    const Tables list = array_of_tables(top, "material");
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, file_, indexed("material", i), scene_table("material"), units());
        const std::string name = r.string("name");
        if (materials_.count(name)) r.fail("name", "a material named '" + name + "' exists already");
        Material m;
        m.density = r.number("density");
        if (r.has("fy") || r.has("law")) {
            SteelSpec s;
            // The law and the keys of its own, as the registry lists them.
            s.law = r.choice("law");
            r.choose_group(s.law);
            const MaterialLaw& law = *find_material_law(s.law);
            for (const LawParameter& p : law.parameters) s.parameters[p.name] = r.number(p.name);
            if (std::string(law.strength) == "fy") {
                if (!r.has("fy")) r.fail("law", "a material law needs a yield stress 'fy'");
                s.E = r.number("E");
                s.fy = r.number("fy");
            } else {
                // A strength of its own (concrete's fc): E, when given, is the initial slope.
                if (r.has("fy")) r.fail("fy", "a " + s.law + " material's strength is '" + law.strength + "'");
                s.fy = s.parameters.at(law.strength);
                if (r.has("E")) {
                    if (r.has("n")) r.fail("n", "E sets n = E·eps_c2/fc: give one of them");
                    s.E = r.number("E");
                    s.parameters["n"] = s.E * s.parameters.at("eps_c2") / s.fy;
                    if (s.parameters["n"] < 1.0) r.fail("E", "expected at least fc/eps_c2 (a parabola of exponent n ≥ 1)");
                } else {
                    s.E = s.parameters.at("n") * s.fy / s.parameters.at("eps_c2");
                }
            }
            s.ultimate_strain = r.number("ultimate_strain");
            if (s.ultimate_strain > 0.0 && std::string(law.strength) != "fy")
                r.fail("ultimate_strain", "a " + s.law + " material's strain limit is eps_cu2");
            if (s.ultimate_strain > 0.0 && s.ultimate_strain <= s.fy / s.E)
                r.fail("ultimate_strain", "expected 0 (never fails) or a strain above fy/E");
            try {
                make_material(s, 0.0);
            } catch (const MaterialParameterError& e) {
                r.fail(e.key, e.what());
            }
            m.E = s.E;
            m.steel = s;
        } else {
            m.E = r.number("E");
        }
        r.finish();
        materials_[name] = m;
    }
}

// A key of another shape ('diameter' on a rectangle) would be read by nothing: say whose it is.
void SceneBuilder::read_sections(TomlTableReader& top) {
    const Tables list = array_of_tables(top, "section");
    for (std::size_t i = 0; i < list.size(); ++i) {
        TomlTableReader r(*list[i].first, file_, indexed("section", i), scene_table("section"), units());
        const std::string name = r.string("name");
        if (section_index_.count(name)) r.fail("name", "a section named '" + name + "' exists already");
        const std::string material = r.string("material");
        auto m = materials_.find(material);
        if (m == materials_.end()) r.fail("material", "no [[material]] named '" + material + "'");
        const SectionShape& shape = read_section_shape(r);
        // Parts of other materials (rebars, a core, a slab) name them by key.
        const MaterialLookup lookup = [&](TomlTableReader& table, const std::string& key) {
            const std::string other = table.string(key);
            const auto found = materials_.find(other);
            if (found == materials_.end()) table.fail(key, "no [[material]] named '" + other + "'");
            return ShapeMaterial{found->second.E, found->second.steel};
        };
        // Hinges by default for an inelastic material, unless its law hardens: a plastic
        // zone follows the hardening along the member, a hinge lumps it at the end.
        const bool hardens = m->second.steel && !find_material_law(m->second.steel->law)->perfectly_plastic;
        const std::string plasticity =
            r.choice_or("plasticity", !m->second.steel ? "none" : hardens ? "distributed" : "hinges");
        SectionParts parts({m->second.E, m->second.steel}, lookup);
        if (plasticity == "distributed" && m->second.steel && !hardens) parts.set_default_layers(default_perfectly_plastic_zone_layers);
        shape.build(r, parts);
        parts.read_rebars(r);
        parts.finish();
        SectionSpec s = std::move(parts.spec());
        if (r.has("plastic"))
            r.fail("plastic", "replaced by plasticity = \"none\" | \"hinges\" | \"distributed\"");
        if (plasticity != "none" && !m->second.steel)
            r.fail("plasticity", "an inelastic section needs a material with 'fy'");
        if (plasticity == "distributed") {
            s.plasticity = Plasticity::distributed;
            // Left open, the formulation follows the scene (resolve_open_formulations): a key
            // only the displacement formulation has chooses it.
            const bool open = !r.has("formulation") &&
                              std::none_of(displacement_only_keys.begin(), displacement_only_keys.end(), [&](const char* k) { return r.has(k); }) &&
                              (!r.has("integration_points") || r.integer("integration_points") >= 3);
            s.formulation = r.choice_or("formulation", "displacement") == "force" ? Formulation::force : Formulation::displacement;
            if (open) open_formulations_.push_back({static_cast<int>(model_.sections.size()), r.has("integration_points")});
            if (s.formulation == Formulation::force) {
                // Lobatto points: three integrate the elastic flexibility exactly.
                s.integration_points = r.integer_or("integration_points", default_force_based_points);
                if (s.integration_points < 3)
                    r.fail("integration_points", "expected a whole number from 3 to 10 for formulation = \"force\" (Gauss–Lobatto points include both ends)");
                for (const char* key : displacement_only_keys)
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
        // A capacity needs some tensile strength: a steel's fy (concrete's ft cracks away).
        const bool carries_tension = std::any_of(s.fibres.begin(), s.fibres.end(), [&](const Fibre& f) {
            const SteelSpec& law = f.material == 0 ? *s.steel : s.other_materials[static_cast<std::size_t>(f.material - 1)];
            return find_material_law(law.law)->strength == std::string("fy");
        });
        if (s.plasticity != Plasticity::none && !carries_tension)
            r.fail("material", "a section of concrete alone carries no tension: give it `rebars`, or make it elastic with plasticity = \"none\"");
        s.name = name;
        s.mass_per_length = m->second.density * s.area;
        s.rotary_inertia_per_length = m->second.density * s.inertia;
        r.finish();
        section_index_[name] = static_cast<int>(model_.sections.size());
        model_.sections.push_back(s);
    }
}

int SceneBuilder::section_of(TomlTableReader& r) {
    const std::string name = r.string("section");
    auto it = section_index_.find(name);
    if (it == section_index_.end()) r.fail("section", "no [[section]] named '" + name + "'");
    return it->second;
}

// A distributed member whose formulation the scene leaves open is force-based, exact for any
// mesh, where its scene is a frame: members in more than one direction, nothing acting along
// them or moving with them. Springs and bases (a ring on plates, a pipe on soil), self-contact
// and follower pressure bring contact forces, and a straight beam between supports can end in
// catenary action; the force formulation's element iterations follow those slowly, while the
// displacement formulation converges there with today's meshes (docs/method.md).
void SceneBuilder::resolve_open_formulations() {
    const bool contact_or_pressure = !model_.springs.empty() || !model_.self_contact.empty() || !model_.pressures.empty();
    if (contact_or_pressure || all_nodes_on_one_line()) return;
    for (const OpenFormulation& open : open_formulations_) {
        SectionSpec& s = model_.sections[static_cast<std::size_t>(open.section)];
        s.formulation = Formulation::force;
        if (!open.points_given) s.integration_points = default_force_based_points;
    }
}

// Before imperfections: a column given a bow is still one straight member.
bool SceneBuilder::all_nodes_on_one_line() const {
    const std::vector<Node>& nodes = model_.nodes;
    if (nodes.size() < 3) return true;
    const Node& origin = nodes[0];
    const auto distance = [&](const Node& n) { return std::hypot(n.x - origin.x, n.y - origin.y); };
    const Node& far = *std::max_element(nodes.begin(), nodes.end(), [&](const Node& a, const Node& b) { return distance(a) < distance(b); });
    const double length = distance(far);
    if (!(length > 0.0)) return true;
    const double ax = (far.x - origin.x) / length, ay = (far.y - origin.y) / length;
    return std::all_of(nodes.begin(), nodes.end(),
                       [&](const Node& n) { return std::abs(ax * (n.y - origin.y) - ay * (n.x - origin.x)) <= 1e-9 * length; });
}

} // namespace plastica::detail
