// Rolled profiles by name: the section built from a table's plates and root radius has the
// table's A, I and W_pl (EN 10365 in mm; AISC W shapes in inches, whose tabulated d and b_f are
// rounded to 0.01 in and whose fillet is taken from k_des, hence their wider tolerance).
#include "rolled_profiles.hpp"
#include "scene_error.hpp"
#include "scene_reader.hpp"
#include "section/fibre_section.hpp"

#include <catch2/catch.hpp>

using namespace plastica;

namespace {

std::string scene(const std::string& profile, const std::string& length) {
    return R"([scene]
name = "p"
[units]
length = ")" + length + R"("
force = "N"
[[material]]
name = "steel"
E = 1
fy = 1
[[section]]
name = "s"
material = "steel"
profile = ")" + profile + R"("
flange_strips = 1
flange_layers = 40
web_fibres = 400
[[line]]
start = [0, 0]
end = [0, 100000]
elements = 1
section = "s"
[[support]]
at = [0, 0]
fix = ["ux", "uy", "rz"]
[[load]]
at = [0, 100000]
fx = 1
[analysis]
scheme = "load_control"
increment = 1
target_load_factor = 1
)";
}

} // namespace

TEST_CASE("Rolled profiles have their tabulated area and second moment and plastic modulus", "[section][profiles]") {
    const char* name = GENERATE("IPE 200", "IPE 300", "IPE 600", "HEA 200", "HEA 400", "HEB 200", "HEB 300", "HEB 500",
                                "HEM 200", "HEM 400", "W14x90", "W8x31", "W24x55", "W36x150");
    const RolledProfile& p = *find_rolled_profile(name);
    CAPTURE(name);
    // Sections in cm (EN) or inches (W), the tables' units: A, I and W_pl compare directly.
    const SectionSpec s = read_scene_text(scene(name, p.inches ? "in" : "cm"), "p.toml").sections.at(0);
    const double tolerance = p.inches ? 0.015 : 0.005;
    CHECK(s.area == Approx(p.area).epsilon(tolerance));
    CHECK(s.inertia == Approx(p.inertia).epsilon(tolerance));
    // W_pl = M_p / fy, with fy = 1: the fibres' fully plastic moment.
    CHECK(FibreSection(s).moment_capacity(0.0, 1.0) == Approx(p.plastic_modulus).epsilon(tolerance));
}

TEST_CASE("A profile's name is read with any spacing and case and a misspelt one suggests the nearest", "[section][profiles]") {
    CHECK(find_rolled_profile("heb200") == find_rolled_profile("HEB 200"));
    CHECK(find_rolled_profile("w14X90") == find_rolled_profile("W14x90"));
    try {
        read_scene_text(scene("HEB 210", "mm"), "p.toml");
        FAIL("an unknown profile was accepted");
    } catch (const SceneError& e) {
        CHECK_THAT(e.what(), Catch::Contains("p.toml:13: 'section[1].profile': no rolled profile named 'HEB 210'"));
        CHECK_THAT(e.what(), Catch::Contains("did you mean 'HEB 200'?"));
    }
}
