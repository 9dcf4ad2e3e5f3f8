// Stability along the path: bifurcations located and reported, branch switching (a perfect
// column's elastica, Roorda's frame against its exact elastica and Koiter's slope), imperfections
// from modes, and a shallow arch's limit point landed on.
#include "analysis_helpers.hpp"
#include "roorda_elastica.hpp"
#include "stability_scenes.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

using namespace plastica;
using namespace plastica::testing;

namespace {

constexpr double pi = 3.14159265358979323846;

// The perfect pinned column of column() on 20 elements, nearly inextensible (EA/EI = 1e7),
// followed by arc length with the given bifurcation rule until its top has come down by `travel`.
std::string perfect_column(const char* rule, double travel) {
    std::string s = column("\"ux\", \"uy\"", "\"ux\"", 20);
    const std::string analysis = s.substr(s.find("[analysis]"));
    s = s.substr(0, s.find("[analysis]"));
    s.replace(s.find("A = 10.0"), 8, "A = 1.0e4");
    return s + "[analysis]\nscheme = \"arc_length\"\nincrement = 0.05\nbifurcation = \"" + rule +
           "\"\ncontrol_at = [0.0, 1.0]\ncontrol_dof = \"uy\"\ntarget_displacement = " + num(travel) +
           "\nmax_steps = 500\n";
}

} // namespace

TEST_CASE("A perfect column reports its bifurcation and ends unstable without switching", "[buckling]") {
    // A travel of 2e-6 is a load factor of 20: past the first mode (9.87), short of the second (39.5).
    const Run p = run_scene(perfect_column("report", 2e-6));
    REQUIRE(p.summary.critical_points.size() == 1);
    const CriticalPoint& c = p.summary.critical_points.front();
    CHECK(c.kind == CriticalKind::bifurcation);
    CHECK(!c.followed);
    // Located where the path's own tangent (the chord's geometric stiffness) turns indefinite:
    // on 20 elements 0.21 % above Euler's load (1 + π²/(12·20²)·…, measured 1.00206).
    CHECK(std::abs(c.load_factor / (pi * pi) - 1.00206) < 2e-4);
    CHECK(c.load_alignment < 1e-6);
    CHECK(p.summary.ends_unstable);
    CHECK(p.summary.reason.find("past a bifurcation at load factor") != std::string::npos);
}

TEST_CASE("A perfect pinned column switched to its buckled branch follows the elastica", "[buckling]") {
    // Timoshenko & Gere, Theory of Elastic Stability, 1961, §2.7: P/P_cr = (2K(k)/π)² with
    // k = sin(θ₀/2), θ₀ the end rotation. On 20 elements the discrete column buckles 0.21 %
    // above P_cr and its elastica stays within that of the continuous one; 0.5 % bounds it.
    const Run p = run_scene(perfect_column("switch", 1.0));
    REQUIRE(p.summary.critical_points.size() >= 1);
    CHECK(p.summary.critical_points.front().followed);
    double largest_rotation = 0.0;
    for (const StepResult& r : p.steps) {
        const double theta = std::abs(r.displacement[2]);
        if (theta < 0.05 || theta > 120.0 * pi / 180.0) continue;
        const double k = std::sin(theta / 2.0);
        const double exact = std::pow(2.0 * std::comp_ellint_1(k) / pi, 2) * pi * pi;
        INFO("θ₀ = " << theta * 180.0 / pi << "°: " << r.load_factor << " against " << exact);
        CHECK(std::abs(r.load_factor / exact - 1.0) < 5e-3);
        largest_rotation = std::max(largest_rotation, theta);
    }
    CHECK(largest_rotation > 110.0 * pi / 180.0);
}

TEST_CASE("A column given its first mode as an imperfection of L/1000 amplifies it by 1/(1 − P/P_cr)", "[buckling]") {
    // Timoshenko & Gere 1961, §1.12: a pinned column of initial shape e₀ sin(πx/L) deflects to
    // e₀/(1 − P/P_E) at midspan. On 40 elements the path's own P_cr is 5e-4 above P_E, which
    // moves the amplification at P/P_E = 0.8 by 4 × 5e-4; the cubic mode differs from the sine
    // by less (3e-7 of its amplitude).
    std::string scene = perfect_column("report", 1.0);
    scene.replace(scene.find("elements = 20"), 13, "elements = 40");
    scene = scene.substr(0, scene.find("[analysis]")) + R"(
[[imperfection]]
mode = 1
amplitude = 0.001
[analysis]
scheme = "load_control"
increment = 0.05
target_load_factor = 0.8
)";
    // The load factor scales a unit load: the target is P = 0.8 in units of … the column's P_E = π².
    scene.replace(scene.find("fy = -1.0"), 9, "fy = -9.869604401089358");
    const Model model = read_scene_text(scene, "imperfect.toml");
    REQUIRE(model.imperfections.size() == 1);
    CHECK(model.imperfections.front().load_factor == Approx(1.0).epsilon(1e-4)); // the mode's own factor
    // The mid node lies 0.001 off the axis: the mode's largest translation.
    const Node& mid = model.nodes[20];
    CHECK(std::abs(mid.x) == Approx(0.001).epsilon(1e-9));
    const Run p = run_scene(scene);
    REQUIRE(p.summary.status == RunStatus::completed);
    for (const StepResult& r : p.steps) {
        if (r.step == 0) continue;
        const double ratio = r.load_factor, e0 = mid.x;
        const double total = e0 + r.displacement[3 * 20];
        INFO("P/P_E = " << ratio << ": " << total / e0 << " against " << 1.0 / (1.0 - ratio));
        CHECK(std::abs(total / e0 * (1.0 - ratio) - 1.0) < 3e-3);
    }
}

namespace {

// The load factor against the joint's rotation θ along a path, at rotations 0.01 … 0.06 the
// rising way (clockwise, θ < 0), and the slope of λ = λ₀ + aθ + bθ² fitted through them, a/λ₀.
struct Branch {
    std::vector<double> theta, load;
    double slope = 0.0;
};

double relative_slope(const std::vector<double>& theta, const std::vector<double>& load) {
    Eigen::MatrixXd A(theta.size(), 3);
    Eigen::VectorXd b(theta.size());
    for (std::size_t k = 0; k < theta.size(); ++k) {
        const auto row = static_cast<Eigen::Index>(k);
        A.row(row) << 1.0, theta[k], theta[k] * theta[k];
        b[row] = load[k];
    }
    const Eigen::Vector3d c = A.colPivHouseholderQr().solve(b);
    return c[1] / c[0];
}

Branch branch_of(const Run& p, int joint) {
    Branch b;
    for (int k = 1; k <= 6; ++k) b.theta.push_back(-0.01 * k);
    const auto rotation = [joint](const StepResult& s) { return s.displacement[3 * joint + 2]; };
    for (double theta : b.theta) b.load.push_back(value_at(p.steps, theta, rotation, [](const StepResult& s) { return s.load_factor; }));
    b.slope = relative_slope(b.theta, b.load);
    return b;
}

std::string shipped_roorda(int elements) {
    std::string s = scene_file_text("models/gallery/roorda_frame.toml");
    for (std::size_t at = s.find("elements = 20"); at != std::string::npos; at = s.find("elements = 20", at + 1))
        s.replace(at, 13, "elements = " + std::to_string(elements));
    return s;
}

} // namespace

TEST_CASE("Roorda's perfect frame switched to its buckled branch follows the exact elastica and Koiter's slope", "[buckling]") {
    // The exact frame (tests/roorda_elastica.hpp) buckles at P_c = 13.8859 EI/L² (Roorda 1965)
    // into Koiter's asymmetric branch, P/P_c = 1 − aθ + O(θ²) (Koiter; Thompson & Hunt, A
    // General Theory of Elastic Stability, 1973, ch. 4): its slope at θ = 0 by central
    // differences is a = 0.3805.
    const double Pc = 0.5 * (RoordaElastica::load_at(1e-5) + RoordaElastica::load_at(-1e-5));
    CHECK(Pc == Approx(13.8859).epsilon(1e-5));
    const double koiter = (RoordaElastica::load_at(-0.005) - RoordaElastica::load_at(0.005)) / (0.01 * Pc);
    CHECK(koiter == Approx(0.3805).epsilon(1e-3));
    Branch exact;
    exact.theta = {-0.01, -0.02, -0.03, -0.04, -0.05, -0.06};
    for (double theta : exact.theta) exact.load.push_back(RoordaElastica::load_at(theta));
    exact.slope = relative_slope(exact.theta, exact.load);
    for (int elements : {20, 40}) {
        const Run p = run_scene(shipped_roorda(elements));
        REQUIRE(p.summary.critical_points.size() >= 1);
        const CriticalPoint& c = p.summary.critical_points.front();
        CHECK(c.kind == CriticalKind::bifurcation);
        CHECK(c.followed);
        CHECK(p.summary.status == RunStatus::completed);
        // The located bifurcation: the path's own tangent (the chord's geometric stiffness)
        // on 20 elements a member is 0.23 % above P_c, on 40 0.06 %.
        const double offset = c.load_factor / Pc - 1.0;
        CAPTURE(elements, c.load_factor);
        CHECK(std::abs(offset) < (elements == 20 ? 5e-3 : 1e-3));
        // Along the branch the path stands above the exact elastica by that same share, to
        // 2e-4 of the load (the rise over these rotations is 2.4 %), and rises the way it does:
        // the fitted slopes (0.379 exact over this range) agree within 1 %.
        const Branch path = branch_of(p, elements); // the column's top
        for (std::size_t k = 0; k < exact.theta.size(); ++k) {
            CAPTURE(exact.theta[k], path.load[k], exact.load[k]);
            CHECK(std::abs(path.load[k] / exact.load[k] - 1.0 - offset) < 2e-4);
        }
        CAPTURE(path.slope, exact.slope);
        CHECK(path.slope == Approx(exact.slope).epsilon(0.01));
    }
}

TEST_CASE("A shallow arch's limit point is landed on within 0.1 % under adaptive increments", "[buckling]") {
    // A pinned circular arch of 20° (R = 100, EI = 1e6, 20 elements) pressed at its crown: an
    // asymmetric bifurcation, then its symmetric limit point. The reference is the same arch by
    // fixed arc lengths 25 times shorter; the adaptive run's located limit, and the largest load
    // it samples before it, lie within 1e-3 of it (measured: 1e-6).
    const auto arch = [](const char* increment, const char* adaptive) {
        return std::string(R"(
[scene]
name = "arch"
[[material]]
name = "m"
E = 1.0e6
[[section]]
name = "s"
material = "m"
A = 100.0
I = 1.0
[[arc]]
center = [0.0, 0.0]
radius = 100.0
start_angle = 80.0
end_angle = 100.0
elements = 20
section = "s"
[[support]]
at = [17.364817766693, 98.480775301221]
fix = ["ux", "uy"]
[[support]]
at = [-17.364817766693, 98.480775301221]
fix = ["ux", "uy"]
[[load]]
at = [0.0, 100.0]
fy = -1.0
[analysis]
scheme = "arc_length"
control_at = [0.0, 100.0]
control_sign = -1.0
target_displacement = 1.0
max_steps = 2000
increment = )") + increment + "\nadaptive = " + adaptive + "\n";
    };
    const auto first_limit = [](const Run& p) -> const CriticalPoint* {
        for (const CriticalPoint& c : p.summary.critical_points)
            if (c.kind == CriticalKind::limit) return &c;
        return nullptr;
    };
    const Run fine = run_scene(arch("0.02", "false")), coarse = run_scene(arch("0.5", "true"));
    const CriticalPoint* reference = first_limit(fine);
    const CriticalPoint* found = first_limit(coarse);
    REQUIRE(reference);
    REQUIRE(found);
    double sampled = 0.0;
    for (const StepResult& r : coarse.steps)
        if (r.step < found->step) sampled = std::max(sampled, r.load_factor);
    INFO("limit " << found->load_factor << ", sampled " << sampled << ", reference " << reference->load_factor);
    CHECK(std::abs(found->load_factor / reference->load_factor - 1.0) < 1e-3);
    CHECK(std::abs(sampled / reference->load_factor - 1.0) < 1e-3);
    CHECK(coarse.steps.size() < fine.steps.size() / 5);
    // Before it, the asymmetric bifurcation: located, not followed.
    REQUIRE(!coarse.summary.critical_points.empty());
    CHECK(coarse.summary.critical_points.front().kind == CriticalKind::bifurcation);
}
