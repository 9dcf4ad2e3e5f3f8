// Newton's method and the increment constraints on toy problems whose exact answers are known:
// a two-DOF snap-through traced past its limit point, a one-spring contact settled inside
// Newton, one plastic hinge driven past its capacity, and the path extrapolation that starts
// an increment.
#include "analysis/increment_constraints.hpp"
#include "analysis/path_extrapolation.hpp"
#include "element/plastic_hinge_law.hpp"
#include "section/fibre_section.hpp"
#include "solver/newton_solver.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace plastica;

namespace {

// A small dense problem in the NewtonProblem form; derived classes give f(x) and K(x).
class ToyProblem : public NewtonProblem {
public:
    ToyProblem(int n, Eigen::VectorXd load) : x_(Eigen::VectorXd::Zero(n)), load_(std::move(load)), K_(n, n) {
        std::vector<Eigen::Triplet<double>> all;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) all.emplace_back(i, j, 1.0);
        K_.setFromTriplets(all.begin(), all.end());
    }
    bool evaluate(int, bool) override {
        ++evaluations;
        Eigen::MatrixXd dense;
        Eigen::VectorXd f;
        internal(f, dense);
        residual_ = lambda_ * load_ - f;
        for (int k = 0; k < K_.outerSize(); ++k)
            for (SparseMatrix::InnerIterator it(K_, k); it; ++it) it.valueRef() = dense(it.row(), it.col());
        return residual_.allFinite();
    }
    const Eigen::VectorXd& residual() const override { return residual_; }
    const Eigen::VectorXd& load_direction() const override { return load_; }
    const SparseMatrix& tangent() const override { return K_; }
    void move(const Eigen::VectorXd& dx, double dlambda) override {
        x_ += dx;
        lambda_ += dlambda;
    }
    double load_factor() const override { return lambda_; }
    double state_norm() const override { return x_.norm(); }
    virtual void internal(Eigen::VectorXd& f, Eigen::MatrixXd& K) = 0;

    Eigen::VectorXd x_;
    double lambda_ = 0.0;
    int evaluations = 0;

private:
    Eigen::VectorXd load_, residual_;
    SparseMatrix K_;
};

// A softening spring f(v) = v³ − 3v² + 2.2v (limit point at v = 1 − √(1 − 2.2/3)) in series with
// a linear spring k = 10 carrying the load: λ = f(v), w = v + λ/k.
struct SnapThrough final : ToyProblem {
    SnapThrough() : ToyProblem(2, Eigen::Vector2d(0.0, 1.0)) {}
    static double f(double v) { return v * v * v - 3.0 * v * v + 2.2 * v; }
    void internal(Eigen::VectorXd& r, Eigen::MatrixXd& K) override {
        const double v = x_[0], w = x_[1], k = 10.0, df = 3.0 * v * v - 6.0 * v + 2.2;
        r = Eigen::Vector2d(f(v) - k * (w - v), k * (w - v));
        K.resize(2, 2);
        K << df + k, -k, -k, k;
    }
};

// A spring k1 and a compression-only spring k2 that engages once u reaches the gap g.
struct OneSpringContact final : ToyProblem {
    OneSpringContact() : ToyProblem(1, Eigen::VectorXd::Ones(1)) {}
    static constexpr double k1 = 1.0, k2 = 1e3, gap = 0.5;
    void internal(Eigen::VectorXd& r, Eigen::MatrixXd& K) override {
        const bool was = active_;
        active_ = x_[0] >= gap;
        changed_ = was != active_;
        r = Eigen::VectorXd::Constant(1, k1 * x_[0] + (active_ ? k2 * (x_[0] - gap) : 0.0));
        K = Eigen::MatrixXd::Constant(1, 1, k1 + (active_ ? k2 : 0.0));
    }
    bool settled() const override { return !changed_; }
    bool active_ = false, changed_ = false;
};

// The same springs with the contact's state kept from the predictor on (a frozen active set),
// re-decided only when Newton releases it: equilibrium with a contradicted set comes first.
struct FrozenContact final : ToyProblem {
    FrozenContact() : ToyProblem(1, Eigen::VectorXd::Ones(1)) {}
    static constexpr double k1 = 1.0, k2 = 1e3, gap = 0.5;
    bool evaluate(int iteration, bool release) override {
        if (iteration == 0 || release) active_ = x_[0] >= gap;
        return ToyProblem::evaluate(iteration, release);
    }
    void internal(Eigen::VectorXd& r, Eigen::MatrixXd& K) override {
        r = Eigen::VectorXd::Constant(1, k1 * x_[0] + (active_ ? k2 * (x_[0] - gap) : 0.0));
        K = Eigen::MatrixXd::Constant(1, 1, k1 + (active_ ? k2 : 0.0));
    }
    bool settled() const override { return active_ == (x_[0] >= gap); }
    bool active_ = false;
};

} // namespace

TEST_CASE("Newton with arc length passes the limit point of a two-DOF snap-through", "[newton]") {
    SnapThrough problem;
    LinearSolver solver;
    NewtonSettings settings;
    settings.residual_tolerance = 1e-10;
    settings.displacement_tolerance = 1e-10;
    Eigen::VectorXd previous;
    const double v_limit = 1.0 - std::sqrt(1.0 - 2.2 / 3.0);
    bool passed_limit = false, negative_pivot = false;
    double peak = 0.0;
    for (int step = 0; step < 200 && problem.x_[0] < 2.5; ++step) {
        ArcLength constraint(0.05, previous);
        settings.reference_level = std::max(peak, 1e-3);
        const NewtonResult r = solve_increment(problem, constraint, settings, solver);
        REQUIRE(r.converged());
        CHECK(r.iterations <= 6);
        previous = r.increment;
        // On the exact path λ = f(v), w = v + λ/k.
        CHECK(problem.lambda_ == Approx(SnapThrough::f(problem.x_[0])).margin(1e-8));
        CHECK(problem.x_[1] == Approx(problem.x_[0] + problem.lambda_ / 10.0).margin(1e-8));
        if (problem.x_[0] < 1.0) peak = std::max(peak, problem.lambda_); // the first limit point
        passed_limit = passed_limit || problem.x_[0] > v_limit + 0.1;
        negative_pivot = negative_pivot || (r.negative_pivots_seen > 0 && problem.x_[0] > v_limit);
    }
    CHECK(passed_limit);
    CHECK(negative_pivot);
    CHECK(peak == Approx(SnapThrough::f(v_limit)).epsilon(2e-3)); // steps of 0.05 sample the peak
    CHECK(problem.x_[0] >= 2.5);
}

TEST_CASE("A state whose own correction is far inside the tolerance is accepted without it, on the same path", "[newton]") {
    // The snap-through spring traced by displacement control up its rising branch, once taking
    // every correction and once accepting a state whose next correction is within 1e-2 of the
    // displacement tolerance: the paths agree to 1e-10 of the step, and the second saves the
    // evaluation after that correction wherever Newton lands on the path to round-off.
    SnapThrough taken, untaken;
    LinearSolver solver;
    NewtonSettings settings;
    settings.residual_tolerance = 1e-6;
    int saved = 0;
    for (int step = 0; step < 10; ++step) {
        DisplacementControl c1(1, 0.02), c2(1, 0.02);
        settings.accept_before_correction = false;
        const NewtonResult a = solve_increment(taken, c1, settings, solver);
        const int evaluations = untaken.evaluations;
        settings.accept_before_correction = true;
        const NewtonResult b = solve_increment(untaken, c2, settings, solver);
        REQUIRE(a.converged());
        REQUIRE(b.converged());
        CHECK(b.iterations == a.iterations); // the same corrections computed
        CHECK((untaken.x_ - taken.x_).norm() <= 1e-10 * a.increment.norm());
        CHECK(std::abs(untaken.lambda_ - taken.lambda_) <= 1e-10 * std::abs(taken.lambda_));
        CHECK(untaken.lambda_ == Approx(SnapThrough::f(untaken.x_[0])).margin(1e-6));
        if (untaken.evaluations - evaluations == b.iterations) ++saved; // one per correction taken, none after the last
        // Keep the two on the same start, so that each step compares one rule against the other.
        untaken.x_ = taken.x_;
        untaken.lambda_ = taken.lambda_;
    }
    CHECK(saved >= 8); // every step here lands on the path to round-off
}

TEST_CASE("Load control past the limit point snaps to the far stable branch or fails, never stops on the unstable one", "[newton]") {
    SnapThrough problem;
    LinearSolver solver;
    NewtonSettings settings;
    const double limit = SnapThrough::f(1.0 - std::sqrt(1.0 - 2.2 / 3.0));
    for (int step = 0; step < 9; ++step) {
        LoadControl constraint(0.1 * limit);
        REQUIRE(solve_increment(problem, constraint, settings, solver).converged());
    }
    problem.lambda_ = 0.9 * limit;
    LoadControl beyond(0.2 * limit);
    const NewtonResult r = solve_increment(problem, beyond, settings, solver);
    if (r.converged()) {
        const double v = problem.x_[0];
        CHECK(v > 1.0 + std::sqrt(1.0 - 2.2 / 3.0)); // beyond the valley: the stable far branch
        CHECK(problem.lambda_ == Approx(SnapThrough::f(v)).margin(1e-6));
    }
}

TEST_CASE("Iterations spent re-deciding a contradicted active set are counted apart", "[newton]") {
    // The increment size adapts to the iterations before settling (analysis/path_following.cpp):
    // re-deciding takes the same iterations at any increment.
    LinearSolver solver;
    NewtonSettings settings;
    settings.residual_tolerance = 1e-12;
    SECTION("the open spring stays open: nothing to re-decide") {
        FrozenContact problem;
        LoadControl constraint(0.4);
        const NewtonResult r = solve_increment(problem, constraint, settings, solver);
        REQUIRE(r.converged());
        CHECK(r.iterations_before_settling == 0);
        CHECK(problem.x_[0] == Approx(0.4 / FrozenContact::k1).epsilon(1e-12));
    }
    SECTION("the spring closes: equilibrium open at iteration 1, then closed") {
        FrozenContact problem;
        LoadControl constraint(1.5);
        const NewtonResult r = solve_increment(problem, constraint, settings, solver);
        REQUIRE(r.converged());
        const double k1 = FrozenContact::k1, k2 = FrozenContact::k2, g = FrozenContact::gap;
        CHECK(problem.x_[0] == Approx((1.5 + k2 * g) / (k1 + k2)).epsilon(1e-12));
        CHECK(r.iterations_before_settling == 1);
        CHECK(r.iterations > r.iterations_before_settling);
    }
}

TEST_CASE("A one-spring contact settles inside Newton and lands on the exact state", "[newton]") {
    OneSpringContact problem;
    LinearSolver solver;
    NewtonSettings settings;
    settings.residual_tolerance = 1e-12;
    // λ = 0.4: open; λ = 1.5: closed, u = (λ + k2 g)/(k1 + k2).
    for (double target : {0.4, 1.5}) {
        LoadControl constraint(target - problem.lambda_);
        const NewtonResult r = solve_increment(problem, constraint, settings, solver);
        REQUIRE(r.converged());
        CHECK(r.rule == Acceptance::residual);
        const double k1 = OneSpringContact::k1, k2 = OneSpringContact::k2, g = OneSpringContact::gap;
        const double exact = target < k1 * g ? target / k1 : (target + k2 * g) / (k1 + k2);
        CHECK(problem.x_[0] == Approx(exact).epsilon(1e-12));
        CHECK(r.iterations <= 4);
    }
}

TEST_CASE("One plastic hinge driven past its capacity: quadratic steps, moment held at Mp", "[newton][plasticity]") {
    // A beam clamped at end i, rotated at end j: the end moment rises elastically, yields, and
    // stays at the capacity while the hinge rotates. Newton on the basic law alone.
    SectionSpec s;
    s.E = 2e8;
    s.area = 200.0;
    s.inertia = 10.0 * 8000.0 / 12.0;
    s.steel = bilinear_steel(2e8, 250.0, 0.0);
    for (int i = 0; i < 10; ++i) s.fibres.push_back({20.0, -10.0 + 2.0 * i + 1.0, 0.0});
    const double Mp = 250.0 * 10.0 * 400.0 / 4.0, L0 = 1000.0;
    struct Hinge final : ToyProblem {
        explicit Hinge(const SectionSpec& s, double L0) : ToyProblem(1, Eigen::VectorXd::Ones(1)), law(s, L0) {}
        void internal(Eigen::VectorXd& r, Eigen::MatrixXd& K) override {
            Eigen::Vector3d q;
            Eigen::Matrix3d k;
            law.trial(Eigen::Vector3d(0.0, 0.0, x_[0]), q, k);
            r = Eigen::VectorXd::Constant(1, q[2]);
            K = Eigen::MatrixXd::Constant(1, 1, k(2, 2));
        }
        PlasticHingeLaw law;
    } problem(s, L0);
    LinearSolver solver;
    NewtonSettings settings;
    const double theta_y = Mp * L0 / (4.0 * s.E * s.inertia);
    int over_three = 0;
    for (int step = 0; step < 60; ++step) {
        DisplacementControl constraint(0, 0.25 * theta_y);
        settings.reference_level = std::max(problem.lambda_, 1.0);
        const NewtonResult r = solve_increment(problem, constraint, settings, solver);
        REQUIRE(r.converged());
        over_three += r.iterations > 3;
        problem.law.commit();
        CHECK(problem.lambda_ <= Mp * (1.0 + 1e-4));
    }
    CHECK(over_three <= 2); // the steps where the end yields or reaches capacity
    CHECK(problem.law.hinge(1).state == HingeState::plastic);
    CHECK(problem.lambda_ == Approx(Mp).epsilon(1e-4));
}

TEST_CASE("The path extrapolation reproduces a quadratic path exactly and keeps distinct parameters", "[newton]") {
    // u(s) = (s², 3s − 1), λ(s) = 2s² + 1, N(s) = (1 − s², 5s) through s = 0, 1, 3: the predictor
    // at 4.5 is exact.
    const auto u = [](double s) { return Eigen::Vector2d(s * s, 3.0 * s - 1.0); };
    const auto lambda = [](double s) { return 2.0 * s * s + 1.0; };
    const auto axial = [](double s) { return Eigen::Vector2d(1.0 - s * s, 5.0 * s); };
    PathExtrapolation path;
    for (double s : {0.0, 1.0}) path.add(s, u(s), lambda(s), axial(s));
    CHECK_FALSE(path.ready());
    path.add(1.0, u(1.0), lambda(1.0), axial(1.0)); // the same parameter again replaces the point there
    CHECK_FALSE(path.ready());
    path.add(3.0, u(3.0), lambda(3.0), axial(3.0));
    REQUIRE(path.ready());
    const PathPoint p = path.at(4.5);
    CHECK((p.displacement - u(4.5)).norm() <= 1e-12 * u(4.5).norm());
    CHECK(p.load_factor == Approx(lambda(4.5)).epsilon(1e-14));
    CHECK((p.axial_forces - axial(4.5)).norm() <= 1e-12 * axial(4.5).norm());
    // A fourth point drops the oldest: through s = 1, 3, 4 it stays exact.
    path.add(4.0, u(4.0), lambda(4.0), axial(4.0));
    CHECK(path.at(6.0).load_factor == Approx(lambda(6.0)).epsilon(1e-14));
}
