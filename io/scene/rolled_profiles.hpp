// Rolled I and H profiles by name (`[[section]] profile = "HEB 200"`): the dimensions of
// EN 10365:2017 (IPE, HEA, HEB, HEM; millimetres) and of the AISC Shapes Database v15.0
// (W shapes; inches, the root radius taken as k_des − t_f), with the tabulated A, I_y and
// W_pl,y that tests/test_rolled_profiles.cpp checks the built sections against.
#pragma once

#include <string>
#include <vector>

namespace plastica {

struct RolledProfile {
    const char* name;      // as tabulated: "HEB 200", "W14x90"
    double depth, flange_width, web_thickness, flange_thickness, root_radius;
    double area, inertia, plastic_modulus; // tabulated: cm², cm⁴, cm³ (W: in², in⁴, in³)
    bool inches;           // W shapes
};

const std::vector<RolledProfile>& rolled_profiles();
// The profile of this name, spaces and case aside ("heb200" is "HEB 200"); null if none.
const RolledProfile* find_rolled_profile(const std::string& name);
// The tabulated name nearest to a misspelt one, for the message.
std::string nearest_profile_name(const std::string& name);

} // namespace plastica
