// Reads what a scene says about motion in time (engine/model/dynamics_spec.hpp): [[mass]],
// [damping], [[time_series]], [[ground_motion]], [[initial_velocity]], and the transient keys
// of [analysis] and [[stage]]. Every value is checked where it is read and a fault is located
// at its file, line and key (SceneError).
#pragma once

#include "model/model.hpp"
#include "toml_table_reader.hpp"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace plastica {

// What the dynamics tables need from the rest of the scene.
struct SceneContext {
    std::string file;                                           // the scene file, for messages and relative paths
    const UnitSystem* units = nullptr;                          // [units], if given
    std::function<int(TomlTableReader&)> node_ref;              // 'node = id' or 'at = [x, y]'
    const std::map<std::string, std::vector<int>>* members = nullptr; // member name → its elements
};

// The [[table]]s under `key`, each with its line; and "key[i+1]", a table's name in messages.
using Tables = std::vector<std::pair<const toml::table*, int>>;
Tables tables_of(TomlTableReader& top, const std::string& key);
inline std::string indexed(const std::string& key, std::size_t i) { return key + "[" + std::to_string(i + 1) + "]"; }
// [[ground_motion]] (ground_motion_reader.cpp).
void read_ground_motions(TomlTableReader& top, const SceneContext& context, Model& model);

// time_step, duration, integrator, alpha of a transient [analysis] or [[stage]].
TransientSpec read_transient(TomlTableReader& r);
// A record is followed at each of its samples only by a step that divides its DT.
void check_transient_step(TomlTableReader& r, const TransientSpec& t, const Model& model);
// The tables at the top level, into model.dynamics (patterns must already be known).
void read_dynamics(TomlTableReader& top, const SceneContext& context, Model& model);

// A PEER AT2 record's accelerations (in g) and its DT, or a plain list with no header (DT 0).
// Throws std::runtime_error naming the line that is not a record's.
struct AccelerationRecord {
    std::vector<double> values;
    double time_step = 0.0;
};
AccelerationRecord parse_acceleration_record(const std::string& text);

} // namespace plastica
