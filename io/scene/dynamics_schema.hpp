// The scene's keys for motion in time (io/scene/scene_schema.hpp declares the rest): [[mass]],
// [damping], [[time_series]], [[ground_motion]], [[initial_velocity]], and the transient keys of
// [analysis] and [[stage]].
#pragma once

#include "scene_schema.hpp"

#include <vector>

namespace plastica {

std::vector<TableSpec> dynamics_table_specs();
// scheme = "transient": its step, its duration and its integrator; first: [analysis]'s (which
// also chooses the mass matrix).
std::vector<KeySpec> transient_keys(bool first);

} // namespace plastica
