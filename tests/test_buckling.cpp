// Linear buckling against closed forms: Euler's four columns, a portal frame's sway by the
// stability functions, Roorda's L-frame, and a ring under hydrostatic pressure.
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

namespace {

constexpr double pi = 3.14159265358979323846;

// A column of length 1 along y, EI = 1, in `elements` elements, pressed by 1 at its top.
std::string column(const std::string& base_fix, const std::string& top_fix, int elements) {
    std::string top = top_fix.empty() ? "" : "[[support]]\nat = [0.0, 1.0]\nfix = [" + top_fix + "]\n";
    return R"(
[scene]
name = "column"
[[material]]
name = "m"
E = 1.0e3
[[section]]
name = "s"
material = "m"
A = 10.0
I = 1.0e-3
[[line]]
start = [0.0, 0.0]
end = [0.0, 1.0]
elements = )" + std::to_string(elements) + R"(
section = "s"
[[support]]
at = [0.0, 0.0]
fix = [)" + base_fix + "]\n" + top + R"(
[[load]]
at = [0.0, 1.0]
fy = -1.0
[analysis]
scheme = "load_control"
increment = 0.1
target_load_factor = 1.0
)";
}

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

namespace {

std::string number(double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

struct Path {
    std::vector<StepResult> steps;
    RunSummary summary;
};

Path follow(const std::string& scene) {
    PathFollowing analysis(read_scene_text(scene, "buckling.toml"));
    Path out;
    out.summary = analysis.run({[&](const StepResult& r) { out.steps.push_back(r); }});
    return out;
}

// The perfect pinned column of column() on 20 elements, nearly inextensible (EA/EI = 1e7),
// followed by arc length with the given bifurcation rule until its top has come down by `travel`.
std::string perfect_column(const char* rule, double travel) {
    std::string s = column("\"ux\", \"uy\"", "\"ux\"", 20);
    const std::string analysis = s.substr(s.find("[analysis]"));
    s = s.substr(0, s.find("[analysis]"));
    s.replace(s.find("A = 10.0"), 8, "A = 1.0e4");
    return s + "[analysis]\nscheme = \"arc_length\"\nincrement = 0.05\nbifurcation = \"" + rule +
           "\"\ncontrol_at = [0.0, 1.0]\ncontrol_dof = \"uy\"\ntarget_displacement = " + number(travel) +
           "\nmax_steps = 500\n";
}

} // namespace

TEST_CASE("A perfect column reports its bifurcation and ends unstable without switching", "[buckling]") {
    // A travel of 2e-6 is a load factor of 20: past the first mode (9.87), short of the second (39.5).
    const Path p = follow(perfect_column("report", 2e-6));
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
    const Path p = follow(perfect_column("switch", 1.0));
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
    const Path p = follow(scene);
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

// The slope dλ/dθ of a path's load factor against the joint rotation θ (node `joint`) past its
// bifurcation λ_c: λ − λ_c = a θ + b θ² by least squares over 0.003 ≤ |θ| ≤ 0.03.
double branch_slope(const Path& p, int joint, double lambda_c) {
    double s11 = 0, s12 = 0, s22 = 0, r1 = 0, r2 = 0;
    int used = 0;
    for (const StepResult& r : p.steps) {
        const double theta = r.displacement[3 * joint + 2];
        if (std::abs(theta) < 0.003 || std::abs(theta) > 0.03) continue;
        const double y = r.load_factor - lambda_c;
        s11 += theta * theta, s12 += theta * theta * theta, s22 += theta * theta * theta * theta;
        r1 += y * theta, r2 += y * theta * theta;
        ++used;
    }
    REQUIRE(used >= 5);
    return (r1 * s22 - r2 * s12) / (s11 * s22 - s12 * s12);
}

std::string shipped_roorda(int elements) {
    std::ifstream in(std::string(PLASTICA_SOURCE_DIR) + "/models/gallery/roorda_frame.toml");
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    for (std::size_t at = s.find("elements = 20"); at != std::string::npos; at = s.find("elements = 20", at + 1))
        s.replace(at, 13, "elements = " + std::to_string(elements));
    return s;
}

} // namespace

TEST_CASE("Roorda's perfect frame switched to its buckled branch rises along Koiter's straight asymmetric branch", "[buckling]") {
    // An asymmetric bifurcation's branch leaves it along a straight line, λ − λ_c ∝ θ (Koiter;
    // Thompson & Hunt, A General Theory of Elastic Stability, 1973, ch. 4): the fitted quadratic
    // term bends it by less than a tenth over |θ| ≤ 0.03. The switch takes the rising side. Its
    // slope converges with the mesh: 20 and 40 elements a member agree within 1 %; per unit P_c
    // it is 0.386 a radian.
    const Path p20 = follow(shipped_roorda(20));
    const Path p40 = follow(shipped_roorda(40));
    for (const Path* p : {&p20, &p40}) {
        REQUIRE(p->summary.critical_points.size() >= 1);
        CHECK(p->summary.critical_points.front().kind == CriticalKind::bifurcation);
        CHECK(p->summary.critical_points.front().followed);
        CHECK(p->summary.status == RunStatus::completed);
    }
    // The located bifurcation: the path's own tangent on 20 elements a member, 0.23 % above
    // 13.8859 (the chord's geometric stiffness; 0.06 % on 40).
    const double c20 = p20.summary.critical_points.front().load_factor, c40 = p40.summary.critical_points.front().load_factor;
    CHECK(std::abs(c20 / 13.8859 - 1.0) < 5e-3);
    CHECK(std::abs(c40 / 13.8859 - 1.0) < std::abs(c20 / 13.8859 - 1.0));
    const int joint20 = 20, joint40 = 40; // the column's top
    const double s20 = branch_slope(p20, joint20, c20), s40 = branch_slope(p40, joint40, c40);
    INFO("dλ/dθ: " << s20 << " (20 elements), " << s40 << " (40)");
    // Rising: the load grows as the joint turns the way the branch went.
    for (const StepResult& r : p20.steps)
        if (std::abs(r.displacement[3 * joint20 + 2]) > 0.01) CHECK(r.load_factor > c20);
    CHECK(std::abs(s20 / s40 - 1.0) < 0.01);
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
    const auto first_limit = [](const Path& p) -> const CriticalPoint* {
        for (const CriticalPoint& c : p.summary.critical_points)
            if (c.kind == CriticalKind::limit) return &c;
        return nullptr;
    };
    const Path fine = follow(arch("0.02", "false")), coarse = follow(arch("0.5", "true"));
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
