#include "dynamics/mass_matrix.hpp"

#include <cmath>

namespace plastica {

MassMatrix::MassMatrix(const Model& model, MassKind kind, std::vector<int> equation, int free_count)
    : kind_(kind), equation_(std::move(equation)), free_count_(free_count), nodal_(model.dynamics.masses) {
    for (const ElementSpec& e : model.elements) {
        const Node& a = model.nodes[static_cast<std::size_t>(e.node_i)];
        const Node& b = model.nodes[static_cast<std::size_t>(e.node_j)];
        const SectionSpec& s = model.sections[static_cast<std::size_t>(e.section)];
        Member m{e.node_i, e.node_j, b.x - a.x, b.y - a.y, std::hypot(b.x - a.x, b.y - a.y), s.mass_per_length,
                 s.rotary_inertia_per_length};
        if (m.mass_per_length == 0.0 && m.rotary_per_length == 0.0) continue;
        total_mass_ += m.mass_per_length * m.length;
        members_.push_back(m);
    }
    for (const NodalMass& n : nodal_) total_mass_ += n.mass;
}

MassMatrix::Matrix6 MassMatrix::element_matrix(const Member& m, const Eigen::VectorXd& u) const {
    const double L = m.length, mA = m.mass_per_length * L;
    Matrix6 local = Matrix6::Zero();
    if (kind_ == MassKind::lumped) {
        for (int k : {0, 1, 3, 4}) local(k, k) = 0.5 * mA;
        local(2, 2) = local(5, 5) = 0.5 * m.rotary_per_length * L;
        return local; // diagonal and isotropic: the same in every frame
    }
    // Local DOFs: u1 v1 θ1 u2 v2 θ2 along and across the chord.
    local(0, 0) = local(3, 3) = mA / 3.0;
    local(0, 3) = local(3, 0) = mA / 6.0;
    const int t[4] = {1, 2, 4, 5};
    const double hermite[4][4] = {{156, 22 * L, 54, -13 * L},
                                  {22 * L, 4 * L * L, 13 * L, -3 * L * L},
                                  {54, 13 * L, 156, -22 * L},
                                  {-13 * L, -3 * L * L, -22 * L, 4 * L * L}};
    const double rotary[4][4] = {{36, 3 * L, -36, 3 * L},
                                 {3 * L, 4 * L * L, -3 * L, -L * L},
                                 {-36, -3 * L, 36, -3 * L},
                                 {3 * L, -L * L, -3 * L, 4 * L * L}};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            local(t[r], t[c]) = mA / 420.0 * hermite[r][c] + m.rotary_per_length / (30.0 * L) * rotary[r][c];
    const int i = dofs_per_node * m.node_i, j = dofs_per_node * m.node_j;
    const double dx = m.dx0 + u[j] - u[i], dy = m.dy0 + u[j + 1] - u[i + 1];
    const double chord = std::hypot(dx, dy);
    const double c = dx / chord, s = dy / chord;
    Matrix6 T = Matrix6::Zero(); // global to local
    for (int n : {0, 3}) {
        T(n, n) = c, T(n, n + 1) = s;
        T(n + 1, n) = -s, T(n + 1, n + 1) = c;
        T(n + 2, n + 2) = 1.0;
    }
    return T.transpose() * local * T;
}

SparseMatrix MassMatrix::assemble(const Eigen::VectorXd& u) const {
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(members_.size() * 36 + nodal_.size() * 3);
    for (const Member& m : members_) {
        const Matrix6 me = element_matrix(m, u);
        int eq[6];
        for (int k = 0; k < 3; ++k) {
            eq[k] = equation_[static_cast<std::size_t>(dofs_per_node * m.node_i + k)];
            eq[k + 3] = equation_[static_cast<std::size_t>(dofs_per_node * m.node_j + k)];
        }
        for (int r = 0; r < 6; ++r)
            for (int c = 0; c < 6; ++c)
                if (eq[r] >= 0 && eq[c] >= 0) entries.emplace_back(eq[r], eq[c], me(r, c));
    }
    for (const NodalMass& n : nodal_)
        for (int k = 0; k < 3; ++k) {
            const int eq = equation_[static_cast<std::size_t>(dofs_per_node * n.node + k)];
            const double value = k < 2 ? n.mass : n.rotational;
            if (eq >= 0 && value != 0.0) entries.emplace_back(eq, eq, value);
        }
    SparseMatrix M(free_count_, free_count_);
    M.setFromTriplets(entries.begin(), entries.end());
    return M;
}

Eigen::VectorXd MassMatrix::times(const Eigen::VectorXd& u, const Eigen::VectorXd& v) const {
    Eigen::VectorXd out = Eigen::VectorXd::Zero(v.size());
    for (const Member& m : members_) {
        const Matrix6 me = element_matrix(m, u);
        Eigen::Matrix<double, 6, 1> ve;
        ve << v.segment<3>(dofs_per_node * m.node_i), v.segment<3>(dofs_per_node * m.node_j);
        const Eigen::Matrix<double, 6, 1> pe = me * ve;
        out.segment<3>(dofs_per_node * m.node_i) += pe.head<3>();
        out.segment<3>(dofs_per_node * m.node_j) += pe.tail<3>();
    }
    for (const NodalMass& n : nodal_) {
        const int d = dofs_per_node * n.node;
        out[d] += n.mass * v[d];
        out[d + 1] += n.mass * v[d + 1];
        out[d + 2] += n.rotational * v[d + 2];
    }
    return out;
}

Eigen::VectorXd MassMatrix::influence(const Eigen::VectorXd& u, int direction) const {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(u.size());
    for (Eigen::Index d = direction; d < r.size(); d += dofs_per_node) r[d] = 1.0;
    const Eigen::VectorXd full = times(u, r);
    Eigen::VectorXd out = Eigen::VectorXd::Zero(free_count_);
    for (std::size_t d = 0; d < equation_.size(); ++d)
        if (equation_[d] >= 0) out[equation_[d]] = full[static_cast<Eigen::Index>(d)];
    return out;
}

} // namespace plastica
