#include "section_shapes.hpp"

#include "rolled_profiles.hpp"
#include "scene_error.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

SectionSpec rectangle_section(double E, double b, double h, int fibres) {
    SectionSpec s;
    s.E = E;
    s.area = b * h;
    s.inertia = b * h * h * h / 12.0;
    for (int i = 0; i < fibres; ++i)
        s.fibres.push_back({b * h / fibres, -h / 2.0 + (i + 0.5) * h / fibres, 0.0, 0, h / (2.0 * fibres)});
    return s;
}

namespace {

// A and I; an inelastic material's fibres in the equivalent rectangle.
void properties(TomlTableReader& t, SectionParts& parts) {
    SectionSpec& s = parts.spec();
    const ShapeMaterial& m = parts.main();
    s.E = m.E;
    s.area = t.number("A");
    s.inertia = t.number("I");
    s.depth = t.number_or("thickness", 0.0); // 0: the equivalent rectangle's depth
    if (m.steel) {
        // A and I alone define no fibres: an equivalent rectangle carries them.
        const double h = std::sqrt(12.0 * s.inertia / s.area);
        s.fibres = rectangle_section(s.E, s.area / h, h, t.integer_or("fibres", parts.default_layers())).fibres;
    }
}

void rectangle(TomlTableReader& t, SectionParts& parts) {
    const double b = t.number("b");
    const double h = t.number("h");
    SectionSpec& s = parts.spec();
    s = rectangle_section(parts.main().E, b, h, t.integer_or("fibres", parts.default_layers()));
    s.depth = h;
}

// A rectangular tube B × H with walls of `thickness`: flanges in layers through their thickness,
// the two webs in `fibres` layers along their height; with `core_material` the core B − 2t by
// H − 2t filled (a concrete-filled tube) in the same layers.
void hollow_rectangle(TomlTableReader& t, SectionParts& parts) {
    const double B = t.number("b"), H = t.number("h"), th = t.number("thickness");
    if (2.0 * th >= std::min(B, H)) t.fail("thickness", "expected less than half the width and the depth");
    const int n = t.integer("fibres"), flange_layers = t.integer("flange_layers");
    SectionSpec& s = parts.spec();
    s.E = parts.main().E;
    const double hw = H - 2.0 * th, bi = B - 2.0 * th;
    s.area = B * H - bi * hw;
    s.inertia = (B * H * H * H - bi * hw * hw * hw) / 12.0;
    s.depth = H;
    for (int side : {-1, 1})
        for (int l = 0; l < flange_layers; ++l)
            s.fibres.push_back({B * th / flange_layers, side * (hw / 2.0 + (l + 0.5) * th / flange_layers), 0.0, 0, th / (2.0 * flange_layers)});
    for (int k = 0; k < n; ++k) s.fibres.push_back({2.0 * th * hw / n, -hw / 2.0 + (k + 0.5) * hw / n, 0.0, 0, hw / (2.0 * n)});
    if (t.has("core_material")) {
        double E = 0.0;
        const int core = parts.material(t, "core_material", E);
        parts.add_stiffness(E, bi * hw, 0.0, bi * hw * hw * hw / 12.0);
        if (parts.main().steel)
            for (int k = 0; k < n; ++k) s.fibres.push_back({bi * hw / n, -hw / 2.0 + (k + 0.5) * hw / n, 0.0, core, hw / (2.0 * n)});
    }
}

const TableSpec& slab_spec() {
    static const TableSpec spec{"slab", false, "", {
        number("width", dimension::length).positive().needed().about("effective width"),
        number("thickness", dimension::length).positive().needed().about("depth of the slab"),
        text("material").needed().about("a `[[material]]`'s name"),
        whole("layers", 1, 1000).fallback(10.0).about("fibres through the thickness"),
    }};
    return spec;
}

// A slab on the top flange (a composite beam): full interaction, its layers from `top` up.
void read_slab(TomlTableReader& t, SectionParts& parts, double top) {
    const toml::table* table = t.table("slab");
    if (!table) t.fail("slab", "expected a table { width = …, thickness = …, material = \"…\" }");
    TomlTableReader r(*table, t.file(), t.qualified("slab"), slab_spec(), t.units());
    const double b = r.number("width"), h = r.number("thickness");
    const int layers = r.integer("layers");
    double E = 0.0;
    const int material = parts.material(r, "material", E);
    r.finish();
    parts.add_stiffness(E, b * h, top + h / 2.0, b * h * h * h / 12.0);
    SectionSpec& s = parts.spec();
    s.depth += h;
    if (parts.main().steel)
        for (int l = 0; l < layers; ++l) s.fibres.push_back({b * h / layers, top + (l + 0.5) * h / layers, 0.0, material, h / (2.0 * layers)});
}

// I or H section: flanges split into strips across the width and layers through the
// thickness (so a residual-stress pattern across the flange is represented), web in layers,
// and with a root radius r the four fillets between web and flanges, each (1 − π/4)·r² with its
// centroid 0.2234·r from the flange (a rolled section's tabulated A, I and W_pl).
// A rolled profile's dimensions in the scene's length unit.
struct IDimensions {
    double d, bf, tf, tw, r;
};

IDimensions rolled_dimensions(TomlTableReader& t) {
    for (const char* key : {"depth", "flange_width", "flange_thickness", "web_thickness", "root_radius"})
        if (t.has(key)) t.fail(key, "the profile sets it; leave it out, or give the plates without `profile`");
    const std::string name = t.string("profile");
    const RolledProfile* p = find_rolled_profile(name);
    if (!p) {
        const std::string near = nearest_profile_name(name);
        t.fail("profile", "no rolled profile named '" + name + "' (EN 10365 IPE, HEA, HEB, HEM; AISC W)" +
                              (near.empty() ? std::string() : "; did you mean '" + near + "'?"));
    }
    if (!t.units())
        t.fail("profile", std::string("a rolled profile's dimensions are in ") + (p->inches ? "inches" : "millimetres") +
                              ": give the scene a [units] table so that they can be converted");
    const double unit = t.units()->to_scene(p->inches ? "1 in" : "1 mm", dimension::length);
    return {p->depth * unit, p->flange_width * unit, p->flange_thickness * unit, p->web_thickness * unit, p->root_radius * unit};
}

void i_section(TomlTableReader& t, SectionParts& parts) {
    const ShapeMaterial& m = parts.main();
    const bool rolled = t.has("profile");
    const IDimensions given = rolled ? rolled_dimensions(t) : IDimensions{t.number("depth"), t.number("flange_width"), t.number("flange_thickness"),
                                                                           t.number("web_thickness"), t.number("root_radius")};
    const double d = given.d, bf = given.bf, tf = given.tf, tw = given.tw;
    if (2.0 * tf >= d) t.fail("flange_thickness", "two flanges must be thinner than the depth");
    if (tw > bf) t.fail("web_thickness", "the web must not be wider than the flanges");
    const int strips = t.integer("flange_strips");
    const int layers = t.integer("flange_layers");
    const int web = t.integer("web_fibres");
    const double ratio = t.number("residual_stress");
    const double hw = d - 2.0 * tf;
    const double r = given.r;
    if (2.0 * r > hw || tw + 2.0 * r > bf)
        t.fail("root_radius", "expected a radius ≥ 0 whose fillets fit between the flanges and within their width");
    const double fillet_area = (1.0 - M_PI / 4.0) * r * r, fillet_y = hw / 2.0 - 0.2234 * r;
    const double fillet_own_inertia = 0.0075 * r * r * r * r; // a spandrel's about its own centroid
    SectionSpec& s = parts.spec();
    s.E = m.E;
    s.area = 2.0 * bf * tf + hw * tw + 4.0 * fillet_area;
    s.inertia = (bf * d * d * d - (bf - tw) * hw * hw * hw) / 12.0 + 4.0 * (fillet_area * fillet_y * fillet_y + fillet_own_inertia);
    s.depth = d;
    const double fy = m.steel ? m.steel->fy : 0.0;
    for (int side : {-1, 1})
        for (int l = 0; l < layers; ++l) {
            const double y = side * (hw / 2.0 + (l + 0.5) * tf / layers);
            for (int k = 0; k < strips; ++k) {
                // ECCS-like linear pattern: compression at the tips, tension at the web,
                // zero mean over the flange so that the section stays in equilibrium.
                const double x = -bf / 2.0 + (k + 0.5) * bf / strips;
                const double sigma = ratio * fy * (1.0 - 4.0 * std::abs(x) / bf);
                s.fibres.push_back({bf * tf / (strips * layers), y, sigma, 0, tf / (2.0 * layers)});
            }
        }
    for (int k = 0; k < web; ++k)
        s.fibres.push_back({hw * tw / web, -hw / 2.0 + (k + 0.5) * hw / web, 0.0, 0, hw / (2.0 * web)});
    if (r > 0.0)
        for (int side : {-1, 1}) s.fibres.push_back({2.0 * fillet_area, side * fillet_y, 0.0, 0, 0.2234 * r});
    if (t.has("slab")) read_slab(t, parts, d / 2.0);
}

void hollow_circle(TomlTableReader& t, SectionParts& parts) {
    const double D = t.number("diameter");
    const double th = t.number("thickness");
    if (2.0 * th > D) t.fail("thickness", "expected at most half the diameter");
    const int n = t.integer("fibres");
    SectionSpec& s = parts.spec();
    s.E = parts.main().E;
    const double d = D - 2.0 * th;
    s.area = M_PI * (D * D - d * d) / 4.0;
    s.inertia = M_PI * (D * D * D * D - d * d * d * d) / 64.0;
    s.depth = D;
    const double rm = (D - th) / 2.0, step = 2.0 * M_PI / n;
    for (int k = 0; k < n; ++k) {
        // At mid-wall; its edge reaches the outer face's highest point over the fibre's arc.
        const double angle = step * (k + 0.5), y = rm * std::sin(angle);
        const double lo = angle - step / 2.0, hi = angle + step / 2.0;
        const bool crest = std::cos(lo) * std::cos(hi) <= 0.0; // the arc holds the top or the bottom
        const double outer = D / 2.0 * (crest ? 1.0 : std::max(std::abs(std::sin(lo)), std::abs(std::sin(hi))));
        s.fibres.push_back({s.area / n, y, 0.0, 0, outer - std::abs(y)});
    }
    if (t.has("core_material")) {
        double E = 0.0;
        const int core = parts.material(t, "core_material", E);
        parts.add_stiffness(E, M_PI * d * d / 4.0, 0.0, M_PI * d * d * d * d / 64.0);
        if (parts.main().steel)
            for (const Fibre& f : disc_layers(d / 2.0, t.integer("core_fibres"), core)) s.fibres.push_back(f);
    }
}

// Fibres given one by one, [area, y] or [area, y, residual_stress], y from the centroid.
void explicit_fibres(TomlTableReader& t, SectionParts& parts) {
    SectionSpec& s = parts.spec();
    s.E = parts.main().E;
    const toml::array* a = t.array("fibres");
    if (!a || a->empty()) t.fail("fibres", "expected a list of [area, y] or [area, y, residual_stress]");
    for (const toml::node& f : *a) {
        const toml::array* v = f.as_array();
        if (!v || v->size() < 2 || v->size() > 3 || !v->is_homogeneous(toml::node_type::none) ||
            !std::all_of(v->begin(), v->end(), [](const toml::node& x) { return x.is_number(); }))
            throw SceneError(t.file(), line_of(f), t.qualified("fibres"), "expected [area, y] or [area, y, residual_stress] of numbers");
        Fibre fib{*(*v)[0].value<double>(), *(*v)[1].value<double>(), v->size() == 3 ? *(*v)[2].value<double>() : 0.0};
        if (!(fib.area > 0.0) || !std::isfinite(fib.y) || !std::isfinite(fib.residual_stress))
            throw SceneError(t.file(), line_of(f), t.qualified("fibres"), "expected a positive fibre area and finite values");
        s.fibres.push_back(fib);
    }
    double A = 0.0, Sy = 0.0, I = 0.0;
    for (const Fibre& f : s.fibres) {
        A += f.area;
        Sy += f.area * f.y;
    }
    for (const Fibre& f : s.fibres) I += f.area * (f.y - Sy / A) * (f.y - Sy / A);
    if (std::abs(Sy) > 1e-9 * A * std::sqrt(I / A)) t.fail("fibres", "fibre y must be measured from the centroid (Σ A·y = 0)");
    s.area = A;
    s.inertia = I;
    if (!(I > 0.0)) t.fail("fibres", "the fibres give no bending stiffness");
}

} // namespace

const std::vector<SectionShape>& section_shapes() {
    static const std::vector<SectionShape> shapes = {
        {"properties", properties},
        {"rectangle", rectangle},
        {"i", i_section},
        {"hollow_circle", hollow_circle},
        {"hollow_rectangle", hollow_rectangle},
        {"fibres", explicit_fibres},
    };
    return shapes;
}

const SectionShape& read_section_shape(TomlTableReader& t) {
    // A rolled profile is an I: `profile` alone chooses the shape.
    const std::string chosen = t.has("profile") && !t.has("shape") ? "i" : t.choice("shape");
    t.choose_group(chosen);
    return *std::find_if(section_shapes().begin(), section_shapes().end(), [&](const SectionShape& s) { return s.name == chosen; });
}

} // namespace plastica
