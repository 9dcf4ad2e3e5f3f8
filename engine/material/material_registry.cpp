#include "material/material_registry.hpp"

#include "material/bilinear_steel.hpp"
#include "material/concrete.hpp"
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
           "hardening or layers: with b = 1e-4 they reach 65 % of the diameter; perfectly plastic fibres in a "
           "plastic zone get 30 layers by default and do too with plates acting along the members (`acts_on`, "
           "docs/method.md)"}}, "bilinear with linear kinematic hardening (tangent b·E past yield, Bauschinger effect)",
         make<KinematicHardeningSteel>, false},
        {"concrete",
         {{"fc", 0.0, HUGE_VAL, "compressive strength (a positive number); the material's strength in place of fy", HUGE_VAL, true},
          {"eps_c2", 1e-4, 0.02, "strain at which the parabola reaches fc (EN 1992-1-1: 0.002 up to C50/60)", 0.002},
          {"eps_cu2", 1e-4, 0.05, "design strain limit of a bent section's compressed face; past it the stress stays fc", 0.0035},
          {"n", 1.0, 10.0, "the parabola's exponent; the initial slope is n·fc/eps_c2 (giving E sets n = E·eps_c2/fc)", 2.0},
          {"ft", 0.0, HUGE_VAL, "tensile strength; 0: no tension", 0.0, true},
          {"eps_tu", 0.0, 1.0, "with ft: the strain beyond the unloading point where tension has softened linearly to zero", 0.001}},
         "EN 1992-1-1's parabola–rectangle with Karsan–Jirsa unloading (OpenSees' Concrete01), no tension unless ft",
         make<Concrete>, false, "fc"},
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
