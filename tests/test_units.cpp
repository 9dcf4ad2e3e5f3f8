// Numbers with units: [units] names the scene's length and force, and a dimensioned value may be
// written "210 GPa", "300 mm", "-49.1 kN/m" (io/scene/units.hpp). The same frame in kN·m numbers, in
// strings with units, and in N·mm gives one load-factor curve.
#include "analysis_helpers.hpp"
#include "units.hpp"

#include <catch2/catch.hpp>

using namespace plastica;
using namespace plastica::testing;

TEST_CASE("Units convert to the scene's length and force", "[scene][units]") {
    const UnitSystem kN_m("m", "kN"), N_mm("mm", "N"), kip_in("in", "kip");
    CHECK(kN_m.to_scene("210 GPa", dimension::stress) == Approx(2.1e8).epsilon(1e-15));
    CHECK(N_mm.to_scene("210 GPa", dimension::stress) == Approx(2.1e5).epsilon(1e-15));
    CHECK(kN_m.to_scene("300 mm", dimension::length) == Approx(0.3).epsilon(1e-15));
    CHECK(N_mm.to_scene("-49.1 kN/m", dimension::force_per_length) == Approx(-49.1).epsilon(1e-15));
    CHECK(kN_m.to_scene("8356 cm4", dimension::second_moment) == Approx(8.356e-5).epsilon(1e-15));
    CHECK(kN_m.to_scene("78.1 cm^2", dimension::area) == Approx(78.1e-4).epsilon(1e-15));
    CHECK(kN_m.to_scene("120 kN*m", dimension::moment) == Approx(120.0).epsilon(1e-15));
    CHECK(N_mm.to_scene("120 kN·m", dimension::moment) == Approx(1.2e8).epsilon(1e-15));
    CHECK(kN_m.to_scene("5000 kN*m/rad", dimension::moment) == Approx(5000.0).epsilon(1e-15));
    CHECK(N_mm.to_scene("355 N/mm²", dimension::stress) == Approx(355.0).epsilon(1e-15));
    // Mass density and gravity: t/m³ and m/s² in kN and m, so that ρ·A·g comes out in kN/m.
    CHECK(kN_m.to_scene("7850 kg/m3", dimension::mass_density) == Approx(7.85).epsilon(1e-15));
    CHECK(kN_m.to_scene("-9.81 m/s2", dimension::acceleration) == Approx(-9.81).epsilon(1e-15));
    CHECK(kip_in.to_scene("50 ksi", dimension::stress) == Approx(50.0).epsilon(1e-12));
    CHECK(kip_in.to_scene("1 ft", dimension::length) == Approx(12.0).epsilon(1e-15));
    CHECK(kip_in.to_scene("1000 lbf", dimension::force) == Approx(1.0).epsilon(1e-15));

    CHECK_THROWS_WITH(kN_m.to_scene("210 kN", dimension::stress),
                      Catch::Contains("'kN' is a force") && Catch::Contains("but this value is a stress"));
    CHECK_THROWS_WITH(kN_m.to_scene("300 mmm", dimension::length), Catch::Contains("unknown unit 'mmm'"));
    CHECK_THROWS_WITH(kN_m.to_scene("300", dimension::length), Catch::Contains("has no unit"));
    CHECK_THROWS_WITH(kN_m.to_scene("mm", dimension::length), Catch::Contains("expected a number and its unit"));
    CHECK_THROWS_WITH(kN_m.to_scene("3 kN m", dimension::moment), Catch::Contains("without * or /"));
    CHECK_THROWS_AS(UnitSystem("kN", "m"), UnitError);
}

namespace {

// The portal (HEB 200 columns, IPE 300 beam, S355), numbers in kN and m.
std::string portal(const std::string& units, const std::string& E, const std::string& fy, const std::string& column,
                   const std::string& beam, const std::string& span, const std::string& height, const std::string& push,
                   const std::string& down, const std::string& increment, const std::string& target) {
    return "[scene]\nname = \"portal\"\n" + units + "[[material]]\nname = \"S355\"\nE = " + E + "\nfy = " + fy +
           "\n[[section]]\nname = \"HEB200\"\nmaterial = \"S355\"\nshape = \"i\"\n" + column +
           "[[section]]\nname = \"IPE300\"\nmaterial = \"S355\"\nshape = \"i\"\n" + beam +
           "[[line]]\nstart = [0.0, 0.0]\nend = [0.0, " + height + "]\nelements = 4\nsection = \"HEB200\"\n"
           "[[line]]\nstart = [0.0, " + height + "]\nend = [" + span + ", " + height + "]\nelements = 4\nsection = \"IPE300\"\n"
           "[[line]]\nstart = [" + span + ", " + height + "]\nend = [" + span + ", 0.0]\nelements = 4\nsection = \"HEB200\"\n"
           "[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n"
           "[[support]]\nat = [" + span + ", 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n"
           "[[load]]\nat = [0.0, " + height + "]\nfx = " + push + "\nfy = " + down + "\n"
           "[[load]]\nat = [" + span + ", " + height + "]\nfy = " + down + "\n"
           "[analysis]\nscheme = \"displacement_control\"\nincrement = " + increment + "\ncontrol_at = [0.0, " + height +
           "]\ncontrol_dof = \"ux\"\ntarget_displacement = " + target + "\nadaptive = false\n";
}

} // namespace

TEST_CASE("One frame in kN and m, in strings with units, and in N and mm has one load-factor curve", "[scene][units][frames]") {
    const Run numbers = run_scene(portal("", "2.1e8", "3.55e5",
                                         "depth = 0.2\nflange_width = 0.2\nflange_thickness = 0.015\nweb_thickness = 0.009\n",
                                         "depth = 0.3\nflange_width = 0.15\nflange_thickness = 0.0107\nweb_thickness = 0.0071\n",
                                         "6.0", "4.0", "100.0", "-250.0", "0.01", "0.2"));
    const Run strings = run_scene(portal("[units]\nlength = \"m\"\nforce = \"kN\"\n", "\"210 GPa\"", "\"355 MPa\"",
                                         "depth = \"200 mm\"\nflange_width = \"200 mm\"\nflange_thickness = \"15 mm\"\nweb_thickness = \"9 mm\"\n",
                                         "depth = \"300 mm\"\nflange_width = \"150 mm\"\nflange_thickness = \"10.7 mm\"\nweb_thickness = \"7.1 mm\"\n",
                                         "\"6 m\"", "4.0", "\"100 kN\"", "\"-250000 N\"", "\"10 mm\"", "\"20 cm\""));
    const Run millimetres = run_scene(portal("[units]\nlength = \"mm\"\nforce = \"N\"\n", "\"210 GPa\"", "355.0",
                                             "depth = 200.0\nflange_width = 200.0\nflange_thickness = 15.0\nweb_thickness = 9.0\n",
                                             "depth = 300.0\nflange_width = 150.0\nflange_thickness = 10.7\nweb_thickness = 7.1\n",
                                             "6000.0", "4000.0", "\"100 kN\"", "-250000.0", "10.0", "200.0"));
    REQUIRE(numbers.summary.reason == "target displacement reached");
    REQUIRE(strings.steps.size() == numbers.steps.size());
    REQUIRE(millimetres.steps.size() == numbers.steps.size());
    CHECK(millimetres.model.report.length_unit == "mm");
    CHECK(millimetres.model.report.force_unit == "N");
    // Equal to round-off: the converted numbers differ from the typed ones in their last bits.
    for (std::size_t k = 0; k < numbers.steps.size(); ++k) {
        CHECK(strings.steps[k].load == Approx(numbers.steps[k].load).epsilon(1e-9));
        CHECK(millimetres.steps[k].load == Approx(numbers.steps[k].load).epsilon(1e-9));
        CHECK(millimetres.steps[k].control_displacement == Approx(1000.0 * numbers.steps[k].control_displacement).epsilon(1e-9));
    }
    CHECK(numbers.max_load() > 1.7); // the frame yields and peaks (about 1.8 on 4 elements)
}

TEST_CASE("A value with a unit of the wrong kind, or without [units], is refused where it is written", "[scene][units]") {
    const std::string base = portal("[units]\nlength = \"m\"\nforce = \"kN\"\n", "\"210 GPa\"", "\"355 MPa\"",
                                    "depth = \"200 mm\"\nflange_width = 0.2\nflange_thickness = 0.015\nweb_thickness = 0.009\n",
                                    "depth = 0.3\nflange_width = 0.15\nflange_thickness = 0.0107\nweb_thickness = 0.0071\n", "6.0",
                                    "4.0", "100.0", "-250.0", "0.01", "0.2");
    auto message = [&](const std::string& from, const std::string& to) -> std::string {
        std::string text = base;
        const auto at = text.find(from);
        REQUIRE(at != std::string::npos);
        text.replace(at, from.size(), to);
        try {
            read_scene_text(text, "portal.toml");
        } catch (const SceneError& e) {
            return e.what();
        }
        return "no error";
    };
    CHECK_THAT(message("E = \"210 GPa\"", "E = \"210 kN\""),
               Catch::StartsWith("portal.toml:8: 'material[1].E': 'kN' is a force") && Catch::Contains("this value is a stress"));
    CHECK_THAT(message("depth = \"200 mm\"", "depth = \"200 N\""),
               Catch::StartsWith("portal.toml:14: 'section[1].depth': 'N' is a force"));
    CHECK_THAT(message("fx = 100.0", "fx = \"100 kN/m\""), Catch::Contains("'load[1].fx': 'kN/m' is a force per length"));
    CHECK_THAT(message("elements = 4\nsection = \"IPE300\"", "elements = \"4 m\"\nsection = \"IPE300\""),
               Catch::Contains("'line[2].elements': expected a whole number"));
    CHECK_THAT(message("[units]\nlength = \"m\"\nforce = \"kN\"\n", ""),
               Catch::Contains("'material[1].E': \"210 GPa\" is a string: a value with a unit needs a [units] table"));
    CHECK_THAT(message("length = \"m\"", "length = \"kN\""), Catch::Contains("'units.length': 'kN' is not a length unit"));
    CHECK_THAT(message("force = \"kN\"", "force = \"kNm\""), Catch::Contains("'units.force': 'kNm' is not a force unit"));
    CHECK_THAT(message("target_displacement = 0.2", "target_displacement = \"0.2 kN\""),
               Catch::Contains("'analysis.target_displacement': 'kN' is a force, but this value is a length"));
    // A pure number keeps no unit: the load factor of a load-controlled analysis.
    CHECK_THAT(message("scheme = \"displacement_control\"\nincrement = 0.01", "scheme = \"displacement_control\"\nincrement = \"0.01 kN\""),
               Catch::Contains("'analysis.increment': 'kN' is a force, but this value is a length"));
}
