// The VTU/PVD series is the contract between the engine and the render stage: read every
// file back with VTK's own XML readers and compare with the engine's results.
#include "analysis/path_following.hpp"
#include "arrays/output_array.hpp"
#include "model/model.hpp"
#include "scene_reader.hpp"
#include "run_report.hpp"
#include "vtu_series_writer.hpp"
#include "xml_dataset.hpp"
#include "result_schema.hpp"

#include <nlohmann/json.hpp>

#include <vtkAbstractArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkCell.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

using namespace plastica;
namespace fs = std::filesystem;

namespace {

struct Series {
    Model model;
    std::vector<StepResult> steps;
    fs::path folder;
};

Series run_with_series(const std::string& scene, int max_steps, int every = 1, Compression compression = Compression::zlib) {
    Series s;
    s.model = read_scene(std::string(PLASTICA_SOURCE_DIR) + "/models/" + scene + ".toml");
    s.model.analysis.max_steps = max_steps;
    // Unique per scene, step count and stride: CTest runs these test cases in parallel.
    s.folder = fs::temp_directory_path() /
               ("plastica_vtu_" + scene + "_" + std::to_string(max_steps) + "_" + std::to_string(every) + "_" +
                std::to_string(static_cast<int>(compression)));
    fs::remove_all(s.folder);
    VtuSeriesWriter writer(s.model, s.folder.string(), {every, SeriesTime::step, compression});
    PathFollowing analysis(s.model);
    analysis.run({std::ref(writer), [&](const StepResult& r) { s.steps.push_back(r); }});
    writer.finish();
    return s;
}

std::vector<std::pair<double, std::string>> pvd_entries(const fs::path& pvd) {
    std::ifstream in(pvd);
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    std::vector<std::pair<double, std::string>> out;
    const std::regex entry("timestep=\"([^\"]+)\" group=\"\" part=\"0\" file=\"([^\"]+)\"");
    for (auto it = std::sregex_iterator(s.begin(), s.end(), entry); it != std::sregex_iterator(); ++it)
        out.emplace_back(std::stod((*it)[1]), (*it)[2]);
    return out;
}

} // namespace

TEST_CASE("Every VTU step reads back through VTK with the engine's values to full precision", "[output]") {
    const Series s = run_with_series("ring_inelastic", 12);
    const auto entries = pvd_entries(s.folder / "ring_inelastic.pvd");
    REQUIRE(entries.size() == s.steps.size());
    for (std::size_t k = 0; k < entries.size(); ++k) {
        CHECK(entries[k].first == Approx(static_cast<double>(k))); // monotone step time
        vtkNew<vtkXMLUnstructuredGridReader> reader;
        reader->SetFileName((s.folder / entries[k].second).string().c_str());
        reader->Update();
        vtkUnstructuredGrid* grid = reader->GetOutput();
        const StepResult& r = s.steps[k];
        REQUIRE(grid->GetNumberOfPoints() == static_cast<vtkIdType>(s.model.nodes.size()));
        REQUIRE(grid->GetNumberOfCells() == static_cast<vtkIdType>(s.model.elements.size()));
        CHECK(grid->GetCellType(0) == VTK_LINE);
        vtkDataArray* u = grid->GetPointData()->GetArray("displacement");
        REQUIRE(u);
        CHECK(grid->GetPointData()->GetVectors() == u);
        CHECK(u->GetDataType() == VTK_DOUBLE);
        for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
            double p[3];
            grid->GetPoint(i, p);
            CHECK(p[0] == s.model.nodes[i].x + r.displacement[3 * i]);
            CHECK(p[1] == s.model.nodes[i].y + r.displacement[3 * i + 1]);
            CHECK(u->GetComponent(i, 1) == r.displacement[3 * i + 1]);
            CHECK(grid->GetPointData()->GetArray("rotation")->GetComponent(i, 0) == r.displacement[3 * i + 2]);
        }
        vtkDataArray* m = grid->GetCellData()->GetArray("moment_j");
        for (vtkIdType e = 0; e < grid->GetNumberOfCells(); ++e)
            CHECK(m->GetComponent(e, 0) == r.elements[e].forces.moment_j);
        vtkFieldData* fd = grid->GetFieldData();
        CHECK(fd->GetArray("load_factor")->GetComponent(0, 0) == r.load_factor);
        CHECK(fd->GetArray("TimeValue")->GetComponent(0, 0) == entries[k].first);
        CHECK(fd->GetArray("step")->GetComponent(0, 0) == r.step);
    }
}

namespace {

// What the engine says an array holds at (tuple, component), computed here from the step's
// results without the writer; NaN where the test has no independent value (text arrays).
double engine_value(const std::string& array, const Series& s, const StepResult& r, vtkIdType t, int c) {
    namespace name = result::name;
    const std::size_t i = static_cast<std::size_t>(t);
    const auto nodal = [&](const std::vector<double>& v) { return c < 2 ? v[3 * i + c] : 0.0; };
    const auto spring = [&](bool unilateral, int k) {
        double sum = 0.0;
        for (const SpringResult& sp : r.springs)
            if (sp.unilateral == unilateral && static_cast<std::size_t>(sp.node) == i) sum += sp.force[k];
        return sum;
    };
    const auto end_state = [&](int end) { return static_cast<double>(static_cast<int>(r.elements[i].hinge[end].state)); };
    if (array == name::node_id || array == name::element_id) return static_cast<double>(i);
    if (array == name::member) return s.model.elements[i].member;
    if (array == name::displacement) return c < 2 ? r.displacement[3 * i + c] : 0.0;
    if (array == name::rotation) return r.displacement[3 * i + 2];
    if (array == name::initial_position) return c == 0 ? s.model.nodes[i].x : c == 1 ? s.model.nodes[i].y : 0.0;
    if (array == name::reaction) return nodal(r.reaction);
    if (array == name::reaction_moment) return r.reaction[3 * i + 2];
    if (array == name::applied_load) return nodal(r.applied_load);
    if (array == name::applied_moment) return r.applied_load[3 * i + 2];
    if (array == name::spring_force) return c < 2 ? spring(false, c) : 0.0;
    if (array == name::spring_moment) return spring(false, 2);
    if (array == name::contact_force) return c < 2 ? spring(true, c) : 0.0;
    if (array == name::axial_force) return r.elements[i].forces.axial;
    if (array == name::moment_i) return r.elements[i].forces.moment_i;
    if (array == name::moment_j) return r.elements[i].forces.moment_j;
    if (array == name::shear) return r.elements[i].forces.shear;
    if (array == name::utilisation_i) return r.elements[i].hinged ? r.elements[i].hinge[0].utilisation : 0.0;
    if (array == name::utilisation_j) return r.elements[i].hinged ? r.elements[i].hinge[1].utilisation : 0.0;
    if (array == name::hinge_state_i) return r.elements[i].hinged ? end_state(0) : 0.0;
    if (array == name::hinge_state_j) return r.elements[i].hinged ? end_state(1) : 0.0;
    if (array == name::section_curvature) return c < static_cast<int>(r.elements[i].sections.size()) ? r.elements[i].sections[c].curvature : 0.0;
    if (array == name::section_moment) return c < static_cast<int>(r.elements[i].sections.size()) ? r.elements[i].sections[c].moment : 0.0;
    if (array == name::section_yielded_share)
        return c < static_cast<int>(r.elements[i].sections.size()) ? r.elements[i].sections[c].yielded_share : 0.0;
    if (array == name::load_factor) return r.load_factor;
    if (array == name::load) return r.load;
    if (array == name::control_displacement) return r.control_displacement;
    if (array == name::step || array == name::time_value) return r.step;
    if (array == name::iterations) return r.iterations;
    if (array == name::contact_count) return r.contact_count;
    if (array == name::hinge_count) return r.hinge_count;
    if (array == name::mirror_x) return *s.model.report.mirror_x;
    if (array == name::stage) return r.stage;
    if (array == name::pattern_factors) return r.pattern_factors[static_cast<std::size_t>(result::active_patterns(s.model)[i])];
    if (array == name::released)
        return (s.model.elements[i].released[0] ? 1 : 0) + (s.model.elements[i].released[1] ? 2 : 0);
    if (array == name::support) {
        int bits = 0;
        for (const Support& sp : s.model.supports)
            if (static_cast<std::size_t>(sp.node) == i)
                bits |= (sp.fixed[0] ? 1 : 0) | (sp.fixed[1] ? 2 : 0) | (sp.fixed[2] ? 4 : 0);
        return bits;
    }
    return std::nan(""); // summaries over several values (bending_moment, gap, contact, yielded_share, …): checked below
}

vtkAbstractArray* array_at(vtkUnstructuredGrid* grid, const result::Array& a) {
    switch (a.where) {
    case result::Where::point: return grid->GetPointData()->GetAbstractArray(std::string(a.name).c_str());
    case result::Where::cell: return grid->GetCellData()->GetAbstractArray(std::string(a.name).c_str());
    default: return grid->GetFieldData()->GetAbstractArray(std::string(a.name).c_str());
    }
}

std::vector<fs::path> shipped_scenes() {
    std::vector<fs::path> scenes;
    for (const char* folder : {"/models", "/models/gallery"})
        for (const auto& f : fs::directory_iterator(std::string(PLASTICA_SOURCE_DIR) + folder))
            if (f.path().extension() == ".toml") scenes.push_back(f.path());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

} // namespace

TEST_CASE("Every shipped scene writes exactly the schema's arrays it needs, of their type, with the engine's values", "[output]") {
    const auto scenes = shipped_scenes();
    REQUIRE(scenes.size() >= 18);
    std::set<std::string> seen; // every schema array is written by some shipped scene
    for (const fs::path& scene : scenes) {
        CAPTURE(scene.filename().string());
        Series s;
        s.model = read_scene(scene.string());
        s.model.analysis.max_steps = 3;
        s.folder = fs::temp_directory_path() / ("plastica_schema_" + scene.stem().string());
        fs::remove_all(s.folder);
        {
            VtuSeriesWriter writer(s.model, s.folder.string(), {1, SeriesTime::step, Compression::none});
            PathFollowing analysis(s.model);
            analysis.run({std::ref(writer), [&](const StepResult& r) { s.steps.push_back(r); }});
            writer.finish();
        }
        const StepResult& r = s.steps.back();
        vtkNew<vtkXMLUnstructuredGridReader> reader;
        reader->SetFileName((s.folder / "vtu" / step_file_name(r.step)).string().c_str());
        reader->Update();
        vtkUnstructuredGrid* grid = reader->GetOutput();
        REQUIRE(grid->GetNumberOfPoints() == static_cast<vtkIdType>(s.model.nodes.size()));
        std::size_t expected_in_file = 0;
        for (const result::Array& a : result::arrays()) {
            if (a.where == result::Where::base) continue;
            const std::string array(a.name);
            CAPTURE(array);
            vtkAbstractArray* read = array_at(grid, a);
            // A critical point's arrays are in the step that passes one, not in every step.
            const bool in_this_step = a.when != result::When::critical_step || r.critical.has_value();
            REQUIRE((read != nullptr) == (result::present(a, s.model) && in_this_step));
            if (!read) continue;
            ++expected_in_file;
            seen.insert(array);
            switch (a.type) {
            case result::Type::float64: CHECK(read->GetDataType() == VTK_DOUBLE); break;
            case result::Type::int32: CHECK(read->GetDataType() == VTK_INT); break;
            case result::Type::text: CHECK(vtkStringArray::SafeDownCast(read) != nullptr); break;
            }
            const int components = a.components == 0 ? s.model.integration_points() : a.components;
            CHECK(read->GetNumberOfComponents() == components);
            // Field data hold one value, but the pattern factors one per load pattern and the
            // member names one per member.
            const vtkIdType tuples = a.where == result::Where::point  ? grid->GetNumberOfPoints()
                                     : a.where == result::Where::cell ? grid->GetNumberOfCells()
                                     : array == result::name::pattern_factors ? static_cast<vtkIdType>(result::active_patterns(s.model).size())
                                     : array == result::name::member_names    ? static_cast<vtkIdType>(s.model.member_names.size())
                                                                              : 1;
            CHECK(read->GetNumberOfTuples() == tuples);
            if (array == result::name::member_names)
                for (vtkIdType t = 0; t < tuples; ++t)
                    CHECK(vtkStringArray::SafeDownCast(read)->GetValue(t) == s.model.member_names[static_cast<std::size_t>(t)]);
            vtkDataArray* values = vtkDataArray::SafeDownCast(read);
            if (!values) continue;
            for (vtkIdType t = 0; t < values->GetNumberOfTuples(); ++t)
                for (int c = 0; c < components; ++c) {
                    const double want = engine_value(array, s, r, t, c);
                    if (!std::isnan(want)) CHECK(values->GetComponent(t, c) == want);
                }
        }
        // Nothing beside the schema.
        CHECK(static_cast<std::size_t>(grid->GetPointData()->GetNumberOfArrays() + grid->GetCellData()->GetNumberOfArrays() +
                                       grid->GetFieldData()->GetNumberOfArrays()) == expected_in_file);
        // The summaries: the nodal moment is the mean of the ends there; a node in contact has
        // a contact force and no gap; the largest yielded share is the largest of the sections'.
        vtkDataArray* nodal_moment = grid->GetPointData()->GetArray(result::name::bending_moment);
        std::vector<double> sum(s.model.nodes.size(), 0.0);
        std::vector<int> count(s.model.nodes.size(), 0);
        for (std::size_t e = 0; e < s.model.elements.size(); ++e) {
            sum[s.model.elements[e].node_i] += r.elements[e].forces.moment_i, ++count[s.model.elements[e].node_i];
            sum[s.model.elements[e].node_j] += r.elements[e].forces.moment_j, ++count[s.model.elements[e].node_j];
        }
        for (std::size_t i = 0; i < sum.size(); ++i)
            CHECK(nodal_moment->GetComponent(i, 0) == Approx(count[i] ? sum[i] / count[i] : 0.0).margin(1e-12));
        if (vtkDataArray* contact = grid->GetPointData()->GetArray(result::name::contact)) {
            int closed = 0;
            for (vtkIdType i = 0; i < contact->GetNumberOfTuples(); ++i)
                closed += contact->GetComponent(i, 0) == static_cast<int>(result::ContactCode::closed);
            CHECK(closed == r.contact_count);
        }
        if (vtkDataArray* share = grid->GetCellData()->GetArray(result::name::yielded_share))
            for (vtkIdType e = 0; e < share->GetNumberOfTuples(); ++e) {
                double largest = 0.0;
                for (const SectionReport& sec : r.elements[e].sections) largest = std::max(largest, sec.yielded_share);
                CHECK(share->GetComponent(e, 0) == largest);
            }
        // A critical point's arrays, in the step that passed it.
        for (const StepResult& step : s.steps) {
            if (!step.critical) continue;
            vtkNew<vtkXMLUnstructuredGridReader> at;
            at->SetFileName((s.folder / "vtu" / step_file_name(step.step)).string().c_str());
            at->Update();
            for (const result::Array& a : result::arrays())
                if (a.when == result::When::critical_step && array_at(at->GetOutput(), a)) seen.insert(std::string(a.name));
        }
        // base.vtp: its arrays as the schema says.
        if (fs::exists(s.folder / "base.vtp")) {
            vtkNew<vtkXMLPolyDataReader> base;
            base->SetFileName((s.folder / "base.vtp").string().c_str());
            base->Update();
            for (const result::Array& a : result::arrays()) {
                if (a.where != result::Where::base) continue;
                CAPTURE(a.name);
                vtkDataArray* read = base->GetOutput()->GetCellData()->GetArray(std::string(a.name).c_str());
                CHECK((read != nullptr) == result::present(a, s.model));
                if (!read) continue;
                seen.insert(std::string(a.name));
                CHECK(read->GetNumberOfComponents() == a.components);
            }
        }
    }
    for (const result::Array& a : result::arrays()) {
        CAPTURE(a.name);
        CHECK(seen.count(std::string(a.name)) == 1);
    }
}

TEST_CASE("Each array group writes the arrays it declares and no others in their order", "[output]") {
    // A row of the schema and the code that fills it live in one file of io/results/arrays/: a group
    // that wrote an array it does not declare (or left out one it does) would break that.
    std::size_t groups_run = 0;
    for (const fs::path& scene : shipped_scenes()) {
        CAPTURE(scene.filename().string());
        Model model = read_scene(scene.string());
        model.analysis.max_steps = 1;
        std::vector<StepResult> steps;
        PathFollowing(model).run({[&](const StepResult& r) { steps.push_back(r); }});
        std::set<std::string> present;
        for (const result::Array& a : result::arrays())
            if (result::present(a, model)) present.emplace(a.name);
        const std::string load_unit = "N", displacement_unit = "m";
        const StepView view{model, steps.back(), 1.0, load_unit, displacement_unit, present};
        for (const OutputGroup& group : output_groups()) {
            if (!group.fill) continue;
            XmlDataset out;
            group.fill(view, out);
            ++groups_run;
            std::vector<std::string> written, declared;
            for (const auto* place : {&out.point_data, &out.cell_data, &out.field_data})
                for (const XmlArray& a : *place) written.push_back(a.name);
            for (result::Where where : {result::Where::point, result::Where::cell, result::Where::field})
                for (const result::Array& a : group.arrays)
                    if (a.where == where && present.count(std::string(a.name)) &&
                        (a.when != result::When::critical_step || steps.back().critical))
                        declared.emplace_back(a.name);
            CHECK(written == declared);
        }
    }
    CHECK(groups_run >= 9 * 18);
}

TEST_CASE("docs/output.md's table of result arrays is the schema's", "[output]") {
    std::ifstream in(std::string(PLASTICA_SOURCE_DIR) + "/docs/output.md");
    std::stringstream text;
    text << in.rdbuf();
    CHECK_THAT(text.str(), Catch::Contains(result::markdown_table()));
    CHECK_THROWS_WITH(result::find("temperature"), Catch::Contains("no array 'temperature'"));
}

TEST_CASE("The sections along the members read back at every integration point", "[output][distributed]") {
    // Far enough for the top and the sides to yield (first yield near δ = 40 of 100).
    const Series s = run_with_series("ring_distributed", 130);
    const StepResult& r = s.steps.back();
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((s.folder / "vtu" / step_file_name(r.step)).string().c_str());
    reader->Update();
    vtkCellData* cd = reader->GetOutput()->GetCellData();
    vtkDataArray* share = cd->GetArray("section_yielded_share");
    vtkDataArray* curvature = cd->GetArray("section_curvature");
    vtkDataArray* moment = cd->GetArray("section_moment");
    vtkDataArray* largest = cd->GetArray("yielded_share");
    REQUIRE(share);
    REQUIRE(curvature);
    REQUIRE(moment);
    REQUIRE(largest);
    // The scene's elements have 4 segments of 2 Gauss points: 8 sections each, in ξ order.
    const int sections_per_element = 8;
    CHECK(s.model.integration_points() == sections_per_element);
    CHECK(share->GetNumberOfComponents() == sections_per_element);
    int yielded = 0;
    for (vtkIdType e = 0; e < reader->GetOutput()->GetNumberOfCells(); ++e) {
        const std::vector<SectionReport>& sections = r.elements[e].sections;
        REQUIRE(sections.size() == static_cast<std::size_t>(sections_per_element));
        for (int k = 1; k < sections_per_element; ++k) CHECK(sections[k].xi > sections[k - 1].xi);
        double most = 0.0;
        for (int k = 0; k < sections_per_element; ++k) {
            CHECK(share->GetComponent(e, k) == sections[k].yielded_share);
            CHECK(curvature->GetComponent(e, k) == sections[k].curvature);
            CHECK(moment->GetComponent(e, k) == sections[k].moment);
            most = std::max(most, sections[k].yielded_share);
        }
        CHECK(largest->GetComponent(e, 0) == most);
        if (most > 0.0) ++yielded;
    }
    CHECK(yielded > 0);
    CHECK(yielded < reader->GetOutput()->GetNumberOfCells()); // a zone, not the whole ring
}

TEST_CASE("A run stopped after k steps leaves a valid PVD of k steps", "[output]") {
    const Series s = run_with_series("ring_elastic", 7);
    const auto entries = pvd_entries(s.folder / "ring_elastic.pvd");
    CHECK(entries.size() == 8); // the unloaded state and 7 steps
    for (const auto& [time, file] : entries) CHECK(fs::exists(s.folder / file));
    // No temporary file is left behind.
    for (const auto& f : fs::recursive_directory_iterator(s.folder))
        CHECK(f.path().string().find(".tmp") == std::string::npos);
}

TEST_CASE("Writing every k-th step keeps the first and the last", "[output]") {
    const Series s = run_with_series("ring_elastic", 7, 3);
    const auto entries = pvd_entries(s.folder / "ring_elastic.pvd");
    std::vector<std::string> files;
    for (const auto& e : entries) files.push_back(e.second);
    CHECK(files == std::vector<std::string>{"vtu/" + step_file_name(0), "vtu/" + step_file_name(3),
                                            "vtu/" + step_file_name(6), "vtu/" + step_file_name(7)});
}

TEST_CASE("run.json is valid JSON whatever the scene path holds", "[output]") {
    const Model model = read_scene(std::string(PLASTICA_SOURCE_DIR) + "/models/ring_elastic.toml");
    RunReport r;
    r.model = &model;
    r.scene_file = "dir\twith a tab/\"quoted\"\\back\u0001.toml";
    r.summary.reason = "line one\nline two";
    r.stage_seconds = {{"read", 0.5}, {"analysis", 1.5}};
    const auto j = nlohmann::json::parse(to_json(r));
    CHECK(j["scene_file"] == r.scene_file);
    CHECK(j["reason"] == r.summary.reason);
    CHECK(j["scene"] == "ring_elastic");
    CHECK(j["seconds"]["analysis"] == 1.5);
    CHECK_FALSE(j.contains("section_solve_failures")); // an elastic scene has no hinges
}

TEST_CASE("Uncompressed, LZ4 and zlib series read back equal to the engine", "[output]") {
    for (const Compression c : {Compression::none, Compression::lz4, Compression::zlib}) {
        const Series s = run_with_series("ring_inelastic", 5, 1, c);
        CAPTURE(static_cast<int>(c));
        for (const StepResult& r : s.steps) {
            vtkNew<vtkXMLUnstructuredGridReader> reader;
            reader->SetFileName((s.folder / "vtu" / step_file_name(r.step)).string().c_str());
            reader->Update();
            vtkUnstructuredGrid* grid = reader->GetOutput();
            REQUIRE(grid->GetNumberOfPoints() == static_cast<vtkIdType>(s.model.nodes.size()));
            vtkDataArray* u = grid->GetPointData()->GetArray("displacement");
            vtkDataArray* n = grid->GetCellData()->GetArray("axial_force");
            REQUIRE(u);
            REQUIRE(n);
            for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) CHECK(u->GetComponent(i, 1) == r.displacement[3 * i + 1]);
            for (vtkIdType e = 0; e < grid->GetNumberOfCells(); ++e) CHECK(n->GetComponent(e, 0) == r.elements[e].forces.axial);
        }
    }
}

TEST_CASE("The XML serialiser's files read back through VTK to the last bit, in one block or many", "[output]") {
    // 6000 points: the coordinates span six 32 kB compression blocks and a partial seventh.
    const std::size_t n = 6000;
    XmlDataset data;
    XmlArray real = real_array("value", n, 2), whole = integer_array("flag", n - 1);
    for (std::size_t i = 0; i < n; ++i) {
        data.points.insert(data.points.end(), {std::sin(0.37 * i) * 1e3, 1.0 / (i + 1.0), -std::ldexp(1.0, -40) * i});
        std::get<std::vector<double>>(real.values)[2 * i] = std::exp(0.01 * i);
        std::get<std::vector<double>>(real.values)[2 * i + 1] = -1.0 / 3.0 * i;
        if (i + 1 < n) {
            data.lines.push_back({static_cast<std::int64_t>(i), static_cast<std::int64_t>(i + 1)});
            std::get<std::vector<std::int32_t>>(whole.values)[i] = static_cast<std::int32_t>(i * 7919 % 1000003) - 500000;
        }
    }
    data.point_data.push_back(real);
    data.active_vectors = "";
    data.cell_data.push_back(whole);
    data.field_data.push_back(field_value("load", 0.1 + 0.2));
    data.field_data.push_back(field_text("title", "ring <R = 100> & \"base\""));
    for (const Compression c : {Compression::none, Compression::lz4, Compression::zlib}) {
        CAPTURE(static_cast<int>(c));
        const fs::path file = fs::temp_directory_path() / ("plastica_xml_" + std::to_string(static_cast<int>(c)) + ".vtu");
        std::ofstream(file, std::ios::binary) << unstructured_grid_xml(data, c);
        vtkNew<vtkXMLUnstructuredGridReader> reader;
        reader->SetFileName(file.string().c_str());
        reader->Update();
        vtkUnstructuredGrid* grid = reader->GetOutput();
        REQUIRE(grid->GetNumberOfPoints() == static_cast<vtkIdType>(n));
        REQUIRE(grid->GetNumberOfCells() == static_cast<vtkIdType>(n - 1));
        int differ = 0;
        for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
            double p[3];
            grid->GetPoint(i, p);
            for (int k = 0; k < 3; ++k) differ += p[k] != data.points[3 * i + k];
            vtkDataArray* v = grid->GetPointData()->GetArray("value");
            for (int k = 0; k < 2; ++k) differ += v->GetComponent(i, k) != std::get<std::vector<double>>(real.values)[2 * i + k];
        }
        vtkDataArray* flag = grid->GetCellData()->GetArray("flag");
        REQUIRE(flag);
        for (vtkIdType e = 0; e < grid->GetNumberOfCells(); ++e) {
            differ += flag->GetComponent(e, 0) != std::get<std::vector<std::int32_t>>(whole.values)[e];
            differ += grid->GetCell(e)->GetPointId(1) != e + 1;
        }
        CHECK(differ == 0);
        CHECK(grid->GetFieldData()->GetArray("load")->GetComponent(0, 0) == 0.1 + 0.2);
        auto* title = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("title"));
        REQUIRE(title);
        CHECK(title->GetValue(0) == "ring <R = 100> & \"base\"");
    }
}

TEST_CASE("A file kept from step to step has the bytes of one written whole, whatever changes between steps", "[output]") {
    const auto dataset = [](double shift, int components) {
        XmlDataset data;
        const std::size_t n = 5;
        XmlArray value = real_array("value", 2 * n / static_cast<std::size_t>(components), components);
        for (std::size_t i = 0; i < n; ++i) {
            data.points.insert(data.points.end(), {i + shift, -shift * i, 0.0});
            if (i + 1 < n) data.lines.push_back({static_cast<std::int64_t>(i), static_cast<std::int64_t>(i + 1)});
        }
        for (std::size_t k = 0; k < 2 * n; ++k) std::get<std::vector<double>>(value.values)[k] = shift * k - 1.0 / 3.0;
        data.point_data.push_back(value);
        data.cell_data.push_back(integer_array("flag", n - 1));
        data.field_data.push_back(field_value("load", shift));
        data.field_data.push_back(field_text("title", "ring"));
        return data;
    };
    UncompressedGridFile file;
    std::vector<XmlDataset> steps = {dataset(0.0, 2), dataset(0.5, 2), dataset(1.5, 2)};
    // The same bytes under another reading of them: one component each, as many tuples again.
    steps.push_back(dataset(2.0, 1));
    // Another active vector, another title of the same length, an array more, one element more.
    steps.push_back(steps.back());
    steps.back().active_vectors = "value";
    steps.push_back(steps.back());
    std::get<std::vector<std::string>>(steps.back().field_data[1].values)[0] = "pipe";
    steps.push_back(steps.back());
    steps.back().cell_data.push_back(real_array("axial", 4));
    steps.push_back(steps.back());
    steps.back().points.insert(steps.back().points.end(), {9.0, 9.0, 0.0});
    steps.back().lines.push_back({4, 5});
    for (XmlArray* a : {&steps.back().point_data[0], &steps.back().cell_data[0], &steps.back().cell_data[1]})
        std::visit([&](auto& v) { v.resize(v.size() + static_cast<std::size_t>(a->components)); }, a->values);
    for (std::size_t k = 0; k < steps.size(); ++k) {
        CAPTURE(k);
        CHECK(write_unstructured_grid(steps[k], file) == unstructured_grid_xml(steps[k]));
    }
}

TEST_CASE("Poly data holds vertices, then lines, with their cell values in that order", "[output]") {
    XmlDataset data;
    XmlArray kind = integer_array("kind", 0);
    for (int i = 0; i < 3; ++i) {
        data.points.insert(data.points.end(), {double(i), 0.0, 0.0});
        data.vertices.push_back(i);
        std::get<std::vector<std::int32_t>>(kind.values).push_back(0);
    }
    data.points.insert(data.points.end(), {-5.0, -1.0, 0.0, 5.0, -1.0, 0.0});
    data.lines.push_back({3, 4});
    std::get<std::vector<std::int32_t>>(kind.values).push_back(1);
    data.cell_data.push_back(kind);
    for (const Compression c : {Compression::none, Compression::zlib}) {
        const fs::path file = fs::temp_directory_path() / ("plastica_xml_" + std::to_string(static_cast<int>(c)) + ".vtp");
        std::ofstream(file, std::ios::binary) << poly_data_xml(data, c);
        vtkNew<vtkXMLPolyDataReader> reader;
        reader->SetFileName(file.string().c_str());
        reader->Update();
        vtkPolyData* poly = reader->GetOutput();
        REQUIRE(poly->GetNumberOfVerts() == 3);
        REQUIRE(poly->GetNumberOfLines() == 1);
        vtkDataArray* k = poly->GetCellData()->GetArray("kind");
        REQUIRE(k);
        for (vtkIdType c2 = 0; c2 < 4; ++c2) CHECK(k->GetComponent(c2, 0) == (c2 < 3 ? 0 : 1));
        CHECK(poly->GetPoint(4)[0] == 5.0);
    }
}
