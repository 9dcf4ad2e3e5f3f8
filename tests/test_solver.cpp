// Path-following solver properties: quadratic convergence of Newton near the solution, and
// stops with the last converged state kept.
#include "analysis_helpers.hpp"

#include "solver/bandwidth_order.hpp"
#include "solver/block_profile_ldlt.hpp"
#include "solver/linear_solver.hpp"
#include "solver/sparse_ldlt.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <catch2/catch.hpp>
#include <random>

using namespace plastica;
using namespace plastica::testing;

TEST_CASE("Newton converges quadratically near a solution", "[solver]") {
    // One load step to PL²/EI = 1 on a 10-element elastica: several iterations to watch.
    const Run r = run_scene(cantilever(1.0, 10, 1.0, 1e2, 1.0, "[[load]]\nat = [1.0, 0.0]\nfy = -1.0\n",
                                       "scheme = \"load_control\"\nincrement = 1.0\ntarget_load_factor = 1.0\n"
                                       "residual_tolerance = 1e-10\ndisplacement_tolerance = 1e-12\nmax_iterations = 40\n"));
    REQUIRE(r.summary.status == RunStatus::completed);
    std::vector<double> res;
    for (const IterationTrace& t : r.trace) res.push_back(t.residual);
    INFO("residuals: " << Catch::Detail::stringify(res));
    // In the tail (residual between 1e-2 and 1e-5, next one above the round-off floor; EA·L²/EI = 100
    // keeps the constant of the quadratic rate modest) each iteration squares the residual, up to a modest constant.
    int quadratic_pairs = 0;
    for (std::size_t k = 2; k < res.size(); ++k) {
        if (res[k - 1] < 1e-2 && res[k - 1] > 1e-5 && res[k] > 1e-9) {
            CHECK(res[k] < 10.0 * res[k - 1] * res[k - 1]);
            ++quadratic_pairs;
        }
    }
    CHECK(quadratic_pairs >= 1);
}

TEST_CASE("A load beyond a softening mechanism stops with 'limit load reached' and keeps the converged steps", "[solver][plasticity]") {
    // A clamped column, axial load P and lateral load 0.1 P: the base hinge forms near
    // 0.1·P·L = Mp, then P-Δ makes the sway mechanism soften, so load control cannot go on.
    // fy/E = 1.25e-6 keeps the first-order collapse load 10 Mp/L = 2500 a close upper bound.
    const std::string scene = R"(
[scene]
name = "collapse"
[[material]]
name = "steel"
E = 2.0e8
fy = 250.0
[[section]]
name = "s"
material = "steel"
shape = "rectangle"
b = 10.0
h = 20.0
fibres = 10
[[line]]
start = [0.0, 0.0]
end = [0.0, 1000.0]
elements = 8
section = "s"
[[support]]
at = [0.0, 0.0]
fix = ["ux", "uy", "rz"]
[[load]]
at = [0.0, 1000.0]
fy = -1000.0
fx = 100.0
[analysis]
scheme = "load_control"
increment = 0.1
target_load_factor = 4.0
)";
    const Run r = run_scene(scene);
    CHECK(r.summary.status == RunStatus::limit_load);
    CHECK_THAT(r.summary.reason, Catch::Contains("limit load reached"));
    REQUIRE(r.steps.size() > 1);
    for (const StepResult& s : r.steps) CHECK(std::isfinite(s.load));
    const double collapse = 2.5; // λ at 0.1·P·L = Mp
    CHECK(r.steps.back().load_factor <= collapse);
    CHECK(r.steps.back().load_factor >= 0.97 * collapse);
}

// Stop reasons that are true at any scale: a mechanism only where the supports leave a rigid
// motion free, never because stiffnesses differ by many orders; round-off named as the cause
// where it sets the floor.
namespace {

std::string mechanism_of(const std::string& toml) {
    const Model m = read_scene_text(toml, "scale.toml");
    PathFollowing analysis(m);
    return analysis.initial_mechanism();
}

const char* small_load_steps = "scheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 1.0\nresidual_tolerance = 1e-8\n";

} // namespace

TEST_CASE("A spring of 1e300 acts as a support, not as a mechanism", "[solver][scale]") {
    // The tip held along x by a spring of 1e300, or by a support: the same run.
    const std::string load = "[[load]]\nat = [1.0, 0.0]\nfy = -1.0\n";
    const std::string sprung = cantilever(1.0, 10, 1.0, 1e2, 1.0, load + "[[foundation]]\nkind = \"bilateral\"\nat = [[1.0, 0.0]]\nkx = 1e300\n", small_load_steps);
    const std::string held = cantilever(1.0, 10, 1.0, 1e2, 1.0, load + "[[support]]\nat = [1.0, 0.0]\nfix = [\"ux\"]\n", small_load_steps);
    CHECK(mechanism_of(sprung).empty());
    const Run a = run_scene(sprung), b = run_scene(held);
    REQUIRE(a.summary.status == RunStatus::completed);
    REQUIRE(b.summary.status == RunStatus::completed);
    const double wa = a.node_dof(a.steps.back(), 1.0, 0.0, 1), wb = b.node_dof(b.steps.back(), 1.0, 0.0, 1);
    CHECK(wa == Approx(wb).epsilon(1e-9));
    CHECK(std::abs(wb) > 0.1); // PL²/EI = 1 against a held tip: a real deflection
}

TEST_CASE("A section with EA·L²/EI = 1e12 is no mechanism and bends as a beam", "[solver][scale]") {
    // PL²/EI = 1e-3: the tip deflection is PL³/3EI to 1e-6 of geometric nonlinearity. The
    // membrane's round-off floor is about 4e-6 of the load here, so the tolerance sits above it.
    const std::string toml = cantilever(1.0, 20, 1.0, 1e12, 1.0, "[[load]]\nat = [1.0, 0.0]\nfy = -1.0e-3\n",
                                        "scheme = \"load_control\"\nincrement = 0.5\ntarget_load_factor = 1.0\nresidual_tolerance = 1e-4\n");
    CHECK(mechanism_of(toml).empty());
    const Run r = run_scene(toml);
    REQUIRE(r.summary.status == RunStatus::completed);
    CHECK(-r.node_dof(r.steps.back(), 1.0, 0.0, 1) == Approx(1e-3 / 3.0).epsilon(1e-4));
}

TEST_CASE("Mechanism or double precision: the supports decide what the message says", "[solver][scale]") {
    const std::string load = "[[load]]\nat = [1.0, 0.0]\nfy = -1.0\n";
    // A roller where the clamp was: free to slide along x.
    std::string roller = cantilever(1.0, 4, 1.0, 1e2, 1.0, load, small_load_steps);
    roller.replace(roller.find("fix = [\"ux\", \"uy\", \"rz\"]"), 24, "fix = [\"uy\", \"rz\"]");
    const std::string free = mechanism_of(roller);
    CHECK_THAT(free, Catch::Contains("mechanism before loading"));
    CHECK_THAT(free, Catch::Contains("a translation along [1, 0]"));
    // A cantilever 1e300 long: its bending stiffness underflows, though the clamp holds it.
    const std::string far = mechanism_of(cantilever(1e300, 4, 1.0, 1e2, 1.0, "[[load]]\nat = [1e300, 0.0]\nfy = -1.0\n", small_load_steps));
    CHECK_THAT(far, Catch::Contains("singular to double precision"));
    CHECK_THAT(far, !Catch::Contains("mechanism"));
}

TEST_CASE("Round-off that sets a floor above the tolerance is named as the reason, never a limit at load factor 0", "[solver][scale]") {
    // 10 000 elements of 1e-4 with EA·L²/EI = 1e6: element terms 12EI/Le³ = 1.2e13 times the
    // structure's tip stiffness, so rounding the displacements leaves far more than 1e-8 of the
    // load out of balance.
    const Run r = run_scene(cantilever(1.0, 10000, 1.0, 1e6, 1.0, "[[load]]\nat = [1.0, 0.0]\nfy = -10.0\n",
                                       "scheme = \"load_control\"\nincrement = 0.02\ntarget_load_factor = 1.0\nresidual_tolerance = 1e-8\n"));
    CHECK(r.summary.status == RunStatus::no_convergence);
    CHECK_THAT(r.summary.reason, Catch::Contains("round-off alone leaves"));
    CHECK_THAT(r.summary.reason, !Catch::Contains("limit load"));
    // A floor relative to the load does not fall with the increment: after three cuts the run
    // stops (it used to cut twenty times, to the smallest increment, for the same message).
    CHECK_THAT(r.summary.reason, Catch::Contains("no smaller increment can help"));
    CHECK(r.summary.cut_steps == 4);
}

TEST_CASE("The replayed sparse LDLᵀ gives Eigen's SimplicialLDLT to the last bit, and stops at a zero pivot", "[solver][ldlt]") {
    // Random symmetric patterns (a band with scattered couplings, as frames give), definite
    // and indefinite: the pivots and solutions must be bit for bit Eigen's, since the engine's
    // curves are kept equal across this change of solver.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    for (int trial = 0; trial < 20; ++trial) {
        const int n = 20 + 7 * trial;
        std::vector<Eigen::Triplet<double>> entries;
        for (int i = 0; i < n; ++i) {
            // Definite for even trials (dominant diagonal), indefinite for odd ones.
            entries.emplace_back(i, i, trial % 2 == 0 ? 10.0 + value(random) : 3.0 * value(random));
            for (int j : {i + 1, i + 2, i + 5, static_cast<int>(random() % static_cast<unsigned>(n))})
                if (j > i && j < n) {
                    const double v = value(random);
                    entries.emplace_back(j, i, v);
                    entries.emplace_back(i, j, v);
                }
        }
        SparseMatrix full(n, n);
        full.setFromTriplets(entries.begin(), entries.end());
        const SparseMatrix upper = full.triangularView<Eigen::Upper>();
        Eigen::SimplicialLDLT<SparseMatrix, Eigen::Upper, Eigen::NaturalOrdering<int>> eigen;
        eigen.compute(upper);
        REQUIRE(eigen.info() == Eigen::Success);
        SparseLdlt replay;
        replay.analyse(upper);
        // Twice: the second factorisation reuses the first one's storage.
        REQUIRE(replay.factorize(upper));
        REQUIRE(replay.factorize(upper));
        CAPTURE(trial, n);
        CHECK((replay.pivots().array() == eigen.vectorD().array()).all());
        Eigen::VectorXd b(n);
        for (int i = 0; i < n; ++i) b[i] = i % 3 == 0 ? 0.0 : value(random); // zeros: Eigen skips them
        Eigen::VectorXd x = b;
        replay.solve_in_place(x);
        const Eigen::VectorXd expected = eigen.solve(b);
        CHECK((x.array() == expected.array()).all());
        CHECK((full * x - b).norm() <= 1e-8 * b.norm() * (1.0 + full.norm()));
        // Two right-hand sides in one pass, zeros in different places: each as solved alone.
        Eigen::VectorXd c(n);
        for (int i = 0; i < n; ++i) c[i] = i % 4 == 1 ? 0.0 : value(random);
        Eigen::VectorXd x2 = b, y2 = c, y = c;
        replay.solve_in_place(x2, y2);
        replay.solve_in_place(y);
        CHECK((x2.array() == x.array()).all());
        CHECK((y2.array() == y.array()).all());
    }
    // [[1, 1], [1, 1]]: the second pivot is exactly zero.
    SparseMatrix singular(2, 2);
    singular.insert(0, 0) = 1.0;
    singular.insert(0, 1) = 1.0;
    singular.insert(1, 1) = 1.0;
    singular.makeCompressed();
    SparseLdlt replay;
    replay.analyse(singular);
    CHECK_FALSE(replay.factorize(singular));
    CHECK(replay.pivots()[1] == 0.0);
}

namespace {
// A symmetric matrix of nodes with 1 to 3 DOFs each (a fixed DOF leaves fewer), coupled along
// a chain, or as a grid of `width` nodes per row, with random values: each pair of coupled
// nodes gets a full block, as members give. Definite with a dominant diagonal, else indefinite.
SparseMatrix node_matrix(int nodes, int width, bool definite, std::mt19937& random) {
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    std::vector<int> first(static_cast<std::size_t>(nodes) + 1, 0);
    for (int a = 0; a < nodes; ++a) first[static_cast<std::size_t>(a) + 1] = first[static_cast<std::size_t>(a)] + 1 + static_cast<int>(random() % 3);
    const int n = first.back();
    std::vector<Eigen::Triplet<double>> entries;
    auto couple = [&](int a, int b) {
        for (int i = first[static_cast<std::size_t>(a)]; i < first[static_cast<std::size_t>(a) + 1]; ++i)
            for (int j = first[static_cast<std::size_t>(b)]; j < first[static_cast<std::size_t>(b) + 1]; ++j) {
                if (a == b && j < i) continue;
                const double v = a == b && i == j ? (definite ? 20.0 + value(random) : 4.0 * value(random)) : value(random);
                entries.emplace_back(i, j, v);
                if (i != j) entries.emplace_back(j, i, v);
            }
    };
    for (int a = 0; a < nodes; ++a) {
        couple(a, a);
        if (a + 1 < nodes && (width == 0 || (a + 1) % width != 0)) couple(a, a + 1);
        if (width > 0 && a + width < nodes) couple(a, a + width);
    }
    SparseMatrix K(n, n);
    K.setFromTriplets(entries.begin(), entries.end());
    K.makeCompressed();
    return K;
}

int negative_eigenvalues(const SparseMatrix& K) {
    const Eigen::MatrixXd dense(K);
    const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense).eigenvalues();
    return static_cast<int>((eigenvalues.array() < 0.0).count());
}
} // namespace

TEST_CASE("Reverse Cuthill-McKee puts a shuffled chain back in a line and a grid in a band", "[solver][order]") {
    std::mt19937 random(3);
    const int n = 60;
    std::vector<int> label(n);
    for (int i = 0; i < n; ++i) label[static_cast<std::size_t>(i)] = i;
    std::shuffle(label.begin(), label.end(), random);
    auto bandwidth = [](const SparseMatrix& K, const std::vector<int>& order) {
        std::vector<int> position(order.size());
        for (std::size_t p = 0; p < order.size(); ++p) position[static_cast<std::size_t>(order[p])] = static_cast<int>(p);
        int width = 0;
        for (int col = 0; col < K.outerSize(); ++col)
            for (SparseMatrix::InnerIterator it(K, col); it; ++it)
                width = std::max(width, std::abs(position[static_cast<std::size_t>(it.row())] - position[static_cast<std::size_t>(col)]));
        return width;
    };
    std::vector<Eigen::Triplet<double>> chain;
    for (int i = 0; i < n; ++i) {
        chain.emplace_back(label[static_cast<std::size_t>(i)], label[static_cast<std::size_t>(i)], 1.0);
        if (i + 1 < n) {
            chain.emplace_back(label[static_cast<std::size_t>(i)], label[static_cast<std::size_t>(i) + 1], 1.0);
            chain.emplace_back(label[static_cast<std::size_t>(i) + 1], label[static_cast<std::size_t>(i)], 1.0);
        }
    }
    SparseMatrix K(n, n);
    K.setFromTriplets(chain.begin(), chain.end());
    const std::vector<int> order = reverse_cuthill_mckee(K);
    CHECK(bandwidth(K, order) == 1);
    std::vector<int> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (int i = 0; i < n; ++i) CHECK(sorted[static_cast<std::size_t>(i)] == i); // a permutation
    // A 6 × 10 grid of single equations: the band of a row of the grid's short side.
    std::vector<Eigen::Triplet<double>> grid;
    for (int i = 0; i < n; ++i) {
        const int a = label[static_cast<std::size_t>(i)];
        grid.emplace_back(a, a, 1.0);
        for (int j : {i + 1, i + 6})
            if (j < n && (j != i + 1 || j % 6 != 0)) {
                grid.emplace_back(a, label[static_cast<std::size_t>(j)], 1.0);
                grid.emplace_back(label[static_cast<std::size_t>(j)], a, 1.0);
            }
    }
    SparseMatrix G(n, n);
    G.setFromTriplets(grid.begin(), grid.end());
    CHECK(bandwidth(G, reverse_cuthill_mckee(G)) <= 7);
}

TEST_CASE("The node-block LDLᵀ solves, counts negative eigenvalues and stops at a zero pivot", "[solver][ldlt]") {
    std::mt19937 random(11);
    for (int trial = 0; trial < 16; ++trial) {
        const bool definite = trial % 2 == 0;
        const SparseMatrix K = node_matrix(10 + 5 * trial, trial % 4 < 2 ? 0 : 3, definite, random);
        CAPTURE(trial, K.rows());
        BlockProfileLdlt blocks;
        REQUIRE(blocks.analyse(K, 3.0));
        // Twice: the second factorisation starts from the first one's storage.
        REQUIRE(blocks.factorize(K));
        REQUIRE(blocks.factorize(K));
        Eigen::VectorXd b = Eigen::VectorXd::Random(K.rows()), c = Eigen::VectorXd::Random(K.rows());
        Eigen::VectorXd x, y;
        blocks.solve(b, c, x, y);
        const double scale = Eigen::MatrixXd(K).norm();
        CHECK((K * x - b).norm() <= 1e-10 * scale * x.norm());
        CHECK((K * y - c).norm() <= 1e-10 * scale * y.norm());
        // Sylvester: the pivots' signs are the eigenvalues' signs.
        const std::vector<double>& D = blocks.pivots();
        CHECK(static_cast<int>(std::count_if(D.begin(), D.end(), [](double d) { return d < 0.0; })) == negative_eigenvalues(K));
        // Every equation has exactly one pivot.
        std::vector<int> equations = blocks.pivot_equations();
        std::sort(equations.begin(), equations.end());
        for (int i = 0; i < K.rows(); ++i) CHECK(equations[static_cast<std::size_t>(i)] == i);
    }
    // A wide grid (30 nodes a row) is left to the general sparse factorisation.
    const SparseMatrix wide = node_matrix(600, 30, true, random);
    BlockProfileLdlt blocks;
    CHECK_FALSE(blocks.analyse(wide, 3.0));
    // [[1, 1], [1, 1]]: the second pivot is exactly zero.
    SparseMatrix singular(2, 2);
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) singular.insert(i, j) = 1.0;
    singular.makeCompressed();
    REQUIRE(blocks.analyse(singular, 3.0));
    CHECK_FALSE(blocks.factorize(singular));
}

TEST_CASE("The linear solver chooses node blocks for a chain and sparse LDLᵀ for a wide grid, with the same answers", "[solver][ldlt]") {
    std::mt19937 random(5);
    for (int width : {0, 30}) {
        const SparseMatrix K = node_matrix(width == 0 ? 200 : 600, width, false, random);
        LinearSolver solver;
        REQUIRE(solver.factorize(K));
        CHECK(solver.uses_node_blocks() == (width == 0));
        const Eigen::VectorXd b = Eigen::VectorXd::Random(K.rows());
        const Eigen::VectorXd x = solver.solve(b);
        CHECK((K * x - b).norm() <= 1e-9 * Eigen::MatrixXd(K).norm() * x.norm());
        CHECK(solver.negative_pivots() == negative_eigenvalues(K));
    }
}
