// base.vtp: what holds the structure from outside, written once per series. Bilateral
// springs' anchors as vertices, each rigid base as a line long enough for a structure that
// spreads over it, with a moving base's travel and load pattern.
#pragma once

#include "arrays/output_array.hpp"

namespace plastica {

// The dataset of base.vtp (empty points when the scene has no springs or bases); `present`
// names the schema's arrays the scene writes.
XmlDataset base_lines_dataset(const Model& model, const std::set<std::string>& present);

} // namespace plastica
