// The factors of the load patterns at a point of the path. The current stage drives one
// pattern, whose factor is the path's unknown λ; every other pattern keeps the factor its last
// stage left it at (OpenSees' loadConst). So each load, pressure, prescribed displacement and
// moving base enters as (constant + rate·λ) times its reference value.
#pragma once

#include "model/model.hpp"

#include <vector>

namespace plastica {

struct PatternFactors {
    int driven = 0;
    std::vector<double> held; // per pattern; the driven pattern's entry is not used

    PatternFactors() = default;
    explicit PatternFactors(std::size_t patterns) : held(patterns, 0.0) {}

    double constant(int pattern) const { return pattern == driven ? 0.0 : held[static_cast<std::size_t>(pattern)]; }
    double rate(int pattern) const { return pattern == driven ? 1.0 : 0.0; }
    double at(int pattern, double lambda) const { return constant(pattern) + rate(pattern) * lambda; }
};

// A base line as the stage sees it: moved to where its held factor put it, and moving on with
// λ only if its pattern is driven (BaseLine::gap at λ is then the true gap).
inline BaseLine base_in_stage(const BaseLine& base, const PatternFactors& factors) {
    BaseLine b = base;
    const double c = factors.constant(base.pattern), r = factors.rate(base.pattern);
    b.point = {base.point[0] + c * base.motion[0], base.point[1] + c * base.motion[1]};
    b.motion = {r * base.motion[0], r * base.motion[1]};
    return b;
}

} // namespace plastica
