// The fibre laws a scene may name (`[[material]] law = …`): each with the keys of its own and a
// maker. Adding a law: its file pair, and one line in material_registry.cpp.
#pragma once

#include "material/uniaxial_material.hpp"
#include "model/model.hpp"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace plastica {

// A law's parameter out of its range: the key, and what was expected.
struct MaterialParameterError : std::invalid_argument {
    MaterialParameterError(std::string key, const std::string& what) : std::invalid_argument(what), key(std::move(key)) {}
    std::string key;
};

// A key of a law's own, with its range [min, max) and what it means (io/scene/scene_schema.cpp
// declares it under `[[material]]` for that law).
struct LawParameter {
    std::string name;
    double min, max;
    const char* doc;
    double fallback = HUGE_VAL; // HUGE_VAL: the key is needed
    bool stress = false;        // a stress (units apply), else a plain number
};

struct MaterialLaw {
    const char* name;
    std::vector<LawParameter> parameters; // keys of this law beyond E, fy and ultimate_strain
    const char* description;
    // Throws MaterialParameterError for a parameter out of range.
    std::unique_ptr<UniaxialMaterial> (*make)(const SteelSpec& spec, double residual_stress);
    // Whether the moment of its sections stops at the fully plastic capacity (its sections then
    // default to refined plastic hinges, else to a plastic zone).
    bool perfectly_plastic;
    // The key of its strength (SteelSpec::fy): `fy`, or one of its parameters (concrete's `fc`).
    const char* strength = "fy";
};

const std::vector<MaterialLaw>& material_laws();
// The ratio b = E_sh/E of a linearly hardening law (its `hardening_ratio`); 0 for a law without.
double hardening_ratio(const SteelSpec& spec);
// Null for an unknown name.
const MaterialLaw* find_material_law(const std::string& name);
// The fibre of a section: residual_stress is its initial stress.
std::unique_ptr<UniaxialMaterial> make_material(const SteelSpec& spec, double residual_stress);

} // namespace plastica
