// Motion in time against closed forms: an SDOF free, damped and forced (with Newmark's exact
// period elongation), HHT's dissipation, an elastic–perfectly plastic SDOF under a ground
// motion against an independent integration, energy and momentum of large free motions.
#include "analysis/path_following.hpp"
#include "dynamics/mass_matrix.hpp"
#include "dynamics_reader.hpp"
#include "scene_error.hpp"
#include "scene_reader.hpp"
#include "scratch_files.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <cmath>
#include <filesystem>
#include <cstdio>
#include <string>
#include <vector>

using namespace plastica;

namespace {

constexpr double pi = 3.14159265358979323846;

struct Run {
    std::vector<StepResult> steps;
    RunSummary summary;
};

Run run_scene(const std::string& text) {
    const Model model = read_scene_text(text, "dynamics.toml");
    PathFollowing analysis(model);
    Run out;
    out.summary = analysis.run({[&](const StepResult& r) { out.steps.push_back(r); }});
    return out;
}

// An axial bar of stiffness k = EA/L = 100 carrying a mass m = 1 at its free end: ω = 10.
std::string sdof(const std::string& extra, double dt, double duration) {
    return R"(
[scene]
name = "sdof"
[[material]]
name = "m"
E = 100.0
[[section]]
name = "s"
material = "m"
A = 1.0
I = 1.0
[[line]]
start = [0.0, 0.0]
end = [1.0, 0.0]
elements = 1
section = "s"
[[support]]
at = [0.0, 0.0]
fix = ["ux", "uy", "rz"]
[[support]]
at = [1.0, 0.0]
fix = ["uy", "rz"]
[[mass]]
at = [1.0, 0.0]
m = 1.0
)" + extra + "\n[analysis]\nscheme = \"transient\"\ntime_step = " + std::to_string(dt) + "\nduration = " +
           std::to_string(duration) + "\ncontrol_at = [1.0, 0.0]\ncontrol_dof = \"ux\"\nresidual_tolerance = 1e-10\n";
}

double ux_at_tip(const StepResult& r) { return r.displacement[3]; }

} // namespace

TEST_CASE("An undamped SDOF vibrates at Newmark's elongated period, exactly as the trapezoidal rule's rotation says") {
    // The average acceleration rule turns the state (u, v/ω) through φ = 2·atan(ωΔt/2) each
    // step (Hughes 1987, §9.3): u_n = (v0/ω) sin(nφ), with no change of amplitude. The
    // closed form sin(ωt) differs by the period elongation (ωΔt)²/12 to first order.
    const double omega = 10.0, v0 = 0.01, dt = 0.02;
    const Run run = run_scene(sdof("[[initial_velocity]]\nat = [1.0, 0.0]\nv = [0.01, 0.0]\n", dt, 2.0));
    REQUIRE(run.summary.status == RunStatus::completed);
    REQUIRE(run.steps.size() == 101);
    const double phi = 2.0 * std::atan(omega * dt / 2.0);
    double worst_discrete = 0.0, worst_exact = 0.0;
    for (const StepResult& r : run.steps) {
        const double discrete = v0 / omega * std::sin(r.step * phi);
        const double exact = v0 / omega * std::sin(omega * r.time);
        worst_discrete = std::max(worst_discrete, std::abs(ux_at_tip(r) - discrete));
        worst_exact = std::max(worst_exact, std::abs(ux_at_tip(r) - exact));
    }
    CHECK(worst_discrete <= 1e-8 * v0 / omega);
    // After ωt = 20 the phase lags by ωt·(ωΔt)²/12 = 0.067: the closed form is that far off.
    const double lag = omega * 2.0 * std::pow(omega * dt, 2) / 12.0;
    CHECK(worst_exact <= 1.05 * lag * v0 / omega);
    CHECK(worst_exact >= 0.8 * lag * v0 / omega);
    CHECK(run.summary.largest_energy_error <= 1e-8);
}

TEST_CASE("A Rayleigh-damped SDOF decays as the closed form") {
    // C = α_M M with α_M = 2ζω: ζ = 0.05; u = (v0/ω_d) e^(−ζωt) sin(ω_d t).
    const double omega = 10.0, zeta = 0.05, v0 = 0.01, dt = 0.002;
    const Run run = run_scene(sdof("[[initial_velocity]]\nat = [1.0, 0.0]\nv = [0.01, 0.0]\n[damping]\nalpha_m = " +
                                       std::to_string(2.0 * zeta * omega) + "\n",
                                   dt, 3.0));
    REQUIRE(run.summary.status == RunStatus::completed);
    const double wd = omega * std::sqrt(1.0 - zeta * zeta);
    double worst = 0.0;
    for (const StepResult& r : run.steps)
        worst = std::max(worst, std::abs(ux_at_tip(r) - v0 / wd * std::exp(-zeta * omega * r.time) * std::sin(wd * r.time)));
    // The phase lags by ωt(ωΔt)²/12 while the amplitude decays as e^(−ζωt): their product is
    // largest, (ωΔt)²/(12ζe) of v0/ω, at ζωt = 1.
    CHECK(worst <= 1.1 * std::pow(omega * dt, 2) / (12.0 * zeta * std::exp(1.0)) * v0 / omega);
    // The damping's work is the energy lost: the balance holds.
    CHECK(run.summary.largest_energy_error <= 1e-6);
    CHECK(run.steps.back().energy.damping > 0.9 * 0.5 * v0 * v0);
}

TEST_CASE("An SDOF under a harmonic force from rest follows the closed form") {
    // F = F0 sin(Ωt), Ω = 0.6 ω, from rest: u = (F0/k)/(1 − r²) (sin Ωt − r sin ωt).
    const double k = 100.0, omega = 10.0, r_ratio = 0.6, F0 = 1.0, dt = 0.002;
    const std::string load = "[[load]]\nat = [1.0, 0.0]\nfx = 1.0\n[[time_series]]\npattern = \"main\"\nkind = \"harmonic\"\nperiod = " +
                             std::to_string(2.0 * pi / (r_ratio * omega)) + "\n";
    const Run run = run_scene(sdof(load, dt, 4.0));
    REQUIRE(run.summary.status == RunStatus::completed);
    const double u_static = F0 / k;
    double worst = 0.0;
    for (const StepResult& r : run.steps) {
        const double t = r.time;
        const double exact = u_static / (1.0 - r_ratio * r_ratio) * (std::sin(r_ratio * omega * t) - r_ratio * std::sin(omega * t));
        worst = std::max(worst, std::abs(ux_at_tip(r) - exact));
    }
    // Phase errors of (ωΔt)²/12 per radian over ωt = 40: 1.3e-3 of the response's scale.
    CHECK(worst <= 2e-3 * u_static / (1.0 - r_ratio * r_ratio));
    CHECK(run.summary.largest_energy_error <= 1e-6);
}

namespace {
// HHT's step on ü + ω²u = 0 written out on its own (Hilber, Hughes & Taylor 1977): the state
// (u, v, a) after n steps of Δt.
Eigen::Vector3d hht_reference(double omega, double dt, double alpha, Eigen::Vector3d z, int steps) {
    const double gamma = 0.5 - alpha, beta = 0.25 * (1.0 - alpha) * (1.0 - alpha), w2 = omega * omega;
    // Unknowns (u1, v1, a1): a1 + (1+α)ω²u1 = αω²u0; u1 − βΔt²a1 = u0 + Δt v0 + (½−β)Δt²a0;
    // v1 − γΔt a1 = v0 + (1−γ)Δt a0.
    Eigen::Matrix3d A;
    A << (1.0 + alpha) * w2, 0.0, 1.0, 1.0, 0.0, -beta * dt * dt, 0.0, 1.0, -gamma * dt;
    for (int n = 0; n < steps; ++n) {
        const Eigen::Vector3d b(alpha * w2 * z[0], z[0] + dt * z[1] + (0.5 - beta) * dt * dt * z[2], z[1] + (1.0 - gamma) * dt * z[2]);
        z = A.lu().solve(b);
    }
    return z;
}
} // namespace

TEST_CASE("HHT damps a mode the step cannot resolve as its own recursion says, and Newmark keeps its amplitude") {
    // ωΔt = 3, twenty steps: the engine's state equals the scalar recursion's, which with
    // α = −0.3 keeps under a tenth of the amplitude; the average acceleration keeps all of it.
    const double dt = 0.3, v0 = 0.01, omega = 10.0;
    for (const double alpha : {0.0, -0.1, -0.3}) {
        std::string text = sdof("[[initial_velocity]]\nat = [1.0, 0.0]\nv = [0.01, 0.0]\n", dt, 6.0);
        if (alpha != 0.0) text += "integrator = \"hht\"\nalpha = " + std::to_string(alpha) + "\n";
        const Run run = run_scene(text);
        REQUIRE(run.summary.status == RunStatus::completed);
        const StepResult& last = run.steps.back();
        const Eigen::Vector3d z = hht_reference(omega, dt, alpha, Eigen::Vector3d(0.0, v0, 0.0), 20);
        CAPTURE(alpha);
        CHECK(std::abs(ux_at_tip(last) - z[0]) <= 1e-8 * v0 / omega);
        CHECK(std::abs(last.velocity[3] - z[1]) <= 1e-8 * v0);
        const double amplitude = std::hypot(ux_at_tip(last) * omega, last.velocity[3]) / v0;
        if (alpha == 0.0) CHECK(std::abs(amplitude - 1.0) <= 1e-8);
        if (alpha == -0.3) CHECK(amplitude <= 0.1);
    }
}

TEST_CASE("An elastic–perfectly plastic SDOF under a ground motion matches an independent integration") {
    // A bar of one fibre (k = EA/L = 100, N_y = fy·A = 0.05) with a mass of 1: the base shakes
    // at 1.2 Hz with 0.2 units of acceleration for 3 s. The reference is a scalar Newmark
    // average-acceleration integration of m ü + f(u) = −m a_g with a return-mapped EPP spring,
    // written here on its own; the two must agree to the Newton tolerance.
    const double dt = 0.005, k = 100.0, Ny = 0.05, m = 1.0;
    std::string record;
    const int samples = 601;
    char value[32];
    for (int i = 0; i < samples; ++i) {
        std::snprintf(value, sizeof value, "%.17g\n", 0.2 * std::sin(2.0 * pi * 1.2 * i * dt));
        record += value;
    }
    const std::string path = std::string(PLASTICA_BINARY_DIR) + "/epp_record.txt";
    {
        std::FILE* f = std::fopen(path.c_str(), "w");
        REQUIRE(f);
        std::fputs(record.c_str(), f);
        std::fclose(f);
    }
    std::string text = sdof("[[ground_motion]]\nfile = \"" + path + "\"\ntime_step = 0.005\nunits = 1.0\n", dt, 3.0);
    text.replace(text.find("E = 100.0"), 9, "E = 100.0\nfy = 0.05");
    // Displacement-based: the reference spring below carries that member's parallel stiffness.
    text.replace(text.find("I = 1.0"), 7, "I = 1.0\nfibres = 2\nplasticity = \"distributed\"\nformulation = \"displacement\"");
    const Run run = run_scene(text);
    REQUIRE(run.summary.status == RunStatus::completed);

    // The reference, independent of the engine.
    double u = 0.0, v = 0.0, a = 0.0, plastic = 0.0;
    // The engine's fibre members keep a parallel axial stiffness of 1e-6 EA at each section
    // (engine/element/distributed_plasticity_law.cpp: a yielded section is not a mechanism), so
    // the reference spring has it too.
    const double parallel = 1e-6 * k;
    auto spring = [&](double trial_u, double& tangent) {
        double f = k * (trial_u - plastic);
        tangent = k;
        if (std::abs(f) > Ny) f = std::copysign(Ny, f), tangent = 0.0;
        tangent += parallel;
        return f + parallel * trial_u;
    };
    auto ground = [&](double t) { return 0.2 * std::sin(2.0 * pi * 1.2 * t); };
    double worst = 0.0, peak = 0.0;
    for (std::size_t n = 1; n < run.steps.size(); ++n) {
        const double t = n * dt;
        double u1 = u, f = 0.0, kt = k;
        for (int it = 0; it < 50; ++it) {
            const double a1 = 4.0 / (dt * dt) * (u1 - u) - 4.0 / dt * v - a;
            f = spring(u1, kt);
            const double r = -m * ground(t) - f - m * a1;
            if (std::abs(r) < 1e-13) break;
            u1 += r / (kt + 4.0 * m / (dt * dt));
        }
        if (std::abs(k * (u1 - plastic)) > Ny) plastic = u1 - std::copysign(Ny, u1 - plastic) / k;
        const double a1 = 4.0 / (dt * dt) * (u1 - u) - 4.0 / dt * v - a;
        v += 0.5 * dt * (a + a1);
        a = a1;
        u = u1;
        worst = std::max(worst, std::abs(ux_at_tip(run.steps[n]) - u));
        peak = std::max(peak, std::abs(u));
    }
    CHECK(peak > 2.0 * Ny / k); // it yields, both ways
    // Each step meets a residual of 1e-10; 600 steps accumulate less than 1e-7 of the peak.
    CHECK(worst <= 1e-7 * peak);
    const EnergyTerms& e = run.steps.back().energy;
    CHECK(e.plastic > 0.1 * std::abs(e.ground));
    CHECK(run.summary.largest_energy_error <= 1e-4);
}

TEST_CASE("A PEER AT2 record is read whole, its header checked") {
    const Model model = read_scene(std::string(PLASTICA_SOURCE_DIR) + "/models/gallery/frame_shaken.toml");
    REQUIRE(model.dynamics.ground_motions.size() == 1);
    const GroundMotionSpec& g = model.dynamics.ground_motions.front();
    CHECK(g.time_step == 0.02);
    CHECK(g.acceleration.size() == 2000u);
    // The first sample, .1297983E-02 g, in m/s² (the scene's [units] are m and kN).
    CHECK(g.acceleration.front() == Approx(0.1297983e-2 * 9.80665).epsilon(1e-12));
    CHECK(model.dynamics.damping.ratio.value_or(0.0) == 0.02);

    CHECK_THROWS_WITH(parse_acceleration_record("title\nsecond\nthird\nNPTS=  3, DT= .01 SEC\n1 2\n"),
                      Catch::Contains("announces NPTS = 3 values, the file holds 2"));
    CHECK_THROWS_WITH(parse_acceleration_record("title\nsecond\nthird\nno header here\n1 2\n"), Catch::Contains("line 4"));
    CHECK_THROWS_WITH(parse_acceleration_record("0.1 0.2\n0.3 x\n"), Catch::Contains("line 2"));
    CHECK(parse_acceleration_record("0.1, 0.2\n0.3\n").values.size() == 3u);
}

TEST_CASE("Dynamics tables' mistakes are located at their file, line and key") {
    struct Case {
        const char* what;
        std::string extra, analysis, message;
    };
    const std::string transient = "scheme = \"transient\"\ntime_step = 0.01\nduration = 1.0\n";
    const std::string record = std::string(PLASTICA_SOURCE_DIR) + "/models/records/ARL360.at2";
    const std::vector<Case> cases = {
        {"missing record", "[[ground_motion]]\nfile = \"no_such.at2\"\nunits = 1.0\n", transient, "'ground_motion[1].file': cannot read the record"},
        {"a step that does not divide the record's", "[[ground_motion]]\nfile = \"" + record + "\"\nunits = 1.0\n",
         "scheme = \"transient\"\ntime_step = 0.03\nduration = 1.0\n", "'analysis.time_step': the step 0.030000 does not divide the record's 0.020000"},
        {"g without units", "[[ground_motion]]\nfile = \"" + record + "\"\n", transient, "'ground_motion[1].units': a record in g needs the scene's [units]"},
        {"alpha on Newmark", "[[initial_velocity]]\nat = [1.0, 0.0]\nv = [0.01, 0.0]\n", transient + "alpha = -0.1\n", "'analysis.alpha': 'alpha' is HHT's"},
        {"alpha out of range", "[[initial_velocity]]\nat = [1.0, 0.0]\nv = [0.01, 0.0]\n", transient + "integrator = \"hht\"\nalpha = -0.5\n",
         "'analysis.alpha'"},
        {"increment in time", "[[initial_velocity]]\nat = [1.0, 0.0]\nv = [0.01, 0.0]\n", transient + "increment = 0.1\n",
         "'analysis.increment': a transient stage steps in time"},
        {"series of an unknown pattern", "[[load]]\nat = [1.0, 0.0]\nfx = 1.0\n[[time_series]]\npattern = \"wind\"\nkind = \"pulse\"\nwidth = 0.1\n",
         transient, "'time_series[1].pattern': no load belongs to pattern 'wind'"},
        {"table times not increasing", "[[load]]\nat = [1.0, 0.0]\nfx = 1.0\n[[time_series]]\npattern = \"main\"\nkind = \"table\"\ntimes = [0.0, 0.2, 0.1]\nvalues = [0.0, 1.0, 0.0]\n",
         transient, "'time_series[1].times': expected increasing times (item 3)"},
        {"ratio and coefficients", "[[initial_velocity]]\nat = [1.0, 0.0]\nv = [0.01, 0.0]\n[damping]\nratio = 0.05\nalpha_m = 0.1\n", transient,
         "'damping.ratio': give either 'ratio'"},
        {"mass at no node", "[[initial_velocity]]\nat = [1.0, 0.0]\nv = [0.01, 0.0]\n[[mass]]\nat = [3.0, 0.0]\nm = 1.0\n", transient,
         "'mass[2].at': no node at [3, 0]"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.what);
        std::string text = sdof(c.extra, 0.01, 1.0);
        text = text.substr(0, text.find("[analysis]")) + "[analysis]\n" + c.analysis + "control_at = [1.0, 0.0]\ncontrol_dof = \"ux\"\n";
        try {
            (void)read_scene_text(text, "bad.toml");
            FAIL("no error");
        } catch (const SceneError& e) {
            CHECK_THAT(e.what(), Catch::Contains("bad.toml:") && Catch::Contains(c.message));
        }
    }
}

namespace {
// A massless rod of length L = 1, pinned at the origin, with a unit mass at its free end under
// gravity g: the rod's rotations carry no mass and its axial stiffness holds the length.
std::string pendulum(const std::string& extra, double dt, double duration, int elements) {
    return R"(
[scene]
name = "pendulum"
[[material]]
name = "rod"
E = 1.0e7
[[section]]
name = "s"
material = "rod"
A = 1.0
I = 0.01
[[line]]
start = [0.0, 0.0]
end = [1.0, 0.0]
elements = )" + std::to_string(elements) + R"(
section = "s"
[[support]]
at = [0.0, 0.0]
fix = ["ux", "uy"]
[[mass]]
at = [1.0, 0.0]
m = 1.0
)" + extra + "\n[analysis]\nscheme = \"transient\"\ntime_step = " + std::to_string(dt) + "\nduration = " + std::to_string(duration) +
           "\ncontrol_at = [1.0, 0.0]\ncontrol_dof = \"uy\"\nresidual_tolerance = 1e-10\n";
}

// Times where the controlled displacement has a local extremum (a parabola through three steps).
std::vector<double> turning_times(const std::vector<StepResult>& steps, int dof) {
    std::vector<double> out;
    for (std::size_t i = 1; i + 1 < steps.size(); ++i) {
        const double a = steps[i - 1].displacement[dof], b = steps[i].displacement[dof], c = steps[i + 1].displacement[dof];
        if ((b - a) * (c - b) > 0.0 || b == a) continue;
        const double dt = steps[i + 1].time - steps[i].time;
        out.push_back(steps[i].time + dt * (a - c) / (2.0 * (a - 2.0 * b + c)));
    }
    return out;
}
} // namespace

TEST_CASE("A pendulum of a massless rod released level swings with the elliptic-integral period from its first step") {
    // T = 4√(L/g)·K(sin 45°) for a release at 90° (K(1/√2) = 1.8540746773013719). The massless
    // rotations start from statics: the first step falls ½gΔt², and the turning points sit on
    // quarter periods within Newmark's phase error, (ωΔt)²/12 per radian with ω = √(g/L) (2e-6 of
    // the period here); starting at rest would lag half a step (8e-4 of it).
    const double g = 9.81, dt = 0.001, quarter = std::sqrt(1.0 / g) * 1.8540746773013719;
    for (int elements : {1, 4}) {
        CAPTURE(elements);
        const Run run = run_scene(pendulum("[[load]]\nat = [1.0, 0.0]\nfy = -9.81\n", dt, 2.5, elements));
        REQUIRE(run.summary.status == RunStatus::completed);
        const int tip_uy = 3 * elements + 1;
        CHECK(run.steps[1].displacement[static_cast<std::size_t>(tip_uy)] == Approx(-0.5 * g * dt * dt).epsilon(1e-6));
        const std::vector<double> turns = turning_times(run.steps, tip_uy);
        REQUIRE(turns.size() == 4);
        for (std::size_t k = 0; k < turns.size(); ++k) CHECK(turns[k] == Approx(static_cast<double>(k + 1) * quarter).epsilon(2e-5));
        CHECK(run.summary.largest_energy_error <= 1e-6);
    }
}

TEST_CASE("A damped SDOF on a massless cantilever reaches its first peak as the closed form") {
    // Tip mass 1 on a massless cantilever of 3EI/L³ = 100 (ω = 10), ζ = 0.05 by C = 2ζωM, started
    // at v0: u = (v0/ω_d)e^(−ζωt) sin ω_d t peaks at t_p = atan(ω_d/ζω)/ω_d. The rotations carry
    // no mass; a₀ = −2ζω v0 at the tip must reach them through the tangent.
    const double omega = 10.0, zeta = 0.05, v0 = 1e-4, dt = 0.001;
    std::string scene = pendulum("[[initial_velocity]]\nat = [1.0, 0.0]\nv = [0.0, 1e-4]\n[damping]\nalpha_m = 1.0\n", dt, 0.3, 4);
    scene.replace(scene.find("E = 1.0e7"), 9, "E = 3333.3333333333333");
    scene.replace(scene.find("fix = [\"ux\", \"uy\"]"), 18, "fix = [\"ux\", \"uy\", \"rz\"]");
    const Run run = run_scene(scene);
    REQUIRE(run.summary.status == RunStatus::completed);
    const std::vector<double> turns = turning_times(run.steps, 13);
    REQUIRE(!turns.empty());
    const double wd = omega * std::sqrt(1.0 - zeta * zeta), tp = std::atan(wd / (zeta * omega)) / wd;
    CHECK(turns.front() == Approx(tp).epsilon(1e-4));
    double peak = 0.0;
    for (const StepResult& r : run.steps) peak = std::max(peak, r.displacement[13]);
    // The sampled peak lies within (ω_dΔt)²/8 = 1.2e-5 of the true one below it.
    CHECK(peak == Approx(v0 / wd * std::exp(-zeta * omega * tp) * std::sin(wd * tp)).epsilon(1e-4));
}

TEST_CASE("A transient stage without mass is refused where it is chosen, naming what to add") {
    const std::string scene = pendulum("[[load]]\nat = [1.0, 0.0]\nfy = -9.81\n", 0.01, 1.0, 2);
    const std::string massless = scene.substr(0, scene.find("[[mass]]")) + scene.substr(scene.find("[[load]]"));
    try {
        (void)read_scene_text(massless, "massless.toml");
        FAIL("a scene without mass was read");
    } catch (const SceneError& e) {
        CHECK_THAT(e.what(), Catch::Contains("massless.toml:") && Catch::Contains("'analysis.scheme'") && Catch::Contains("density") &&
                                 Catch::Contains("[[mass]]"));
    }
}

TEST_CASE("A record header announcing more values than a file can hold is refused, naming the file") {
    // NPTS= 99999999999 threw std::out_of_range past the reader (exit 134); a plain header's
    // count of 1e20 overflowed its conversion to int.
    const std::filesystem::path dir = scratch::fresh_folder("npts");
    const std::vector<std::string> headers = {"NPTS= 99999999999, DT= .0200 SEC", "1e20 0.02", "NPTS= 12.5, DT= 0.02"};
    for (const std::string& header : headers) {
        CAPTURE(header);
        scratch::write(dir / "huge.at2", "PEER NGA STRONG MOTION DATABASE\nrecord\nACCELERATION IN UNITS OF G\n" + header + "\n0.1 0.2\n");
        const std::string text = sdof("[[ground_motion]]\nfile = \"" + (dir / "huge.at2").string() + "\"\nunits = 1.0\n", 0.02, 1.0);
        try {
            (void)read_scene_text(text, "shaken.toml");
            FAIL("read");
        } catch (const SceneError& e) {
            CHECK_THAT(e.what(), Catch::Contains("shaken.toml:") && Catch::Contains("'ground_motion[1].file'") && Catch::Contains("NPTS"));
        }
    }
}

TEST_CASE("Transient stages are held to ten million steps together, not only each") {
    const std::string stage = "[[stage]]\nscheme = \"transient\"\ntime_step = 0.001\nduration = 6000.0\n";
    const std::string text = sdof("[[initial_velocity]]\nat = [1.0, 0.0]\nv = [0.01, 0.0]\n", 0.001, 6000.0) + stage;
    try {
        (void)read_scene_text(text, "long.toml");
        FAIL("read");
    } catch (const SceneError& e) {
        CHECK_THAT(e.what(), Catch::Contains("long.toml:") && Catch::Contains("'stage[1].duration'") && Catch::Contains("12000000 steps in all"));
    }
}
