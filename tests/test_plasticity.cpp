// Refined plastic hinges against plastic theory (Neal, "The Plastic Methods of Structural
// Analysis", 1977; Liew, White & Chen, J. Struct. Eng. 119(11), 1993): collapse loads of
// beams and a portal frame, elastic unloading, and the inelastic ring (models/ring_inelastic.toml).
#include "analysis_helpers.hpp"
#include "scene_overrides.hpp"
#include "plastic_beam_scenes.hpp"
#include "analysis/hinge_allocation.hpp"
#include "element/plastic_hinge_law.hpp"
#include "section/fibre_section.hpp"

#include <catch2/catch.hpp>

using namespace plastica;
using namespace plastica::testing;

namespace {
constexpr double Mp = rectangle_Mp;
const std::string header = plastic_beam_header("hinges");
std::string control(double x, double y, const std::string& dof, double increment, double target) {
    return displacement_control(x, y, dof, increment, target);
}
} // namespace

TEST_CASE("A fixed-fixed beam under a central load collapses at 8 Mp / L", "[plasticity]") {
    const double L = 2000.0;
    const Run r = run_scene(header + fixed_fixed_beam("8") + control(1000.0, 0.0, "uy", 0.01, 0.1));
    REQUIRE(r.summary.status == RunStatus::completed);
    // The mechanism forms near δ = 0.04; at δ = 0.1 the load sits on the plateau. (Further on,
    // the restrained axial stretch raises N and lowers M_p(N): membrane action of the model.)
    CHECK(r.steps.back().load == Approx(8.0 * Mp / L).epsilon(0.01));
    CHECK(r.max_load() <= 8.0 * Mp / L * 1.01);
    CHECK(r.steps.back().plastic_hinge_count >= 3);
}

TEST_CASE("A propped cantilever under a central load collapses at 6 Mp / L", "[plasticity]") {
    const double L = 2000.0;
    const Run r = run_scene(header + propped_cantilever("8") + control(1000.0, 0.0, "uy", 0.01, 1.5));
    REQUIRE(r.summary.status == RunStatus::completed);
    CHECK(r.steps.back().load == Approx(6.0 * Mp / L).epsilon(0.01));
    CHECK(r.max_load() <= 6.0 * Mp / L * 1.01);
}

TEST_CASE("A fixed-base portal frame collapses by the combined mechanism", "[plasticity]") {
    // Mechanisms in portal_frame()'s comment: the combined one governs, λ = 0.75 Mp/1000.
    const Run r = run_scene(header + portal_frame() + control(0.0, 4000.0, "ux", 0.02, 1.3));
    // δ = 1.3 lies on the plateau where the fourth hinge is forming; past the complete
    // mechanism the tangent is singular and displacement control stalls.
    REQUIRE(r.summary.status == RunStatus::completed);
    const double combined = 0.75 * Mp / 1000.0;
    const double lambda = r.steps.back().load_factor;
    CHECK(lambda == Approx(combined).epsilon(0.015));
    CHECK(r.steps.back().plastic_hinge_count >= 2);
    CHECK(r.steps.back().hinge_count >= 4);
}

TEST_CASE("Load, yield, unload: the residual rotation is the plastic rotation, unloading is elastic", "[plasticity]") {
    SectionSpec s = rectangle_section(2e8, 10.0, 20.0, 10);
    s.steel = bilinear_steel(2e8, 250.0, 0.0);
    const double L0 = 1000.0, EI = s.E * s.inertia;
    PlasticHingeLaw law(s, L0);
    Eigen::Vector3d q;
    Eigen::Matrix3d k;
    // End i clamped in the basic frame, end j rotated: M_j reaches Mp, then a free hinge.
    const double theta_hinge = Mp * L0 / (4.0 * EI);
    // The L/6 pseudo-spring lets the last elastic fibre pair go slowly: the end reaches its
    // capacity after about five times the elastic hinge rotation for 10 fibres.
    const double theta_max = 20.0 * theta_hinge;
    const int n = 2000;
    for (int step = 1; step <= n; ++step) {
        law.trial(Eigen::Vector3d(0.0, 0.0, theta_max * step / n), q, k);
        law.commit();
    }
    CHECK(law.hinge(1).state == HingeState::plastic);
    const double plastic_at_peak = law.plastic_deformation()[2];
    // On the capacity curve, not beyond: only the regularising hardening, h·(4EI/L) per radian
    // of plastic rotation, may lift the moment above Mp.
    const double hardening = PlasticHingeLaw::regularising_hardening * 4.0 * EI / L0 * plastic_at_peak;
    CHECK(q[2] >= Mp * (1.0 - 1e-12));
    CHECK(q[2] <= Mp + 1.01 * hardening + 1e-12 * Mp);
    CHECK(plastic_at_peak > 1.5 * theta_hinge);
    // Unload until M_j = 0 in small steps; every step must use the elastic stiffness 4EI/L.
    double theta = theta_max;
    const double dtheta = -theta_hinge / 100.0;
    double previous = q[2];
    while (q[2] > 1e-9 * Mp) {
        theta += dtheta;
        law.trial(Eigen::Vector3d(0.0, 0.0, theta), q, k);
        CHECK((q[2] - previous) / dtheta == Approx(4.0 * EI / L0).epsilon(1e-9));
        previous = q[2];
        law.commit();
        if (q[2] < 0.0) break;
    }
    // Residual rotation once M_j = 0 (interpolating the last elastic step).
    const double residual = theta - q[2] / (4.0 * EI / L0);
    CHECK(residual == Approx(theta_max - (Mp + hardening) * L0 / (4.0 * EI)).epsilon(1e-6));
    // Elastic unloading leaves the plastic part of the deformation unchanged.
    CHECK(law.plastic_deformation()[2] == Approx(plastic_at_peak).epsilon(1e-9));
}

TEST_CASE("The inelastic ring reaches a top displacement of 100 with every step converged", "[plasticity][ring]") {
    const Run r = run_model(read_scene(std::string(PLASTICA_SOURCE_DIR) + "/models/ring_inelastic.toml"));
    REQUIRE(r.summary.status == RunStatus::completed);
    CHECK(r.summary.cut_steps == 0);
    CHECK(r.steps.back().control_displacement >= 100.0);
    // First yield, exactly: the first step with a yielded end is the first whose largest end
    // moment reaches the fibre section's first-yield moment at the end's axial force (the
    // outer fibre's centre at fy), and no end before it had.
    const FibreSection section(r.model.sections.front());
    const auto utilisation = [&](const StepResult& s) {
        double largest = 0.0;
        for (const ElementResult& e : s.elements)
            largest = std::max(largest, std::max(std::abs(e.forces.moment_i), std::abs(e.forces.moment_j)) /
                                            section.first_fibre_yield_moment(e.forces.axial));
        return largest;
    };
    auto first_hinge = std::find_if(r.steps.begin(), r.steps.end(), [](const StepResult& s) { return s.hinge_count > 0; });
    REQUIRE(first_hinge != r.steps.begin());
    REQUIRE(first_hinge != r.steps.end());
    CHECK(utilisation(*(first_hinge - 1)) < 1.0);
    CHECK(utilisation(*first_hinge) >= 1.0);
    // The pinched ring's first-order estimate P = π My / R (My = fy·I/(h/2)) lies below: the
    // outer fibre's centre sits at 0.9 h/2 and the ring has softened geometrically by then.
    const double My = 36518.0 * 1e-6 / (0.010954451150103323 / 2.0);
    CHECK(first_hinge->load > M_PI * My / 100.0);
    // The inelastic ring carries less than the elastic one at the same displacement.
    CHECK(r.steps.back().load < 0.47);
}

TEST_CASE("Adaptive increments bound the pseudo-springs' step error: the portal frame as fine fixed increments give it", "[plasticity][adaptive]") {
    // The pseudo-springs take η from the start of a step, so a step that carries an end far into
    // its yielding range overshoots its moment. With adaptive increments no step carries a hinge
    // section more than 0.05 of M_p into that range; the frame's curve (adaptive as shipped, from
    // a first increment of 0.002 and of 0.01) then stays within 0.35 % of its peak of the curve in
    // fixed increments ten times finer (measured 0.32 % and 0.32 %). The joints' hinges and
    // springs sit in the columns, whose ends yield at N/N_y ≈ 0.8 where η falls fastest with the
    // moment (analysis/hinge_allocation.hpp); while the beams' ends at N ≈ 0 served the joints
    // and the columns' tops could pass their capacity, this measured 0.19 % and 0.25 %.
    const std::string scene = std::string(PLASTICA_SOURCE_DIR) + "/models/gallery/portal_frame.toml";
    auto run = [&](const std::vector<Override>& overrides) { return run_model(read_scene(scene, overrides)); };
    const Run fine = run({{"analysis.adaptive", "false"}, {"analysis.increment", "0.0002"}, {"analysis.max_steps", "3000"}});
    REQUIRE(fine.summary.status == RunStatus::completed);
    const double peak = fine.max_load();
    for (const char* first : {"0.002", "0.01"}) {
        const Run adaptive = run({{"analysis.increment", first}});
        REQUIRE(adaptive.summary.status == RunStatus::completed);
        CHECK(adaptive.summary.refined_steps > 0);
        double worst = 0.0;
        for (std::size_t k = 1; k < adaptive.steps.size(); ++k) {
            const double d = adaptive.steps[k].control_displacement;
            const double reference = value_at(fine.steps, d, [](const StepResult& s) { return s.control_displacement; },
                                              [](const StepResult& s) { return s.load; });
            worst = std::max(worst, std::abs(adaptive.steps[k].load - reference) / peak);
        }
        CAPTURE(first);
        CHECK(worst < 3.5e-3);
    }
}

TEST_CASE("One hinge and one pseudo-spring serve a node where two equal sections meet, a stronger section keeps its spring", "[plasticity]") {
    // Two springs in series at one node, both going soft as the section nears its capacity,
    // leave the split of the node's rotation between them nearly free: the tangent nearly
    // singular, Newton cycling across their kinks. One spring of half the stiffness is the
    // same pair in series.
    const std::string stronger = "[[section]]\nname = \"t\"\nmaterial = \"steel\"\nshape = \"rectangle\"\nb = 10.0\n"
                                 "h = 30.0\nfibres = 10\nplasticity = \"hinges\"\n";
    const std::string clamps = std::string("[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n") +
                               "[[support]]\nat = [2000.0, 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n" +
                               "[[load]]\nat = [1000.0, 0.0]\nfy = -1.0\n" + control(1000.0, 0.0, "uy", 0.01, 0.1);
    SECTION("equal sections") {
        const Model m = read_scene_text(header + "[[line]]\nstart = [0.0, 0.0]\nend = [2000.0, 0.0]\nelements = 2\n"
                                                 "section = \"s\"\n" + clamps, "equal.toml");
        const std::vector<HingeEnds> served = allocate_hinge_capacity(m);
        REQUIRE(served.size() == 2u);
        CHECK(served[0].capacity == std::array<int, 2>{1, 2});
        CHECK(served[0].spring == std::array<int, 2>{1, 2});
        CHECK(served[1].capacity == std::array<int, 2>{0, 1});
        CHECK(served[1].spring == std::array<int, 2>{0, 1});
    }
    SECTION("a weaker and a stronger section") {
        const Model m = read_scene_text(header + stronger +
                                            "[[line]]\nstart = [0.0, 0.0]\nend = [1000.0, 0.0]\nelements = 1\nsection = \"t\"\n"
                                            "[[line]]\nstart = [1000.0, 0.0]\nend = [2000.0, 0.0]\nelements = 1\nsection = \"s\"\n" +
                                            clamps,
                                        "unequal.toml");
        const std::vector<HingeEnds> served = allocate_hinge_capacity(m);
        REQUIRE(served.size() == 2u);
        CHECK(served[0].capacity == std::array<int, 2>{1, 0}); // the stronger section's end
        CHECK(served[1].capacity == std::array<int, 2>{2, 1});
        CHECK(served[0].spring == std::array<int, 2>{1, 1});
        CHECK(served[1].spring == std::array<int, 2>{1, 1});
    }
}

TEST_CASE("The portal frame sways to its target on one to four elements per member, with one peak", "[plasticity]") {
    // With a pseudo-spring at each of two ends meeting mid-column, the frame in 2 or 3 elements
    // per member crept past its peak at millionths of its sway per step until the step limit.
    // The peak is the hinges' (P-Δ, residual stresses), not the mesh's: measured 1.0432, 1.0436,
    // 1.0446, 1.0455, 1.0474, 1.0474 and 1.0476 on 2, 1, 3, 4, 8, 16 and 20 elements per member,
    // so within 0.5 % of the 8-element one and rising towards it as the mesh is refined: the
    // pseudo-spring's stiffness 6EI/L·η/(1 − η) is an element's, and the columns' ends, which
    // carry the joints' hinges at N/N_y ≈ 0.8, soften over a range of moment that a long
    // element spreads further.
    const std::string scene = std::string(PLASTICA_SOURCE_DIR) + "/models/gallery/portal_frame.toml";
    auto run = [&](int elements) {
        const std::string n = std::to_string(elements);
        return run_model(read_scene(scene, {{"line[left column].elements", n}, {"line[beam].elements", n}, {"line[right column].elements", n}}));
    };
    const double peak = run(8).max_load();
    for (int elements : {1, 2, 3, 4}) {
        const Run r = run(elements);
        CAPTURE(elements);
        REQUIRE(r.summary.status == RunStatus::completed);
        CHECK(r.steps.size() < 150u); // 57 to 74 steps
        CHECK(r.max_load() == Approx(peak).epsilon(5e-3));
        CHECK(r.steps.back().load < 0.7 * peak); // far past the peak
    }
}
