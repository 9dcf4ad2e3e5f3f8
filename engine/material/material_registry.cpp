#include "material/material_registry.hpp"

#include "material/bilinear_steel.hpp"
#include "material/kinematic_hardening_steel.hpp"

namespace plastica {

namespace {

template <class Law>
std::unique_ptr<UniaxialMaterial> make(const SteelSpec& spec, double residual_stress) {
    return std::make_unique<Law>(spec, residual_stress);
}

} // namespace

const std::vector<MaterialLaw>& material_laws() {
    static const std::vector<MaterialLaw> laws{
        {"bilinear", {}, "elastic–perfectly plastic (the CS-ASA paper's law)", make<BilinearSteel>, true},
        {"kinematic_hardening",
         {{"hardening_ratio", 0.0, 1.0,
           "b = E_sh/E; fibre sections crushed far into the plastic range (a ring between plates) need some "
           "hardening: with b = 1e-4 they reach 65 % of the diameter, perfectly plastic fibres stop far earlier"}}, "bilinear with linear kinematic hardening (tangent b·E past yield, Bauschinger effect)",
         make<KinematicHardeningSteel>, false},
    };
    return laws;
}

double hardening_ratio(const SteelSpec& spec) {
    const auto b = spec.parameters.find("hardening_ratio");
    return b == spec.parameters.end() ? 0.0 : b->second;
}

const MaterialLaw* find_material_law(const std::string& name) {
    for (const MaterialLaw& law : material_laws())
        if (name == law.name) return &law;
    return nullptr;
}

std::unique_ptr<UniaxialMaterial> make_material(const SteelSpec& spec, double residual_stress) {
    const MaterialLaw* law = find_material_law(spec.law);
    if (!law) throw MaterialParameterError("law", "no material law named '" + spec.law + "'");
    return law->make(spec, residual_stress);
}

} // namespace plastica
