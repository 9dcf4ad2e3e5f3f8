// The section shapes a scene may name (`[[section]] shape = …`): each with the builder of its
// fibre layout and elastic properties. A new shape is one entry here and its keys in
// io/scene/scene_schema.cpp (declared `.of("shape name")`).
#pragma once

#include "model/model.hpp"
#include "section_parts.hpp"
#include "toml_table_reader.hpp"

#include <optional>
#include <string>
#include <vector>

namespace plastica {

struct SectionShape {
    std::string name;
    // Fills parts.spec(): A and I of its own material about its centre y = 0, and the fibres.
    void (*build)(TomlTableReader& table, SectionParts& parts);
};

const std::vector<SectionShape>& section_shapes();
// The shape a [[section]] table names (default "properties"), chosen as the table's group so
// that a key of another shape is a located error naming that shape.
const SectionShape& read_section_shape(TomlTableReader& table);

// A b × h rectangle in `fibres` equal layers through its depth.
SectionSpec rectangle_section(double E, double b, double h, int fibres);

} // namespace plastica
