#include "scene_reader.hpp"

#include "scene_builder.hpp"

#include "bounded_file.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace plastica::detail {

Model SceneBuilder::build() {
    TomlTableReader top(root_, file_, "", scene_root_table());
    read_scene_table(top);
    read_units(top);
    read_materials(top);
    read_sections(top);
    read_nodes(top);
    read_lines(top);
    read_arcs(top);
    read_elements(top);
    check_nodes(top);
    read_supports(top);
    read_loads(top);
    read_distributed_loads(top);
    read_prescribed(top);
    read_foundations(top);
    read_self_contact(top);
    read_dynamics(top, dynamics_context(), model_);
    check_released_moments();
    read_analysis(top);
    read_stages(top);
    read_report(top);
    resolve_open_formulations();
    read_imperfections(top);
    top.finish();
    if (!model_.loaded() && !model_.has_moving_base() && !(model_.transient() && model_.dynamics.excites()))
        throw SceneError(file_, 1, "load",
                         "the scene has no [[load]], no [[distributed_load]], no [[prescribed]] displacement, no moving base "
                         "(base_motion), and no [[ground_motion]] or [[initial_velocity]] for a transient stage");
    check_patterns_driven(top);
    return std::move(model_);
}

SceneBuilder::Tables SceneBuilder::array_of_tables(TomlTableReader& top, const std::string& key) {
    Tables out;
    const toml::node* n = top.node(key);
    if (!n) return out;
    const toml::array* a = n->as_array();
    if (!a || !a->is_array_of_tables())
        top.fail(key, "expected an array of tables, written [[" + key + "]]");
    for (const toml::node& item : *a) out.emplace_back(item.as_table(), line_of(item));
    return out;
}

std::string SceneBuilder::indexed(const std::string& key, std::size_t i) const {
    return key + "[" + std::to_string(i + 1) + "]";
}

void SceneBuilder::read_scene_table(TomlTableReader& top) {
    const toml::table* t = top.table("scene");
    if (!t) top.fail("", "missing required table [scene] (with a 'name')");
    TomlTableReader r(*t, file_, "scene", scene_table("scene"), units());
    model_.name = r.string("name");
    if (model_.name.empty() || model_.name.size() > 64 ||
        !std::all_of(model_.name.begin(), model_.name.end(), [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
        }))
        r.fail("name", "expected 1 to 64 letters, digits, '_' or '-' (it names the output folder)");
    model_.title = r.string("title");
    r.finish();
}

SceneContext SceneBuilder::dynamics_context() {
    SceneContext c;
    c.file = file_;
    c.units = units();
    c.node_ref = [this](TomlTableReader& r) { return node_ref(r); };
    c.members = &mesh_.member_elements();
    return c;
}

} // namespace plastica::detail

namespace plastica {

using detail::SceneBuilder;

Model read_scene_text(const std::string& text, const std::string& name_for_errors) {
    toml::table root;
    try {
        root = toml::parse(text, name_for_errors);
    } catch (const toml::parse_error& e) {
        throw SceneError(name_for_errors, static_cast<int>(e.source().begin.line), "",
                         std::string(e.description()));
    }
    return read_scene_table(root, name_for_errors);
}

Model read_scene_table(const toml::table& root, const std::string& name_for_errors) {
    Model m = SceneBuilder(root, name_for_errors).build();
    m.source = name_for_errors;
    return m;
}

Model read_scene(const std::string& path) {
    std::string text;
    try {
        text = read_bounded_file(path, scene_file_limit);
    } catch (const FileReadError& e) {
        throw SceneError(path, 0, "", std::string("cannot read the scene file: ") + e.what());
    }
    return read_scene_text(text, path);
}

} // namespace plastica
