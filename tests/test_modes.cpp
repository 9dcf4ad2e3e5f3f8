// Natural frequencies against Euler–Bernoulli, and the conservation laws of large free motion:
// energy of an elastic cantilever swinging through tens of degrees, momentum and angular
// momentum of a free beam spinning and flying.
#include "analysis/path_following.hpp"
#include "dynamics/mass_matrix.hpp"
#include "scene_reader.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

using namespace plastica;

namespace {

constexpr double pi = 3.14159265358979323846;

// A beam of length 1, EI = 1, ρA = 1 (r/L = 1e-3: rotary inertia changes the fourth
// frequency by 1e-4 %), in `elements` elements; supports as given.
std::string beam(int elements, const std::string& supports, const std::string& mass, const std::string& analysis) {
    return R"(
[scene]
name = "beam"
[[material]]
name = "m"
E = 1.0
density = 1e-6
[[section]]
name = "s"
material = "m"
A = 1.0e6
I = 1.0
[[line]]
start = [0.0, 0.0]
end = [1.0, 0.0]
elements = )" + std::to_string(elements) + "\nsection = \"s\"\n" + supports + "\n[analysis]\nmass = \"" + mass + "\"\n" + analysis;
}

const std::string clamped = "[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n";
const std::string pinned = "[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"uy\"]\n[[support]]\nat = [1.0, 0.0]\nfix = [\"uy\"]\n";
const std::string free_vibration = "scheme = \"transient\"\ntime_step = 0.01\nduration = 0.01\n";
const std::string nudge = "[[initial_velocity]]\nat = [1.0, 0.0]\nv = [0.0, 1e-9]\n";

std::vector<double> frequencies(int elements, const std::string& supports, const std::string& mass, int count) {
    const Model model = read_scene_text(beam(elements, supports + nudge, mass, free_vibration), "beam.toml");
    PathFollowing analysis(model);
    const ModalResult modes = analysis.modes(count + 2);
    std::vector<double> out;
    for (const ModeRow& m : modes.modes) out.push_back(m.omega);
    return out;
}

// ω of bending modes, EI = ρA = L = 1: (βL)² for the cantilever, (nπ)² simply supported.
const double cantilever_beta[] = {1.875104069, 4.694091133, 7.854757438, 10.99554073};

} // namespace

TEST_CASE("Ten consistent-mass elements give a cantilever's and a simple beam's frequencies within 0.5 %") {
    // Hermitian elements with their consistent mass are Rayleigh–Ritz: every frequency lies above
    // the exact one, and the error falls as h⁴ (a quarter of the mesh: 1/16).
    const std::vector<double> cantilever = frequencies(10, clamped, "consistent", 4);
    const std::vector<double> finer = frequencies(20, clamped, "consistent", 4);
    const std::vector<double> simple = frequencies(10, pinned, "consistent", 4);
    REQUIRE(cantilever.size() >= 4);
    REQUIRE(simple.size() >= 4);
    for (int n = 0; n < 4; ++n) {
        const double exact_c = std::pow(cantilever_beta[n], 2), exact_s = std::pow((n + 1) * pi, 2);
        CAPTURE(n + 1, cantilever[n] / exact_c - 1.0, simple[n] / exact_s - 1.0);
        // Below the Euler–Bernoulli value only by what rotary inertia takes off a Rayleigh beam,
        // about ½(β r)² with r = √(I/A) = 1e-3 (β = √ω here).
        const double rotary_c = std::pow(1e-3, 2) * exact_c, rotary_s = std::pow(1e-3, 2) * exact_s;
        CHECK(cantilever[n] / exact_c - 1.0 <= 5e-3);
        CHECK(cantilever[n] / exact_c - 1.0 >= -rotary_c);
        CHECK(simple[n] / exact_s - 1.0 <= 5e-3);
        CHECK(simple[n] / exact_s - 1.0 >= -rotary_s);
    }
    const double e10 = cantilever[2] / std::pow(cantilever_beta[2], 2) - 1.0, e20 = finer[2] / std::pow(cantilever_beta[2], 2) - 1.0;
    CHECK(e20 <= e10 / 12.0);
}

TEST_CASE("Lumped mass converges from below as h²") {
    // A diagonal mass with massless rotations underestimates the frequencies; halving the
    // elements quarters the error.
    std::vector<double> errors;
    for (int elements : {10, 20, 40}) {
        const std::vector<double> w = frequencies(elements, clamped, "lumped", 2);
        errors.push_back(w[1] / std::pow(cantilever_beta[1], 2) - 1.0);
    }
    CAPTURE(errors[0], errors[1], errors[2]);
    CHECK(errors[0] < 0.0);
    CHECK(errors[0] >= -0.02);
    for (int k = 0; k < 2; ++k) {
        const double ratio = errors[static_cast<std::size_t>(k)] / errors[static_cast<std::size_t>(k) + 1];
        CHECK(ratio == Approx(4.0).epsilon(0.05));
    }
}

namespace {

struct Momentum {
    double px = 0.0, py = 0.0, angular = 0.0;
};

// p = M v per DOF; the angular momentum about the origin is Σ x × p over the translations
// plus the rotations' own (Hermitian shape functions carry the cross-section's turning).
Momentum momentum_of(const Model& model, const StepResult& r) {
    std::vector<int> all(static_cast<std::size_t>(model.dof_count()));
    for (std::size_t d = 0; d < all.size(); ++d) all[d] = static_cast<int>(d);
    const MassMatrix mass(model, model.dynamics.mass, all, model.dof_count());
    const Eigen::Map<const Eigen::VectorXd> u(r.displacement.data(), static_cast<Eigen::Index>(r.displacement.size()));
    const Eigen::Map<const Eigen::VectorXd> v(r.velocity.data(), static_cast<Eigen::Index>(r.velocity.size()));
    const Eigen::VectorXd p = mass.times(u, v);
    Momentum out;
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        const double x = model.nodes[n].x + u[3 * n], y = model.nodes[n].y + u[3 * n + 1];
        out.px += p[3 * n];
        out.py += p[3 * n + 1];
        out.angular += x * p[3 * n + 1] - y * p[3 * n] + p[3 * n + 2];
    }
    return out;
}

} // namespace

TEST_CASE("A free beam spinning and flying keeps its momentum, angular momentum and energy") {
    // A bar of mass 1 and length 1 (I = 1/12 about its centre) flies at (0.3, 0.2) turning at
    // 1 rad/s for 10 s, 1.6 turns: p = (0.3, 0.2), H = I ω = 1/12, T = 0.065 + 1/24.
    const std::string text = beam(10, "", "consistent",
                                  "scheme = \"transient\"\ntime_step = 0.01\nduration = 10.0\ncontrol_at = [1.0, 0.0]\n") +
                             "[[initial_velocity]]\non = \"all\"\nv = [0.3, 0.2]\nspin = 1.0\nabout = [0.5, 0.0]\n";
    const Model model = read_scene_text(text, "spin.toml");
    PathFollowing analysis(model);
    std::vector<StepResult> steps;
    const RunSummary summary = analysis.run({[&](const StepResult& r) { steps.push_back(r); }});
    REQUIRE(summary.status == RunStatus::completed);
    REQUIRE(steps.size() == 1001);
    // The rotation after 10 s: the chord of the bar turned by 10 rad, its centre moved by (3, 2).
    const StepResult& last = steps.back();
    const double turned = std::atan2(last.displacement[3 * 10 + 1] - last.displacement[1] + 0.0, 1.0 + last.displacement[3 * 10] - last.displacement[0]);
    CHECK(std::remainder(turned - 10.0, 2.0 * pi) == Approx(0.0).margin(1e-3));
    for (const StepResult& r : steps) {
        if (r.step == 0) continue;
        const Momentum m = momentum_of(model, r);
        // Translations conserve exactly what the rule conserves; the chord's mass matrix turns
        // with it, which the trapezoidal rule follows to (ωΔt)² = 1e-4 of a turn's change.
        CHECK(m.px == Approx(0.3).margin(1e-6));
        CHECK(m.py == Approx(0.2).margin(1e-6));
        CHECK(m.angular - (0.5 * 0.2 - 0.0) == Approx(1.0 / 12.0 + 0.0).margin(1e-5));
        CHECK(r.energy.error <= 1e-4);
    }
    CHECK(last.energy.kinetic == Approx(0.065 + 1.0 / 24.0).epsilon(1e-4));
}

TEST_CASE("An elastic cantilever swinging through tens of degrees keeps its energy within 1e-3") {
    // Thrown as a rigid body turning at 2 rad/s about its clamp, the cantilever bends until its
    // tip turns by more than 20°, and swings back; undamped, nothing is lost but the rule's error.
    const std::string text = beam(20, clamped, "consistent",
                                  "scheme = \"transient\"\ntime_step = 0.005\nduration = 4.0\ncontrol_at = [1.0, 0.0]\n") +
                             "[[initial_velocity]]\non = \"all\"\nspin = 2.0\n";
    std::vector<StepResult> steps;
    const Model model = read_scene_text(text, "swing.toml");
    PathFollowing analysis(model);
    const RunSummary summary = analysis.run({[&](const StepResult& r) { steps.push_back(r); }});
    REQUIRE(summary.status == RunStatus::completed);
    double largest_tip_rotation = 0.0;
    for (const StepResult& r : steps) largest_tip_rotation = std::max(largest_tip_rotation, std::abs(r.displacement[3 * 20 + 2]));
    CAPTURE(largest_tip_rotation, summary.largest_energy_error);
    CHECK(largest_tip_rotation >= 20.0 * pi / 180.0);
    CHECK(summary.largest_energy_error <= 1e-3);
    // Elastic members dissipate nothing: the trapezoidal work of their forces differs from their
    // strain energy only by the rule's O(Δt²) error (the co-rotational energy is not quadratic).
    const double thrown = 4.0 / 6.0; // ½∫ρA(ωx)²dx = ρAω²L³/6
    CHECK(std::abs(steps.back().energy.plastic) <= 1e-3 * thrown);
}
