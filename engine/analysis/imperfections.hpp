// Imperfections in the shape of buckling modes (EN 1993-1-1 §5.3.2(11) allows the first mode as
// the equivalent geometric imperfection): the linear buckling modes of each imperfection's
// pattern on the perfect geometry (analysis/linear_buckling.hpp), scaled to a largest nodal
// translation of `amplitude` and added to the nodes' coordinates. Several add up, each taken
// from the perfect geometry.
#pragma once

#include "model/model.hpp"

#include <stdexcept>
#include <string>

namespace plastica {

// Which imperfection (its index in model.imperfections) could not be made, and why.
class ImperfectionError : public std::runtime_error {
public:
    ImperfectionError(std::size_t index, const std::string& why) : std::runtime_error(why), index_(index) {}
    std::size_t index() const { return index_; }

private:
    std::size_t index_;
};

// Moves model.nodes by model.imperfections (and notes each mode's critical factor in it).
void add_imperfections(Model& model);

} // namespace plastica
