// Linear buckling against closed forms: Euler's four columns, a portal frame's sway by the
// stability functions, Roorda's L-frame, and a ring under hydrostatic pressure.
#include "stability_scenes.hpp"
#include "analysis/eigen_at_step.hpp"
#include "analysis/path_following.hpp"
#include "scene_reader.hpp"
#include "solver/linear_solver.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace plastica;
using namespace plastica::testing;

namespace {

constexpr double pi = 3.14159265358979323846;

double lowest_factor(const std::string& scene, int count = 1) {
    PathFollowing analysis(read_scene_text(scene, "buckling.toml"));
    return analysis.buckling(count).modes.front().load_factor;
}

} // namespace

TEST_CASE("Euler's four columns on 8 elements", "[buckling]") {
    // The Hermitian geometric stiffness converges as h⁴: a pinned column on 4 elements per
    // half-wave (fixed–fixed on 8) is 5e-4 high, on 8 (pinned–pinned) 3e-5.
    struct Case {
        const char* base;
        const char* top;
        double effective_length;
    };
    const Case cases[] = {{"\"ux\", \"uy\"", "\"ux\"", 1.0},
                          {"\"ux\", \"uy\", \"rz\"", "", 2.0},
                          {"\"ux\", \"uy\", \"rz\"", "\"ux\"", pi / 4.493409457909064},
                          {"\"ux\", \"uy\", \"rz\"", "\"ux\", \"rz\"", 0.5}};
    for (const Case& c : cases) {
        const double euler = pi * pi * 1.0 / std::pow(c.effective_length, 2);
        const double found = lowest_factor(column(c.base, c.top, 8));
        INFO("effective length " << c.effective_length << ": " << found << " against " << euler);
        CHECK(found / euler - 1.0 > -1e-6); // from above: the cubic shape is a Rayleigh–Ritz bound
        CHECK(found / euler - 1.0 < 1e-3);
    }
}

namespace {

// The sway buckling of a fixed-base portal (columns h, beam b, one section, P on each column
// top) by slope–deflection with Livesley's stability functions s and c: the sway mode's
// determinant (s + 6r)(k²h² − 2s(1 + c)) + s²(1 + c)² = 0 with r = (I_b/b)/(I_c/h), solved
// for kh by bisection.
double portal_sway_kh(double r) {
    const auto det = [r](double x) {
        const double sn = std::sin(x), cs = std::cos(x);
        const double s = x * (sn - x * cs) / (2.0 - 2.0 * cs - x * sn);
        const double c = (x - sn) / (sn - x * cs);
        return (s + 6.0 * r) * (x * x - 2.0 * s * (1.0 + c)) + s * s * (1.0 + c) * (1.0 + c);
    };
    double lo = 0.1, hi = pi - 1e-9;
    REQUIRE(det(lo) * det(hi) < 0.0);
    for (int k = 0; k < 200; ++k) {
        const double mid = 0.5 * (lo + hi);
        (det(lo) * det(mid) <= 0.0 ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
}

std::string member(const char* name, double x0, double y0, double x1, double y1, int elements) {
    return "[[line]]\nname = \"" + std::string(name) + "\"\nstart = [" + std::to_string(x0) + ", " + std::to_string(y0) +
           "]\nend = [" + std::to_string(x1) + ", " + std::to_string(y1) + "]\nelements = " + std::to_string(elements) +
           "\nsection = \"s\"\n";
}

const char* elastic_section = R"(
[[material]]
name = "m"
E = 1.0e3
[[section]]
name = "s"
material = "m"
A = 10.0
I = 1.0e-3
)";

} // namespace

TEST_CASE("A portal frame's sway buckling against the stability functions", "[buckling]") {
    const double h = 5.0, b = 4.0, EI = 1.0;
    const std::string scene = "[scene]\nname = \"portal\"\n" + std::string(elastic_section) + member("left", 0, 0, 0, h, 8) +
                              member("beam", 0, h, b, h, 8) + member("right", b, h, b, 0, 8) + R"(
[[support]]
at = [0.0, 0.0]
fix = ["ux", "uy", "rz"]
[[support]]
at = [4.0, 0.0]
fix = ["ux", "uy", "rz"]
[[load]]
at = [0.0, 5.0]
fy = -1.0
[[load]]
at = [4.0, 5.0]
fy = -1.0
[analysis]
scheme = "load_control"
increment = 0.1
target_load_factor = 1.0
)";
    const double kh = portal_sway_kh(h / b);
    const double exact = kh * kh * EI / (h * h);
    const double found = lowest_factor(scene);
    INFO(found << " against " << exact);
    // The columns' antisymmetric half-wave spans more than h: on 8 elements below 1e-4.
    CHECK(std::abs(found / exact - 1.0) < 1e-4);
}

TEST_CASE("Roorda's frame: linear buckling at 13.8859 EI/L² on 20 elements a member", "[buckling]") {
    // Roorda, "Stability of structures with small imperfections", J. Eng. Mech. Div. 91, 1965:
    // an L of two members of length L, rigidly joined, pinned at their far ends, pressed down
    // at the joint along the column.
    const std::string scene = "[scene]\nname = \"roorda\"\n" + std::string(elastic_section) + member("column", 0, 0, 0, 1, 20) +
                              member("beam", 0, 1, 1, 1, 20) + R"(
[[support]]
at = [0.0, 0.0]
fix = ["ux", "uy"]
[[support]]
at = [1.0, 1.0]
fix = ["ux", "uy"]
[[load]]
at = [0.0, 1.0]
fy = -1.0
[analysis]
scheme = "load_control"
increment = 0.1
target_load_factor = 1.0
)";
    const double found = lowest_factor(scene);
    INFO(found);
    CHECK(std::abs(found / 13.8859 - 1.0) < 3e-3);
}

TEST_CASE("A ring under hydrostatic pressure buckles at 3EI/R³", "[buckling]") {
    // The shipped scene's pressure is 3EI/R³: its factor is p/p_cr. The point load that seeds
    // its oval is a part of its loads, 3e-5 of the pressure's resultant.
    const Model model = read_scene(std::string(PLASTICA_SOURCE_DIR) + "/models/gallery/ring_external_pressure.toml");
    PathFollowing analysis(model);
    const BucklingResult found = analysis.buckling(3);
    INFO(found.modes.front().load_factor);
    // The polygon of chords converges as h²: 0.80 % high on 32 elements, 0.20 % on 64, 0.05 %
    // on 128. The modes come in pairs (an oval and the same turned by 45°): the third is the
    // three-lobed one, at (n² − 1)EI/R³ = 8/3 of 3EI/R³.
    const double h2 = 0.008 * std::pow(32.0 / 64.0, 2);
    CHECK(found.modes[0].load_factor > 1.0);
    CHECK(found.modes[0].load_factor - 1.0 < 1.25 * h2);
    CHECK(std::abs(found.modes[1].load_factor / found.modes[0].load_factor - 1.0) < 1e-4);
    CHECK(std::abs(found.modes[2].load_factor * 3.0 / 8.0 - 1.0) < 2.0 * h2);
}
