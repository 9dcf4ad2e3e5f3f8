// Published frames: Vogel's six-storey calibration frame against its plastic-zone load factor,
// and portals pushed sideways under held gravity against the rigid-plastic mechanism line of
// second-order plastic theory (Horne, "Elastic-plastic failure loads of plane frames", Proc. R.
// Soc. A 274, 1963; Horne & Merchant, "The Stability of Frames", 1965): once the mechanism has
// formed, H·h + ΣP·Δ = Σ M_p(N) over its hinges.
#include "analysis_helpers.hpp"
#include "section/fibre_section.hpp"

#include <catch2/catch.hpp>

using namespace plastica;
using namespace plastica::testing;

namespace {

std::string with(std::string text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) text.replace(at, from.size(), to);
    return text;
}

double peak_of(const std::string& scene) {
    const Run run = run_scene(scene);
    REQUIRE(run.summary.status == RunStatus::completed);
    return run.max_load();
}

} // namespace

TEST_CASE("Vogel's six-storey frame reaches its published plastic-zone load factor 1.11", "[frames][published][distributed]") {
    // The scene leaves the formulation open, so its fibre members are force-based: the moments
    // along a member are exact, and what the mesh still resolves is the members' own P–δ, which
    // the co-rotational frame takes at the nodes. Measured: 1.1271, 1.1220, 1.1193 and 1.1189 on
    // 4/6, 8/12, 16/24 and 32/48 elements per column/beam (displacement-based members, first
    // order and high: 1.188, 1.161, 1.148, 1.140). The published value lies between the two
    // section idealisations: with fillets (as here) the frame converges 0.8 % above 1.11, without
    // them (root_radius 0, 3.5–4 % less W_pl) below it; 2.5 % is that band.
    const std::string vogel = scene_file_text("tests/frames/vogel_six_storey.toml");
    auto meshed = [&](int columns, int beams) {
        return with(with(vogel, "elements = 4\n", "elements = " + std::to_string(columns) + "\n"), "elements = 6\n",
                    "elements = " + std::to_string(beams) + "\n");
    };
    const double coarse = peak_of(vogel), middle = peak_of(meshed(8, 12)), fine = peak_of(meshed(16, 24));
    CHECK(coarse > middle);
    CHECK(middle > fine);
    // The default converges on frames: 8 elements per member within 1 % of the finest mesh,
    // whose own gap to the next (32/48) is 0.04 %.
    CHECK(std::abs(middle - fine) < 0.01 * fine);
    CHECK(fine == Approx(1.11).epsilon(0.025));
    // Refined plastic hinges on the coarse mesh: 1.128 (later refined-hinge studies: 1.11–1.13),
    // within 1 % of the converged plastic zone.
    const double hinges = peak_of(with(vogel, "plasticity = \"distributed\"", "plasticity = \"hinges\""));
    CHECK(hinges == Approx(1.11).epsilon(0.025));
    CHECK(std::abs(hinges - fine) < 0.01 * fine);
    // Displacement-based members on the coarse mesh stay first-order high, as documented.
    const double displacement = peak_of(with(vogel, "plasticity = \"distributed\"", "plasticity = \"distributed\"\nformulation = \"displacement\""));
    CHECK(displacement > 1.05 * fine);
}

namespace {

// A fixed-base portal, HEB 200 columns 4 m, beam 6 m, S355: gravity P on each column top held,
// then H pushed by the sway of the left column top to Δ = 0.2 (θ = 1/20).
std::string pushed_portal(const std::string& beam_section, const std::string& beam_extra, double P) {
    return R"([scene]
name = "portal"
[[material]]
name = "S355"
E = 2.1e8
fy = 3.55e5
[[section]]
name = "HEB200"
material = "S355"
shape = "i"
depth = 0.2
flange_width = 0.2
flange_thickness = 0.015
web_thickness = 0.009
[[section]]
name = "IPE400"
material = "S355"
shape = "i"
depth = 0.4
flange_width = 0.18
flange_thickness = 0.0135
web_thickness = 0.0086
[[line]]
name = "left column"
start = [0.0, 0.0]
end = [0.0, 4.0]
elements = 8
section = "HEB200"
[[line]]
name = "beam"
start = [0.0, 4.0]
end = [6.0, 4.0]
elements = 8
section = ")" + beam_section + "\"\n" + beam_extra + R"(
[[line]]
name = "right column"
start = [6.0, 4.0]
end = [6.0, 0.0]
elements = 8
section = "HEB200"
[[support]]
at = [0.0, 0.0]
fix = ["ux", "uy", "rz"]
[[support]]
at = [6.0, 0.0]
fix = ["ux", "uy", "rz"]
[[load]]
at = [0.0, 4.0]
fy = )" + std::to_string(-P) + R"(
pattern = "gravity"
[[load]]
at = [6.0, 4.0]
fy = )" + std::to_string(-P) + R"(
pattern = "gravity"
[[load]]
at = [0.0, 4.0]
fx = 1.0
pattern = "lateral"
[analysis]
pattern = "gravity"
scheme = "load_control"
increment = 0.25
target_load_factor = 1.0
[[stage]]
pattern = "lateral"
scheme = "displacement_control"
increment = 0.002
target_displacement = 0.2
control_at = [0.0, 4.0]
control_dof = "ux"
)";
}

double horizontal_reaction(const StepResult& s) {
    double h = 0.0;
    for (std::size_t k = 0; k < s.reaction.size(); k += 3) h += s.reaction[k];
    return -h;
}

} // namespace

TEST_CASE("A portal whose beam is pinned to its columns follows the cantilevers' mechanism line under held gravity", "[frames][published][releases][patterns]") {
    // Released beam ends leave two cantilevers carrying P each (the beam only links their
    // sways): the mechanism is a hinge at each base, and 2·M_p(P) = H·h + 2·P·Δ exactly, the
    // columns' axial force being P whatever H. Before yield each cantilever's sway is
    // Δ = H/2/(P·k)·(tan kh − kh), k = √(P/EI) (Timoshenko & Gere, "Theory of Elastic
    // Stability", 1961, §1.11).
    const double P = 500.0, h = 4.0;
    const Run run = run_scene(pushed_portal("IPE400", "releases = [\"start\", \"end\"]", P));
    REQUIRE(run.summary.reason == "target displacement reached (2 stages)");
    const FibreSection column(run.model.sections[0]);
    const double mp = column.moment_capacity(-P, 1.0);
    const double k = std::sqrt(P / (2.1e8 * run.model.sections[0].inertia));
    int on_line = 0, elastic = 0;
    for (const StepResult& s : run.steps) {
        if (s.stage != 2) continue;
        const double H = horizontal_reaction(s), sway = s.control_displacement;
        CAPTURE(s.step, sway, H);
        // Elastic while the base moment stays below 0.7 M_p (first yield of an HEB 200 near 0.85 M_p).
        if ((H * h + 2.0 * P * sway) / 2.0 < 0.7 * mp && sway > 0.0) {
            ++elastic;
            CHECK(sway == Approx(H / 2.0 / (P * k) * (std::tan(k * h) - k * h)).epsilon(2e-3));
        }
        if (sway >= 0.12) {
            ++on_line;
            // From θ = 0.03 on, once the refined hinges have plastified to their capacity (at
            // θ = 0.025 the line is still 1 % away): within 0.5 %, the chord rotation
            // (cos θ ≥ 0.9987 at θ ≤ 1/20) and the hinges' smooth capacity against the fibre
            // polygon (≤ 1e-3).
            CHECK(H * h + 2.0 * P * sway == Approx(2.0 * mp).epsilon(5e-3));
        }
    }
    CHECK(elastic > 3);
    CHECK(on_line > 10);
}

TEST_CASE("A rigid portal with a strong beam follows the sway mechanism line under held gravity", "[frames][published][patterns]") {
    // Hinges at both ends of both columns (the IPE 400 is stronger than an HEB 200 at any N):
    // Σ M_p(N_i) over the four = H·h + 2·P·Δ, each column at its own axial force, which the
    // frame's overturning moves by ±(H·h + 2PΔ − Σ base moments)/L from P.
    const double P = 500.0, h = 4.0;
    const Run run = run_scene(pushed_portal("IPE400", "", P));
    REQUIRE(run.summary.reason == "target displacement reached (2 stages)");
    const FibreSection column(run.model.sections[0]);
    int on_line = 0;
    double peak = 0.0;
    for (const StepResult& s : run.steps) {
        if (s.stage != 2) continue;
        const double H = horizontal_reaction(s), sway = s.control_displacement;
        peak = std::max(peak, H);
        if (sway < 0.12) continue; // the hinges plastified (as in the released portal above)
        ++on_line;
        // The columns' axial forces at their bases (elements 0 and 23): N_left in less compression.
        const double n_left = s.elements.front().forces.axial, n_right = s.elements.back().forces.axial;
        CAPTURE(s.step, sway, H, n_left, n_right);
        CHECK(n_left > -P);
        CHECK(n_right < -P);
        const double capacity = 2.0 * column.moment_capacity(n_left, 1.0) + 2.0 * column.moment_capacity(n_right, 1.0);
        CHECK(H * h + 2.0 * P * sway == Approx(capacity).epsilon(5e-3));
    }
    CHECK(on_line > 10);
    // The peak lies below the first-order plastic collapse 4·M_p(P)/h.
    CHECK(peak < 4.0 * column.moment_capacity(-P, 1.0) / h);
}
