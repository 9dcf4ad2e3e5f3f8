// The section shapes a scene may name (`[[section]] shape = …`): each with the builder of its
// fibre layout and elastic properties. A new shape is one entry here and its keys in
// io/scene_schema.cpp (declared `.of("shape name")`).
#pragma once

#include "model/model.hpp"
#include "toml_table_reader.hpp"

#include <optional>
#include <string>
#include <vector>

namespace plastica {

// What a shape takes from its material.
struct ShapeMaterial {
    double E = 0.0;
    std::optional<SteelSpec> steel; // fibres only for an inelastic material (their residual stresses read fy)
};

struct SectionShape {
    std::string name;
    SectionSpec (*build)(TomlTableReader& table, const ShapeMaterial& material);
};

const std::vector<SectionShape>& section_shapes();
// The shape a [[section]] table names (default "properties"), chosen as the table's group so
// that a key of another shape is a located error naming that shape.
const SectionShape& read_section_shape(TomlTableReader& table);

// A b × h rectangle in `fibres` equal layers through its depth.
SectionSpec rectangle_section(double E, double b, double h, int fibres);

} // namespace plastica
