// Moment releases at member ends (engine/element/released_ends_law.hpp): a beam between two
// clamps released at both ends is simply supported (deflection and collapse load exact), and two
// bars pinned at their apex are the von Mises truss, whose snap-through has a closed form.
#include "analysis_helpers.hpp"

#include <catch2/catch.hpp>

using namespace plastica;
using namespace plastica::testing;

namespace {

// A beam 6 long between a clamp at x = 0 and a clamp at x = 6 that slides along the beam (so no
// chord tension builds up), released at both ends, under a uniform wy. The section is elastic
// (EI = 2e4) or a 0.1 × 0.2 rectangle of fy = 2.5e5 (M_p = 250) with the plasticity given.
std::string released_beam(int elements, const std::string& section, const std::string& analysis) {
    return "[scene]\nname = \"released_beam\"\n[[material]]\nname = \"m\"\nE = 2.0e8\n" + section +
           "[[line]]\nstart = [0.0, 0.0]\nend = [6.0, 0.0]\nelements = " + std::to_string(elements) +
           "\nsection = \"s\"\nreleases = [\"start\", \"end\"]\n"
           "[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n"
           "[[support]]\nat = [6.0, 0.0]\nfix = [\"uy\", \"rz\"]\n"
           "[[distributed_load]]\non = \"line1\"\nwy = -10.0\n"
           "[analysis]\ncontrol_at = [3.0, 0.0]\n" + analysis;
}

const std::string elastic_section = "[[section]]\nname = \"s\"\nmaterial = \"m\"\nA = 0.01\nI = 1.0e-4\n";

std::string plastic_section(const std::string& plasticity) {
    return "[[material]]\nname = \"steel\"\nE = 2.0e8\nfy = 2.5e5\n"
           "[[section]]\nname = \"s\"\nmaterial = \"steel\"\nshape = \"rectangle\"\nb = 0.1\nh = 0.2\nplasticity = \"" +
           plasticity + "\"\n";
}

// Midspan deflection of a simply supported beam under point loads (P, a): for each, the
// elastic line P·b·x·(L² − b² − x²)/(6·L·EI) at x ≤ a, mirrored otherwise.
double midspan_deflection(const std::vector<std::pair<double, double>>& loads, double L, double EI) {
    double v = 0.0;
    for (auto [P, a] : loads) {
        if (a < L / 2) a = L - a;
        const double b = L - a, x = L / 2;
        v += P * b * x * (L * L - b * b - x * x) / (6 * L * EI);
    }
    return v;
}

} // namespace

TEST_CASE("A beam between two clamps released at both ends deflects as a simply supported one", "[releases]") {
    const double L = 6.0, EI = 2.0e4, w = 10.0;
    for (int n : {2, 8, 32}) {
        CAPTURE(n);
        const Run run = run_scene(released_beam(n, elastic_section, "scheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 1.0\n"));
        REQUIRE(run.summary.status == RunStatus::completed);
        const StepResult& last = run.steps.back();
        // The line load goes half to each end of every element: w·h at the inner nodes. Cubic
        // elements are exact for nodal loads, so the deflection is the closed form's for them
        // (δ/L = 1.4e-3: the second-order terms are of that order squared).
        std::vector<std::pair<double, double>> lumped;
        const double h = L / n;
        for (int k = 1; k < n; ++k) lumped.push_back({w * h, k * h});
        const double deflection = last.control_displacement; // downward, as the load
        CHECK(deflection == Approx(midspan_deflection(lumped, L, EI)).epsilon(1e-5));
        // …which tends to 5wL⁴/384EI as the lumping's share vanishes: 0.80/n² (n = 2, 8, 32).
        const double exact = 5 * w * L * L * L * L / (384 * EI);
        CHECK(std::abs(deflection / exact - 1.0) < 0.85 / (n * n));
        // The clamps carry no moment: the released ends pass none to them.
        CHECK(std::abs(last.reaction[2]) < 1e-9 * w * L * L);
        CHECK(std::abs(last.reaction[3 * n + 2]) < 1e-9 * w * L * L);
        CHECK(last.reaction[1] == Approx(w * L / 2).epsilon(1e-6)); // to the residual tolerance
    }
}

TEST_CASE("A beam released at both ends collapses at 8·M_p/L², with hinges and with fibre sections", "[releases][plasticity]") {
    const std::string plasticity = GENERATE("hinges", "distributed");
    CAPTURE(plasticity);
    const double L = 6.0, Mp = 2.5e5 * 0.1 * 0.2 * 0.2 / 4;
    const Run run = run_scene(released_beam(8, plastic_section(plasticity),
                                            "scheme = \"displacement_control\"\nincrement = 0.005\ntarget_displacement = 0.125\n"));
    REQUIRE(run.summary.status == RunStatus::completed);
    // The reported load is w·L (the total of the lumped loads, the supports' shares included);
    // lumped loads give the exact midspan moment wL²/8. At δ = L/48 the mechanism's plateau is
    // reached (the plastic zone is still spreading through the rectangle's depth: 1 % allowed,
    // as for the other collapse loads in tests/test_plasticity.cpp).
    const double collapse = 8 * Mp / (L * L) * L;
    CHECK(run.steps.back().load == Approx(collapse).epsilon(0.01));
    CHECK(run.max_load() <= collapse * 1.01);
}

TEST_CASE("Two bars pinned at their apex snap through as the von Mises truss", "[releases]") {
    // Bars from (∓1, 0) to (0, 0.1), pinned at their feet, released at the apex; EA = 1e4. With
    // the engineering strain of the co-rotational element the apex load at a descent w is
    // P(w) = 2·EA·(L0 − L)/L0 · (h − w)/L, L = √(a² + (h − w)²) (the truss analogue of Williams'
    // toggle; Crisfield, "Non-linear Finite Element Analysis of Solids and Structures" 1, 1991,
    // §1.2). EI = 1e3 keeps each bar's Euler load 300 times its largest force.
    const double a = 1.0, h = 0.1, EA = 1.0e4, L0 = std::hypot(a, h);
    const auto closed_form = [&](double w) {
        const double L = std::hypot(a, h - w);
        return 2 * EA * (L0 - L) / L0 * (h - w) / L;
    };
    const int elements = GENERATE(1, 4);
    CAPTURE(elements);
    const std::string scene =
        "[scene]\nname = \"von_mises_truss\"\n[[material]]\nname = \"m\"\nE = 1.0e6\n"
        "[[section]]\nname = \"s\"\nmaterial = \"m\"\nA = 0.01\nI = 1.0e-3\n"
        "[[line]]\nstart = [-1.0, 0.0]\nend = [0.0, 0.1]\nelements = " + std::to_string(elements) + "\nsection = \"s\"\nreleases = [\"end\"]\n"
        "[[line]]\nstart = [1.0, 0.0]\nend = [0.0, 0.1]\nelements = " + std::to_string(elements) + "\nsection = \"s\"\nreleases = [\"end\"]\n"
        "[[support]]\nat = [-1.0, 0.0]\nfix = [\"ux\", \"uy\"]\n"
        "[[support]]\nat = [1.0, 0.0]\nfix = [\"ux\", \"uy\"]\n"
        "[[load]]\nat = [0.0, 0.1]\nfy = -1.0\n"
        "[analysis]\nscheme = \"displacement_control\"\nincrement = 0.002\nadaptive = false\ncontrol_at = [0.0, 0.1]\n"
        "target_displacement = 0.18\nmax_steps = 200\n";
    const Run run = run_scene(scene);
    REQUIRE(run.summary.status == RunStatus::completed);
    // The shallow limit (2/(3√3))·EA·(h/L0)³ is within 2 % of the exact peak; the peak itself
    // from the closed form, at w = h(1 − 1/√3) nearly.
    double peak = 0.0;
    for (int k = 1; k <= 2000; ++k) peak = std::max(peak, closed_form(0.18 * k / 2000.0));
    for (const StepResult& s : run.steps) {
        CAPTURE(s.step, s.control_displacement);
        // Every converged step lies on the closed form (the residual is 1e-6 of the load).
        CHECK(s.load == Approx(closed_form(s.control_displacement)).margin(1e-5 * peak));
        CHECK(s.load <= peak * (1 + 1e-5));
    }
    CHECK(run.max_load() == Approx(peak).epsilon(2e-3)); // steps of 0.002 sample the flat peak
    // Through the snap: below its feet the apex is pulled back up by the bars, still compressed.
    CHECK(run.steps.back().load < 0.0);
}

TEST_CASE("A frame standing by a pinned brace carries N_y·cos θ less the P–Δ shear once the brace yields", "[releases][patterns][plasticity]") {
    // models/gallery/braced_frame.toml: pinned column bases, a beam pinned to the columns, a
    // brace pinned at both ends: the columns lean on the brace. Gravity ΣP = 720 kN held, then
    // the sway δ pushed. Once the brace yields (N_y = 0.05² × 355e3 = 887.5 kN), the tops are
    // in equilibrium with the brace at N_y along its deformed chord (6 + δ, 4), and the columns
    // carry ΣP plus the brace's pull N_y·sin θ: their P–Δ shear is that times δ/h.
    const Run run = run_scene_file("models/gallery/braced_frame.toml");
    REQUIRE(run.summary.status == RunStatus::completed);
    const double Ny = 0.05 * 0.05 * 3.55e5, P = 720.0, h = 4.0;
    int yielded = 0;
    for (const StepResult& s : run.steps) {
        if (s.stage == 1) continue; // gravity: the brace, shortened with the right column, sways it by 0.8 mm
        const double d = s.control_displacement;
        if (d < 0.03) continue; // the brace yields at δ ≈ 0.0147 + the beam's and columns' share
        ++yielded;
        const double chord = std::hypot(6.0 + d, 4.0);
        const double expected = Ny * (6.0 + d) / chord - (P + Ny * 4.0 / chord) * d / h;
        CAPTURE(s.step, d, s.load, expected);
        // The columns' shortening and the tops' small vertical motion are left out: 0.13 % at
        // δ = 0.1 (the largest).
        CHECK(s.load == Approx(expected).epsilon(2.5e-3));
    }
    CHECK(yielded >= 3);
}

TEST_CASE("Release mistakes are located errors", "[releases][scene]") {
    const auto error_of = [](const std::string& text) { return scene_error_of(text, "r.toml"); };
    const std::string beam = released_beam(4, elastic_section, "scheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 1.0\n");
    std::string wrong = beam;
    wrong.replace(wrong.find("[\"start\", \"end\"]"), 16, "[\"middle\"]");
    CHECK_THAT(error_of(wrong), Catch::Contains("r.toml:16: 'line[1].releases': expected a list of \"start\" and \"end\""));
    // A moment where every member end is released: nothing carries it.
    const std::string pinned_apex =
        "[scene]\nname = \"apex\"\n[[material]]\nname = \"m\"\nE = 1.0\n[[section]]\nname = \"s\"\nmaterial = \"m\"\nA = 1.0\nI = 1.0\n"
        "[[line]]\nstart = [-1.0, 0.0]\nend = [0.0, 1.0]\nsection = \"s\"\nelements = 1\nreleases = [\"end\"]\n"
        "[[line]]\nstart = [1.0, 0.0]\nend = [0.0, 1.0]\nsection = \"s\"\nelements = 1\nreleases = [\"end\"]\n"
        "[[support]]\nat = [-1.0, 0.0]\nfix = [\"ux\", \"uy\"]\n[[support]]\nat = [1.0, 0.0]\nfix = [\"ux\", \"uy\"]\n"
        "[[load]]\nat = [0.0, 1.0]\nmoment = 1.0\n"
        "[analysis]\nscheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 1.0\n";
    CHECK_THAT(error_of(pinned_apex), Catch::Contains("'load[1].moment': every member end at [0, 1] is released"));
}

TEST_CASE("A frame that its releases leave free is named a mechanism of its releases, not round-off", "[releases][mechanisms]") {
    // The braced frame without its brace: pinned bases, a beam pinned to both columns, a sway
    // mechanism. Holding the released ends makes it a stable portal.
    std::string text = scene_file_text("models/gallery/braced_frame.toml");
    const std::size_t brace = text.find("[[line]]\nname = \"brace\"");
    text.erase(brace, text.find("[[support]]") - brace);
    const Model model = read_scene_text(text, "unbraced.toml");
    PathFollowing analysis(model);
    const std::string why = analysis.initial_mechanism();
    CHECK_THAT(why, Catch::Contains("the structure is a mechanism before loading"));
    CHECK_THAT(why, Catch::Contains("because of the moment releases (released member ends at [0, 4], [6, 4])"));
    // With the brace it stands.
    PathFollowing braced(read_scene_text(scene_file_text("models/gallery/braced_frame.toml"), "braced.toml"));
    CHECK(braced.initial_mechanism().empty());
}
