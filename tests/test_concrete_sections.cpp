// Sections of several materials: the concrete law against its formulas, the capacity of a
// reinforced-concrete rectangle by the strain-limit method of EN 1992-1-1 against a hand
// calculation (the stress block integrated in 20 000 strips, independent of the fibres), the
// squash load of filled tubes and the plastic moment of composite beams from the plastic neutral
// axis, and the RC column pushed over beside OpenSees.
#include "analysis_helpers.hpp"
#include "material/concrete.hpp"
#include "section/fibre_section.hpp"
#include "section/strain_limit_capacity.hpp"

#include <catch2/catch.hpp>

#include <fstream>

using namespace plastica;
using namespace plastica::testing;

namespace {

SteelSpec concrete(double fc, double ft = 0.0) {
    SteelSpec s;
    s.law = "concrete";
    s.fy = fc;
    s.E = 2.0 * fc / 0.002;
    if (ft > 0.0) s.parameters["ft"] = ft;
    return s;
}

const char* materials = R"(
[scene]
name = "sections"
[units]
length = "mm"
force = "N"
[[material]]
name = "C30"
law = "concrete"
fc = 30
[[material]]
name = "C40"
law = "concrete"
fc = 40
[[material]]
name = "B500"
E = 200000
fy = 500
[[material]]
name = "S355"
E = 210000
fy = 355
)";

const char* frame = R"(
[[line]]
start = [0, 0]
end = [0, 3000]
elements = 2
section = "s"
[[support]]
at = [0, 0]
fix = ["ux", "uy", "rz"]
[[load]]
at = [0, 3000]
fx = 1
[analysis]
scheme = "load_control"
increment = 1
target_load_factor = 1
)";

SectionSpec section_of(const std::string& section) {
    return read_scene_text(std::string(materials) + section + frame, "sections.toml").sections.at(0);
}

// EN 1992-1-1's parabola–rectangle (n = 2), compression negative, no tension.
double concrete_stress(double strain, double fc) {
    if (strain >= 0.0) return 0.0;
    if (strain <= -0.002) return -fc;
    const double u = 1.0 + strain / 0.002;
    return -fc * (1.0 - u * u);
}

struct Bar {
    double y, area;
};

// N and M of a b × h rectangle of fc with bars of B500, under ε(y) = top + (h/2 − y)·slope.
std::pair<double, double> rc_resultants(double b, double h, double fc, const std::vector<Bar>& bars, double top, double slope) {
    double N = 0.0, M = 0.0;
    const int strips = 20000;
    for (int k = 0; k < strips; ++k) {
        const double y = -h / 2.0 + (k + 0.5) * h / strips;
        const double force = concrete_stress(top + (h / 2.0 - y) * slope, fc) * b * h / strips;
        N += force;
        M -= force * y;
    }
    for (const Bar& bar : bars) {
        const double strain = top + (h / 2.0 - bar.y) * slope;
        const double stress = std::clamp(200000.0 * strain, -500.0, 500.0) - concrete_stress(strain, fc);
        N += stress * bar.area;
        M -= stress * bar.area * bar.y;
    }
    return {N, M};
}

} // namespace

TEST_CASE("Concrete follows the parabola-rectangle and unloads as Karsan and Jirsa", "[concrete]") {
    Concrete c(concrete(30.0), 0.0);
    CHECK(c.elastic_modulus() == Approx(30000.0));
    CHECK(c.set_trial_strain(-0.001).stress == Approx(-22.5));        // −fc·(1 − (1 − 0.5)²)
    CHECK(c.set_trial_strain(-0.001).tangent == Approx(15000.0));     // fc·n·(1 − η)/εc2
    CHECK(c.set_trial_strain(-0.0025).stress == Approx(-30.0));
    CHECK(c.set_trial_strain(-0.005).stress == Approx(-30.0));        // past εcu2 it stays at fc
    CHECK(c.set_trial_strain(0.001).stress == 0.0);                   // no tension
    // To −0.003 and back: η = 1.5, εp = (0.145·2.25 + 0.13·1.5)·εc2 = 0.0010425; the line from
    // (−0.003, −30) to εp has slope 30/0.0019575, gentler than E.
    c.set_trial_strain(-0.003);
    c.commit();
    const double slope = 30.0 / (0.003 - 0.0010425);
    CHECK(c.set_trial_strain(-0.002).stress == Approx(slope * (-0.002 + 0.0010425)));
    CHECK(c.set_trial_strain(-0.002).tangent == Approx(slope));
    CHECK(c.set_trial_strain(-0.0005).stress == 0.0);                 // past εp: open
    c.set_trial_strain(-0.0005);
    c.commit();
    CHECK(c.set_trial_strain(-0.0025).stress == Approx(slope * (-0.0025 + 0.0010425))); // reloads on the line
    CHECK(c.set_trial_strain(-0.0035).stress == Approx(-30.0));       // and back on the envelope
    // A small excursion unloads at E: from −0.0002 (η = 0.1), εp = (0.00145 + 0.013)·εc2.
    Concrete d(concrete(30.0), 0.0);
    const double s0 = d.set_trial_strain(-0.0002).stress;
    d.commit();
    const double ep = -(0.145 * 0.01 + 0.13 * 0.1) * 0.002;
    const double expected_slope = std::min(30000.0, s0 / (-0.0002 - ep));
    CHECK(d.set_trial_strain(-0.0001).tangent == Approx(expected_slope));
}

TEST_CASE("Concrete with a tensile strength cracks and softens linearly and unloads to its origin", "[concrete]") {
    SteelSpec spec = concrete(30.0, 3.0);
    spec.parameters["eps_tu"] = 0.001;
    Concrete c(spec, 0.0);
    CHECK(c.set_trial_strain(5e-5).stress == Approx(1.5));
    CHECK(c.set_trial_strain(1e-4).stress == Approx(3.0));
    CHECK(c.set_trial_strain(5.5e-4).stress == Approx(3.0 * (0.001 - 5.5e-4) / (0.001 - 1e-4)));
    CHECK(c.set_trial_strain(2e-3).stress == 0.0);
    c.set_trial_strain(5.5e-4);
    c.commit();
    CHECK(c.set_trial_strain(2.75e-4).stress == Approx(0.75)); // along the secant to the origin
    CHECK(c.set_trial_strain(-0.001).stress == Approx(-22.5)); // compression is unaffected
}

TEST_CASE("A reinforced-concrete rectangle's capacity by strain limits matches the hand calculation", "[concrete][section]") {
    // 300 × 500, C30, 942 mm² of B500 at 50 from each face; 200 layers.
    const SectionSpec spec = section_of(R"(
[[section]]
name = "s"
material = "C30"
shape = "rectangle"
b = 300
h = 500
fibres = 200
rebars = [{ y = 200, area = 942, material = "B500" }, { y = -200, area = 942, material = "B500" }]
)");
    const FibreSection section(spec);
    const std::vector<Bar> bars{{200.0, 942.0}, {-200.0, 942.0}};
    REQUIRE(section.has_strain_limits());
    const CapacityCurve& capacity = section.hinge_capacity(1.0);
    // Squash: the whole section at εc2; the bars at E·εc2 = 400 < fy. (Profiles a little
    // inclined carry more, with the compressed bars at fy, and a moment: the curve reaches below.)
    const double squash = -(30.0 * (150000.0 - 1884.0) + 1884.0 * 400.0);
    const LimitState uniform = strain_limit_states(section)[0].back();
    CHECK(uniform.N == Approx(squash).epsilon(0.01));
    CHECK(std::abs(uniform.M) < 1e-5 * std::abs(squash) * 500.0); // the layers that give up the bars' area lie within 2.5 of them
    CHECK(capacity.lowest() <= uniform.N);
    CHECK(capacity.highest() == Approx(1884.0 * 500.0).epsilon(0.01));
    // Pure bending: εcu2 at the top, the neutral axis where N = 0.
    double lo = 1.0, hi = 500.0;
    for (int it = 0; it < 100; ++it) {
        const double x = 0.5 * (lo + hi);
        (rc_resultants(300.0, 500.0, 30.0, bars, -0.0035, 0.0035 / x).first < 0.0 ? hi : lo) = x;
    }
    const double pure = rc_resultants(300.0, 500.0, 30.0, bars, -0.0035, 0.0035 / lo).second;
    CAPTURE(pure, capacity.at(0.0).moment);
    CHECK(capacity.at(0.0).moment == Approx(pure).epsilon(0.01));
    // Balanced: εcu2 at the top with the tension bars at fy/E (x = 0.0035/0.006 · 450).
    const double x = 0.0035 / 0.006 * 450.0;
    const auto [N, M] = rc_resultants(300.0, 500.0, 30.0, bars, -0.0035, 0.0035 / x);
    CAPTURE(N, M, capacity.at(N).moment);
    CHECK(capacity.at(N).moment == Approx(M).epsilon(0.01));
    // The section is symmetric: the negative bending capacity is the same.
    CHECK(section.hinge_capacity(-1.0).at(N).moment == Approx(M).epsilon(0.01));
    // The fibres' fully plastic capacity (stress fc over the compressed depth) lies above it.
    CHECK(section.moment_capacity(N, 1.0) > M);
}

TEST_CASE("Filled tubes squash at A_a fy plus A_c fc", "[concrete][section]") {
    SECTION("circular") {
        const FibreSection tube(section_of(R"(
[[section]]
name = "s"
material = "S355"
shape = "hollow_circle"
diameter = 323.9
thickness = 8
fibres = 48
core_material = "C40"
core_fibres = 40
)"));
        const double d = 323.9 - 16.0;
        const double steel = M_PI * (323.9 * 323.9 - d * d) / 4.0, core = M_PI * d * d / 4.0;
        CHECK(tube.axial_capacity_compression() == Approx(steel * 355.0 + core * 40.0).epsilon(1e-9));
        // By strain limits the steel also yields (E·εc2 = 420 > 355) and the core is at fc.
        CHECK(-tube.hinge_capacity(1.0).lowest() == Approx(steel * 355.0 + core * 40.0).epsilon(1e-3));
    }
    SECTION("rectangular") {
        const FibreSection tube(section_of(R"(
[[section]]
name = "s"
material = "S355"
shape = "hollow_rectangle"
b = 200
h = 300
thickness = 10
core_material = "C30"
)"));
        const double steel = 200.0 * 300.0 - 180.0 * 280.0, core = 180.0 * 280.0;
        CHECK(tube.axial_capacity_compression() == Approx(steel * 355.0 + core * 30.0).epsilon(1e-9));
        CHECK(tube.axial_capacity_tension() == Approx(steel * 355.0).epsilon(1e-9));
    }
}

TEST_CASE("A composite beam's plastic moment from its plastic neutral axis", "[concrete][section]") {
    // An I 300 × 150 (flanges 10.7, web 7.1) of S355 under a slab of C30.
    const double bf = 150.0, tf = 10.7, tw = 7.1, d = 300.0, fy = 355.0;
    const double steel_area = 2.0 * bf * tf + (d - 2.0 * tf) * tw, Fa = steel_area * fy;
    const auto beam = [&](double width, double thickness) {
        return FibreSection(section_of(R"(
[[section]]
name = "s"
material = "S355"
shape = "i"
depth = 300
flange_width = 150
flange_thickness = 10.7
web_thickness = 7.1
flange_layers = 8
web_fibres = 40
slab = { width = )" + std::to_string(width) + ", thickness = " + std::to_string(thickness) + R"(, material = "C30", layers = 40 }
)"));
    };
    SECTION("the neutral axis in the slab") {
        const FibreSection s = beam(1500.0, 120.0);
        const double z = Fa / (1500.0 * 30.0); // depth of the compressed slab
        REQUIRE(z < 120.0);
        const double Mpl = Fa * (d / 2.0 + 120.0 - z / 2.0);
        CHECK(s.moment_capacity(0.0, 1.0) == Approx(Mpl).epsilon(2e-3));
    }
    SECTION("the neutral axis in the steel's top flange") {
        const FibreSection s = beam(300.0, 100.0);
        const double slab = 300.0 * 100.0 * 30.0;
        const double compressed_steel = (Fa - slab) / 2.0, z = compressed_steel / (bf * fy);
        REQUIRE(z < tf);
        // Moments about the steel's centre (N = 0): the slab, and the flange's compressed part
        // counted twice (it is compressed instead of stretched).
        const double Mpl = slab * (d / 2.0 + 50.0) + 2.0 * compressed_steel * (d / 2.0 - z / 2.0);
        CHECK(s.moment_capacity(0.0, 1.0) == Approx(Mpl).epsilon(2e-3));
    }
    SECTION("the domain of an eccentric section: both edges meet at the tension squash load, off M = 0") {
        // Moments are taken about the elastic centroid (concrete E = 2 fc / εc2 = 30 000). In
        // pure tension the slab carries nothing and the steel pulls at its own centre, y_c
        // below that centroid: M = Fa·y_c on both edges, and near it only sagging is carried.
        const FibreSection s = beam(1500.0, 120.0);
        const double Es = 210000.0, Ec = 30000.0, slab_area = 1500.0 * 120.0;
        const double y_c = Ec * slab_area * (d / 2.0 + 60.0) / (Es * steel_area + Ec * slab_area);
        const double Nt = s.axial_capacity_tension();
        CHECK(Nt == Approx(Fa).epsilon(1e-9));
        CHECK(s.moment_bound(Nt, 1.0) == Approx(Fa * y_c).epsilon(1e-3));
        CHECK(s.moment_bound(Nt, -1.0) == Approx(Fa * y_c).epsilon(1e-3));
        CHECK(s.moment_bound(0.0, -1.0) < 0.0);
        CHECK(s.moment_bound(0.9 * Nt, -1.0) > 0.0);
        // The hinges cannot carry a lower edge above zero: their capacity on that side is none.
        CHECK(s.moment_capacity(0.9 * Nt, -1.0) == 0.0);
        CHECK(s.hinge_moment_capacity(0.9 * Nt, -1.0) == 0.0);
        // The capacity by strain limits has the same tension tip (the steel governs there). In
        // hogging with little compression the slab is in tension and the steel beyond it has no
        // strain limit, so it is the fully plastic one, to the smooth hinge curve's rounding of
        // the polygon's corners (up to 0.3 %).
        CHECK(s.hinge_moment_bound(Nt, -1.0) == Approx(Fa * y_c).epsilon(1e-3));
        for (const FibreSection& beam : {s, FibreSection(read_scene_text(scene_file_text("models/gallery/composite_beam.toml"),
                                                                         "composite_beam.toml").sections.at(0))}) {
            const double Nc = beam.axial_capacity_compression(), Nt_beam = beam.axial_capacity_tension();
            for (int k = 0; k < 40; ++k) {
                const double N = -0.2 * Nc + (0.2 * Nc + Nt_beam) * k / 40.0;
                CAPTURE(N);
                CHECK(beam.hinge_moment_bound(N, -1.0) == Approx(beam.moment_bound(N, -1.0)).margin(5e-3 * beam.moment_capacity(0.0, -1.0)));
            }
        }
    }
}

TEST_CASE("A tube's first yield is at its outer face and its hinge capacity is symmetric in N", "[section]") {
    const FibreSection tube(section_of(R"(
[[section]]
name = "s"
material = "S355"
shape = "hollow_circle"
diameter = 200
thickness = 5
fibres = 24
)"));
    const double I = M_PI * (std::pow(200.0, 4) - std::pow(190.0, 4)) / 64.0;
    CHECK(tube.first_yield_moment(0.0) == Approx(355.0 * I / 100.0).epsilon(1e-3));
    // The section is symmetric: so is the hinge's capacity between +N and −N (the fibres that
    // share a height act as one; they left it 0.8 % lopsided).
    const double squash = tube.axial_capacity_tension();
    for (double share : {0.1, 0.3, 0.5, 0.7, 0.9})
        CHECK(tube.hinge_moment_capacity(share * squash, 1.0) == Approx(tube.hinge_moment_capacity(-share * squash, 1.0)).epsilon(1e-9));
}

TEST_CASE("The RC column pushed under axial load follows OpenSees' force-based fibre elements", "[concrete][opensees]") {
    const Run run = run_scene_file("models/gallery/rc_column.toml");
    REQUIRE(run.summary.status == RunStatus::completed);
    std::ifstream in(std::string(PLASTICA_SOURCE_DIR) + "/tests/reference/opensees/rc_column_opensees.out");
    double u = 0.0, load = 0.0;
    int compared = 0;
    double worst = 0.0;
    while (in >> u >> load) {
        for (const StepResult& s : run.steps)
            if (s.stage == 2 && std::abs(s.control_displacement - u) < 0.01) {
                worst = std::max(worst, std::abs(s.load - load) / load);
                ++compared;
            }
    }
    CAPTURE(compared, worst);
    CHECK(compared >= 45); // OpenSees stops at 49 mm
    CHECK(worst < 0.03);
}
