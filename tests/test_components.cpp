// The components of the structural system on their own (analysis/component.hpp): each one's
// tangent is the derivative of the forces it adds, and the system's forces and tangent are the
// sums of its components'. States are taken along the paths of shipped scenes, where springs
// press on bases and rings press on each other.
#include "analysis/foundation_component.hpp"
#include "analysis/member_set.hpp"
#include "analysis/structural_system.hpp"
#include "analysis/surface_contact_component.hpp"
#include "analysis_helpers.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

using namespace plastica;
using namespace plastica::testing;

namespace {

// A scene's model and the displacements of the last step of a run of it (at most `steps` steps).
struct State {
    Model model;
    Eigen::VectorXd u, ubar;
    std::vector<int> equation; // per DOF, as the system numbers them
    int free_count = 0;
};

State state_along(const std::string& scene, int steps) {
    Model model = read_scene_text(scene_file_text(scene), scene);
    model.analysis.max_steps = steps;
    const Run run = run_model(model);
    REQUIRE(run.steps.size() == static_cast<std::size_t>(steps) + 1);
    State s;
    s.model = model;
    s.u = Eigen::Map<const Eigen::VectorXd>(run.steps.back().displacement.data(), model.dof_count());
    s.ubar = Eigen::VectorXd::Zero(model.dof_count());
    const StructuralSystem system(model);
    for (int dof = 0; dof < model.dof_count(); ++dof) s.equation.push_back(system.equation(dof));
    s.free_count = system.free_count();
    return s;
}

// A tangent stored as its lower triangle, whole.
Eigen::MatrixXd dense_symmetric(const SparseMatrix& lower) {
    const SparseMatrix full = lower.selfadjointView<Eigen::Lower>();
    return Eigen::MatrixXd(full);
}

// The component's forces on the free DOFs at u, and its tangent there (full, symmetric).
struct Linearised {
    Eigen::VectorXd force;
    Eigen::MatrixXd tangent;
};

Linearised linearise(Component& c, const State& s, const Eigen::VectorXd& u) {
    Eigen::VectorXd internal = Eigen::VectorXd::Zero(s.model.dof_count()), coupling = Eigen::VectorXd::Zero(s.free_count);
    REQUIRE(c.evaluate({u, s.ubar, 1.0, false, false, false}, internal, coupling));
    std::vector<std::vector<int>> blocks;
    c.append_blocks(blocks);
    BlockAssembler assembler(s.free_count, blocks);
    assembler.set_zero();
    c.assemble(assembler, 0);
    Linearised out;
    out.force = Eigen::VectorXd::Zero(s.free_count);
    for (int dof = 0; dof < s.model.dof_count(); ++dof)
        if (s.equation[dof] >= 0) out.force[s.equation[dof]] = internal[dof];
    out.tangent = dense_symmetric(assembler.matrix());
    return out;
}

// Central differences of the component's forces along each free DOF of the nodes in `nodes`,
// against its tangent's columns, relative to the tangent's largest entry.
double tangent_error(Component& c, const State& s, const std::vector<int>& nodes, double h) {
    const Linearised at = linearise(c, s, s.u);
    const double scale = at.tangent.cwiseAbs().maxCoeff();
    REQUIRE(scale > 0.0);
    double worst = 0.0;
    for (int node : nodes)
        for (int d = 0; d < dofs_per_node; ++d) {
            const int eq = s.equation[dofs_per_node * node + d];
            if (eq < 0) continue;
            Eigen::VectorXd plus = s.u, minus = s.u;
            plus[dofs_per_node * node + d] += h;
            minus[dofs_per_node * node + d] -= h;
            const Eigen::VectorXd column = (linearise(c, s, plus).force - linearise(c, s, minus).force) / (2 * h);
            worst = std::max(worst, (column - at.tangent.col(eq)).cwiseAbs().maxCoeff() / scale);
        }
    return worst;
}

} // namespace

TEST_CASE("A foundation's tangent is the derivative of its spring forces on a pipe pressed into soil", "[components]") {
    const State s = state_along("models/gallery/pipe_on_soil.toml", 20);
    FoundationComponent foundation(s.model, s.equation);
    std::vector<int> touching;
    Eigen::VectorXd internal = Eigen::VectorXd::Zero(s.model.dof_count()), coupling = Eigen::VectorXd::Zero(s.free_count);
    foundation.evaluate({s.u, s.ubar, 1.0, false, false, false}, internal, coupling);
    for (const SpringState& st : foundation.foundation().states())
        if (st.unilateral && st.active) touching.push_back(st.node);
    REQUIRE(touching.size() >= 3);
    // The penalty is linear in the gap: differences are exact but for round-off, with a step
    // that keeps every touching node on the base.
    CHECK(tangent_error(foundation, s, touching, 1e-7) < 1e-9);
    std::vector<std::vector<int>> blocks;
    foundation.append_blocks(blocks);
    CHECK(blocks.size() == s.model.springs.size());
}

TEST_CASE("The members' tangent is the derivative of their forces on a bent ring", "[components]") {
    const State s = state_along("models/ring_elastic.toml", 20);
    FollowerPressure no_pressure(s.model);
    MemberSet members(s.model, s.equation, no_pressure);
    // Central differences with a step of 1e-6 of the radius: their truncation error is of
    // order (1e-6)² and the round-off of the forces 1e-16/1e-6 of them.
    CHECK(tangent_error(members, s, {0, 5, 10}, 1e-6 * 100.0) < 1e-8);
    std::vector<std::vector<int>> blocks;
    members.append_blocks(blocks);
    CHECK(blocks.size() == s.model.elements.size());
}

TEST_CASE("Surface contact brings blocks where rings touch and its tangent is the derivative of its forces", "[components]") {
    const State s = state_along("tests/contact/two_rings_stacked.toml", 6);
    SurfaceContactComponent surfaces(s.model, s.equation);
    std::vector<std::vector<int>> blocks;
    surfaces.append_blocks(blocks);
    CHECK(blocks.empty()); // nothing has touched yet
    Eigen::VectorXd internal = Eigen::VectorXd::Zero(s.model.dof_count()), coupling = Eigen::VectorXd::Zero(s.free_count);
    surfaces.evaluate({s.u, s.ubar, 1.0, false, false, false}, internal, coupling);
    REQUIRE_FALSE(surfaces.self_contact().contacts().empty());
    CHECK(surfaces.blocks_changed());
    surfaces.append_blocks(blocks);
    CHECK(blocks.size() == surfaces.self_contact().contacts().size());
    std::vector<int> nodes;
    double penetration = 1e300;
    for (const SurfaceContact& c : surfaces.self_contact().contacts()) {
        nodes.push_back(c.node);
        if (c.gap < 0.0) penetration = std::min(penetration, -c.gap);
    }
    REQUIRE(penetration < 1e300);
    // A step of a hundredth of the smallest penetration keeps every pair closed (the penalty's
    // penetration here is about 1e-9 of the radius); the positions' round-off, 1e-14 of the
    // radius, is then a few 1e-5 of the step.
    CHECK(tangent_error(surfaces, s, nodes, 1e-2 * penetration) < 1e-4);
    // Committed where every pair still touches, the blocks stay.
    surfaces.commit();
    CHECK_FALSE(surfaces.blocks_changed());
}

TEST_CASE("The system's forces and tangent are the sums of its components'", "[components]") {
    const State s = state_along("tests/contact/two_rings_stacked.toml", 6);
    StructuralSystem system(s.model);
    REQUIRE(system.evaluate(s.u, s.ubar, 1.0, false));
    FollowerPressure no_pressure(s.model);
    MemberSet members(s.model, s.equation, no_pressure);
    FoundationComponent foundation(s.model, s.equation);
    SurfaceContactComponent surfaces(s.model, s.equation);
    Eigen::VectorXd force = Eigen::VectorXd::Zero(s.free_count);
    Eigen::MatrixXd tangent = Eigen::MatrixXd::Zero(s.free_count, s.free_count);
    for (Component* c : std::initializer_list<Component*>{&members, &foundation, &surfaces}) {
        const Linearised part = linearise(*c, s, s.u);
        force += part.force;
        tangent += part.tangent;
    }
    const Eigen::MatrixXd K = dense_symmetric(system.tangent());
    CHECK((system.gather(system.internal_force()) - force).cwiseAbs().maxCoeff() <= 1e-12 * force.cwiseAbs().maxCoeff());
    CHECK((K - tangent).cwiseAbs().maxCoeff() <= 1e-12 * K.cwiseAbs().maxCoeff());
    CHECK(system.self_contact().contacts().size() == surfaces.self_contact().contacts().size());
}
