// The robustness matrix's crushing cases (study/crushing_cases.cpp).
#pragma once

#include "stability_cases.hpp"

#include <vector>

namespace plastica {

// Appends the crushed rings and the flattened pipes, each to complete to its target.
void append_crushing_cases(std::vector<StabilityCase>& cases);

} // namespace plastica
