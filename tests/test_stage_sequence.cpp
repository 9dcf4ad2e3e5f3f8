// The stages of a run on their own (analysis/stage_sequence.hpp): the settings each stage runs
// under, its direction toward the target, and where a state lies against that target.
#include "analysis/stage_sequence.hpp"

#include <catch2/catch.hpp>

using namespace plastica;

namespace {
// Two nodes; the controlled DOF is node 1's uy, reported downward positive.
Model two_stage_model() {
    Model m;
    m.nodes = {{0.0, 0.0}, {0.0, 1.0}};
    m.analysis.scheme = Scheme::arc_length;
    m.analysis.initial_increment = 0.05;
    m.analysis.min_increment = 1e-8;
    m.analysis.target_load_factor = 2.0;
    m.analysis.control = {1, 1, -1.0};
    StageSpec unload; // back to λ = 0
    unload.scheme = Scheme::load_control;
    unload.increment = 0.25;
    unload.target_load_factor = 0.0;
    unload.pattern = 1;
    unload.control = m.analysis.control;
    StageSpec push; // then push the node down to 3
    push.scheme = Scheme::displacement_control;
    push.increment = 0.5;
    push.adaptive = true;
    push.target_displacement = 3.0;
    push.control = m.analysis.control;
    m.stages = {unload, push};
    return m;
}

Eigen::VectorXd with_drop(double drop) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(6);
    u[4] = -drop; // node 1, uy
    return u;
}
} // namespace

TEST_CASE("The first stage counts its target load factor either way", "[stage_sequence]") {
    const StageSequence stages(two_stage_model());
    const Eigen::VectorXd u = with_drop(0.0);
    CHECK(stages.number() == 1);
    CHECK(stages.current().scheme == Scheme::arc_length);
    CHECK(stages.past_target(1.5, u) == Approx(-0.5));
    CHECK_FALSE(stages.target_reached(1.5, u));
    CHECK(stages.target_reached(2.0, u));
    CHECK(stages.target_reached(-2.0, u)); // a load that turned negative along the path
    // Within the round-off of its increment a state is on the target, beyond it not.
    CHECK(stages.target_reached(2.0 - 1e-12, u));
    CHECK_FALSE(stages.target_reached(2.0 - 1e-9, u));
    CHECK(stages.remaining(1.5, u) == Approx(0.5));
    CHECK(stages.landing_scheme() == Scheme::load_control);
}

TEST_CASE("A stage that turns back travels toward its target from where the last ended", "[stage_sequence]") {
    StageSequence stages(two_stage_model());
    REQUIRE(stages.has_next());
    CHECK(stages.next().pattern == 1);
    const double first = stages.begin_next(2.0, with_drop(1.0));
    CHECK(first == Approx(-0.25)); // toward λ = 0
    CHECK(stages.turned_back());
    CHECK(stages.number() == 2);
    const AnalysisSpec& a = stages.current();
    CHECK(a.scheme == Scheme::load_control);
    CHECK(a.pattern == 1);
    CHECK(a.initial_increment == 0.25);
    CHECK(a.max_increment == Approx(2.5));
    CHECK(a.min_increment == Approx(1e-8)); // the smaller of [analysis]'s and a millionth of the increment
    // Short of λ = 0 coming down; past it below.
    CHECK(stages.past_target(0.5, with_drop(0.5)) == Approx(-0.5));
    CHECK(stages.past_target(-0.1, with_drop(0.5)) == Approx(0.1));
    CHECK(stages.remaining(0.5, with_drop(0.5)) == Approx(-0.5));
}

TEST_CASE("A stage under displacement control measures its target on its controlled DOF", "[stage_sequence]") {
    StageSequence stages(two_stage_model());
    stages.begin_next(2.0, with_drop(1.0));
    REQUIRE(stages.has_next());
    const double first = stages.begin_next(0.0, with_drop(0.8));
    CHECK(first == Approx(0.5)); // down, toward a drop of 3
    CHECK(stages.turned_back()); // the unloading went the other way
    CHECK_FALSE(stages.has_next());
    CHECK(stages.control_value(with_drop(0.8)) == Approx(0.8));
    CHECK(stages.past_target(0.0, with_drop(2.0)) == Approx(-1.0));
    CHECK(stages.target_reached(0.0, with_drop(3.0)));
    CHECK(stages.remaining(0.0, with_drop(2.0)) == Approx(1.0));
    CHECK(stages.landing_scheme() == Scheme::displacement_control);
    CHECK(stages.current().min_increment == Approx(1e-8));
}

TEST_CASE("A run without a target is never past it", "[stage_sequence]") {
    Model m = two_stage_model();
    m.analysis.target_load_factor.reset();
    m.stages.clear();
    const StageSequence stages(m);
    CHECK_FALSE(stages.has_next());
    CHECK_FALSE(stages.target_reached(1e9, with_drop(1e9)));
}
