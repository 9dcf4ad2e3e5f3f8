// The model-building steps of io/scene/model_building.hpp on models made in code (no scene file):
// line loads lumped to nodes, tributary lengths, the members' normal at a node, what the
// reported load measures, and the cantilever the closed form describes.
#include "model_building.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace plastica;

namespace {
constexpr double pi = 3.14159265358979323846;

// A straight member from (0, 0) to (L, 0) in n equal elements, its section of mass m per length.
Model straight_member(double L, int n, double mass_per_length = 0.0) {
    Model m;
    SectionSpec s;
    s.E = 1.0;
    s.area = 1.0;
    s.inertia = 1.0;
    s.mass_per_length = mass_per_length;
    m.sections.push_back(s);
    for (int k = 0; k <= n; ++k) m.nodes.push_back({L * k / n, 0.0});
    for (int k = 0; k < n; ++k) {
        ElementSpec e;
        e.node_i = k;
        e.node_j = k + 1;
        m.elements.push_back(e);
    }
    return m;
}
} // namespace

TEST_CASE("A uniform line load is lumped half to each end of every element", "[model_building]") {
    const Model m = straight_member(4.0, 4);
    const auto lumped = lumped_line_load(m, {0, 1, 2, 3}, {0.0, -3.0}, {0.0, 0.0});
    REQUIRE(lumped.size() == 5);
    // wL/8 at the ends, wL/4 inside: the total is w·L.
    CHECK(lumped.at(0)[1] == Approx(-1.5));
    CHECK(lumped.at(1)[1] == Approx(-3.0));
    CHECK(lumped.at(4)[1] == Approx(-1.5));
    double total = 0.0;
    for (const auto& [node, f] : lumped) total += f[1];
    CHECK(total == Approx(-12.0));
    // Only the elements listed: the second half.
    const auto half = lumped_line_load(m, {2, 3}, {0.0, -3.0}, {0.0, 0.0});
    CHECK(half.count(1) == 0);
    CHECK(half.at(2)[1] == Approx(-1.5));
}

TEST_CASE("Self weight is the section's mass per length times gravity", "[model_building]") {
    const Model m = straight_member(2.0, 2, 7.85);
    const auto lumped = lumped_line_load(m, {0, 1}, {0.0, 0.0}, {0.0, -9.81});
    double total = 0.0;
    for (const auto& [node, f] : lumped) total += f[1];
    CHECK(total == Approx(-7.85 * 9.81 * 2.0));
    CHECK(lumped.at(1)[1] == Approx(-7.85 * 9.81));
}

TEST_CASE("Tributary lengths are half of each element that meets a node", "[model_building]") {
    Model m = straight_member(3.0, 3);
    m.nodes[1].x = 0.5; // elements of 0.5, 1.5 and 1
    const std::vector<double> t = tributary_lengths(m);
    REQUIRE(t.size() == 4);
    CHECK(t[0] == Approx(0.25));
    CHECK(t[1] == Approx(1.0));
    CHECK(t[2] == Approx(1.25));
    CHECK(t[3] == Approx(0.5));
    CHECK(t[0] + t[1] + t[2] + t[3] == Approx(3.0));
}

TEST_CASE("The members' normal at a node points to the centre of a counter-clockwise arc", "[model_building]") {
    // Five points on a unit circle, counter-clockwise from −90° to 90°.
    Model m;
    for (int k = 0; k <= 4; ++k) {
        const double angle = -pi / 2 + pi * k / 4;
        m.nodes.push_back({std::cos(angle), std::sin(angle)});
    }
    for (int k = 0; k < 4; ++k) {
        ElementSpec e;
        e.node_i = k;
        e.node_j = k + 1;
        m.elements.push_back(e);
    }
    const auto middle = member_normal(m, 2); // at (1, 0): toward the centre, −x
    REQUIRE(middle);
    CHECK((*middle)[0] == Approx(-1.0));
    CHECK((*middle)[1] == Approx(0.0).margin(1e-15));
    const auto end = member_normal(m, 0); // the end's own element, at 22.5° above −x
    REQUIRE(end);
    CHECK(std::hypot((*end)[0], (*end)[1]) == Approx(1.0));
    // A node no element meets has no normal.
    m.nodes.push_back({5.0, 5.0});
    CHECK_FALSE(member_normal(m, 5));
}

TEST_CASE("The reported load is the total of parallel loads and the factor of others", "[model_building]") {
    Model m = straight_member(2.0, 2);
    m.patterns = {"default"};
    m.loads.push_back({2, {0.0, -1.0, 0.0}, 0});
    infer_report_measure(m);
    CHECK(m.report.measure == ReportSpec::Measure::total);
    m.loads.push_back({1, {1.0, 0.0, 0.0}, 0}); // not parallel to the first
    infer_report_measure(m);
    CHECK(m.report.measure == ReportSpec::Measure::factor);
    CHECK(m.report.load_label == "load factor");
}

TEST_CASE("Only a clamped straight cantilever with one transverse tip load is the closed form's", "[model_building]") {
    Model m = straight_member(2.0, 4);
    Support clamp;
    clamp.node = 0;
    clamp.fixed = {true, true, true};
    m.supports.push_back(clamp);
    m.patterns = {"default"};
    m.loads.push_back({4, {0.0, -1.0, 0.0}, 0});
    CHECK(is_cantilever_with_tip_load(m));
    Model axial = m;
    axial.loads[0].value = {1.0, 0.0, 0.0}; // along the member: not transverse
    CHECK_FALSE(is_cantilever_with_tip_load(axial));
    Model mid = m;
    mid.loads[0].node = 2; // not at the tip
    CHECK_FALSE(is_cantilever_with_tip_load(mid));
    Model pinned = m;
    pinned.supports[0].fixed = {true, true, false};
    CHECK_FALSE(is_cantilever_with_tip_load(pinned));
}
