#include "scene_schema.hpp"

#include "dynamics_schema.hpp"

#include "scene_reader.hpp"
#include "section_shapes.hpp"

#include "material/material_registry.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace plastica {

bool KeyRange::contains(double v) const {
    return (min_open ? v > min : v >= min) && (max_open ? v < max : v <= max);
}

bool KeyRange::bounded() const { return std::isfinite(min) || std::isfinite(max); }

namespace {

std::string format_number(double v) {
    std::ostringstream s;
    s << std::setprecision(12) << v;
    return s.str();
}

std::string quoted_list(const std::vector<std::string>& values) {
    std::string out;
    for (const std::string& v : values) out += (out.empty() ? "`\"" : ", `\"") + v + "\"`";
    return out;
}

// " > 0", " ≥ 0", " 1–16", " in [0, 1)".
std::string range_text(const KeyRange& r) {
    if (!r.bounded()) return "";
    const bool lo = std::isfinite(r.min), hi = std::isfinite(r.max);
    if (lo && hi && !r.min_open && !r.max_open) return " " + format_number(r.min) + "–" + format_number(r.max);
    if (lo && hi)
        return std::string(" in ") + (r.min_open ? "(" : "[") + format_number(r.min) + ", " + format_number(r.max) + (r.max_open ? ")" : "]");
    if (lo) return std::string(r.min_open ? " > " : " ≥ ") + format_number(r.min);
    return std::string(r.max_open ? " < " : " ≤ ") + format_number(r.max);
}

std::string dimension_words(const KeySpec& k) {
    if (!k.dimension_text.empty()) return ", " + k.dimension_text;
    if (k.dimension == dimension::none) return "";
    return ", " + describe(k.dimension, false);
}

} // namespace

std::string KeySpec::type_description() const {
    switch (kind) {
    case ValueKind::number: return "number" + range_text(range) + dimension_words(*this);
    case ValueKind::integer: return "whole number" + range_text(range);
    case ValueKind::boolean: return "true or false";
    case ValueKind::string: return "string";
    case ValueKind::choice: return quoted_list(choices) + (type_text.empty() ? "" : " " + type_text);
    case ValueKind::point: return "point [x, y]" + dimension_words(*this);
    case ValueKind::other: return type_text;
    }
    return "";
}

std::string KeySpec::default_description() const {
    if (required) return "required";
    if (!default_text.empty()) return default_text;
    if (const double* v = std::get_if<double>(&fixed_default)) return format_number(*v);
    if (const bool* b = std::get_if<bool>(&fixed_default)) return *b ? "true" : "false";
    if (const std::string* s = std::get_if<std::string>(&fixed_default)) return s->empty() ? "none" : "`\"" + *s + "\"`";
    return "none";
}

namespace {

KeySpec key_of(std::string name, ValueKind kind) {
    KeySpec k;
    k.name = std::move(name);
    k.kind = kind;
    return k;
}

} // namespace

KeySpec number(std::string name, Dimension d) {
    KeySpec k = key_of(std::move(name), ValueKind::number);
    k.dimension = d;
    return k;
}

KeySpec whole(std::string name, int min, int max) { return key_of(std::move(name), ValueKind::integer).between(min, max); }

KeySpec flag(std::string name, bool fallback) { return key_of(std::move(name), ValueKind::boolean).fallback(fallback); }

KeySpec text(std::string name) { return key_of(std::move(name), ValueKind::string); }

KeySpec one_of(std::string name, std::vector<std::string> choices) {
    KeySpec k = key_of(std::move(name), ValueKind::choice);
    k.choices = std::move(choices);
    return k;
}

KeySpec point(std::string name, Dimension d) {
    KeySpec k = key_of(std::move(name), ValueKind::point);
    k.dimension = d;
    return k;
}

KeySpec other(std::string name, std::string type_text) { return key_of(std::move(name), ValueKind::other).or_also(std::move(type_text)); }

const KeySpec* TableSpec::find(const std::string& key, const std::string& chosen) const {
    for (const KeySpec& k : keys)
        if (k.name == key && (k.group.empty() || k.group == chosen)) return &k;
    return nullptr;
}

const KeySpec* TableSpec::find_anywhere(const std::string& key) const {
    for (const KeySpec& k : keys)
        if (k.name == key) return &k;
    return nullptr;
}

std::vector<std::string> TableSpec::key_names(const std::string& chosen) const {
    std::vector<std::string> out;
    for (const KeySpec& k : keys)
        if ((k.group.empty() || k.group == chosen) && std::find(out.begin(), out.end(), k.name) == out.end()) out.push_back(k.name);
    return out;
}

std::vector<std::string> TableSpec::all_key_names() const {
    std::vector<std::string> out;
    for (const KeySpec& k : keys)
        if (std::find(out.begin(), out.end(), k.name) == out.end()) out.push_back(k.name);
    return out;
}

namespace {

// Keys several tables share.
KeySpec node_id(std::string name = "node") {
    return whole(std::move(name), 0, 1'000'000'000).about("an explicit node's `id` (instead of `at`)");
}
KeySpec node_at(std::string name = "at") {
    return point(std::move(name), dimension::length).about("the node at this point; `at` or `node` is required");
}
KeySpec pattern_key(std::string doc) {
    return text("pattern").fallback(std::string("main")).about(std::move(doc));
}
KeySpec section_key() { return text("section").needed().about("a `[[section]]`'s name"); }
KeySpec releases_key() {
    return other("releases", "list of `\"start\"`, `\"end\"`")
        .about("moment releases at the member's first or last node (a beam pinned to its columns, a brace pinned at both ends)");
}
KeySpec elements_key() {
    return whole("elements", 1, max_elements).needed().varied_in_studies().about("equal elements along the member");
}

TableSpec scene_table_spec() {
    return {"scene", false, "", {
        text("name").needed().about("1–64 letters, digits, `_`, `-`; names the output folder"),
        text("title").fallback(std::string()).about("free text"),
    }};
}

TableSpec units_table_spec() {
    return {"units", false, "", {
        text("length").needed().about("`m`, `mm`, `cm`, `km`, `in`, `ft`"),
        text("force").needed().about("`N`, `kN`, `MN`, `lbf`, `kip`"),
    }};
}

TableSpec material_table_spec() {
    std::vector<std::string> laws;
    for (const MaterialLaw& law : material_laws()) laws.push_back(law.name);
    TableSpec t{"material", true, "law", {
        text("name").needed().about("referenced by sections"),
        number("E", dimension::stress).positive().follows("needed; `concrete`: n·fc/eps_c2")
            .about("Young's modulus; for `concrete` the parabola's initial slope (it sets n = E·eps_c2/fc)"),
        number("fy", dimension::stress).positive().about("yield stress: makes the material inelastic (fibre sections); `concrete` has `fc`"),
        one_of("law", laws).fallback(std::string("bilinear"))
            .about("the fibres' law (with `fy`). `bilinear`: elastic–perfectly plastic, the CS-ASA paper's law. "
                   "`kinematic_hardening`: bilinear with linear kinematic hardening (OpenSees' Steel01): tangent b·E past yield, "
                   "an elastic range 2·fy wide that moves with the back stress (Bauschinger effect); its sections use "
                   "`plasticity = \"distributed\"` by default; with `plasticity = \"hinges\"` a hinge's capacity rows harden by b of its "
                   "end's elastic stiffness (4EI/ℓ of its element, so a finer mesh hardens faster), its moment rising past "
                   "M_p(N) as it turns (a portal of b = 1e-3 on 8 elements a member: 5 % above M_p(N) at a drift of 0.25 m; steel rings crushed by plates: within 0.955–1.066 of "
                   "DeRuntz & Hodge's crush load, tests/test_crushing.cpp)"),
        number("ultimate_strain").at_least(0.0).fallback(0.0)
            .about("εu; a fibre past it fails and carries nothing; 0 never fails; else it must exceed fy/E"),
        number("density", dimension::mass_density).at_least(0.0).fallback(0.0)
            .about("mass per unit volume; self weight (`[[distributed_load]]` `gravity`) is ρ·A·g per unit length"),
    }};
    for (const MaterialLaw& law : material_laws())
        for (const LawParameter& p : law.parameters) {
            KeySpec k = number(p.name, p.stress ? dimension::stress : dimension::none).of(law.name)
                            .about(std::string("`") + law.name + "` only: " + p.doc);
            if (std::isfinite(p.fallback)) k.fallback(p.fallback);
            else k.needed();
            k.range.min = p.min;
            k.range.max = p.max;
            k.range.max_open = true;
            t.keys.push_back(k);
        }
    return t;
}

TableSpec section_table_spec() {
    std::vector<std::string> shapes;
    for (const SectionShape& s : section_shapes()) shapes.push_back(s.name);
    const std::string distributed = "`distributed` only: ";
    const std::string layers_default = "10; 30 with a perfectly plastic law and `plasticity = \"distributed\"` (its M–κ turns flat once every layer has yielded)";
    return {"section", true, "shape", {
        text("name").needed().about("referenced by members"),
        text("material").needed().about("a `[[material]]`'s name"),
        one_of("shape", shapes).fallback(std::string("properties"))
            .about("each shape reads its own keys below; a key of another shape is an error that names its shape"),
        number("A", dimension::area).positive().needed().of("properties")
            .about("`properties`: area; with an inelastic material an equivalent rectangle of `fibres` layers carries the fibres"),
        number("I", dimension::second_moment).positive().needed().of("properties").about("`properties`: second moment of area"),
        number("thickness", dimension::length).positive().follows("√(12 I/A)").of("properties")
            .about("`properties`: the distance between the section's surfaces, for `[[self_contact]]` (the default is the depth of "
                   "the rectangle with the same A and I). The other shapes have theirs: `h`, `depth`, `diameter`"),
        whole("fibres", 2, 100000).follows(layers_default).of("properties").varied_in_studies()
            .about("`properties` with an inelastic material: layers of the equivalent rectangle"),
        number("b", dimension::length).positive().needed().of("rectangle").about("`rectangle`: width"),
        number("h", dimension::length).positive().needed().of("rectangle").about("`rectangle`: depth"),
        whole("fibres", 1, 100000).follows(layers_default).of("rectangle").varied_in_studies().about("`rectangle`: layers through the depth"),
        text("profile").of("i")
            .about("`i`: a rolled profile by name, its plates and root radius from the tables of EN 10365 (`\"IPE 300\"`, "
                   "`\"HEA 200\"`, `\"HEB 200\"`, `\"HEM 200\"`, in mm) and the AISC Shapes Database v15.0 (`\"W14x90\"`, in "
                   "inches), converted to the scene's [units] (which it needs); chooses `shape = \"i\"` by itself; the list: "
                   "io/scene/rolled_profiles.cpp"),
        number("depth", dimension::length).positive().needed().of("i").about("`i`: doubly symmetric I/H section, overall depth"),
        number("flange_width", dimension::length).positive().needed().of("i").about("`i`"),
        number("flange_thickness", dimension::length).positive().needed().of("i").about("`i`; two flanges thinner than the depth"),
        number("web_thickness", dimension::length).positive().needed().of("i").about("`i`; not wider than the flanges"),
        number("root_radius", dimension::length).at_least(0.0).fallback(0.0).of("i")
            .about("`i`: the fillets between web and flanges of a rolled section, giving its tabulated A, I and W_pl "
                   "(HEB 200: r = 18 mm, 642.5 cm³; without fillets 620 cm³)"),
        whole("flange_strips", 1, 1000).fallback(10.0).of("i").about("`i`: fibres across the flange width"),
        whole("flange_layers", 1, 1000).fallback(2.0).of("i").about("`i`: fibres through the flange thickness"),
        whole("web_fibres", 1, 10000).fallback(10.0).of("i").about("`i`: fibres along the web"),
        number("residual_stress").at_least(0.0).below(1.0).fallback(0.0).of("i")
            .about("`i`: a fraction of fy; linear pattern across the flanges, −r·fy at the tips, +r·fy at the web, zero mean"),
        other("slab", "table").of("i")
            .about("`i`: a slab on the top flange for a composite beam (full interaction), `{ width, thickness, material, layers = 10 }`; "
                   "the section is centred on its elastic centroid"),
        number("diameter", dimension::length).positive().needed().of("hollow_circle").about("`hollow_circle`: outer diameter"),
        number("thickness", dimension::length).positive().needed().of("hollow_circle").about("`hollow_circle`: wall, at most half the diameter"),
        whole("fibres", 4, 100000).fallback(24.0).of("hollow_circle").varied_in_studies().about("`hollow_circle`: fibres round the wall"),
        text("core_material").of("hollow_circle").about("`hollow_circle`: a `[[material]]` filling the tube (a concrete-filled tube)"),
        whole("core_fibres", 2, 100000).fallback(20.0).of("hollow_circle").about("`hollow_circle` with `core_material`: layers of the core"),
        number("b", dimension::length).positive().needed().of("hollow_rectangle").about("`hollow_rectangle`: outer width"),
        number("h", dimension::length).positive().needed().of("hollow_rectangle").about("`hollow_rectangle`: outer depth"),
        number("thickness", dimension::length).positive().needed().of("hollow_rectangle").about("`hollow_rectangle`: wall"),
        whole("fibres", 1, 100000).fallback(20.0).of("hollow_rectangle").varied_in_studies()
            .about("`hollow_rectangle`: layers along the webs (and the core)"),
        whole("flange_layers", 1, 1000).fallback(2.0).of("hollow_rectangle").about("`hollow_rectangle`: layers through each flange"),
        text("core_material").of("hollow_rectangle").about("`hollow_rectangle`: a `[[material]]` filling the tube"),
        other("fibres", "list of `[area, y]` or `[area, y, residual_stress]`").needed().of("fibres")
            .about("`fibres`: y from the centroid (Σ A·y = 0)"),
        other("rebars", "list of tables")
            .about("any shape: bars as point fibres, `[{ y, area, material }, …]`, y from the shape's centre; the layer a bar "
                   "lies in gives up the bar's area (the concrete it displaces is not counted twice)"),
        one_of("plasticity", {"none", "hinges", "distributed"})
            .follows("`\"hinges\"` with `fy` (`\"distributed\"` for a hardening law), else `\"none\"`")
            .about("how an inelastic section yields. `hinges`: refined plastic hinges at element ends (pseudo-springs from the "
                   "section's tangent below capacity; at capacity, N–M plasticity with plastic rotation and axial strain; one hinge "
                   "per node where two elements meet). `distributed`: fibre sections at integration points along every element "
                   "(plastic zone; force- or displacement-based, see `formulation`). The former boolean `plastic` is refused with "
                   "a message naming this key"),
        one_of("formulation", {"displacement", "force"})
            .follows("`\"force\"` in a frame (nodes not all on one line) without springs, bases, `[[self_contact]]` or pressure; "
                     "else `\"displacement\"`, as when the section gives `segments`, `segment_grading`, `axial_strain` or "
                     "`integration_points = 2`")
            .about(distributed + "how the sections follow the element's ends. `displacement`: curvature linear along the element "
                   "(or each segment), no element iterations; collapse loads first-order high in the element length (3.6 % on a "
                   "portal with 8 elements per member). `force`: moments from the end forces by equilibrium (exact), sections at "
                   "Gauss–Lobatto points including the ends, element iterations; collapse loads of beams exact on 2 elements, the "
                   "portal within 0.1 % on 8, at 2–13 × the analysis time on frames; the default for frames; under contact "
                   "and catenary action its element iterations crawl, so straight beams and scenes with contact default to "
                   "`displacement` (docs/method.md, force-based "
                   "members)"),
        whole("integration_points", 2, 10).follows("3; `force`: 5").varied_in_studies()
            .about(distributed + "Gauss–Legendre points per element, or per segment (one point would leave the antisymmetric "
                   "bending mode without stiffness); with `formulation = \"force\"`, 3–10 Gauss–Lobatto points per element"),
        whole("segments", 1, 16).fallback(static_cast<double>(default_segments)).varied_in_studies()
            .about(distributed + "with `formulation = \"displacement\"`: each element cut into this many segments of linear "
                   "curvature, their inner nodes' transverse motion and rotation condensed by element iterations (one axial "
                   "strain per element, as with one segment, unless `axial_strain`): the plastic zone resolved as by a mesh this "
                   "many times finer, without more unknowns and with the element's own co-rotational frame; 4 segments of 2 "
                   "points bring the ring from 1.3 % to 0.25 % of its converged load at 3.7 × the hinge ring's analysis time "
                   "(docs/method.md)"),
        number("segment_grading").between(0.25, 4.0).fallback(1.0)
            .about(distributed + "with 3 segments or more: each segment this many times as long as its neighbour nearer the "
                   "element end (2 with 8 segments: lengths 1, 2, 4, 8, 8, 4, 2, 1), so that the sections next to a hinge at a "
                   "node sit close to it; 8 segments graded by 2 bring the collapse loads of beams and frames within 0.5 % on 8 "
                   "elements per member (docs/method.md, graded segments)"),
        one_of("axial_strain", {"per_element", "per_segment"}).fallback(std::string("per_element"))
            .about(distributed + "with 2 segments or more: `per_segment` gives each segment an axial strain of its own (the "
                   "inner nodes' axial motion condensed too), so that every segment carries the member's axial force and a "
                   "column base yields at M_p(N): a portal whose columns carry axial load comes within 0.25 % of its converged "
                   "peak on 8 elements of 8 segments graded by 2 (5.5 % high with one strain per element); not the default "
                   "because where the shortest segments take a hinge's axial flow under arc length (a shallow arch snapping "
                   "onto a floor) Newton crawls (docs/method.md, axial strain per segment)"),
    }};
}

TableSpec node_table_spec() {
    return {"node", true, "", {
        whole("id", 0, 1'000'000'000).needed().about("the node's number, for `[[element]]` `nodes` and `node` keys"),
        number("x", dimension::length).needed().about("position"),
        number("y", dimension::length).needed().about("position"),
    }};
}

TableSpec line_table_spec() {
    return {"line", true, "", {
        text("name").follows("`line1`, `line2`, … in order").about("the member's name, for `on` keys and `--set line[name]`"),
        point("start", dimension::length).needed().about("first end"),
        point("end", dimension::length).needed().about("second end"),
        elements_key(),
        section_key(),
        releases_key(),
    }};
}

TableSpec arc_table_spec() {
    return {"arc", true, "", {
        text("name").follows("`arc1`, `arc2`, … in order").about("the member's name, for `on` keys and `--set arc[name]`"),
        point("center", dimension::length).needed().about("the circle's centre"),
        number("radius", dimension::length).positive().needed().about("the circle's radius"),
        number("start_angle").needed().about("degrees, counter-clockwise from the x axis"),
        number("end_angle").needed().about("degrees; the arc runs counter-clockwise from start to end, more than 0° and at most 360° (which closes a ring)"),
        elements_key(),
        section_key(),
        releases_key(),
    }};
}

TableSpec element_table_spec() {
    return {"element", true, "", {
        other("nodes", "`[id, id]`").needed().about("two `[[node]]` ids"),
        section_key(),
        releases_key(),
    }};
}

TableSpec support_table_spec() {
    return {"support", true, "", {
        node_at(),
        node_id(),
        other("fix", "list of `\"ux\"`, `\"uy\"`, `\"rz\"`").needed().about("the fixed DOFs"),
    }};
}

TableSpec load_table_spec() {
    return {"load", true, "", {
        node_at(),
        node_id(),
        number("fx", dimension::force).fallback(0.0).about("reference force, scaled by its pattern's factor"),
        number("fy", dimension::force).fallback(0.0).about("reference force; at least one component acts on a DOF that is not supported"),
        number("moment", dimension::moment).fallback(0.0).about("reference moment, counter-clockwise positive"),
        pattern_key("the load pattern the load belongs to (letters, digits, `_`, `-`)"),
    }};
}

TableSpec distributed_load_table_spec() {
    return {"distributed_load", true, "", {
        text("on").needed().about("`\"all\"` or a `[[line]]`/`[[arc]]` name"),
        number("wx", dimension::force_per_length).fallback(0.0)
            .about("force per unit initial length in a fixed direction (a floor load, wind on a column); each element's share "
                   "goes half to each of its nodes, which moves the deflection of a simply supported beam from 5wL⁴/384EI by a "
                   "share of order (L/n)² and gives the exact midspan moment and collapse loads"),
        number("wy", dimension::force_per_length).fallback(0.0).about("as `wx`, along y"),
        point("gravity", dimension::acceleration)
            .about("`[gx, gy]`: self weight ρ·A·g per unit initial length of every element named (each section's material needs "
                   "`density`), lumped like `wx`, `wy`"),
        number("pressure", dimension::force_per_length).fallback(0.0)
            .about("force per unit deformed length along the member's left normal, following the members as they deform "
                   "(hydrostatic pressure, a fluid or soil load on a pipe); on a counter-clockwise `[[arc]]` a positive value "
                   "pushes toward the centre. Its load stiffness is in the tangent, so a ring under external pressure buckles at "
                   "3EI/R³ (a fixed-direction load would give 4EI/R³). At `geometry = \"first_order\"` it acts on the initial chords"),
        pattern_key("the load pattern the loads belong to"),
    }};
}

TableSpec prescribed_table_spec() {
    return {"prescribed", true, "", {
        node_at(),
        node_id(),
        one_of("dof", {"ux", "uy", "rz"}).needed().about("the DOF moved; it must not also be in a support's `fix`"),
        number("value").needed().dimension_follows("a length; a rotation in radians for `rz`")
            .about("reference displacement, scaled by its pattern's factor (a settlement)"),
        pattern_key("the load pattern that drives it"),
    }};
}

TableSpec foundation_table_spec() {
    const std::string k_dimension = "a force per length; with `per_length` a stress";
    return {"foundation", true, "", {
        one_of("kind", {"bilateral", "unilateral", "tensionless"}).fallback(std::string("bilateral"))
            .about("unilateral: compression only against a rigid base line; tensionless: a Winkler bed that pushes but never "
                   "pulls, anchored at each node's initial position (soil under an arch or around a pipe)"),
        text("on").follows("none").about("`\"all\"` or a `[[line]]`/`[[arc]]` name: the nodes that get springs"),
        other("at", "list of points `[[x, y], …]`").about("further nodes"),
        number("below", dimension::length).about("keep only the selected nodes whose initial y is at most this"),
        other("halve_at", "list of points").about("nodes on a symmetry line: half the stiffness"),
        number("kx", dimension::force_per_length).at_least(0.0).fallback(0.0).dimension_follows(k_dimension)
            .about("spring stiffness along x"),
        number("ky", dimension::force_per_length).at_least(0.0).fallback(0.0).dimension_follows(k_dimension)
            .about("spring stiffness along y; for a unilateral base the normal penalty stiffness (frictionless); a tensionless "
                   "bed has `ky` alone. The penalty should be large against the structure's local stiffness (EI/s³ for spring "
                   "spacing s): the ring converges to 1e-4 between ky = 1e8 and 1e12"),
        number("krot", dimension::moment).at_least(0.0).fallback(0.0)
            .dimension_follows("a moment per radian; with `per_length` a force").about("rotational spring stiffness"),
        flag("per_length", false).about("stiffness per unit length, times the node's tributary length"),
        one_of("acts_on", {"nodes", "members"}).fallback(std::string("nodes"))
            .about("unilateral only: `nodes`: a spring at each selected node meets the base on its own, so a contact zone "
                   "grows node by node and the load jumps as each one lands; `members`: the base presses each member whose "
                   "two ends are selected over its exact overlap with the line (the centre line the cubic through the nodes "
                   "and their tangents), `ky` is then a penalty per unit length (a stress) and the force grows smoothly as "
                   "the zone spreads (engine/contact/member_overlap.hpp); no `halve_at`, `kx`, `krot` or `per_length`"),
        point("base_point", dimension::length).follows("the lowest selected node")
            .about("unilateral: a point of the base line. Foundations on the same line share it; another line is another base "
                   "(a ring between two plates: one facing up, one facing down)"),
        point("base_normal").follows("[0, 1]").about("unilateral: the base line's normal, toward the structure"),
        point("base_motion", dimension::length)
            .about("a platen: the base line moves by λ × this vector, so the load factor drives it (as `[[prescribed]]` "
                   "displacements are driven). A scene may then have no load at all; its reported load is the force the moving "
                   "bases press with (the sum of their contact forces × `load_scale`, labelled \"platen force\"), and Newton's "
                   "residual is measured against that force"),
        one_of("direction", {"left_normal", "right_normal"}).or_also("or a vector `[x, y]`").follows("[0, 1]")
            .about("tensionless only: the direction the bed pushes on the structure, or the members' normal at each node (mean "
                   "of the adjacent elements'; the left normal of a counter-clockwise `[[arc]]` points to its centre, so soil "
                   "around a pipe is `\"left_normal\"`). A node bears while it has moved against this direction from where it "
                   "started, with stiffness `ky`"),
        pattern_key("with `base_motion`: the load pattern whose factor moves the platen"),
    }};
}

TableSpec self_contact_table_spec() {
    return {"self_contact", true, "", {
        other("on", "`\"all\"`, a `[[line]]`/`[[arc]]` name, or a list of names").follows("`\"all\"`")
            .about("the members whose surfaces touch each other and themselves; `[[element]]`s are taken by `\"all\"`"),
        one_of("acts_on", {"nodes", "members"}).fallback(std::string("nodes"))
            .about("`nodes`: each node presses on the other surface's element chords, so a contact zone grows node by node; "
                   "`members`: points along each element (4 Gauss–Lobatto points, its ends among them) press, so it grows a third of an element at a time, and "
                   "`stiffness` is then a penalty per unit length (a stress), the surfaces pressing with stiffness·penetration "
                   "per unit length (engine/contact/self_contact.hpp)"),
        number("stiffness", dimension::force_per_length).positive().follows("from the members")
            .dimension_follows("a force per length; with `acts_on = \"members\"` a stress")
            .about("the penalty per pair; along the members per unit length: the default below over the element length; by default, over the members' elements, the largest of the smaller of E·A/ℓ and "
                   "100·12·E·I/ℓ³: a pressed node sinks into the surface no more than an element end shortens under the same "
                   "force, nor more than a hundredth of what an element bends under it, and the tangent stays as well "
                   "conditioned as the members make it (measured: 0.004 mm in the 5 mm walls of "
                   "`gallery/steel_pipe_flattened.toml`; two stacked elastic rings are 3.5e-7 more flexible for it)"),
    }};
}

TableSpec imperfection_table_spec() {
    return {"imperfection", true, "", {
        whole("mode", 1, 1000).needed().about("the buckling mode of the pattern's loads on the perfect geometry (1: the lowest)"),
        number("amplitude", dimension::length).needed()
            .about("the largest nodal translation of the scaled mode, signed (its sign flips the shape); e.g. L/300 of a column"),
        pattern_key("the load pattern whose buckling modes are taken (that of `[analysis]` when left out)")
            .follows("`[analysis]`'s pattern"),
    }};
}

// The keys that name and steer a controlled DOF, in [analysis] and [[stage]].
std::vector<KeySpec> control_keys(const std::string& point_default, const std::string& dof_default) {
    return {
        point("control_at", dimension::length).follows(point_default).about("the point whose DOF is controlled and reported"),
        whole("control_node", 0, 1'000'000'000).about("a node id instead of `control_at`"),
        one_of("control_dof", {"ux", "uy", "rz"}).fallback(std::string("uy")).follows(dof_default).about("the controlled DOF"),
        number("control_sign").between(-1.0, 1.0).follows("the direction of the load on that DOF")
            .about("1 or -1 (−1 reports downward as positive); 1 when the DOF carries no load; a sign against that load is an error"),
    };
}

TableSpec analysis_table_spec() {
    const std::string stepped = "a length (displacement control of ux, uy); else a pure number";
    TableSpec t{"analysis", false, "", {
        one_of("scheme", {"arc_length", "load_control", "displacement_control", "transient"}).fallback(std::string("arc_length"))
            .about("arc length is Crisfield's cylindrical; `transient` integrates in time (`time_step`, `duration`; docs/dynamics.md)"),
        number("increment").positive().follows("required, except for `transient`").dimension_follows(stepped).varied_in_studies()
            .about("Δλ, the control DOF's Δu, or the arc length Δl of the first step"),
        number("min_increment").positive().follows("1e-6 × increment").dimension_follows(stepped)
            .about("the smallest adapted or cut increment; at most the first increment"),
        number("max_increment").positive().follows("10 × increment").dimension_follows(stepped)
            .about("the largest adapted increment; at least the first increment"),
        flag("adaptive", false).follows("true except load control").about("adapt increments toward `desired_iterations`"),
        whole("desired_iterations", 1, 100).follows("5; 8 with distributed plasticity")
            .about("Newton iterations a step aims at (fibre branches along a member take about three more to settle at any step size)"),
        whole("max_iterations", 1, 1000).fallback(static_cast<double>(AnalysisSpec{}.max_iterations)).about("Newton iterations before a step is cut"),
        whole("max_steps", 1, 10'000'000).fallback(static_cast<double>(AnalysisSpec{}.max_steps)).about("converged steps over all stages"),
        number("residual_tolerance").positive().follows("1e-6, raised to the round-off floor")
            .about("‖R‖ relative to the reference load (largest converged load level). Left out, it is 1e-6 or the state's "
                   "round-off floor (eps·|K|·|u| against the load: a fine mesh, a stiff penalty) where that lies above, so that "
                   "every mesh and penalty completes; `run.json`'s `residual_tolerance` gives the largest used and at which "
                   "step. Given, it is honoured as written, round-off stagnation accepted within 10 × it, and a floor above it "
                   "stops the run saying so"),
        number("displacement_tolerance").positive().fallback(AnalysisSpec::default_displacement_tolerance)
            .about("‖δu‖ relative to the increment's ‖Δu‖"),
        number("target_load_factor").positive()
            .about("the stop, a positive load factor (a load the other way: reverse the `[[load]]`); exactly one stop is given. "
                   "Every scheme ends on the target exactly: an arc-length step past it is taken again under load control to it"),
        number("target_displacement").positive().dimension_follows("a length; a rotation in radians for `rz`")
            .about("the stop at the control DOF's displacement, signed as reported; needs `control_at`"),
        pattern_key("the load pattern λ drives (it must hold a load, a pressure, a prescribed displacement or a moving base)"),
        one_of("bifurcation", {"report", "switch"}).fallback(std::string("report"))
            .about("at a bifurcation (one more negative pivot with the critical mode orthogonal to the load), `report` "
                   "locates it, warns and goes on along the fundamental path; `switch` goes on along the buckled branch, its "
                   "first step started along the mode (docs/stability.md)"),
        one_of("geometry", {"large_displacement", "first_order"}).fallback(std::string("large_displacement"))
            .about("the members' kinematics: `large_displacement` (co-rotational: any displacement and rotation) or "
                   "`first_order` (small displacements: equilibrium on the initial geometry, no P-Δ, pressure on the initial "
                   "chords; plasticity and contact as usual), the analysis of design by hand (docs/stability.md)"),
        flag("allow_crossing", false)
            .about("without `[[self_contact]]`, a structure passing through itself, through its symmetry line (`mirror_x`) or "
                   "below the base at a node the base does not hold stops the run (exit 3); `true` lets it pass (a cantilever "
                   "rolled into two turns)"),
    }};
    for (KeySpec& k : control_keys("the first load's node", "`\"uy\"`")) t.keys.push_back(k);
    for (KeySpec& k : transient_keys(true)) t.keys.push_back(k);
    return t;
}

TableSpec stage_table_spec() {
    TableSpec t{"stage", true, "", {
        pattern_key("the load pattern the stage drives; every other keeps the factor it had"),
        one_of("scheme", {"load_control", "displacement_control", "transient"}).fallback(std::string("load_control"))
            .about("displacement control is of the stage's control DOF; `transient` integrates in time"),
        number("increment").positive().follows("required, except for `transient`").dimension_follows("a length (displacement control of ux, uy); else a pure number")
            .about("|Δλ| or |Δu|; the sign follows the target"),
        flag("adaptive", false).about("adapt increments as in `[analysis]`"),
        number("target_load_factor").about("the stop of a load-controlled stage, any sign: `0.0` releases the load; exactly one stop is given"),
        number("target_displacement").dimension_follows("a length; a rotation in radians for `rz`")
            .about("the stop of a displacement-controlled stage, any sign"),
    }};
    for (KeySpec& k : control_keys("the previous stage's", "`\"uy\"` with a point named")) {
        k.about(k.doc + "; left out, the previous stage's (or `[analysis]`'s); `control_dof` and `control_sign` need the point named too");
        t.keys.push_back(k);
    }
    for (KeySpec& k : transient_keys(false)) t.keys.push_back(k);
    return t;
}

TableSpec report_table_spec() {
    return {"report", false, "", {
        one_of("load", {"total", "factor"})
            .follows("`\"total\"` when the loads are parallel, else `\"factor\"`")
            .about("what is reported as the load: `total` = λ × the sum of the reference loads along their common direction "
                   "(parallel forces, or moments only: twelve loads of 12.5 give 150 λ); `factor` = λ. Loads in more than one "
                   "direction have no total, and `total` is then an error; a scene driven by moving bases alone reports their force"),
        number("load_scale").positive().fallback(1.0).about("multiplies the reported load (2 for a half model)"),
        text("load_label").follows("\"load\" (\"load factor\" when the factor is reported)").about("name of the load in pictures (title, chart axis)"),
        text("displacement_label").fallback(std::string("control displacement")).about("name of the control displacement in pictures"),
        text("length_unit").follows("`[units]`'s").about("the scene's length unit for pictures (at most 16 characters)"),
        text("force_unit").follows("`[units]`'s")
            .about("the scene's force unit for pictures: the axes, the status line, colour bars and arrow values carry them, "
                   "moments as force·length, a pressure as force/length; the load factor has none"),
        other("load_at", "list of numbers")
            .about("control displacements (in the control's units, numbers) at which run.json gives the load under "
                   "`load_at`, interpolated between the steps where the path first passes each (a flattening test's "
                   "travel: δ/D = 0.5 as 0.5 D)"),
        number("mirror_x", dimension::length)
            .about("the scene is half of a structure symmetric about the line x = mirror_x: pictures draw the mirrored half too "
                   "(results are unchanged); every node must lie on one side of the line"),
        one_of("exact", {"cantilever_tip_load"})
            .about("the closed form of this scene for `plastica study --reference exact`: the exact elastica of a cantilever "
                   "under a transverse tip load; refused unless the scene is that cantilever: straight, elastic, one clamp at one "
                   "end, one transverse load at the other, no springs"),
    }};
}

std::vector<TableSpec> build_schema() {
    std::vector<TableSpec> tables{scene_table_spec(), units_table_spec(), material_table_spec(), section_table_spec(), node_table_spec(),
            line_table_spec(), arc_table_spec(), element_table_spec(), support_table_spec(), load_table_spec(),
            distributed_load_table_spec(), prescribed_table_spec(), foundation_table_spec(), self_contact_table_spec(),
            imperfection_table_spec(), analysis_table_spec(), stage_table_spec(), report_table_spec()};
    for (TableSpec& t : dynamics_table_specs()) tables.push_back(std::move(t));
    return tables;
}

} // namespace

const std::vector<TableSpec>& scene_schema() {
    static const std::vector<TableSpec> schema = build_schema();
    return schema;
}

const TableSpec* find_scene_table(const std::string& name) {
    for (const TableSpec& t : scene_schema())
        if (t.name == name) return &t;
    return nullptr;
}

const TableSpec& scene_table(const std::string& name) {
    if (const TableSpec* t = find_scene_table(name)) return *t;
    throw std::logic_error("io/scene/scene_schema.cpp declares no table '" + name + "'");
}

const TableSpec& scene_root_table() {
    static const TableSpec root = [] {
        TableSpec t{"", false, "", {}};
        for (const TableSpec& table : scene_schema()) t.keys.push_back(other(table.name, table.array ? "array of tables" : "table"));
        return t;
    }();
    return root;
}

std::vector<std::string> scene_table_names() {
    std::vector<std::string> out;
    for (const TableSpec& t : scene_schema()) out.push_back(t.name);
    return out;
}

std::vector<std::string> studied_keys() {
    std::vector<std::string> out;
    for (const TableSpec& t : scene_schema())
        for (const KeySpec& k : t.keys)
            if (k.studied && std::find(out.begin(), out.end(), k.name) == out.end()) out.push_back(k.name);
    return out;
}

namespace {

// A bar inside a cell (|Δu|) would end it.
std::string table_cell(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

} // namespace

std::string scene_keys_begin_marker(const TableSpec& table) {
    return "<!-- generated by `plastica schema --scene`: keys of " + table.heading() + " -->";
}

std::string scene_keys_markdown(const TableSpec& table) {
    std::ostringstream s;
    s << scene_keys_begin_marker(table) << "\n";
    s << "| key | type | default | meaning |\n|---|---|---|---|\n";
    for (const KeySpec& k : table.keys) {
        s << "| `" << k.name << "` | " << table_cell(k.type_description()) << " | " << table_cell(k.default_description())
          << " | " << table_cell(k.doc) << " |\n";
    }
    s << scene_keys_end_marker() << "\n";
    return s.str();
}

} // namespace plastica
