// A stuck step taken with fibre members stiffened (element/step_stiffening.hpp): the spring acts
// on the step's increment alone, exactly ratio × the elastic stiffness, and the force it gathered
// is kept once the step is committed, for the three fibre members alike; and the crushed ring
// whose fully plastic crown floats off the plate, which stopped without it.
#include "analysis_helpers.hpp"
#include "tangent_check.hpp"
#include "element/distributed_plasticity_law.hpp"
#include "element/force_based_plasticity_law.hpp"
#include "element/segmented_plasticity_law.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

using namespace plastica;
using namespace plastica::testing;

namespace {

std::unique_ptr<BasicLaw> fibre_law(const std::string& kind, double L0) {
    if (kind == "force") return std::make_unique<ForceBasedPlasticityLaw>(hardening_rectangle(Formulation::force), L0, 5);
    const SectionSpec s = hardening_rectangle(Formulation::displacement);
    if (kind == "segmented") return std::make_unique<SegmentedPlasticityLaw<2>>(s, L0, 4, 2, 1.0);
    return std::make_unique<DistributedPlasticityLaw>(s, L0, 3);
}

} // namespace

TEST_CASE("A stiffened step adds ratio times the elastic stiffness on its increment and keeps the force it gathered", "[plasticity][distributed]") {
    const std::string kind = GENERATE(as<std::string>(), "displacement", "force", "segmented");
    INFO(kind);
    const double L0 = 1000.0, kappa_y = 2.0 * 1.25e-3 / 20.0, ratio = 1e-4;
    const SectionSpec s = hardening_rectangle(Formulation::displacement);
    const Eigen::Matrix3d elastic = elastic_basic_stiffness(s.E * s.area, s.E * s.inertia, L0);
    // Two copies loaded alike into the plastic range (end j at three times its yield curvature).
    std::unique_ptr<BasicLaw> own = fibre_law(kind, L0), stiffened = fibre_law(kind, L0);
    const Eigen::Vector3d loaded(-2e-4 * L0, 0.0, 3.0 * kappa_y * L0);
    Eigen::Vector3d q_own, q_stiff;
    Eigen::Matrix3d k_own, k_stiff;
    for (int step = 1; step <= 10; ++step) {
        for (BasicLaw* law : {own.get(), stiffened.get()}) {
            law->trial(loaded * (step / 10.0), q_own, k_own);
            REQUIRE(law->states_consistent());
            law->commit();
        }
    }
    // The stiffened step: the same fibres, plus the spring on the increment.
    const Eigen::Vector3d step(1e-6 * L0, 0.1 * kappa_y * L0, 0.2 * kappa_y * L0);
    stiffened->stiffen_capacity(ratio);
    own->trial(loaded + step, q_own, k_own);
    stiffened->trial(loaded + step, q_stiff, k_stiff);
    const Eigen::Vector3d spring = ratio * elastic * step;
    CAPTURE(q_own.transpose(), q_stiff.transpose(), spring.transpose());
    CHECK((q_stiff - q_own - spring).norm() <= 1e-9 * q_own.norm());
    CHECK((k_stiff - k_own - ratio * elastic).norm() <= 1e-9 * k_own.norm());
    // A reverted step leaves nothing behind.
    stiffened->revert();
    stiffened->trial(loaded, q_stiff, k_stiff);
    own->revert();
    own->trial(loaded, q_own, k_own);
    CHECK((q_stiff - q_own).norm() <= 1e-9 * q_own.norm());
    // Taken and committed, then ended: the spring's force stays and adds no stiffness.
    for (BasicLaw* law : {own.get(), stiffened.get()}) {
        law->trial(loaded + step, q_own, k_own);
        law->commit();
    }
    stiffened->stiffen_capacity(0.0);
    const Eigen::Vector3d next = loaded + 2.0 * step;
    own->trial(next, q_own, k_own);
    stiffened->trial(next, q_stiff, k_stiff);
    CHECK((q_stiff - q_own - spring).norm() <= 1e-9 * q_own.norm());
    CHECK((k_stiff - k_own).norm() <= 1e-9 * k_own.norm());
}

TEST_CASE("A perfectly plastic ring on 64 elements whose crown floats off the plate is crushed to the end", "[contact][member][crushing]") {
    // models/gallery/steel_ring_crushed.toml with the paper's law, R/h = 10, 64 elements and
    // plates ten times as stiff (3482 MPa): the crown's element becomes wholly plastic and leaves
    // the plate (a gap of 0.05) at a travel of 16.2, where every scheme stopped, each increment
    // down to 5e-7 running off along it. One stiffened step takes it on. DeRuntz & Hodge within
    // 5 % from δ = 0.2 D as on 50 elements.
    const std::string scheme = GENERATE(as<std::string>(), "load_control", "displacement_control", "arc_length");
    INFO(scheme);
    std::vector<std::pair<std::string, std::string>> edits = {{"h = 5.0\n", "h = 10.0\n"},
                                                              {"elements = 50\n", "elements = 64\n"},
                                                              {"ky = \"350 MPa\"", "ky = \"3482 MPa\""},
                                                              {"ky = \"350 MPa\"", "ky = \"3482 MPa\""},
                                                              {"law = \"kinematic_hardening\"\nhardening_ratio = 1e-4\n", "law = \"bilinear\"\n"},
                                                              {"scheme = \"load_control\"", "scheme = \"" + scheme + "\""}};
    if (scheme == "displacement_control") edits.push_back({"target_load_factor = 130.0", "target_displacement = 130.0"});
    const Run r = run_scene(edited_scene("models/gallery/steel_ring_crushed.toml", edits));
    INFO(r.summary.reason);
    REQUIRE(r.summary.status == RunStatus::completed);
    CHECK(r.summary.stiffened_steps >= 1);
    CHECK(r.summary.stiffened_steps <= r.summary.steps / 50);
    const double Mp = 355.0 * 10.0 * 10.0 / 4.0;
    for (double ratio : {0.2, 0.4, 0.6}) {
        double P = 0.0;
        for (std::size_t k = 1; k < r.steps.size() && P == 0.0; ++k)
            if (r.steps[k].load_factor >= ratio * 200.0) {
                const StepResult &a = r.steps[k - 1], &b = r.steps[k];
                P = a.load + (ratio * 200.0 - a.load_factor) / (b.load_factor - a.load_factor) * (b.load - a.load);
            }
        const double rigid_plastic = 4.0 * Mp / 100.0 / std::sqrt(1.0 - ratio * ratio);
        INFO("δ/D = " << ratio << ": P = " << P << ", DeRuntz & Hodge " << rigid_plastic);
        CHECK(std::abs(P / rigid_plastic - 1.0) < 0.05);
    }
}
