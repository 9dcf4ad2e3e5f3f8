// The check that ends a run whose structure passed through itself: crossing chords are found
// whichever axis the chords are swept along (x for a beam, y for a half ring, whose upper and
// lower arms share their x range), chords that meet at a node or only touch are not crossings.
#include "analysis/penetration_check.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace plastica;

namespace {

// A chain of elements through the given points.
Model chain(const std::vector<Node>& points) {
    Model m;
    m.nodes = points;
    for (int i = 0; i + 1 < static_cast<int>(points.size()); ++i) m.elements.push_back({i, i + 1, 0});
    return m;
}

// Displacements that move each node to the given place.
Eigen::VectorXd moved_to(const Model& m, const std::vector<Node>& places) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(dofs_per_node * static_cast<Eigen::Index>(m.nodes.size()));
    for (std::size_t i = 0; i < places.size(); ++i) {
        u[dofs_per_node * static_cast<Eigen::Index>(i)] = places[i].x - m.nodes[i].x;
        u[dofs_per_node * static_cast<Eigen::Index>(i) + 1] = places[i].y - m.nodes[i].y;
    }
    return u;
}

// A half ring of radius 1 from the top (0, 1) round the right to the bottom (0, −1).
std::vector<Node> half_ring(int elements, double squash) {
    std::vector<Node> points;
    for (int k = 0; k <= elements; ++k) {
        const double angle = M_PI * k / elements;
        points.push_back({std::sin(angle), squash * std::cos(angle)});
    }
    return points;
}

} // namespace

TEST_CASE("A half ring whose arms are pushed past each other is found, one pressed flat is not", "[penetration]") {
    const Model ring = chain(half_ring(24, 1.0));
    CHECK(find_penetration(ring, Eigen::VectorXd::Zero(3 * 25), 0.0).empty());
    // Pressed to a third of its height: the arms come closer, nothing crosses.
    CHECK(find_penetration(ring, moved_to(ring, half_ring(24, 0.3)), 0.0).empty());
    // The upper arm pushed below the lower one (the ends held): the chords from the top and to
    // the bottom cross at (0.1, 0).
    std::vector<Node> pushed = half_ring(24, 1.0);
    for (int k = 1; k < 24; ++k)
        if (k != 12) pushed[static_cast<std::size_t>(k)].y = k < 12 ? -0.3 : 0.3;
    const std::string crossed = find_penetration(ring, moved_to(ring, pushed), 0.0);
    INFO(crossed);
    CHECK(crossed.find("passes through itself") != std::string::npos);
    CHECK(crossed.find("element 1 ") != std::string::npos);
    CHECK(crossed.find("element 24 ") != std::string::npos);
}

TEST_CASE("A beam folded back across itself is found along x, a vertical column standing is not", "[penetration]") {
    // Five elements along x; the last two folded back under the first three and up through them.
    const Model beam = chain({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}});
    CHECK(find_penetration(beam, Eigen::VectorXd::Zero(18), 0.0).empty());
    const std::string folded = find_penetration(beam, moved_to(beam, {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {3.2, -1}, {1.5, 0.5}}), 0.0);
    CHECK(folded.find("passes through itself") != std::string::npos);
    // Flat in x: every chord has the same x range, so the sweep runs along y.
    const Model column = chain({{0, 0}, {0, 1}, {0, 2}, {0, 3}});
    CHECK(find_penetration(column, Eigen::VectorXd::Zero(12), 0.0).empty());
    const Model zigzag = chain({{0, 0}, {0, 1}, {0, 2}, {0, 3}});
    const std::string crossed = find_penetration(zigzag, moved_to(zigzag, {{0, 0}, {0, 2}, {-1, 1}, {1, 1.5}}), 0.0);
    CHECK(crossed.find("passes through itself") != std::string::npos);
}
