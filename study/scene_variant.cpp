#include "scene_variant.hpp"

#include "scene_error.hpp"
#include "study_error.hpp"
#include "scene_reader.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <set>
#include <sstream>

namespace plastica {

namespace {

int set_in_tables(toml::table& root, const char* array, const char* key, double value) {
    int changed = 0;
    if (toml::array* list = root[array].as_array())
        for (toml::node& item : *list)
            if (toml::table* t = item.as_table(); t && t->contains(key)) {
                t->insert_or_assign(key, static_cast<int64_t>(std::llround(value)));
                ++changed;
            }
    return changed;
}

// Sets `plasticity` on every section whose material has a yield stress; returns how many.
// "force_based" is distributed plasticity in force-based members (their own Lobatto points, no
// segments); "distributed" the default displacement-based members.
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
                } else if (plasticity != "distributed") {
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
    int changed = 0;
    if (parameter == "elements") {
        changed = set_in_tables(root, "line", "elements", value) + set_in_tables(root, "arc", "elements", value);
    } else if (parameter == "fibres") {
        changed = set_in_tables(root, "section", "fibres", value);
    } else if (parameter == "integration_points" || parameter == "segments") {
        // Every section with distributed plasticity, whether or not it names the count.
        if (toml::array* sections = root["section"].as_array())
            for (toml::node& item : *sections)
                if (toml::table* t = item.as_table(); t && (*t)["plasticity"].value_or(std::string()) == "distributed") {
                    t->insert_or_assign(parameter, static_cast<int64_t>(std::llround(value)));
                    ++changed;
                }
    } else if (parameter == "increment") {
        if (toml::table* a = root["analysis"].as_table(); a && a->contains("increment")) {
            const double old = a->get("increment")->value_or(value);
            a->insert_or_assign("increment", value);
            // Room for the smaller steps to reach the same target.
            const int64_t steps = (*a)["max_steps"].value_or(int64_t{200});
            a->insert_or_assign("max_steps", std::max<int64_t>(steps, static_cast<int64_t>(std::ceil(steps * old / value))));
            changed = 1;
        }
    } else {
        throw StudyError("cannot vary '" + parameter + "': the parameters are elements, fibres, integration_points, segments and increment");
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
