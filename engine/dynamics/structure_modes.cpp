#include "dynamics/structure_modes.hpp"

#include "dynamics/mass_matrix.hpp"
#include "dynamics/modal_analysis.hpp"

#include <cmath>
#include <limits>

namespace plastica {

ModalResult structure_modes(StructuralSystem& system, const Model& model, const Eigen::VectorXd& u, int count) {
    std::vector<int> equation(static_cast<std::size_t>(system.dof_count()));
    for (int d = 0; d < system.dof_count(); ++d) equation[static_cast<std::size_t>(d)] = system.equation(d);
    const MassMatrix mass(model, model.dynamics.mass, equation, system.free_count());
    if (mass.total_mass() <= 0.0)
        throw ModalError("the structure has no mass: give its material a 'density' or add [[mass]]");
    const SparseMatrix M = mass.assemble(u);
    const NaturalModes found = lowest_modes(system.tangent(), M, count);
    const Eigen::VectorXd rx = mass.influence(u, 0), ry = mass.influence(u, 1);
    ModalResult out;
    // r_fᵀ M r over the free DOFs: the translation's mass the free DOFs carry.
    Eigen::VectorXd unit_x = Eigen::VectorXd::Zero(u.size()), unit_y = unit_x;
    for (Eigen::Index d = 0; d < u.size(); d += dofs_per_node) unit_x[d] = 1.0, unit_y[d + 1] = 1.0;
    out.mass_x = system.gather(unit_x).dot(rx);
    out.mass_y = system.gather(unit_y).dot(ry);
    constexpr double two_pi = 6.28318530717958647692;
    for (std::size_t k = 0; k < found.omega_squared.size(); ++k) {
        ModeRow row;
        row.mode = static_cast<int>(k) + 1;
        row.omega = std::sqrt(std::max(0.0, found.omega_squared[k]));
        row.frequency = row.omega / two_pi;
        row.period = row.omega > 0.0 ? 1.0 / row.frequency : std::numeric_limits<double>::infinity();
        const Eigen::VectorXd phi = found.shapes.col(static_cast<Eigen::Index>(k));
        row.effective_mass_x = std::pow(phi.dot(rx), 2);
        row.effective_mass_y = std::pow(phi.dot(ry), 2);
        Eigen::VectorXd full = Eigen::VectorXd::Zero(u.size());
        system.scatter(phi, full);
        row.shape.assign(full.data(), full.data() + full.size());
        out.modes.push_back(std::move(row));
    }
    return out;
}

} // namespace plastica
