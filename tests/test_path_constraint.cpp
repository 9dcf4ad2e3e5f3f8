// What each scheme fixes along the path (analysis/path_constraint.hpp), on its own: the path
// parameter, the landing on a stage's target, the start from the extrapolation, the corrector's
// constraint and the arc-length increments it refuses.
#include "analysis/path_constraint.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace plastica;

namespace {
const PathPosition at{1.5, 0.4, 7.0}; // λ, controlled displacement, arc length
constexpr double pi = 3.14159265358979323846;
} // namespace

TEST_CASE("Each scheme measures the path in its own quantity", "[path_constraint]") {
    CHECK(make_path_constraint(Scheme::load_control)->parameter(at) == 1.5);
    CHECK(make_path_constraint(Scheme::displacement_control)->parameter(at) == 0.4);
    CHECK(make_path_constraint(Scheme::arc_length)->parameter(at) == 7.0);
    for (Scheme s : {Scheme::load_control, Scheme::displacement_control, Scheme::arc_length})
        CHECK(make_path_constraint(s)->scheme() == s);
}

TEST_CASE("Load and displacement control land on their targets and an arc is taken again", "[path_constraint]") {
    AnalysisSpec stage;
    stage.target_load_factor = 1.6;
    const auto load = make_path_constraint(Scheme::load_control);
    CHECK(load->landing(0.5, at, stage) == Approx(0.1));
    CHECK(load->landing(0.05, at, stage) == 0.05);
    CHECK_FALSE(load->retakes_past_target());
    // A target in the other quantity is not the load factor's to land on.
    const auto displacement = make_path_constraint(Scheme::displacement_control);
    CHECK(displacement->landing(0.5, at, stage) == 0.5);
    stage.target_load_factor.reset();
    stage.target_displacement = 0.6;
    CHECK(displacement->landing(0.5, at, stage) == Approx(0.2));
    CHECK(load->landing(0.5, at, stage) == 0.5);
    const auto arc = make_path_constraint(Scheme::arc_length);
    CHECK(arc->landing(0.5, at, stage) == 0.5);
    CHECK(arc->retakes_past_target());
}

TEST_CASE("Only load control prescribes the load and only an arc does not extrapolate", "[path_constraint]") {
    const auto load = make_path_constraint(Scheme::load_control);
    const auto displacement = make_path_constraint(Scheme::displacement_control);
    const auto arc = make_path_constraint(Scheme::arc_length);
    CHECK(load->prescribes_load_factor());
    CHECK_FALSE(displacement->prescribes_load_factor());
    CHECK_FALSE(arc->prescribes_load_factor());
    CHECK(load->starts_from_extrapolation());
    CHECK(displacement->starts_from_extrapolation());
    CHECK_FALSE(arc->starts_from_extrapolation());
    // Under load control the extrapolated start keeps the load step exactly.
    CHECK(load->extrapolated_load_change(0.1, 0.0999) == 0.1);
    CHECK(displacement->extrapolated_load_change(0.1, 0.0999) == 0.0999);
}

TEST_CASE("The correctors keep the load step or the controlled DOF's", "[path_constraint]") {
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(3);
    Eigen::VectorXd du_load(3);
    du_load << 0.0, 4.0, 1.0;
    CorrectorContext context;
    context.control_equation = 1;
    context.control_sign = -1.0; // reported downward: the DOF moves by −h
    context.previous = &zero;
    const auto load = make_path_constraint(Scheme::load_control)->corrector(0.2, context);
    CHECK(load->load_change(0, zero, zero, du_load) == 0.2);
    CHECK(load->load_change(1, zero, zero, du_load) == 0.0);
    const auto displacement = make_path_constraint(Scheme::displacement_control)->corrector(0.2, context);
    // δλ·du_load[1] = −0.2 moves the controlled equation by the increment.
    CHECK(displacement->load_change(0, zero, zero, du_load) == Approx(-0.05));
}

TEST_CASE("An arc-length increment that turns back on the path is refused", "[path_constraint]") {
    const auto arc = make_path_constraint(Scheme::arc_length);
    Eigen::VectorXd previous(2);
    previous << 1.0, 0.0;
    auto turned = [](double degrees) {
        Eigen::VectorXd v(2);
        v << std::cos(degrees * pi / 180.0), std::sin(degrees * pi / 180.0);
        return v;
    };
    CHECK_FALSE(arc->turned_back(turned(5.0), previous));
    CHECK_FALSE(arc->turned_back(turned(137.0), previous)); // where the arch lifts off the floor
    CHECK(arc->turned_back(turned(170.0), previous));
    CHECK(arc->turned_back(turned(180.0), previous));
    CHECK_FALSE(make_path_constraint(Scheme::load_control)->turned_back(turned(180.0), previous));
}
