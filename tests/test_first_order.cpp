// First-order analysis ([analysis] geometry = "first_order") against the closed forms of linear
// theory: a cantilever whose deflection stays proportional to its load however large, a
// portal's sway without P-Δ (and with it, amplified as EN 1993-1-1 §5.2.2 says), a propped
// cantilever's collapse load, and pressure that stays on the initial chords.
#include "analysis_helpers.hpp"
#include "plastic_beam_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace plastica;
using namespace plastica::testing;

namespace {

// A cantilever of length 1 along x, EI = 1, EA = 1e7, in 4 elements, pressed down at its tip
// by λ (or, with `pressure`, by a uniform load λ per unit length) up to λ = target.
std::string cantilever(const std::string& geometry, bool pressure, double target) {
    const std::string load = pressure ? "[[distributed_load]]\non = \"all\"\npressure = -1.0\n" : "[[load]]\nat = [1.0, 0.0]\nfy = -1.0\n";
    return "[scene]\nname = \"cantilever\"\n[[material]]\nname = \"m\"\nE = 1.0e3\n[[section]]\nname = \"s\"\n"
           "material = \"m\"\nA = 1.0e4\nI = 1.0e-3\n[[line]]\nstart = [0.0, 0.0]\nend = [1.0, 0.0]\nelements = 4\n"
           "section = \"s\"\n[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n" + load +
           "[analysis]\ngeometry = \"" + geometry + "\"\nscheme = \"load_control\"\nincrement = " + num(target / 4.0) +
           "\ntarget_load_factor = " + num(target) + "\ncontrol_at = [1.0, 0.0]\ncontrol_dof = \"uy\"\n";
}

// A fixed-base portal, columns 4 high, beam 6 wide, EI = 1e3 throughout (EA = 1e8), H = λ at
// its left joint and, with `gravity`, 100 λ down on each column top.
std::string portal(const std::string& geometry, bool gravity) {
    std::string s = "[scene]\nname = \"portal\"\n[[material]]\nname = \"m\"\nE = 1.0e3\n[[section]]\nname = \"s\"\n"
                    "material = \"m\"\nA = 1.0e5\nI = 1.0\n";
    const double ends[3][4] = {{0, 0, 0, 4}, {0, 4, 6, 4}, {6, 4, 6, 0}};
    for (const auto& e : ends)
        s += "[[line]]\nstart = [" + num(e[0]) + ", " + num(e[1]) + "]\nend = [" + num(e[2]) + ", " + num(e[3]) +
             "]\nelements = 8\nsection = \"s\"\n";
    for (const char* x : {"0.0", "6.0"}) s += "[[support]]\nat = [" + std::string(x) + ", 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n";
    s += "[[load]]\nat = [0.0, 4.0]\nfx = 1.0\n";
    if (gravity)
        for (const char* x : {"0.0", "6.0"}) s += "[[load]]\nat = [" + std::string(x) + ", 4.0]\nfy = -100.0\n";
    return s + "[analysis]\ngeometry = \"" + geometry + "\"\nscheme = \"load_control\"\nincrement = 0.25\n"
               "target_load_factor = 1.0\ncontrol_at = [0.0, 4.0]\ncontrol_dof = \"ux\"\n";
}

} // namespace

TEST_CASE("A first-order cantilever deflects by PL³/3EI at any load where the co-rotational one follows the elastica", "[first_order]") {
    // Hermitian cubics carry a point load's moment exactly: 4 elements give PL³/3EI to the
    // axial share (1e-7). At P L²/EI = 3 the elastica's tip has come down by 0.6L only
    // (Bisshopp & Drucker 1945: 0.603), where first order says L.
    for (double P : {0.3, 3.0}) {
        const Run linear = run_scene(cantilever("first_order", false, P));
        REQUIRE(linear.summary.status == RunStatus::completed);
        for (const StepResult& s : linear.steps) CHECK(linear.node_dof(s, 1.0, 0.0, 1) == Approx(-s.load_factor / 3.0).epsilon(1e-6));
    }
    const Run elastica = run_scene(cantilever("large_displacement", false, 3.0));
    REQUIRE(elastica.summary.status == RunStatus::completed);
    CHECK(-elastica.node_dof(elastica.steps.back(), 1.0, 0.0, 1) == Approx(0.603).margin(0.005));
}

TEST_CASE("First-order pressure acts on the initial chords: the deflection is linear in it", "[first_order]") {
    // Pressure lumped to the nodes of 4 elements; the response to it is linear at first order,
    // so doubling the load doubles every displacement to round-off, even where the tip has
    // come down by a third of the span and a follower load would have turned.
    const Run r = run_scene(cantilever("first_order", true, 2.8));
    REQUIRE(r.summary.status == RunStatus::completed);
    const StepResult &half = r.steps[2], &full = r.steps[4];
    REQUIRE(full.load_factor == Approx(2.0 * half.load_factor).epsilon(1e-12));
    CHECK(-full.displacement[3 * 4 + 1] > 0.3);
    for (int i = 0; i < 15; ++i) CHECK(full.displacement[i] == Approx(2.0 * half.displacement[i]).epsilon(1e-9).margin(1e-14));
}

TEST_CASE("A portal's first-order sway is the slope-deflection value unmoved by gravity and amplified by P-Δ by 1/(1 − 1/α_cr)", "[first_order]") {
    // Slope deflection with the joints' rotations equal (antisymmetry), k = (I_b/L)/(I_c/h):
    // Δ = H h³ (2 + 3k) / (12 EI (1 + 6k)); k = 2/3 here, Δ = 256 H / (60 EI). Cubic elements
    // are exact for it; the members' axial strain adds 5e-6.
    const double exact = 256.0 / 60.0 / 1e3;
    const Run bare = run_scene(portal("first_order", false));
    const Run loaded = run_scene(portal("first_order", true));
    REQUIRE(bare.summary.status == RunStatus::completed);
    REQUIRE(loaded.summary.status == RunStatus::completed);
    const double sway = bare.node_dof(bare.steps.back(), 0.0, 4.0, 0);
    CHECK(sway == Approx(exact).epsilon(1e-5));
    CHECK(loaded.node_dof(loaded.steps.back(), 0.0, 4.0, 0) == Approx(sway).epsilon(1e-6));
    // With large displacements the gravity load amplifies it. The portal's α_cr under its
    // gravity load is 4.128 (plastica buckling; the stability functions, test_buckling.cpp);
    // 1/(1 − 1/α_cr) is exact for a first-order shape of the first mode's, and the sway's share
    // in the next mode (α = 14.8) moves it by less than 1 %.
    const Run second = run_scene(portal("large_displacement", true));
    REQUIRE(second.summary.status == RunStatus::completed);
    PathFollowing analysis(read_scene_text(portal("first_order", true), "portal.toml"));
    const double alpha_cr = analysis.buckling(1).modes.front().load_factor;
    CHECK(alpha_cr == Approx(4.128).epsilon(1e-3));
    const double amplified = second.node_dof(second.steps.back(), 0.0, 4.0, 0) / sway;
    INFO("amplification " << amplified << " against " << 1.0 / (1.0 - 1.0 / alpha_cr));
    CHECK(amplified == Approx(1.0 / (1.0 - 1.0 / alpha_cr)).epsilon(0.01));
}

TEST_CASE("A first-order propped cantilever collapses at 6 Mp/L with refined hinges", "[first_order]") {
    // Plastic theory (Neal, The Plastic Methods of Structural Analysis, 1977): hinges at the
    // clamp and under the central load, P_c = 6 M_p/L. At a travel of L/200 the hinges have
    // turned by 0.01: their regularising hardening (1e-6 of 4EI/ℓ) lifts the plateau by 3e-4.
    std::string scene = plastic_beam_header("hinges") + propped_cantilever("8") + displacement_control(1000.0, 0.0, "uy", 0.5, 10.0);
    scene.replace(scene.find("[analysis]\n"), 11, "[analysis]\ngeometry = \"first_order\"\n");
    const Run r = run_scene(scene);
    REQUIRE(r.summary.status == RunStatus::completed);
    const double Pc = 6.0 * rectangle_Mp / 2000.0;
    CHECK(r.steps.back().load == Approx(Pc).epsilon(1e-3));
    CHECK(r.max_load() <= Pc * (1.0 + 1e-3));
}
