// Stages: load, unload, reload. An elastic structure returns to its unloaded shape and retraces
// its path; an inelastic one unloads along its elastic stiffness and keeps the plastic part.
#include "analysis_helpers.hpp"
#include "plastic_beam_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace plastica;
using namespace plastica::testing;

TEST_CASE("An elastic cantilever loaded, unloaded and reloaded returns to its shape and retraces its path", "[stages]") {
    // PL²/EI = 2: the tip moves by about 0.5 L, far from linear.
    const std::string scene = cantilever(10.0, 20, 100.0, 1.0e4, 1.0, "[[load]]\nat = [10.0, 0.0]\nfy = -2.0\n",
                                         "scheme = \"load_control\"\nincrement = 0.1\nadaptive = false\ntarget_load_factor = 1.0\n"
                                         "control_at = [10.0, 0.0]\n") +
                              "[[stage]]\nincrement = 0.1\ntarget_load_factor = 0.0\n"
                              "[[stage]]\nincrement = 0.25\ntarget_load_factor = 1.0\n";
    const Run r = run_scene(scene);
    REQUIRE(r.summary.status == RunStatus::completed);
    CHECK_THAT(r.summary.reason, Catch::Contains("3 stages"));
    REQUIRE(r.steps.size() == 1 + 10 + 10 + 4);
    const StepResult& loaded = r.steps[10];
    const StepResult& unloaded = r.steps[20];
    const StepResult& reloaded = r.steps.back();
    CHECK(loaded.load_factor == Approx(1.0));
    CHECK(unloaded.load_factor == Approx(0.0).margin(1e-12));
    CHECK(reloaded.load_factor == Approx(1.0));
    CHECK(loaded.control_displacement > 4.0); // reported along the load
    for (double u : unloaded.displacement) CHECK(std::abs(u) < 1e-8);
    for (std::size_t k = 0; k < loaded.displacement.size(); ++k)
        CHECK(reloaded.displacement[k] == Approx(loaded.displacement[k]).margin(1e-8));
    // Unloading passes through the loading states in reverse.
    for (int k = 1; k < 10; ++k) CHECK(r.steps[20 - k].control_displacement == Approx(r.steps[k].control_displacement).margin(1e-8));
}

TEST_CASE("A plastic beam unloads along its elastic stiffness and keeps its plastic deflection", "[stages][plasticity]") {
    // A simply supported beam (L = 2000) under a central load, pushed to δ = 1.0 (its collapse
    // load 4Mp/L forms near δ = 0.27), then unloaded to P = 0 and reloaded to the same δ. The
    // unloading is elastic (the Euler beam's P·L³/48EI), so the
    // permanent deflection is δ_max − P_max L³/48EI; reloading meets the collapse load again.
    const double L = 2000.0, EI = 2.0e8 * 10.0 * 20.0 * 20.0 * 20.0 / 12.0;
    for (const char* plasticity : {"hinges", "distributed"}) {
        INFO(plasticity);
        const Run r = run_scene(plastic_beam_header(plasticity) +
                                "[[line]]\nstart = [0.0, 0.0]\nend = [2000.0, 0.0]\nelements = 16\nsection = \"s\"\n"
                                "[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"uy\"]\n[[support]]\nat = [2000.0, 0.0]\nfix = [\"uy\"]\n"
                                "[[load]]\nat = [1000.0, 0.0]\nfy = -1.0\n" +
                                displacement_control(1000.0, 0.0, "uy", 0.02, 1.0) +
                                "[[stage]]\nscheme = \"load_control\"\nincrement = 50.0\ntarget_load_factor = 0.0\n"
                                "[[stage]]\nscheme = \"displacement_control\"\nincrement = 0.02\ntarget_displacement = 1.0\n");
        REQUIRE(r.summary.status == RunStatus::completed);
        std::size_t top = 0, bottom = 0;
        for (std::size_t k = 0; k < r.steps.size(); ++k) {
            if (r.steps[k].control_displacement >= r.steps[top].control_displacement - 1e-12 && bottom == 0) top = k;
            if (top > 0 && r.steps[k].load_factor == 0.0 && bottom == 0) bottom = k;
        }
        REQUIRE(bottom > top);
        const double p_max = r.steps[top].load, d_max = r.steps[top].control_displacement;
        const double residual = r.steps[bottom].control_displacement;
        CAPTURE(p_max, d_max, residual);
        CHECK(residual > 0.5 * d_max);
        // The fibre sections along the members bend with the 10 layers' b h³/12 (1 − 1/10²).
        const double layers = std::string(plasticity) == "distributed" ? 1.0 - 1.0 / 100.0 : 1.0;
        const double flexibility = L * L * L / (48.0 * EI * layers);
        CHECK(d_max - residual == Approx(p_max * flexibility).epsilon(2e-3));
        // Every unloading step on the elastic line through the top of the curve.
        for (std::size_t k = top + 1; k <= bottom; ++k)
            CHECK(d_max - r.steps[k].control_displacement == Approx((p_max - r.steps[k].load) * flexibility).margin(2e-3 * p_max * flexibility));
        // Reloaded to the same deflection: back at the peak load.
        CHECK(r.steps.back().load == Approx(p_max).epsilon(5e-3));
    }
}
