// The scene reader's builder: it reads a parsed scene's tables into a Model, table by table,
// each fault located at its file, line and key. Its parts by subject: scene_reader.cpp (the
// order, the top level), scene_sections_reader.cpp, scene_geometry_reader.cpp,
// scene_loads_reader.cpp, scene_analysis_reader.cpp, and dynamics_reader.cpp for motion in time.
#pragma once

#include "dynamics_reader.hpp"
#include "mesh_builder.hpp"
#include "scene_error.hpp"
#include "scene_schema.hpp"
#include "toml_table_reader.hpp"
#include "units.hpp"

#include "model/model.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace plastica::detail {

struct Material {
    double E = 0.0;
    double density = 0.0; // mass per unit volume, for self weight
    std::optional<SteelSpec> steel;
};

class SceneBuilder {
public:
    SceneBuilder(const toml::table& root, std::string file) : root_(root), file_(std::move(file)) {}

    Model build();

private:
    using Tables = std::vector<std::pair<const toml::table*, int>>;

    // The top level (scene_reader.cpp).
    Tables array_of_tables(TomlTableReader& top, const std::string& key);
    std::string indexed(const std::string& key, std::size_t i) const;
    void read_scene_table(TomlTableReader& top);

    // Units, materials, sections (scene_sections_reader.cpp).
    void read_units(TomlTableReader& top);
    const UnitSystem* units() const { return units_ ? &*units_ : nullptr; }
    void read_materials(TomlTableReader& top);
    void read_sections(TomlTableReader& top);
    void resolve_open_formulations();
    bool all_nodes_on_one_line() const;
    int section_of(TomlTableReader& r);

    // Geometry and the nodes other tables name (scene_geometry_reader.cpp).
    // A mesh step's refusal, located at the key that asked for it.
    template <class Step>
    auto meshed(TomlTableReader& r, const std::string& key, Step step) {
        try {
            return step();
        } catch (const MeshError& e) {
            r.fail(key, e.what());
        }
    }
    void read_nodes(TomlTableReader& top);
    void read_releases(TomlTableReader& r, int first_element, int last_element);
    void read_lines(TomlTableReader& top);
    void read_arcs(TomlTableReader& top);
    int node_by_id(TomlTableReader& r, const std::string& key, int64_t id);
    void read_elements(TomlTableReader& top);
    void read_self_contact(TomlTableReader& top);
    void check_nodes(TomlTableReader& top);
    int node_ref(TomlTableReader& r, const std::string& id_key = "node", const std::string& at_key = "at");
    int node_at(TomlTableReader& r, const std::string& key, const std::array<double, 2>& p);

    // Load patterns (scene_analysis_reader.cpp).
    int pattern_of(TomlTableReader& r);
    int driven_pattern(TomlTableReader& r);

    // Supports, loads, prescribed displacements, foundations (scene_loads_reader.cpp).
    bool supported(int node, int dof) const;
    static int dof_index(TomlTableReader& r, const std::string& key, const std::string& name);
    // A controlled displacement is a length, or a rotation in radians (a pure number).
    static Dimension control_dimension(const DofRef& c) { return c.dof == 2 ? dimension::none : dimension::length; }
    void read_supports(TomlTableReader& top);
    void read_loads(TomlTableReader& top);
    void read_distributed_loads(TomlTableReader& top);
    void read_prescribed(TomlTableReader& top);
    void read_foundations(TomlTableReader& top);
    std::vector<std::array<double, 2>> bed_directions(TomlTableReader& r, const std::vector<int>& nodes);
    void add_base_edges(TomlTableReader& r, const std::map<int, int>& spring_of, double ky);

    // Stages, analysis, control and report (scene_analysis_reader.cpp).
    void read_stages(TomlTableReader& top);
    void check_released_moments() const;
    void check_patterns_driven(TomlTableReader& top);
    std::string describe_node(int n) const { return mesh_.describe(n); }
    SceneContext dynamics_context();
    void read_analysis(TomlTableReader& top);
    // [[imperfection]]s, applied to the nodes once the loads and the analysis are known
    // (scene_imperfection_reader.cpp).
    void read_imperfections(TomlTableReader& top);
    void read_transient_analysis(TomlTableReader& r);
    DofRef read_control(TomlTableReader& r, int pattern);
    void read_report(TomlTableReader& top);

    const toml::table& root_;
    std::string file_;
    Model model_;
    std::optional<UnitSystem> units_;
    std::map<std::string, Material> materials_;
    std::map<std::string, int> section_index_;
    struct OpenFormulation {
        int section = 0;
        bool points_given = false;
    };
    std::vector<OpenFormulation> open_formulations_; // distributed sections without a formulation
    MeshBuilder mesh_{model_, max_elements};
    std::vector<int> load_lines_; // of each [[load]], in order
    int nodal_loads_ = 0;                                     // [[load]]s, ahead of the lumped ones
};

} // namespace plastica::detail
