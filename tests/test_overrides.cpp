// Command-line overrides of scene keys (--set KEY=VALUE): by index and by name, typed values,
// and errors that name the override rather than a line of the file.
#include "scene_overrides.hpp"
#include "scene_reader.hpp"

#include "model_fingerprint.hpp"

#include <toml++/toml.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <catch2/catch.hpp>

using namespace plastica;

namespace {
std::string ring() { return std::string(PLASTICA_SOURCE_DIR) + "/models/ring_inelastic.toml"; }

Model with(std::initializer_list<const char*> texts) {
    std::vector<Override> o;
    for (const char* t : texts) o.push_back(parse_override(t));
    return read_scene(ring(), o);
}

std::string error_of(std::initializer_list<const char*> texts) {
    try {
        with(texts);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "no error";
}
} // namespace

TEST_CASE("Overrides set keys by index and by name, read as TOML values", "[scene][overrides]") {
    const Model plain = read_scene(ring());
    CHECK(plain.sections[0].steel->fy == 36518.0);
    CHECK(with({"material[1].fy=20000"}).sections[0].steel->fy == 20000.0);
    CHECK(with({"material[steel].fy=1.5e4"}).sections[0].steel->fy == 15000.0);
    CHECK(with({"arc[ring].elements=20"}).elements.size() == 20u);
    CHECK(with({"analysis.increment=0.25"}).analysis.initial_increment == 0.25);
    CHECK(with({"analysis.adaptive=true"}).analysis.adaptive);
    // A bare word is a string; a key the file does not have is added (and validated).
    const Model d = with({"section[ring].plasticity=distributed", "section[ring].integration_points=4"});
    CHECK(d.sections[0].plasticity == Plasticity::distributed);
    CHECK(d.sections[0].integration_points == 4);
    // Later overrides win.
    CHECK(with({"foundation[1].ky=10", "foundation[1].ky=20"}).springs[1].ky == 20.0);
}

TEST_CASE("A bad override is named in its error", "[scene][overrides]") {
    CHECK(error_of({"material[steel].fy=-1"}) == "--set material[steel].fy: expected a positive number, got -1");
    // Paths are checked against the scene schema before anything is read.
    CHECK(error_of({"analysis.incremnt=2"}) == "--set analysis.incremnt: [analysis] has no key 'incremnt'; did you mean 'increment'?");
    CHECK(error_of({"anlysis.increment=2"}) == "--set anlysis.increment: a scene has no table 'anlysis'; did you mean 'analysis'?");
    CHECK(error_of({"analysis[1].increment=2"}) == "--set analysis[1].increment: [analysis] is one table, not a list");
    CHECK(error_of({"section[ring].diameter=2"}).find("section[ring].diameter") != std::string::npos);
    CHECK(error_of({"material[iron].fy=2"}) == "--set material[iron].fy: no [[material]] named 'iron'");
    CHECK(error_of({"material[stel].fy=2"}) == "--set material[stel].fy: no [[material]] named 'stel'; did you mean 'steel'?");
    CHECK(error_of({"material[3].fy=2"}) == "--set material[3].fy: the scene has 1 [[material]] table(s), not 3");
    CHECK(error_of({"foundation[1].ky=abc def"}) ==
          "--set foundation[1].ky: cannot read 'abc def' as a TOML value (quote strings with spaces)");
    CHECK(error_of({"analysis"}) == "--set analysis: expected KEY=VALUE, e.g. material[steel].fy=250");
    CHECK(error_of({"material.fy=2"}) == "--set material.fy: 'material' is a list: name one, e.g. material[1].fy");
    // A value the key does not accept.
    CHECK_THAT(error_of({"section[ring].plasticity=zones"}), Catch::Contains("--set section[ring].plasticity: expected one of"));
}

TEST_CASE("A run with --set equals the run of the edited file to the last digit", "[scene][overrides]") {
    std::ifstream in(ring());
    std::stringstream text;
    text << in.rdbuf();
    std::string edited = text.str();
    auto edit = [&](const std::string& from, const std::string& to) {
        REQUIRE(edited.find(from) != std::string::npos);
        edited.replace(edited.find(from), from.size(), to);
    };
    edit("fy = 36518.0", "fy = 30000.0");
    edit("elements = 50", "elements = 30");
    edit("ky = 1200.0", "ky = 900.0");
    edit("target_displacement = 100.0", "target_displacement = 40.0");
    auto loads = [](const Model& m) {
        std::vector<double> out;
        PathFollowing analysis(m);
        analysis.run({[&](const StepResult& r) { out.push_back(r.load); }});
        return out;
    };
    const std::vector<double> from_file = loads(read_scene_text(edited, "edited.toml"));
    const std::vector<double> from_set = loads(with({"material[steel].fy=30000.0", "arc[ring].elements=30",
                                                    "foundation[1].ky=900.0", "analysis.target_displacement=40.0"}));
    REQUIRE(from_file.size() > 50u);
    CHECK(from_file == from_set);
}

namespace {

// Every leaf key of a TOML table as (path, value text), with list entries by 1-based index.
void leaves(const toml::table& table, const std::string& prefix, std::vector<std::pair<std::string, std::string>>& out) {
    for (auto&& [key, node] : table) {
        const std::string path = prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
        if (const toml::table* t = node.as_table()) {
            leaves(*t, path, out);
        } else if (const toml::array* a = node.as_array(); a && a->is_array_of_tables()) {
            for (std::size_t i = 0; i < a->size(); ++i) leaves(*(*a)[i].as_table(), path + "[" + std::to_string(i + 1) + "]", out);
        } else {
            std::ostringstream value;
            node.visit([&](auto&& v) { value << v; }); // TOML text: strings quoted, arrays bracketed
            out.emplace_back(path, value.str());
        }
    }
}

} // namespace

TEST_CASE("Every key of every shipped scene can be set by its path, and setting its own value changes nothing", "[scene][overrides]") {
    namespace fs = std::filesystem;
    int keys = 0, scenes = 0;
    for (const char* folder : {"models", "models/gallery"}) {
        for (const auto& entry : fs::directory_iterator(fs::path(PLASTICA_SOURCE_DIR) / folder)) {
            if (entry.path().extension() != ".toml") continue;
            const std::string file = entry.path().string();
            const std::string plain = fingerprint(read_scene(file, {}));
            std::vector<std::pair<std::string, std::string>> all;
            leaves(toml::parse_file(file), "", all);
            ++scenes;
            for (const auto& [path, value] : all) {
                CAPTURE(file, path, value);
                CHECK(fingerprint(read_scene(file, {parse_override(path + "=" + value)})) == plain);
                ++keys;
            }
        }
    }
    CHECK(scenes >= 15);
    CHECK(keys > 400);
}

TEST_CASE("Documented keys that no shipped scene uses can be added by --set, as the edited file would", "[scene][overrides]") {
    struct Case {
        std::string scene, path, value, after, line; // the file's edit: `line` inserted after the line `after`
    };
    const std::vector<Case> cases = {
        {"ring_inelastic", "material[steel].density", "7850.0", "fy = 36518.0", "density = 7850.0"},
        {"ring_inelastic", "material[steel].ultimate_strain", "0.2", "fy = 36518.0", "ultimate_strain = 0.2"},
        {"ring_inelastic", "material[steel].law", "\"kinematic_hardening\"", "fy = 36518.0", "law = \"kinematic_hardening\"\nhardening_ratio = 0.01"},
        {"ring_inelastic", "foundation[1].kx", "5.0", "ky = 1200.0", "kx = 5.0"},
        {"ring_inelastic", "analysis.max_iterations", "25", "[analysis]", "max_iterations = 25"},
        {"ring_inelastic", "analysis.displacement_tolerance", "1e-7", "[analysis]", "displacement_tolerance = 1e-7"},
        {"ring_inelastic", "analysis.min_increment", "1e-4", "[analysis]", "min_increment = 1e-4"},
        {"ring_inelastic", "analysis.max_increment", "0.75", "[analysis]", "max_increment = 0.75"},
        {"ring_inelastic", "analysis.allow_crossing", "true", "[analysis]", "allow_crossing = true"},
        {"ring_inelastic", "load[1].moment", "0.5", "fy = -1.0", "moment = 0.5"},
        {"gallery/portal_frame", "section[1].web_fibres", "16", "shape = \"i\"", "web_fibres = 16"},
        {"gallery/portal_frame", "section[1].flange_layers", "3", "shape = \"i\"", "flange_layers = 3"},
        {"gallery/portal_frame", "section[1].flange_strips", "8", "shape = \"i\"", "flange_strips = 8"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.scene, c.path);
        const std::string file = std::string(PLASTICA_SOURCE_DIR) + "/models/" + c.scene + ".toml";
        std::ifstream in(file);
        std::stringstream text;
        text << in.rdbuf();
        std::string edited = text.str();
        const std::size_t at = edited.find(c.after + "\n");
        REQUIRE(at != std::string::npos);
        edited.insert(at + c.after.size() + 1, c.line + "\n");
        std::vector<Override> overrides{parse_override(c.path + "=" + c.value)};
        if (c.path.find(".law") != std::string::npos) overrides.push_back(parse_override("material[steel].hardening_ratio=0.01"));
        const std::string from_set = fingerprint(read_scene(file, overrides));
        const std::string from_file = fingerprint(read_scene_text(edited, file));
        CHECK(from_set == from_file);
        CHECK(from_set != fingerprint(read_scene(file, {}))); // the key changed what runs
    }
}
