#include "scene_variant.hpp"

#include "scene_error.hpp"
#include "study_error.hpp"
#include "scene_reader.hpp"
#include "scene_schema.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace plastica {

namespace {

// Sets `key` in every table of kind `table` that names it (a whole number, or for a float key
// the value as given); returns how many.
int set_where_named(toml::table& root, const TableSpec& table, const std::string& key, double value) {
    const KeySpec& spec = *table.find_anywhere(key);
    const auto set = [&](toml::table& t) {
        if (!t.contains(key)) return 0;
        if (spec.kind == ValueKind::integer) t.insert_or_assign(key, static_cast<int64_t>(std::llround(value)));
        else t.insert_or_assign(key, value);
        return 1;
    };
    int changed = 0;
    if (toml::array* list = root[table.name].as_array())
        for (toml::node& item : *list) changed += item.as_table() ? set(*item.as_table()) : 0;
    else if (toml::table* one = root[table.name].as_table())
        changed += set(*one);
    return changed;
}

// Sets `plasticity` on every section whose material has a yield stress; returns how many.
// "force_based" is distributed plasticity in force-based members (their own Lobatto points, no
// segments); "distributed" displacement-based members, named so that the two stay apart
// whatever the scene's own default would be.
int set_plasticity(toml::table& root, const std::string& method) {
    const bool force_based = method == "force_based";
    const std::string plasticity = force_based ? "distributed" : method;
    std::set<std::string> inelastic;
    if (toml::array* materials = root["material"].as_array())
        for (toml::node& m : *materials)
            if (toml::table* t = m.as_table(); t && t->contains("fy"))
                inelastic.insert((*t)["name"].value_or(std::string()));
    int changed = 0;
    if (toml::array* sections = root["section"].as_array())
        for (toml::node& item : *sections)
            if (toml::table* t = item.as_table(); t && inelastic.count((*t)["material"].value_or(std::string()))) {
                t->insert_or_assign("plasticity", plasticity);
                t->erase("formulation");
                if (force_based) {
                    t->insert_or_assign("formulation", "force");
                    t->erase("integration_points");
                    t->erase("segments");
                    t->erase("segment_grading");
                    t->erase("axial_strain");
                } else if (plasticity == "distributed") {
                    t->insert_or_assign("formulation", "displacement");
                } else {
                    t->erase("integration_points");
                    t->erase("segments");
                    t->erase("segment_grading");
                    t->erase("axial_strain");
                }
                ++changed;
            }
    return changed;
}

} // namespace

Model scene_variant(const std::string& file, const std::string& parameter, double value, const std::string& plasticity) {
    toml::table root;
    try {
        root = toml::parse_file(file);
    } catch (const toml::parse_error& e) {
        throw SceneError(file, static_cast<int>(e.source().begin.line), "", std::string(e.description()));
    }
    const std::vector<std::string> studied = studied_keys();
    if (std::find(studied.begin(), studied.end(), parameter) == studied.end()) {
        std::string names;
        for (std::size_t k = 0; k < studied.size(); ++k)
            names += (k == 0 ? "" : k + 1 == studied.size() ? " and " : ", ") + studied[k];
        throw StudyError("cannot vary '" + parameter + "': the parameters are " + names);
    }
    int changed = 0;
    if (parameter == "integration_points" || parameter == "segments") {
        // Every section with distributed plasticity, whether or not it names the count.
        if (toml::array* sections = root["section"].as_array())
            for (toml::node& item : *sections)
                if (toml::table* t = item.as_table(); t && (*t)["plasticity"].value_or(std::string()) == "distributed") {
                    t->insert_or_assign(parameter, static_cast<int64_t>(std::llround(value)));
                    ++changed;
                }
    } else {
        // Every table the schema lets a study vary this key in, where the scene names it.
        int64_t old_steps = 0;
        double old_increment = value;
        if (parameter == "increment")
            if (toml::table* a = root["analysis"].as_table()) {
                old_steps = (*a)["max_steps"].value_or(int64_t{200});
                old_increment = (*a)["increment"].value_or(value);
            }
        for (const TableSpec& table : scene_schema())
            if (const KeySpec* k = table.find_anywhere(parameter); k && k->studied) changed += set_where_named(root, table, parameter, value);
        // Room for the smaller steps to reach the same target.
        if (parameter == "increment" && changed > 0)
            root["analysis"].as_table()->insert_or_assign(
                "max_steps", std::max<int64_t>(old_steps, static_cast<int64_t>(std::ceil(old_steps * old_increment / value))));
    }
    if (changed == 0) throw StudyError(file + ": no '" + parameter + "' to vary in this scene");
    if (!plasticity.empty() && set_plasticity(root, plasticity) == 0)
        throw StudyError(file + ": no inelastic section whose plasticity could be varied");
    std::ostringstream text;
    text << root;
    return read_scene_text(text.str(), file + " (" + parameter + " = " + std::to_string(value) +
                                           (plasticity.empty() ? "" : ", plasticity = " + plasticity) + ")");
}

} // namespace plastica
