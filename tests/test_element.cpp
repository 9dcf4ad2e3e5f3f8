// Unit tests of the co-rotational beam: the tangent is the derivative of the internal force,
// a rigid motion produces no force, and the geometric part vanishes without axial force.
#include "element/corotational_beam.hpp"
#include "element/plastic_hinge_law.hpp"
#include "scene_reader.hpp"

#include <catch2/catch.hpp>

using namespace plastica;

namespace {

Matrix6 finite_difference_tangent(CorotationalBeam& beam, const Vector6& d) {
    Matrix6 K;
    Vector6 fp, fm;
    for (int j = 0; j < 6; ++j) {
        const double h = 1e-6 * std::max(1.0, std::abs(d[j]));
        Vector6 dp = d, dm = d;
        dp[j] += h;
        dm[j] -= h;
        beam.compute(dp, fp, nullptr);
        beam.compute(dm, fm, nullptr);
        K.col(j) = (fp - fm) / (2.0 * h);
    }
    return K;
}

} // namespace

TEST_CASE("The co-rotational tangent equals a finite difference of the internal force", "[element]") {
    CorotationalBeam beam({0.3, -0.2}, {2.1, 0.9}, std::make_unique<ElasticLaw>(50.0, 3.0, 2.1));
    // A large, general motion: stretch, rotation past π/2, bending.
    Vector6 d;
    d << 0.1, -0.3, 1.9, -1.7, 0.8, 2.6;
    Vector6 f;
    Matrix6 K;
    beam.compute(d, f, &K);
    const Matrix6 K_fd = finite_difference_tangent(beam, d);
    INFO("K =\n" << K << "\nK_fd =\n" << K_fd);
    CHECK((K - K_fd).norm() < 1e-6 * K.norm());
    CHECK((K - K.transpose()).norm() < 1e-10 * K.norm()); // conservative loading: symmetric
}

TEST_CASE("A rigid-body rotation of any size produces no internal force", "[element]") {
    const Node a{1.0, 2.0}, b{4.0, 6.0};
    for (double angle : {0.3, 2.0, 3.1, 3.2, -2.9, 7.0, -13.0}) {
        CorotationalBeam beam(a, b, std::make_unique<ElasticLaw>(1e6, 1e3, 5.0));
        // Rotate about node a by `angle`, in small committed steps so the unwrapping follows.
        Vector6 f;
        const int steps = 64;
        for (int k = 1; k <= steps; ++k) {
            const double t = angle * k / steps, c = std::cos(t), s = std::sin(t);
            const double bx = a.x + c * (b.x - a.x) - s * (b.y - a.y);
            const double by = a.y + s * (b.x - a.x) + c * (b.y - a.y);
            Vector6 d;
            d << 0.0, 0.0, t, bx - b.x, by - b.y, t;
            beam.compute(d, f, nullptr);
            beam.commit();
        }
        CAPTURE(angle);
        CHECK(f.norm() < 1e-6);
        CHECK(beam.rigid_rotation() == Approx(angle).margin(1e-12));
    }
}

TEST_CASE("The geometric stiffness vanishes when the element carries no force", "[element]") {
    CorotationalBeam beam({0.0, 0.0}, {1.0, 1.0}, std::make_unique<ElasticLaw>(100.0, 1.0, std::sqrt(2.0)));
    Vector6 d = Vector6::Zero();
    Vector6 f;
    Matrix6 K;
    beam.compute(d, f, &K);
    // At the undeformed state K is the linear frame stiffness: B has rows r, e3 − z/L, e6 − z/L.
    CHECK(f.norm() < 1e-12);
    CHECK((K - finite_difference_tangent(beam, d)).norm() < 1e-6 * K.norm());
    CHECK((K - K.transpose()).norm() < 1e-12);
}

TEST_CASE("The plastic hinge tangent equals a finite difference within one loading regime", "[element][plasticity]") {
    SectionSpec s = rectangle_section(200e3, 10.0, 20.0, 20);
    s.steel = bilinear_steel(200e3, 250.0, 0.0);
    CorotationalBeam beam({0.0, 0.0}, {1000.0, 0.0}, std::make_unique<PlasticHingeLaw>(s, 1000.0));
    Vector6 d;
    d << 0.0, 0.0, 0.0, 0.0, 0.5, 0.0004; // elastic regime: every η = 1
    Vector6 f;
    Matrix6 K;
    beam.compute(d, f, &K);
    CHECK((K - finite_difference_tangent(beam, d)).norm() < 1e-6 * K.norm());
}
