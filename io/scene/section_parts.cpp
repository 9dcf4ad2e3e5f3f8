#include "section_parts.hpp"

#include "scene_error.hpp"
#include "scene_schema.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

namespace {

const TableSpec& rebar_spec() {
    static const TableSpec spec{"rebar", false, "", {
        number("y", dimension::length).needed().about("from the shape's centre, +y up"),
        number("area", dimension::area).positive().needed().about("the bar's area"),
        text("material").needed().about("a `[[material]]`'s name"),
    }};
    return spec;
}

} // namespace

int SectionParts::material(TomlTableReader& table, const std::string& key, double& E) {
    const ShapeMaterial m = lookup_(table, key);
    E = m.E;
    if (!main_.steel) return 0; // an elastic section: stiffness only, no fibres
    if (!m.steel) table.fail(key, "an inelastic section's parts need an inelastic material (fy, or a law such as concrete)");
    section_.other_materials.push_back(*m.steel);
    return static_cast<int>(section_.other_materials.size());
}

void SectionParts::add_stiffness(double E, double area, double centroid, double own_inertia) {
    parts_.push_back({E * area, E * area * centroid, E * (own_inertia + area * centroid * centroid)});
}

void SectionParts::read_rebars(TomlTableReader& t) {
    if (!t.has("rebars")) return;
    const toml::array* list = t.array("rebars");
    if (!list || list->empty()) t.fail("rebars", "expected a list of tables { y = …, area = …, material = \"…\" }");
    for (std::size_t i = 0; i < list->size(); ++i) {
        const toml::table* bar = (*list)[i].as_table();
        if (!bar) throw SceneError(t.file(), line_of((*list)[i]), t.qualified("rebars"), "expected a table { y = …, area = …, material = \"…\" }");
        TomlTableReader r(*bar, t.file(), t.qualified("rebars") + "[" + std::to_string(i + 1) + "]", rebar_spec(), t.units());
        const double y = r.number("y"), area = r.number("area");
        double E = 0.0;
        const int index = material(r, "material", E);
        r.finish();
        add_stiffness(E, area, y, 0.0);
        if (!main_.steel) {
            add_stiffness(main_.E, -area, y, 0.0); // an elastic section's bars sit in its own material
            continue;
        }
        // The layer the bar sits in (concrete, of the shape or a slab), and its nearest
        // neighbours of the same material where the bar is larger, give up the bar's area.
        auto host = std::find_if(section_.fibres.begin(), section_.fibres.end(), [&](const Fibre& f) {
            return f.material != index && f.extent > 0.0 && std::abs(f.y - y) <= f.extent;
        });
        if (host != section_.fibres.end()) {
            const int host_material = host->material;
            const double host_E = host_material == 0 ? main_.E : section_.other_materials[static_cast<std::size_t>(host_material - 1)].E;
            std::vector<Fibre*> nearest;
            for (Fibre& f : section_.fibres)
                if (f.material == host_material && f.extent > 0.0) nearest.push_back(&f);
            std::sort(nearest.begin(), nearest.end(), [&](const Fibre* a, const Fibre* b) { return std::abs(a->y - y) < std::abs(b->y - y); });
            double left = area;
            for (Fibre* f : nearest) {
                if (left <= 0.0) break;
                const double taken = std::min(left, f->area);
                add_stiffness(host_E, -taken, f->y, 0.0);
                f->area -= taken;
                left -= taken;
            }
            section_.fibres.erase(std::remove_if(section_.fibres.begin(), section_.fibres.end(), [](const Fibre& f) { return f.area <= 0.0; }),
                                  section_.fibres.end());
        }
        section_.fibres.push_back({area, y, 0.0, index, 0.0});
    }
}

void SectionParts::finish() {
    PartStiffness total{main_.E * section_.area, 0.0, main_.E * section_.inertia};
    for (const PartStiffness& p : parts_) {
        total.EA += p.EA;
        total.ES += p.ES;
        total.EI += p.EI;
    }
    if (parts_.empty()) return;
    const double centroid = total.ES / total.EA;
    section_.area = total.EA / main_.E;
    section_.inertia = (total.EI - total.EA * centroid * centroid) / main_.E;
    for (Fibre& f : section_.fibres) f.y -= centroid;
}

std::vector<Fibre> disc_layers(double R, int layers, int material) {
    // Area under the chord width 2√(R² − y²) up to y, and its first moment.
    const auto area_to = [R](double y) { return y * std::sqrt(R * R - y * y) + R * R * std::asin(y / R); };
    const auto moment_to = [R](double y) { return -2.0 / 3.0 * std::pow(R * R - y * y, 1.5); };
    std::vector<Fibre> out;
    for (int k = 0; k < layers; ++k) {
        const double lo = -R + 2.0 * R * k / layers, hi = -R + 2.0 * R * (k + 1) / layers;
        const double area = area_to(hi) - area_to(lo);
        out.push_back({area, (moment_to(hi) - moment_to(lo)) / area, 0.0, material, R / layers});
    }
    return out;
}

} // namespace plastica
