#include "section_shapes.hpp"

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
        s.fibres.push_back({b * h / fibres, -h / 2.0 + (i + 0.5) * h / fibres, 0.0});
    return s;
}

namespace {

// A and I; an inelastic material's fibres in the equivalent rectangle.
SectionSpec properties(TomlTableReader& t, const ShapeMaterial& m) {
    SectionSpec s;
    s.E = m.E;
    s.area = t.positive("A", dimension::area);
    s.inertia = t.positive("I", dimension::second_moment);
    s.depth = t.number_or("thickness", 0.0, dimension::length);
    if (t.has("thickness") && !(s.depth > 0.0)) t.fail("thickness", "expected a positive depth between the surfaces");
    if (m.steel) {
        // A and I alone define no fibres: an equivalent rectangle carries them.
        const double h = std::sqrt(12.0 * s.inertia / s.area);
        s.fibres = rectangle_section(s.E, s.area / h, h, t.integer_or("fibres", 10, 2, 100000)).fibres;
    }
    return s;
}

SectionSpec rectangle(TomlTableReader& t, const ShapeMaterial& m) {
    const double b = t.positive("b", dimension::length);
    const double h = t.positive("h", dimension::length);
    SectionSpec s = rectangle_section(m.E, b, h, t.integer_or("fibres", 10, 1, 100000));
    s.depth = h;
    return s;
}

// I or H section: flanges split into strips across the width and layers through the
// thickness (so a residual-stress pattern across the flange is represented), web in layers,
// and with a root radius r the four fillets between web and flanges, each (1 − π/4)·r² with its
// centroid 0.2234·r from the flange (a rolled section's tabulated A, I and W_pl).
SectionSpec i_section(TomlTableReader& t, const ShapeMaterial& m) {
    const double d = t.positive("depth", dimension::length);
    const double bf = t.positive("flange_width", dimension::length);
    const double tf = t.positive("flange_thickness", dimension::length);
    const double tw = t.positive("web_thickness", dimension::length);
    if (2.0 * tf >= d) t.fail("flange_thickness", "two flanges must be thinner than the depth");
    if (tw > bf) t.fail("web_thickness", "the web must not be wider than the flanges");
    const int strips = t.integer_or("flange_strips", 10, 1, 1000);
    const int layers = t.integer_or("flange_layers", 2, 1, 1000);
    const int web = t.integer_or("web_fibres", 10, 1, 10000);
    const double ratio = t.number_or("residual_stress", 0.0);
    if (ratio < 0.0 || ratio >= 1.0) t.fail("residual_stress", "expected a fraction of fy in [0, 1)");
    const double hw = d - 2.0 * tf;
    const double r = t.number_or("root_radius", 0.0, dimension::length);
    if (r < 0.0 || 2.0 * r > hw || tw + 2.0 * r > bf)
        t.fail("root_radius", "expected a radius ≥ 0 whose fillets fit between the flanges and within their width");
    const double fillet_area = (1.0 - M_PI / 4.0) * r * r, fillet_y = hw / 2.0 - 0.2234 * r;
    const double fillet_own_inertia = 0.0075 * r * r * r * r; // a spandrel's about its own centroid
    SectionSpec s;
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
                s.fibres.push_back({bf * tf / (strips * layers), y, sigma});
            }
        }
    for (int k = 0; k < web; ++k)
        s.fibres.push_back({hw * tw / web, -hw / 2.0 + (k + 0.5) * hw / web, 0.0});
    if (r > 0.0)
        for (int side : {-1, 1}) s.fibres.push_back({2.0 * fillet_area, side * fillet_y, 0.0});
    return s;
}

SectionSpec hollow_circle(TomlTableReader& t, const ShapeMaterial& m) {
    const double D = t.positive("diameter", dimension::length);
    const double th = t.positive("thickness", dimension::length);
    if (2.0 * th > D) t.fail("thickness", "expected at most half the diameter");
    const int n = t.integer_or("fibres", 24, 4, 100000);
    SectionSpec s;
    s.E = m.E;
    const double d = D - 2.0 * th;
    s.area = M_PI * (D * D - d * d) / 4.0;
    s.inertia = M_PI * (D * D * D * D - d * d * d * d) / 64.0;
    s.depth = D;
    const double rm = (D - th) / 2.0;
    for (int k = 0; k < n; ++k) s.fibres.push_back({s.area / n, rm * std::sin(2.0 * M_PI * (k + 0.5) / n), 0.0});
    return s;
}

// Fibres given one by one, [area, y] or [area, y, residual_stress], y from the centroid.
SectionSpec explicit_fibres(TomlTableReader& t, const ShapeMaterial& m) {
    SectionSpec s;
    s.E = m.E;
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
    return s;
}

} // namespace

const std::vector<SectionShape>& section_shapes() {
    static const std::vector<SectionShape> shapes = {
        {"properties", {"A", "I", "fibres", "thickness"}, properties},
        {"rectangle", {"b", "h", "fibres"}, rectangle},
        {"i", {"depth", "flange_width", "flange_thickness", "web_thickness", "flange_strips", "flange_layers", "web_fibres",
               "residual_stress", "root_radius"}, i_section},
        {"hollow_circle", {"diameter", "thickness", "fibres"}, hollow_circle},
        {"fibres", {"fibres"}, explicit_fibres},
    };
    return shapes;
}

const SectionShape& read_section_shape(TomlTableReader& t) {
    std::vector<std::string> names;
    for (const SectionShape& s : section_shapes()) names.push_back(s.name);
    const std::string chosen = t.choice("shape", names, "properties");
    const SectionShape& own = *std::find_if(section_shapes().begin(), section_shapes().end(),
                                            [&](const SectionShape& s) { return s.name == chosen; });
    for (const SectionShape& other : section_shapes())
        for (const std::string& key : other.keys)
            if (&other != &own && t.has(key) && std::find(own.keys.begin(), own.keys.end(), key) == own.keys.end())
                t.fail(key, "a key of shape = \"" + other.name + "\", not of shape = \"" + own.name + "\"");
    return own;
}

} // namespace plastica
