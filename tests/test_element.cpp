// Unit tests of the co-rotational beam: the tangent is the derivative of the internal force,
// a rigid motion produces no force, and the geometric part vanishes without axial force.
#include "element/corotational_beam.hpp"
#include "element/plastic_hinge_law.hpp"
#include "scene_reader.hpp"

#include <catch2/catch.hpp>

using namespace plastica;

namespace {

// Central differences of a response f(x) (a vector of the size of x), step relative to each
// component with a floor for components near zero.
template <class Vector, class Response>
Eigen::Matrix<double, Vector::RowsAtCompileTime, Vector::RowsAtCompileTime>
central_differences(const Vector& x, double relative_step, double floor, Response f) {
    Eigen::Matrix<double, Vector::RowsAtCompileTime, Vector::RowsAtCompileTime> K;
    for (int j = 0; j < x.size(); ++j) {
        const double h = relative_step * std::max(floor, std::abs(x[j]));
        Vector xp = x, xm = x;
        xp[j] += h;
        xm[j] -= h;
        K.col(j) = (f(xp) - f(xm)) / (2.0 * h);
    }
    return K;
}

Matrix6 finite_difference_tangent(CorotationalBeam& beam, const Vector6& d) {
    return central_differences(d, 1e-6, 1.0, [&beam](const Vector6& x) {
        Vector6 f;
        beam.compute(x, f, nullptr);
        return f;
    });
}

// An elastic element from (0.3, −0.2) to (2.1, 0.9) and a large, general motion of it: stretch,
// rotation past π/2, bending.
CorotationalBeam general_beam() { return CorotationalBeam({0.3, -0.2}, {2.1, 0.9}, std::make_unique<ElasticLaw>(50.0, 3.0, 2.1)); }

Vector6 general_motion() {
    Vector6 d;
    d << 0.1, -0.3, 1.9, -1.7, 0.8, 2.6;
    return d;
}

} // namespace

TEST_CASE("The co-rotational tangent equals a finite difference of the internal force", "[element]") {
    CorotationalBeam beam = general_beam();
    const Vector6 d = general_motion();
    Vector6 f;
    Matrix6 K;
    beam.compute(d, f, &K);
    const Matrix6 K_fd = finite_difference_tangent(beam, d);
    INFO("K =\n" << K << "\nK_fd =\n" << K_fd);
    CHECK((K - K_fd).norm() < 1e-6 * K.norm());
    CHECK((K - K.transpose()).norm() < 1e-10 * K.norm()); // conservative loading: symmetric
}

TEST_CASE("A tangent given another axial force differs by that force's geometric stiffness alone", "[element]") {
    // K(N') − K(N) = z zᵀ (N' − N)/L with z = [s −c 0 −s c 0] of the current chord: the first
    // tangent at an extrapolated start takes the path's axial force this way.
    CorotationalBeam beam = general_beam();
    Vector6 f;
    Matrix6 K;
    beam.compute(general_motion(), f, &K);
    beam.commit(); // forces() reports the trial's axial force
    const double dx = (2.1 - 1.7) - (0.3 + 0.1), dy = (0.9 + 0.8) - (-0.2 - 0.3), L = std::hypot(dx, dy);
    Vector6 z;
    z << dy / L, -dx / L, 0.0, -dy / L, dx / L, 0.0;
    const Matrix6 zz = z * z.transpose() / L;
    Matrix6 K_unstressed, K_other;
    beam.tangent(K_unstressed, 0.0);
    beam.tangent(K_other, 7.5);
    REQUIRE(std::abs(beam.forces().axial) > 1.0);
    CHECK((K - K_unstressed - zz * beam.forces().axial).norm() < 1e-12 * K.norm());
    CHECK((K_other - K_unstressed - zz * 7.5).norm() < 1e-12 * K.norm());
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

namespace {

// Central differences of a basic law's trial forces about e, every trial from the same
// committed state (the return map is path independent within a step).
Eigen::Matrix3d finite_difference_basic(BasicLaw& law, const Eigen::Vector3d& e) {
    return central_differences(e, 1e-7, 1e-3, [&law](const Eigen::Vector3d& x) {
        Eigen::Vector3d q;
        Eigen::Matrix3d k;
        law.trial(x, q, k);
        return q;
    });
}

} // namespace

TEST_CASE("The plastic hinge tangent equals a finite difference while yielding and while fully plastic", "[element][plasticity]") {
    // Rectangle 10 × 20, E = 200e3, fy = 250: My = 1.667e5, Mp = 1.5 My; L = 1000, so the
    // antisymmetric end rotation θ gives M = 6EI θ / L and first yield near θ = 0.021; the
    // ends reach capacity near θ = 0.4, once every fibre has yielded. A stretch gives
    // N = 0.2 Ny (less once the ends flow along the capacity's normal), so the capacity rows
    // have a slope dMp/dN that the tangent must carry.
    SectionSpec s = rectangle_section(200e3, 10.0, 20.0, 20);
    s.steel = bilinear_steel(200e3, 250.0, 0.0);
    const double L = 1000.0, EA = 200e3 * 200.0, Ny = 250.0 * 200.0;
    PlasticHingeLaw law(s, L);
    const double stretch = 0.2 * Ny * L / EA; // reached at θ = 0.01, then held
    Eigen::Vector3d q;
    Eigen::Matrix3d k;
    bool checked[3] = {false, false, false};
    double theta = 0.0;
    for (int step = 0; step < 200 && !(checked[1] && checked[2]); ++step) {
        theta += 0.005;
        const Eigen::Vector3d e(std::min(theta / 0.01, 1.0) * stretch, theta, theta);
        law.trial(e, q, k);
        law.commit();
        const HingeState state = law.hinge(0).state;
        const int regime = state == HingeState::yielding ? 1 : state == HingeState::plastic ? 2 : 0;
        if (checked[regime] || regime == 0) continue;
        // A trial a little further along the same path, in the same regime as the committed state.
        const Eigen::Vector3d ahead = e + 2e-4 * Eigen::Vector3d(0.0, 1.0, 1.0);
        law.trial(ahead, q, k);
        const Eigen::Matrix3d k_fd = finite_difference_basic(law, ahead);
        CAPTURE(regime, theta, q.transpose(), k, k_fd);
        CHECK((k - k_fd).norm() <= 1e-6 * k.norm());
        // The tangent has lost stiffness against the elastic one in bending.
        CHECK(k(1, 1) < 0.999 * 4.0 * 200e3 * (10.0 * 8000.0 / 12.0) / L);
        law.trial(e, q, k); // back to the committed state's trial before going on
        checked[regime] = true;
    }
    CHECK(checked[1]);
    CHECK(checked[2]);
}

TEST_CASE("The plastic hinge tangent equals a finite difference after a long plastic step", "[element][plasticity]") {
    // The section of the case above at capacity under N = 0.2 Ny, then one trial that turns the
    // ends on by 0.3 more. Its plastic rotation multiplies the capacity's curvature into the
    // axial response: (Δθp·M_p(0))·|M_p″|/M_p(0)·EA/L = 2Δθp·M_p(0)·EA/(L·Ny²) ≈ 2.4, far past
    // where repeating N ← N(linearised at N) converges, so the state on the curved surface must
    // be solved for, or the forces and the tangent no longer belong together.
    SectionSpec s = rectangle_section(200e3, 10.0, 20.0, 20);
    s.steel = bilinear_steel(200e3, 250.0, 0.0);
    const double L = 1000.0, EA = 200e3 * 200.0, Ny = 250.0 * 200.0;
    PlasticHingeLaw law(s, L);
    Eigen::Vector3d q;
    Eigen::Matrix3d k;
    Eigen::Vector3d e(0.2 * Ny * L / EA, 0.0, 0.0);
    for (int step = 0; step < 100 && law.hinge(0).state != HingeState::plastic; ++step) {
        e[1] += 0.005;
        e[2] += 0.005;
        law.trial(e, q, k);
        law.commit();
    }
    REQUIRE(law.hinge(0).state == HingeState::plastic);
    const Eigen::Vector3d ahead = e + 0.3 * Eigen::Vector3d(0.0, 1.0, 1.0);
    law.trial(ahead, q, k);
    const Eigen::Matrix3d k_fd = finite_difference_basic(law, ahead);
    CAPTURE(q.transpose(), k, k_fd);
    // To 1e-5: the regularising hardening, 1e-6 of the stiffness along the capacity's normal,
    // turns with N as the normal does, and the tangent leaves that change out.
    CHECK((k - k_fd).norm() <= 1e-5 * k.norm());
    CHECK(std::abs(q[0]) < Ny);
}
