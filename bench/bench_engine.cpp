// The engine's costs: one element, one section solve, one Newton iteration by ring size, and
// whole ring analyses without output.
#include "bench_scenes.hpp"

#include "analysis/path_following.hpp"
#include "analysis/structural_system.hpp"
#include "element/basic_law.hpp"
#include "element/corotational_beam.hpp"
#include "section/fibre_section.hpp"
#include "solver/linear_solver.hpp"

#include <benchmark/benchmark.h>

#include <string>

namespace plastica::bench {

// Internal force and tangent of one co-rotational element at a large rotation.
void element_tangent(benchmark::State& state) {
    CorotationalBeam beam({0.0, 0.0}, {10.0, 0.0}, std::make_unique<ElasticLaw>(1e8, 1e3, 10.0));
    Vector6 d;
    d << 0.0, 0.0, 0.3, -2.0, 5.0, 0.9;
    Vector6 force;
    Matrix6 tangent;
    for (auto _ : state) {
        beam.compute(d, force, &tangent);
        benchmark::DoNotOptimize(tangent.data());
    }
}
BENCHMARK(element_tangent);

// The Strain Compatibility Method: the deformation that carries (N, M) past first yield.
void section_solve(benchmark::State& state) {
    SectionSpec spec = rectangle_section(1e9, 9.128709291752768, 0.010954451150103323, static_cast<int>(state.range(0)));
    spec.steel = bilinear_steel(1e9, 36518.0, 0.0);
    FibreSection section(spec);
    for (auto _ : state) {
        const ScmResult r = section.solve_for_forces(500.0, 9.0);
        benchmark::DoNotOptimize(r);
        section.revert();
    }
}
BENCHMARK(section_solve)->Arg(10)->Arg(100);

// One Newton iteration: element forces and tangent assembled, LDLᵀ factorised, solved.
void newton_iteration(benchmark::State& state) {
    const int elements = static_cast<int>(state.range(0));
    const Model model = ring("ring_elastic", elements);
    StructuralSystem system(model);
    Eigen::VectorXd u = Eigen::VectorXd::Zero(system.dof_count());
    for (int i = 0; i < u.size(); i += 3) u[i + 1] = -1e-3 * (i % 7); // a deformed state
    const Eigen::VectorXd ubar = Eigen::VectorXd::Zero(system.dof_count());
    const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(system.free_count());
    LinearSolver solver;
    for (auto _ : state) {
        system.evaluate(u, ubar, 0.0, false);
        solver.factorize(system.tangent());
        const Eigen::VectorXd du = solver.solve(rhs);
        benchmark::DoNotOptimize(du.data());
    }
    state.counters["elements"] = elements;
    state.SetComplexityN(elements);
}
BENCHMARK(newton_iteration)->Arg(50)->Arg(500)->Arg(5000)->Arg(50000)->Unit(benchmark::kMicrosecond)->Complexity(benchmark::oN);

// The whole 200-step ring to a top displacement of 100, nothing written, and each step's result
// as a curves-only run has it (no sections along the members).
void ring_analysis(benchmark::State& state, const char* scene) {
    const Model model = ring(scene);
    RunControl curve_alone;
    curve_alone.report_sections = false;
    int steps = 0;
    for (auto _ : state) {
        PathFollowing analysis(model);
        const RunSummary summary = analysis.run({}, curve_alone);
        steps = summary.steps;
    }
    state.counters["steps"] = steps;
}
BENCHMARK_CAPTURE(ring_analysis, elastic, "ring_elastic")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ring_analysis, inelastic, "ring_inelastic")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ring_analysis, distributed, "ring_distributed")->Unit(benchmark::kMillisecond);

// A plastic-zone analysis in either formulation, as ring_analysis runs it: the ring on 50
// elements of 5 Lobatto points (force) against its shipped 4 segments, and the portal of
// tests/frames/portal_weak_columns.toml on 8 elements per member in fibre sections.
void plastic_zone_analysis(benchmark::State& state, const char* scene, const char* formulation) {
    const bool force = std::string(formulation) == "force";
    const Model model =
        std::string(scene) == "ring"
            ? edited_scene("models/ring_distributed.toml",
                           force ? std::vector<std::pair<std::string, std::string>>{{"segments = 4\n", "formulation = \"force\"\n"},
                                                                                     {"integration_points = 2\n", ""}}
                                 : std::vector<std::pair<std::string, std::string>>{})
            : edited_scene("tests/frames/portal_weak_columns.toml",
                           {{"web_thickness = 0.009\n", std::string("web_thickness = 0.009\nplasticity = \"distributed\"\nformulation = \"") + formulation + "\"\n"},
                            {"web_thickness = 0.0071\n", std::string("web_thickness = 0.0071\nplasticity = \"distributed\"\nformulation = \"") + formulation + "\"\n"}});
    RunControl curve_alone;
    curve_alone.report_sections = false;
    int steps = 0;
    for (auto _ : state) {
        PathFollowing analysis(model);
        steps = analysis.run({}, curve_alone).steps;
    }
    state.counters["steps"] = steps;
}
BENCHMARK_CAPTURE(plastic_zone_analysis, ring_displacement, "ring", "displacement")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(plastic_zone_analysis, ring_force, "ring", "force")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(plastic_zone_analysis, portal_displacement, "portal", "displacement")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(plastic_zone_analysis, portal_force, "portal", "force")->Unit(benchmark::kMillisecond);

} // namespace plastica::bench
