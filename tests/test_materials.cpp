// Fibre laws behind the uniaxial-material interface, against closed forms: the hardening law's
// cyclic path, the registry, a section's moment–curvature and a cantilever's deflection.
#include "analysis_helpers.hpp"
#include "plastic_beam_scenes.hpp"
#include "material/material_registry.hpp"
#include "section/fibre_section.hpp"

#include <catch2/catch.hpp>

#include <functional>

using namespace plastica;
using namespace plastica::testing;

namespace {

constexpr double E = 200e3, fy = 250.0, ey = fy / E;

SteelSpec hardening(double b) {
    SteelSpec s = bilinear_steel(E, fy);
    s.law = "kinematic_hardening";
    s.parameters["hardening_ratio"] = b;
    return s;
}

// Strain steps, each committed: the stress after each.
std::vector<double> stresses(UniaxialMaterial& m, const std::vector<double>& strains) {
    std::vector<double> out;
    for (double e : strains) {
        out.push_back(m.set_trial_strain(e).stress);
        m.commit();
    }
    return out;
}

} // namespace

TEST_CASE("Kinematic hardening: slope b·E past yield, an elastic range of 2 fy that moves (Bauschinger)", "[material]") {
    const double b = 0.02;
    auto m = make_material(hardening(b), 0.0);
    // To 3 εy: σ = fy + bE·2εy = 1.04 fy. Back to εy: the elastic range is 2 fy wide, so the
    // reverse yield starts exactly there at σ = 1.04 fy − 2 fy = −0.96 fy; on to −3 εy:
    // −0.96 fy − bE·4εy = −1.04 fy. Up again: yield at −εy (at −1.04 fy + 2 fy = 0.96 fy), so
    // σ(εy) = fy and σ(3 εy) = 1.04 fy.
    const std::vector<double> path{1.0 * ey, 3.0 * ey, 2.0 * ey, 1.0 * ey, -1.0 * ey, -3.0 * ey, 1.0 * ey, 3.0 * ey};
    const std::vector<double> got = stresses(*m, path);
    // Row by row: elastic unloading from 1.04 fy by εy gives 0.04 fy.
    CHECK(got[0] == Approx(fy).epsilon(1e-12));
    CHECK(got[1] == Approx(1.04 * fy).epsilon(1e-12));
    CHECK(got[2] == Approx(0.04 * fy).epsilon(1e-12));
    CHECK(got[3] == Approx(-0.96 * fy).epsilon(1e-12));
    CHECK(got[4] == Approx(-0.96 * fy - b * E * 2.0 * ey).epsilon(1e-12));
    CHECK(got[5] == Approx(-1.04 * fy).epsilon(1e-12));
    CHECK(got[6] == Approx(fy).epsilon(1e-12)); // yield again at −εy (0.96 fy), then + bE·2εy
    CHECK(got[7] == Approx(1.04 * fy).epsilon(1e-12));
    CHECK(m->tangent() == Approx(b * E).epsilon(1e-12));
    CHECK(m->yielding());
    // One step across the whole elastic range and beyond is exact too (the return map of
    // linear hardening): from 0 straight to 3 εy.
    auto jump = make_material(hardening(b), 0.0);
    CHECK(jump->set_trial_strain(3.0 * ey).stress == Approx(1.04 * fy).epsilon(1e-12));
}

TEST_CASE("With b = 0 the hardening law is the bilinear law, step for step", "[material]") {
    // Both with a residual stress of 30 and an ultimate strain of 0.05.
    SteelSpec failing = hardening(0.0);
    failing.ultimate_strain = 0.05;
    auto hard = make_material(failing, 30.0), plain = make_material(bilinear_steel(E, fy, 0.05), 30.0);
    double strain = 0.0;
    for (int k = 0; k < 400; ++k) {
        strain += 4e-4 * std::sin(0.07 * k) + 2e-4; // cycles drifting into tension, past εu at the end
        const StressTangent a = hard->set_trial_strain(strain), c = plain->set_trial_strain(strain);
        CAPTURE(k, strain);
        CHECK(a.stress == Approx(c.stress).margin(1e-9 * fy));
        CHECK(a.tangent == Approx(c.tangent).margin(1e-9 * E));
        CHECK(hard->failed() == plain->failed());
        hard->commit();
        plain->commit();
    }
    CHECK(plain->failed());
}

TEST_CASE("The registry makes every law it lists and names what is wrong", "[material]") {
    for (const MaterialLaw& law : material_laws()) {
        SteelSpec s = bilinear_steel(E, fy);
        s.law = law.name;
        for (const LawParameter& p : law.parameters) s.parameters[p.name] = std::isfinite(p.fallback) ? p.fallback : p.stress ? fy : 0.01;
        auto m = make_material(s, 0.0);
        CAPTURE(law.name);
        // Steels are linear to fy in both senses; concrete's strength fc is its compressive limit.
        if (std::string(law.strength) == "fy") {
            CHECK(m->elastic_modulus() == E);
            CHECK(m->limit_stress(1.0) == fy);
            CHECK(m->set_trial_strain(0.5 * ey).stress == Approx(0.5 * fy));
        } else {
            CHECK(m->limit_stress(-1.0) == fy);
            CHECK(m->set_trial_strain(-1.0).stress == Approx(-fy));
        }
    }
    SteelSpec unknown = bilinear_steel(E, fy);
    unknown.law = "timber";
    CHECK_THROWS_AS(make_material(unknown, 0.0), MaterialParameterError);
    try {
        make_material(hardening(1.5), 0.0);
        FAIL("a hardening ratio of 1.5 was accepted");
    } catch (const MaterialParameterError& e) {
        CHECK(e.key == "hardening_ratio");
    }
}

TEST_CASE("A hardening rectangle's moment–curvature is (1 − b)·M_epp(κ) + b·EI·κ", "[material][section]") {
    // Monotonic loading superposes the elastic–perfectly plastic law (share 1 − b) and an
    // elastic one (share b); for the rectangle M_epp = M_y (1.5 − 0.5 (κ_y/κ)²) past yield.
    const double b = 0.05, width = 10.0, depth = 20.0;
    SectionSpec spec = rectangle_section(E, width, depth, 400);
    spec.steel = hardening(b);
    const FibreSection section(spec);
    const double EI = E * width * depth * depth * depth / 12.0, My = fy * width * depth * depth / 6.0, ky = My / EI;
    const std::vector<MomentCurvaturePoint> curve = section.moment_curvature(0.0, 8.0 * ky, 16);
    for (const MomentCurvaturePoint& p : curve) {
        const double k = p.curvature;
        const double epp = k <= ky ? EI * k : My * (1.5 - 0.5 * (ky / k) * (ky / k));
        CAPTURE(k / ky);
        // 400 layers: the fibre rectangle is within 1e-5 of the continuum one.
        CHECK(p.moment == Approx((1.0 - b) * epp + b * EI * k).epsilon(2e-5));
    }
}

TEST_CASE("A hardening cantilever with distributed plasticity deflects as ∫κ(s)·s ds, at second order", "[material][distributed]") {
    // Rectangle, tip load P = 1.6 M_y/L, beyond the perfectly plastic collapse 1.5 M_y/L: only
    // hardening carries it. κ(M) inverts (1 − b) M_epp(κ) + b EI κ = M (monotone).
    const double b = 0.05, width = 10.0, depth = 20.0, L = 1000.0, Es = 2e11, fys = 250.0;
    const double I = width * depth * depth * depth / 12.0, EI = Es * I, My = fys * width * depth * depth / 6.0, ky = My / EI;
    const double P = 1.6 * My / L;
    auto moment_of = [&](double k) { return (1.0 - b) * (k <= ky ? EI * k : My * (1.5 - 0.5 * (ky / k) * (ky / k))) + b * EI * k; };
    auto kappa = [&](double s) {
        const double M = P * s;
        if (M <= My) return M / EI;
        double lo = ky, hi = 1e3 * ky;
        for (int it = 0; it < 200; ++it) {
            const double mid = 0.5 * (lo + hi);
            (moment_of(mid) < M ? lo : hi) = mid;
        }
        return 0.5 * (lo + hi);
    };
    // Simpson on a fine grid (the integrand is smooth on either side of s = M_y/P).
    auto integrate = [&](double a, double c) {
        const int n = 20000;
        double sum = 0.0;
        for (int k = 0; k <= n; ++k) {
            const double s = a + (c - a) * k / n, w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
            sum += w * kappa(s) * s;
        }
        return sum * (c - a) / (3.0 * n);
    };
    const double exact = integrate(0.0, My / P) + integrate(My / P, L);
    std::vector<double> errors;
    for (int elements : {2, 4, 8, 16}) {
        const Run r = run_scene(tip_loaded_rectangle_cantilever(
            Es, fys, "law = \"kinematic_hardening\"\nhardening_ratio = " + num(b) + "\n", elements, P));
        REQUIRE(r.summary.status == RunStatus::completed);
        const double tip = -r.node_dof(r.steps.back(), 1000.0, 0.0, 1);
        errors.push_back(std::abs(tip - exact) / exact);
        CAPTURE(elements, tip, exact);
    }
    // Measured 7.5e-2, 8.8e-3, 1.8e-4, 6.1e-6: at least second order (faster here, since the
    // yield boundary s = M_y/P = 0.625 L falls on a node from 8 elements on), down to the
    // 400-layer rectangle's own 1e-5.
    for (std::size_t k = 1; k < errors.size(); ++k) {
        CAPTURE(errors[k - 1], errors[k]);
        CHECK(std::log2(errors[k - 1] / errors[k]) > 1.7);
    }
    CHECK(errors.back() < 2e-5);
}

TEST_CASE("A hardening material's sections are distributed by default", "[material][scene]") {
    std::string text = cantilever(1.0, 2, 1.0, 1.0, 1.0, "[[load]]\nat = [1.0, 0.0]\nfy = -1.0\n",
                                  "scheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 1.0\n");
    text.replace(text.find("E = 1.0"), 7, "E = 1.0\nfy = 0.001\nlaw = \"kinematic_hardening\"\nhardening_ratio = 0.01");
    const Model model = read_scene_text(text, "hardening.toml");
    CHECK(model.sections[0].plasticity == Plasticity::distributed);
    CHECK(model.sections[0].steel->parameters.at("hardening_ratio") == 0.01);
}
