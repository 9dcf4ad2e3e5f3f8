#include "analysis/linear_buckling.hpp"

#include "solver/linear_solver.hpp"

#include <cmath>

namespace plastica {

void scale_to_unit_translation(std::vector<double>& shape) {
    double largest = 0.0, sign = 1.0;
    for (std::size_t d = 0; d + 1 < shape.size(); d += dofs_per_node) {
        const double t = std::hypot(shape[d], shape[d + 1]);
        if (t > largest) {
            largest = t;
            sign = std::abs(shape[d]) >= std::abs(shape[d + 1]) ? (shape[d] < 0.0 ? -1.0 : 1.0) : (shape[d + 1] < 0.0 ? -1.0 : 1.0);
        }
    }
    if (largest == 0.0) return;
    for (double& v : shape) v *= sign / largest;
}

BucklingResult linear_buckling(const StructuralSystem& system, const Eigen::VectorXd& ubar, double load_factor, int count,
                               bool cubic) {
    const SparseMatrix& K = system.tangent();
    LinearSolver solver;
    if (!solver.factorize(K)) throw BucklingError("the tangent is singular: the structure is a mechanism at this state");
    const Eigen::VectorXd f = system.gather(system.load()) - system.coupling();
    if (f.norm() == 0.0) throw BucklingError("the stage drives no load: give its pattern loads, a pressure or a prescribed motion");
    Eigen::VectorXd rate = ubar; // the prescribed DOFs move at their rate
    system.scatter(solver.solve(f), rate);
    const Eigen::VectorXd axial_rates = system.axial_force_rates(rate);
    const SparseMatrix B = -system.geometric_stiffness(axial_rates, cubic);
    const BucklingEigenpairs found = lowest_buckling_factors(K, B, count);
    BucklingResult out;
    out.state_load_factor = load_factor;
    out.tangent_indefinite = found.tangent_indefinite;
    for (std::size_t k = 0; k < found.factors.size(); ++k) {
        BucklingMode m;
        m.mode = static_cast<int>(k) + 1;
        m.above_state = found.factors[k];
        m.load_factor = load_factor + m.above_state;
        Eigen::VectorXd full = Eigen::VectorXd::Zero(rate.size());
        system.scatter(found.shapes.col(static_cast<Eigen::Index>(k)), full);
        m.shape.assign(full.data(), full.data() + full.size());
        scale_to_unit_translation(m.shape);
        out.modes.push_back(std::move(m));
    }
    return out;
}

} // namespace plastica
