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
    s.area = t.number("A");
    s.inertia = t.number("I");
    s.depth = t.number_or("thickness", 0.0); // 0: the equivalent rectangle's depth
    if (m.steel) {
        // A and I alone define no fibres: an equivalent rectangle carries them.
        const double h = std::sqrt(12.0 * s.inertia / s.area);
        s.fibres = rectangle_section(s.E, s.area / h, h, t.integer("fibres")).fibres;
    }
    return s;
}

SectionSpec rectangle(TomlTableReader& t, const ShapeMaterial& m) {
    const double b = t.number("b");
    const double h = t.number("h");
    SectionSpec s = rectangle_section(m.E, b, h, t.integer("fibres"));
    s.depth = h;
    return s;
}

// I or H section: flanges split into strips across the width and layers through the
// thickness (so a residual-stress pattern across the flange is represented), web in layers,
// and with a root radius r the four fillets between web and flanges, each (1 − π/4)·r² with its
// centroid 0.2234·r from the flange (a rolled section's tabulated A, I and W_pl).
SectionSpec i_section(TomlTableReader& t, const ShapeMaterial& m) {
    const double d = t.number("depth");
    const double bf = t.number("flange_width");
    const double tf = t.number("flange_thickness");
    const double tw = t.number("web_thickness");
    if (2.0 * tf >= d) t.fail("flange_thickness", "two flanges must be thinner than the depth");
    if (tw > bf) t.fail("web_thickness", "the web must not be wider than the flanges");
    const int strips = t.integer("flange_strips");
    const int layers = t.integer("flange_layers");
    const int web = t.integer("web_fibres");
    const double ratio = t.number("residual_stress");
    const double hw = d - 2.0 * tf;
    const double r = t.number("root_radius");
    if (2.0 * r > hw || tw + 2.0 * r > bf)
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
    const double D = t.number("diameter");
    const double th = t.number("thickness");
    if (2.0 * th > D) t.fail("thickness", "expected at most half the diameter");
    const int n = t.integer("fibres");
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
        {"properties", properties},
        {"rectangle", rectangle},
        {"i", i_section},
        {"hollow_circle", hollow_circle},
        {"fibres", explicit_fibres},
    };
    return shapes;
}

const SectionShape& read_section_shape(TomlTableReader& t) {
    const std::string chosen = t.choice("shape");
    t.choose_group(chosen);
    return *std::find_if(section_shapes().begin(), section_shapes().end(), [&](const SectionShape& s) { return s.name == chosen; });
}

} // namespace plastica
