// Pressure normal to the deformed members (a follower load): each element's chord carries p per
// unit current length along its left normal (toward the centre of a counter-clockwise arc, so
// p > 0 on a ring is external pressure), lumped half to each end. On a closed contour the nodal
// forces are the gradient of p times the enclosed area, a conservative load whose stiffness is
// symmetric; the skew part each element adds cancels between neighbours. At the free ends of an
// open member it does not, and only the symmetric part is kept there (Newton then converges
// linearly at those nodes; the equilibrium it reaches is the exact one).
#pragma once

#include "model/model.hpp"

#include <Eigen/Dense>
#include <vector>

namespace plastica {

class FollowerPressure {
public:
    explicit FollowerPressure(const Model& model);

    bool empty() const { return loaded_.empty(); }
    // Nodal forces per unit load factor at displacements u (full vector, 3 per node).
    void add_forces(const Eigen::VectorXd& u, Eigen::VectorXd& force) const;
    // −∂(λ·forces)/∂u of element e's chord (the load stiffness), symmetric part, in the
    // element's DOF order [u_i v_i θ_i u_j v_j θ_j]; zero for an element without pressure.
    Eigen::Matrix<double, 6, 6> stiffness(std::size_t element, double load_factor) const;
    double pressure(std::size_t element) const { return pressure_[element]; }

private:
    std::vector<ElementSpec> elements_;
    std::vector<Node> nodes_;
    std::vector<double> pressure_;  // per element, reference value
    std::vector<std::size_t> loaded_; // elements with p ≠ 0
};

} // namespace plastica
