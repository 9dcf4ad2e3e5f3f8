// The parts of a section of several materials: rebars on any shape, the concrete core of a tube,
// the slab of a composite beam. Each part adds fibres of its own law and its share of the elastic
// stiffness; the section is then centred on its elastic centroid (Σ E·A·y = 0), so that its axial
// force and its moment do not couple while it is elastic.
#pragma once

#include "model/model.hpp"
#include "toml_table_reader.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace plastica {

// What a shape takes from a material.
struct ShapeMaterial {
    double E = 0.0;
    std::optional<SteelSpec> steel; // fibres only for an inelastic material (their residual stresses read fy)
};

// The material a key names (`core_material`, a rebar's `material`), an error located at it if
// there is none of that name.
using MaterialLookup = std::function<ShapeMaterial(TomlTableReader& table, const std::string& key)>;

// A part's elastic stiffness about the shape's own axis y = 0: E·A, E·A·ȳ and E·(I_own + A·ȳ²).
struct PartStiffness {
    double EA = 0.0, ES = 0.0, EI = 0.0;
};

class SectionParts {
public:
    SectionParts(const ShapeMaterial& main, MaterialLookup lookup) : main_(main), lookup_(std::move(lookup)) {}

    // The section the shape builds (its own A and I about y = 0, its fibres).
    SectionSpec& spec() { return section_; }
    const ShapeMaterial& main() const { return main_; }
    // Layers through a rectangle's depth where the scene gives no `fibres`.
    int default_layers() const { return default_layers_; }
    void set_default_layers(int layers) { default_layers_ = layers; }

    // The fibre material index of the material `key` names (1 + its place in other_materials);
    // its E through `E`. Refused for an elastic material in an inelastic section.
    int material(TomlTableReader& table, const std::string& key, double& E);
    void add_stiffness(double E, double area, double centroid, double own_inertia);
    // `rebars = [{ y, area, material }, …]`: point fibres; the section's own fibre that holds a
    // bar gives up the bar's area (the concrete a bar displaces is not counted twice).
    void read_rebars(TomlTableReader& table);
    // The main shape's own stiffness (its A and I about y = 0), then E-weighted centring.
    void finish();

private:
    SectionSpec section_;
    ShapeMaterial main_;
    MaterialLookup lookup_;
    std::vector<PartStiffness> parts_;
    int default_layers_ = plastica::default_layers;
};

// Horizontal layers of a disc of radius R (a filled tube's core): exact areas and centroids.
std::vector<Fibre> disc_layers(double R, int layers, int material);

} // namespace plastica
