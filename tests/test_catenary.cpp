// Catenary action of a clamped beam against rigid–perfectly-plastic theory (Haythornthwaite
// 1957; Jones, Structural Impact, 1989): the stress-resultant hinges must
// carry the axial force up to the squash load, never beyond, and turn into a plastic string.
#include "analysis_helpers.hpp"
#include "element/plastic_hinge_law.hpp"

#include <catch2/catch.hpp>
#include <string>


using namespace plastica;
using namespace plastica::testing;


TEST_CASE("A clamped beam turns into a plastic string: P/Pc = 1 + (W/H)², then 2W/H", "[plasticity][catenary]") {
    // Increments of at most H/20, so that the bending range below is sampled ten times.
    std::string scene = scene_file_text("models/gallery/catenary_beam.toml");
    scene.replace(scene.find("max_steps = 2000"), 16, "max_steps = 2000\nmax_increment = 0.005");
    const Run r = run_scene(scene);
    REQUIRE(r.summary.status == RunStatus::completed);
    // models/gallery/catenary_beam.toml: span 2L = 2, H = 0.1, B = 0.05, fy = 2.5e8, E = 2.1e11.
    const double B = 0.05, H = 0.1, L = 1.0, fy = 2.5e8, E = 2.1e11;
    const double M0 = fy * B * H * H / 4.0, N0 = fy * B * H, Pc = 4.0 * M0 / L;
    // Elastic deflection at Pc, relative to H: (fy/E)(2L/H)²/8 = 0.060.
    const double elastic = fy / E * (2.0 * L / H) * (2.0 * L / H) / 8.0;
    int bending = 0, string = 0;
    for (const StepResult& s : r.steps) {
        // The axial force never exceeds the squash load (beyond the regularising hardening:
        // 1e-6 of EA/L times the plastic elongation of an element, below 1e-4 of N0 here).
        for (const ElementResult& e : s.elements) REQUIRE(e.forces.axial <= N0 * (1.0 + 1e-4));
        const double w = s.control_displacement / H, p = s.load / Pc;
        if (w >= 0.5 && w <= 1.0) {
            // Bending with membrane action: the elastic–plastic beam lies below the rigid–plastic
            // curve by at most its elastic compliance, (d/dw)(1 + w²)·δ_el/H = 2w·0.06.
            const double rigid = 1.0 + w * w;
            CAPTURE(w, p, rigid);
            CHECK(p <= rigid);
            CHECK(p >= rigid - 2.0 * w * elastic);
            ++bending;
        }
        if (w >= 1.5) {
            // The plastic string: N = N0, M = 0 and P = 2 N0 sin θ. Haythornthwaite's 2W/H is its
            // small-angle form; the co-rotational beam has the exact angle, W/√(L² + W²).
            const double small_angle = 2.0 * w;
            const double exact_angle = small_angle / std::sqrt(1.0 + (w * H / L) * (w * H / L));
            CAPTURE(w, p, small_angle, exact_angle);
            CHECK(p == Approx(exact_angle).epsilon(2e-3));
            CHECK(p <= small_angle);
            for (const ElementResult& e : s.elements) CHECK(e.forces.axial >= 0.995 * N0);
            ++string;
        }
    }
    CHECK(bending >= 10);
    CHECK(string >= 10);
    CHECK(r.steps.back().control_displacement == Approx(3.0 * H));
}
