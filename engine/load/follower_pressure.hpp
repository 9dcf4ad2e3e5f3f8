// Pressure normal to the deformed members (a follower load): each element's chord carries p per
// unit current length along its left normal (toward the centre of a counter-clockwise arc, so
// p > 0 on a ring is external pressure), lumped half to each end. On a closed contour the nodal
// forces are the gradient of p times the enclosed area, a conservative load whose stiffness is
// symmetric; the skew part each element adds cancels between neighbours. At the free ends of an
// open member it does not, and only the symmetric part is kept there (Newton then converges
// linearly at those nodes; the equilibrium it reaches is the exact one).
#pragma once

#include "load/pattern_factors.hpp"
#include "model/model.hpp"

#include <Eigen/Dense>
#include <vector>

namespace plastica {

class FollowerPressure {
public:
    explicit FollowerPressure(const Model& model);

    bool empty() const { return loaded_.empty(); }
    // False at first order (Geometry::first_order): the pressure then acts on the initial chords.
    bool follows_deformation() const { return follows_ && !empty(); }
    // Nodal forces per unit load factor of the driven pattern at displacements u (full vector,
    // 3 per node).
    void add_forces(const Eigen::VectorXd& u, Eigen::VectorXd& force) const { add_forces(u, pressure_, force); }
    // The held patterns' nodal forces at u (constant factors, PatternFactors).
    void add_held_forces(const Eigen::VectorXd& u, Eigen::VectorXd& force) const { add_forces(u, held_, force); }
    // −∂(forces at λ)/∂u of element e's chord (the load stiffness), symmetric part, in the
    // element's DOF order [u_i v_i θ_i u_j v_j θ_j]; zero for an element without pressure.
    Eigen::Matrix<double, 6, 6> stiffness(std::size_t element, double load_factor) const;
    bool loads(std::size_t element) const { return pressure_[element] != 0.0 || held_[element] != 0.0; }

    // A new stage: the driven pattern's pressures scale with λ, the others are held.
    void set_pattern_factors(const PatternFactors& factors);

private:
    void add_forces(const Eigen::VectorXd& u, const std::vector<double>& pressure, Eigen::VectorXd& force) const;

    std::vector<ElementPressure> reference_;
    bool follows_;
    std::vector<ElementSpec> elements_;
    std::vector<Node> nodes_;
    std::vector<double> pressure_;    // per element, the driven pattern's reference value
    std::vector<double> held_;        // per element, the held patterns' pressure
    std::vector<std::size_t> loaded_; // elements with a pressure in any pattern
};

} // namespace plastica
