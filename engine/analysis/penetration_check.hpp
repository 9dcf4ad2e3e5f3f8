// Detects a deformed structure that has passed through itself (two element chords that cross,
// or a half model crossing its symmetry line) or through the rigid base at a node the base
// does not hold. Contact between members is not modelled, so such a state is not physical.
#pragma once

#include "load/pattern_factors.hpp"
#include "model/model.hpp"

#include <Eigen/Dense>
#include <string>

namespace plastica {

// Empty, or the first element whose chord is shorter than half its length or longer than three
// times it: beyond any beam's reach (an element crushed through itself). Empty in first order.
std::string element_beyond_reach(const Model& model, const Eigen::VectorXd& u);

// Empty when the state is admissible; otherwise says what crossed what, and where. Moving bases
// stand where the pattern factors put them at λ = load_factor (the first stage's when none given).
std::string find_penetration(const Model& model, const Eigen::VectorXd& u, double load_factor,
                             const PatternFactors* factors = nullptr);

} // namespace plastica
