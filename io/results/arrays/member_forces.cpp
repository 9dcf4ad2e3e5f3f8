// The members' forces: N, the end moments and the shear per element (local), the same as global
// end forces, the nodes' bending moment, and which member ends are released.
#include "arrays/output_array.hpp"

#include <cmath>

namespace plastica {

namespace {

using namespace result;

void fill_member_forces(const StepView& v, XmlDataset& out) {
    const Model& m = v.model;
    const std::size_t n = m.nodes.size(), ne = m.elements.size();
    // Nodal bending moment: the mean of the element-end moments meeting at the node.
    XmlArray moment = real_array(name::bending_moment, n);
    std::vector<int> count(n, 0);
    XmlArray axial = real_array(name::axial_force, ne), mi = real_array(name::moment_i, ne), mj = real_array(name::moment_j, ne),
             shear = real_array(name::shear, ne), global = real_array(name::end_forces, ne, 6);
    const bool moves = m.analysis.geometry != Geometry::first_order; // first order: equilibrium on the initial chords
    const std::vector<double>& u = v.result.displacement;
    for (std::size_t e = 0; e < ne; ++e) {
        const BeamForces& f = v.result.elements[e].forces;
        real(axial)[e] = f.axial;
        real(mi)[e] = f.moment_i;
        real(mj)[e] = f.moment_j;
        real(shear)[e] = f.shear;
        // What the nodes exert on the element, f = Bᵀq (corotational_beam.hpp) with q = (N, −M_i,
        // M_j): along the chord (c, s), N pulls the ends apart and V = (M_j − M_i)/L turns them.
        const ElementSpec& ends = m.elements[e];
        const int a = 3 * ends.node_i, b = 3 * ends.node_j;
        const double dx = m.nodes[ends.node_j].x - m.nodes[ends.node_i].x + (moves ? u[b] - u[a] : 0.0);
        const double dy = m.nodes[ends.node_j].y - m.nodes[ends.node_i].y + (moves ? u[b + 1] - u[a + 1] : 0.0);
        const double L = std::hypot(dx, dy), c = dx / L, s = dy / L;
        double* g = &real(global)[6 * e];
        g[0] = -c * f.axial - s * f.shear, g[1] = -s * f.axial + c * f.shear, g[2] = -f.moment_i;
        g[3] = -g[0], g[4] = -g[1], g[5] = f.moment_j;
        // A released end carries no moment: the node's moment is its other members'.
        const ElementSpec& spec = m.elements[e];
        if (!spec.released[0]) real(moment)[spec.node_i] += f.moment_i, ++count[spec.node_i];
        if (!spec.released[1]) real(moment)[spec.node_j] += f.moment_j, ++count[spec.node_j];
    }
    for (std::size_t i = 0; i < n; ++i)
        if (count[i] > 0) real(moment)[i] /= count[i];
    out.point_data.push_back(std::move(moment));
    out.cell_data.push_back(std::move(axial));
    out.cell_data.push_back(std::move(mi));
    out.cell_data.push_back(std::move(mj));
    out.cell_data.push_back(std::move(shear));
    out.cell_data.push_back(std::move(global));
    if (v.has(name::released)) {
        XmlArray released = integer_array(name::released, ne);
        for (std::size_t e = 0; e < ne; ++e)
            integer(released)[e] = (m.elements[e].released[0] ? 1 : 0) + (m.elements[e].released[1] ? 2 : 0);
        out.cell_data.push_back(std::move(released));
    }
}

} // namespace

OutputGroup member_force_arrays() {
    return {{
                {name::bending_moment, Where::point, Type::float64, 1, Quantity::moment, When::always, "mean of the element-end moments at the node"},
                {name::axial_force, Where::cell, Type::float64, 1, Quantity::force, When::always, "N, positive in tension"},
                {name::moment_i, Where::cell, Type::float64, 1, Quantity::moment, When::always, "bending moment EI·dθ/ds at the first node"},
                {name::moment_j, Where::cell, Type::float64, 1, Quantity::moment, When::always, "bending moment at the second node"},
                {name::shear, Where::cell, Type::float64, 1, Quantity::force, When::always, "(moment_j − moment_i)/L, the reported end moments over the current length"},
                {name::end_forces, Where::cell, Type::float64, 6, Quantity::force, When::always,
                 "global end forces: Fx, Fy, M at the first node, then at the second, that the nodes exert on the element "
                 "(the element's pull on the nodes is their opposite); Fx, Fy from axial_force along the current chord and "
                 "shear across it, M = −moment_i and moment_j (moments counter-clockwise positive; M in force·length)"},
                {name::released, Where::cell, Type::int32, 1, Quantity::none, When::releases, "moment releases: 1 at the first node, 2 at the second, 3 at both"},
            },
            fill_member_forces};
}

} // namespace plastica
