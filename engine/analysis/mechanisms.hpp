// Where a structure can move without resisting, in words, for a run's first message or its
// stop: before loading (a missing support, member-end releases that leave a mechanism, or
// stiffnesses beyond a double's digits), and where contact with a base that held it is lost.
#pragma once

#include "analysis/structural_system.hpp"
#include "model/model.hpp"
#include "solver/linear_solver.hpp"

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace plastica {

// Empty when the structure at u is stable; otherwise names the DOF that is free and why. The
// system is evaluated there and reverted.
std::string unloaded_mechanism(const Model& model, StructuralSystem& system, LinearSolver& solver,
                               const Eigen::VectorXd& u, const Eigen::VectorXd& ubar, double load_factor);
// Where the tangent is singular although the supports hold every rigid motion: the mechanism
// the member-end releases leave, if holding them makes it stable; else empty.
std::string release_mechanism(const Model& model, const Eigen::VectorXd& u, const Eigen::VectorXd& ubar,
                              double load_factor);
// Per foundation spring: a unilateral one touching its base at the last evaluation.
std::vector<bool> touching_bases(const StructuralSystem& system);
// Where the last evaluation left a base that touched before (touching_before) and that frees a
// rigid motion: the contact lost and the motion, in words; else empty.
std::string lost_contact_mechanism(const Model& model, const StructuralSystem& system,
                                   const std::vector<bool>& touching_before);
// The same where the failed iterate does not show it: a small step along the load's response
// from the converged state (the system is left there: revert after).
std::string probe_lost_contact(const Model& model, StructuralSystem& system, LinearSolver& solver,
                               const std::vector<bool>& touching_before, const Eigen::VectorXd& u_converged,
                               const Eigen::VectorXd& ubar, double lambda_converged);

} // namespace plastica
