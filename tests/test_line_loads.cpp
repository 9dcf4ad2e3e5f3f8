// Distributed loads against closed forms: line loads lumped to the nodes (beam theory),
// self weight (statics), follower pressure on a ring (membrane state and the buckling
// pressure 3EI/R³) and plastic collapse under a uniform load (plastic theory).
#include "analysis_helpers.hpp"
#include "plastic_beam_scenes.hpp"
#include "load/follower_pressure.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace plastica;
using namespace plastica::testing;

namespace {

constexpr double pi = 3.14159265358979323846;

// A beam [0, L] on a pin at x = 0 and a roller at x = L, with n elements and the given loads.
std::string simply_supported(double L, int n, double E, double A, double I, const std::string& loads,
                             const std::string& analysis, const std::string& material_extra = "") {
    return "[scene]\nname = \"beam\"\n[[material]]\nname = \"m\"\nE = " + num(E) + "\n" + material_extra +
           "[[section]]\nname = \"s\"\nmaterial = \"m\"\nA = " + num(A) + "\nI = " + num(I) +
           "\n[[line]]\nname = \"beam\"\nstart = [0.0, 0.0]\nend = [" + num(L) + ", 0.0]\nelements = " +
           std::to_string(n) + "\nsection = \"s\"\n[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"uy\"]\n"
           "[[support]]\nat = [" + num(L) + ", 0.0]\nfix = [\"uy\"]\n" + loads + analysis;
}

std::string load_control_to(double target, int steps, const std::string& extra = "") {
    return "[analysis]\nscheme = \"load_control\"\nincrement = " + num(target / steps) +
           "\nadaptive = false\ntarget_load_factor = " + num(target) + "\n" + extra;
}

// Midspan deflection of a simply supported beam under point loads P at x = a ≤ L/2 and their
// mirror images at L − a: Σ P a (3L² − 4a²) / 48EI, the exact answer for the lumped loads.
double midspan_deflection_of_lumped_load(double w, double L, int n, double EI) {
    const double h = L / n;
    double d = 0.0;
    for (int k = 1; k < n; ++k) {
        const double a = std::min(k * h, L - k * h);
        d += w * h * a * (3 * L * L - 4 * a * a) / (48 * EI);
    }
    return d;
}

// A full ring of radius R and n elements under follower pressure p, held against rigid motion
// (uy at the ends of the horizontal diameter, ux at the top).
std::string ring_under_pressure(int n, double p, double increment, double target) {
    return "[scene]\nname = \"ring\"\n[[material]]\nname = \"steel\"\nE = 1.0e9\n[[section]]\nname = \"ring\"\n"
           "material = \"steel\"\nA = 0.1\nI = 1.0e-6\n[[arc]]\nname = \"ring\"\ncenter = [0.0, 0.0]\nradius = 100.0\n"
           "start_angle = 0.0\nend_angle = 360.0\nelements = " + std::to_string(n) +
           "\nsection = \"ring\"\n[[support]]\nat = [100.0, 0.0]\nfix = [\"uy\"]\n[[support]]\nat = [-100.0, 0.0]\n"
           "fix = [\"uy\"]\n[[support]]\nat = [0.0, 100.0]\nfix = [\"ux\"]\n[[distributed_load]]\non = \"ring\"\n"
           "pressure = " + num(p) + "\n[analysis]\nscheme = \"load_control\"\nincrement = " + num(increment) +
           "\nadaptive = false\ncontrol_at = [0.0, 100.0]\ncontrol_dof = \"uy\"\ntarget_load_factor = " + num(target) +
           "\nmax_steps = 5000\n";
}

// The load factor of the first step whose tangent has a negative pivot.
double first_negative_pivot(const Run& r) {
    for (const StepResult& s : r.steps)
        if (s.negative_pivots > 0) return s.load_factor;
    return NAN;
}

} // namespace

TEST_CASE("A uniform line load lumped to the nodes bends a simply supported beam as beam theory says", "[loads]") {
    // Deflections of 1e-7 L keep the run linear to 1e-12; Hermite beams are exact under nodal
    // loads, so the lumped load's deflection is met to round-off, and it tends to 5wL⁴/384EI
    // as h² (the lumped load misses the load's moment over each element, of order w h²).
    const double L = 10.0, E = 2.0e11, I = 8.0e-6, A = 4.0e-3, w = 1.0;
    const double exact = 5 * w * std::pow(L, 4) / (384 * E * I);
    double previous_error = 0.0;
    for (int n : {4, 8, 16}) {
        INFO("elements: " << n);
        const Run r = run_scene(simply_supported(L, n, E, A, I, "[[distributed_load]]\non = \"beam\"\nwy = -1.0\n",
                                                 load_control_to(1.0, 1, "control_at = [5.0, 0.0]\n")));
        REQUIRE(r.summary.status == RunStatus::completed);
        const double midspan = -r.node_dof(r.steps.back(), L / 2, 0.0, 1);
        CHECK(midspan == Approx(midspan_deflection_of_lumped_load(w, L, n, E * I)).epsilon(1e-9));
        CHECK(r.steps.back().load == Approx(w * L).epsilon(1e-12)); // the reported load is the total
        const double error = std::abs(midspan - exact) / exact;
        if (previous_error > 0.0) CHECK(previous_error / error == Approx(4.0).epsilon(0.05));
        previous_error = error;
    }
}

TEST_CASE("Self weight is ρ A g along every member and equals the same line load", "[loads]") {
    const double L = 10.0, E = 2.0e11, I = 8.0e-6, A = 4.0e-3, rho = 7850.0, g = 9.81;
    const std::string analysis = load_control_to(1.0, 2, "control_at = [5.0, 0.0]\n");
    const Run weight = run_scene(simply_supported(L, 10, E, A, I, "[[distributed_load]]\non = \"all\"\ngravity = [0.0, -9.81]\n",
                                                  analysis, "density = 7850.0\n"));
    const Run line = run_scene(simply_supported(L, 10, E, A, I, "[[distributed_load]]\non = \"beam\"\nwy = " + num(-rho * A * g) + "\n",
                                                analysis, "density = 7850.0\n"));
    REQUIRE(weight.summary.status == RunStatus::completed);
    REQUIRE(line.summary.status == RunStatus::completed);
    const StepResult& s = weight.steps.back();
    double vertical = 0.0, horizontal = 0.0;
    for (std::size_t k = 0; k < weight.model.nodes.size(); ++k) horizontal += s.reaction[3 * k], vertical += s.reaction[3 * k + 1];
    CHECK(vertical == Approx(rho * A * g * L).epsilon(1e-9)); // the supports carry the weight
    CHECK(std::abs(horizontal) < 1e-9 * rho * A * g * L);
    CHECK(s.displacement == line.steps.back().displacement);
}

TEST_CASE("Follower pressure keeps a ring's polygon in its membrane state", "[loads][pressure]") {
    // Before buckling the n-gon only shortens: the chord forces of p c make its hoop force
    // p R cos(π/n), so every node moves in by p R² cos(π/n) / EA (to strains of 3e-9).
    for (int n : {16, 64}) {
        INFO("elements: " << n);
        const double p = 3.0e-3;
        const Run r = run_scene(ring_under_pressure(n, p, 0.25, 0.5));
        REQUIRE(r.summary.status == RunStatus::completed);
        const StepResult& s = r.steps.back();
        const double inward = s.load_factor * p * 100.0 * 100.0 * std::cos(pi / n) / (1.0e9 * 0.1);
        CHECK(-s.control_displacement == Approx(inward).epsilon(1e-6));
        CHECK(r.node_dof(s, 0.0, -100.0, 1) == Approx(inward).epsilon(1e-6)); // the bottom moves up as much
        CHECK(s.load == Approx(s.load_factor * p).epsilon(1e-12));                  // the load is the pressure
    }
}

TEST_CASE("A ring under follower pressure buckles at 3EI/R³, the polygon's error falling as 1/n²", "[loads][pressure]") {
    // The load factor is p / (3EI/R³). A fixed-direction or centre-directed load would buckle
    // the ring at 4 or 4.5 EI/R³: 3 needs the pressure's load stiffness. Steps of 0.001 bracket
    // the first negative pivot (the ovalising n = 2 mode, twice); the n-gon is stiffer than the
    // ring by a share of order (2π/n)².
    const double p_cr = 3.0 * 1.0e9 * 1.0e-6 / 1.0e6;
    const Run r32 = run_scene(ring_under_pressure(32, p_cr, 0.001, 1.03));
    const Run r64 = run_scene(ring_under_pressure(64, p_cr, 0.001, 1.03));
    REQUIRE(r32.summary.status == RunStatus::completed);
    REQUIRE(r64.summary.status == RunStatus::completed);
    const double l32 = first_negative_pivot(r32), l64 = first_negative_pivot(r64);
    CHECK(l64 > 1.0);
    CHECK(l64 < 1.01);
    CHECK(l32 > l64);
    CHECK((l32 - 1.0) / (l64 - 1.0) == Approx(4.0).margin(0.8)); // ±0.001 steps on errors of 0.018 and 0.0045
    CHECK(r64.steps.back().negative_pivots == 2);                  // the two orientations of the oval
}

namespace {

// A beam of plastic_beam_scenes.hpp, 2000 long on n elements under a uniform load wy = −1,
// pinned–roller or clamped at both ends, pushed down at midspan.
Run uniformly_loaded_beam(const std::string& plasticity, int n, bool clamped, double increment, double target) {
    const std::string fix = clamped ? "[\"ux\", \"uy\", \"rz\"]" : "[\"ux\", \"uy\"]";
    return run_scene(plastic_beam_header(plasticity) + "[[line]]\nname = \"beam\"\nstart = [0.0, 0.0]\nend = [2000.0, 0.0]\nelements = " +
                     std::to_string(n) + "\nsection = \"s\"\n[[distributed_load]]\non = \"beam\"\nwy = -1.0\n[[support]]\nat = [0.0, 0.0]\nfix = " +
                     fix + "\n[[support]]\nat = [2000.0, 0.0]\nfix = " + (clamped ? fix : "[\"uy\"]") + "\n" +
                     displacement_control(1000.0, 0.0, "uy", increment, target));
}

} // namespace

TEST_CASE("A uniform load collapses a simply supported beam at 8 Mp/L² and a clamped one at 16 Mp/L²", "[loads][plasticity]") {
    // The lumped loads do the same virtual work as the uniform load on the beam mechanisms
    // (a hinge at midspan, where there is a node), so the collapse loads are those of plastic
    // theory; the total W = wL is reported: 8 Mp/L and 16 Mp/L.
    const double L = 2000.0, pinned_limit = 8.0 * rectangle_Mp / L, clamped_limit = 16.0 * rectangle_Mp / L;
    SECTION("refined plastic hinges, 8 elements: the mechanism load") {
        const Run pinned = uniformly_loaded_beam("hinges", 8, false, 0.02, 1.0);
        REQUIRE(pinned.summary.status == RunStatus::completed);
        CHECK(pinned.steps.back().load == Approx(pinned_limit).epsilon(0.01));
        CHECK(pinned.max_load() <= pinned_limit * 1.01);
        const Run clamped = uniformly_loaded_beam("hinges", 8, true, 0.01, 0.15);
        REQUIRE(clamped.summary.status == RunStatus::completed);
        CHECK(clamped.steps.back().load == Approx(clamped_limit).epsilon(0.01));
        CHECK(clamped.max_load() <= clamped_limit * 1.01);
    }
    SECTION("distributed plasticity: second order where the shear vanishes, first order where it does not") {
        // Gauss points sample the moment off the hinge. At midspan of the simply supported beam
        // the moment is flat (M_p − w s²/2), so the excess falls as h² (1.8 %, 0.45 %, 0.11 % with
        // 8, 16, 32 elements); at a clamped end the shear wL/2 makes it fall as h (7.7 %, 3.7 %
        // with 16, 32), and the extrapolation to h = 0 gives the mechanism load.
        const double p8 = uniformly_loaded_beam("distributed", 8, false, 0.02, 1.0).steps.back().load;
        const double p16 = uniformly_loaded_beam("distributed", 16, false, 0.02, 1.0).steps.back().load;
        CAPTURE(p8, p16);
        CHECK(p16 > pinned_limit);
        CHECK(std::log2((p8 - pinned_limit) / (p16 - pinned_limit)) == Approx(2.0).margin(0.2));
        CHECK(p16 == Approx(pinned_limit).epsilon(0.005));
        const double c16 = uniformly_loaded_beam("distributed", 16, true, 0.01, 0.3).steps.back().load;
        const double c32 = uniformly_loaded_beam("distributed", 32, true, 0.01, 0.3).steps.back().load;
        CAPTURE(c16, c32);
        CHECK(c32 > clamped_limit);
        CHECK(std::log2((c16 - clamped_limit) / (c32 - clamped_limit)) == Approx(1.0).margin(0.2));
        CHECK(2.0 * c32 - c16 == Approx(clamped_limit).epsilon(0.005));
    }
}

TEST_CASE("The load stiffness of pressure on a closed ring is the derivative of its nodal forces", "[loads][pressure]") {
    // The forces are linear in the node positions, so central differences are exact to
    // round-off; on a closed contour the symmetric element parts add up to the whole
    // derivative (the skew parts cancel between neighbours), at any deformed state.
    const Model model = read_scene_text(ring_under_pressure(12, 2.0, 0.1, 1.0), "ring.toml");
    const FollowerPressure pressure(model);
    const int n = model.dof_count();
    const double lambda = 0.7;
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
    for (std::size_t e = 0; e < model.elements.size(); ++e) {
        const int dofs[2] = {3 * model.elements[e].node_i, 3 * model.elements[e].node_j};
        const Eigen::Matrix<double, 6, 6> k = pressure.stiffness(e, lambda);
        for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b) K.block<3, 3>(dofs[a], dofs[b]) += k.block<3, 3>(3 * a, 3 * b);
    }
    std::srand(11);
    const Eigen::VectorXd u = 10.0 * Eigen::VectorXd::Random(n); // an arbitrary deformed state
    Eigen::MatrixXd numeric(n, n);
    for (int j = 0; j < n; ++j) {
        Eigen::VectorXd plus = Eigen::VectorXd::Zero(n), minus = Eigen::VectorXd::Zero(n);
        Eigen::VectorXd up = u, um = u;
        up[j] += 0.5, um[j] -= 0.5;
        pressure.add_forces(up, plus);
        pressure.add_forces(um, minus);
        numeric.col(j) = -lambda * (plus - minus);
    }
    CHECK((numeric - K).norm() <= 1e-13 * K.norm());
    CHECK(K.norm() > 1.0); // the stiffness is there: λp/2 = 0.7 in 4 entries per element
}

TEST_CASE("Past buckling, the ring's top and bottom meet at p = 5.247 EI/R³", "[loads][pressure]") {
    // The elastica of a ring under hydrostatic pressure (Flaherty, Keller & Rubinow 1972): the
    // oval flattens under a rising pressure until opposite points touch at pR³/EI = 5.247,
    // when the top has moved in by R. The polygon is stiff by a share of order (2π/n)², as at
    // buckling: +0.41 % with 64 elements, +0.16 % with 96; extrapolated in 1/n² the two give
    // the elastica within 0.1 %.
    auto pressure_at_contact = [](int elements) {
        std::string scene = scene_file_text("models/gallery/ring_external_pressure.toml");
        for (const auto& [from, to] : {std::pair<std::string, std::string>{"elements = 64", "elements = " + std::to_string(elements)},
                                       {"target_displacement = 99.0", "target_displacement = 101.0\nallow_crossing = true"}}) {
            const std::size_t at = scene.find(from);
            REQUIRE(at != std::string::npos);
            scene.replace(at, from.size(), to);
        }
        const Run r = run_scene(scene);
        REQUIRE(r.summary.status == RunStatus::completed);
        // The load factor is p/(3EI/R³).
        return 3.0 * value_at(r.steps, 100.0, [](const StepResult& s) { return s.control_displacement; },
                              [](const StepResult& s) { return s.load_factor; });
    };
    const double p64 = pressure_at_contact(64), p96 = pressure_at_contact(96), elastica = 5.247;
    CAPTURE(p64, p96);
    CHECK(p64 > p96);
    CHECK(p96 > elastica);
    CHECK(p64 == Approx(elastica).epsilon(0.01));
    const double extrapolated = (96.0 * 96.0 * p96 - 64.0 * 64.0 * p64) / (96.0 * 96.0 - 64.0 * 64.0);
    CHECK(extrapolated == Approx(elastica).epsilon(0.001));
}
