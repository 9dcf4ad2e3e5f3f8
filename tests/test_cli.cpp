// End-to-end tests of the command line: exit codes, messages, and what the files hold (values
// of the CSV and JSON files, pixels of the pictures).
#include "cli_helpers.hpp"
#include "png_file.hpp"
#include "render_helpers.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

using cli_test::command;
using cli_test::model;
using cli_test::Result;

// A CSV file of numbers under a header: column by name, rows in order (text cells read as NaN).
struct CsvTable {
    std::vector<std::string> columns;
    std::vector<std::vector<double>> rows;
    double at(std::size_t row, const std::string& column) const {
        const auto c = std::find(columns.begin(), columns.end(), column);
        REQUIRE(c != columns.end());
        return rows.at(row).at(static_cast<std::size_t>(c - columns.begin()));
    }
};

CsvTable read_csv(const fs::path& path) {
    CsvTable t;
    std::ifstream in(path);
    std::string line;
    for (bool header = true; std::getline(in, line); header = false) {
        if (line.empty() || line[0] == '#') continue;
        std::stringstream cells(line);
        std::vector<double> row;
        for (std::string cell; std::getline(cells, cell, ',');) {
            if (header) {
                t.columns.push_back(cell);
                continue;
            }
            char* end = nullptr;
            const double v = std::strtod(cell.c_str(), &end);
            row.push_back(end != cell.c_str() && *end == '\0' ? v : std::nan(""));
        }
        if (!header) t.rows.push_back(row);
    }
    return t;
}

nlohmann::json read_json(const fs::path& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
}

// The share of a picture's pixels that are not its background (white).
double ink(const fs::path& png) {
    REQUIRE(fs::exists(png));
    auto image = plastica::render::read_png(png.string());
    int d[3];
    image->GetDimensions(d);
    const long drawn = plastica::testing::count_pixels(image, [](plastica::testing::Pixel p) { return p.r < 250 || p.g < 250 || p.b < 250; });
    return static_cast<double>(drawn) / (static_cast<double>(d[0]) * d[1]);
}

// The load of the shipped rings at δ = 100, as stored (tests/reference/ring_curves.csv).
constexpr double elastic_ring_load_at_100 = 0.472936510795;

fs::path scratch(const std::string& name) {
    const fs::path p = fs::temp_directory_path() / ("plastica_cli_" + name);
    fs::remove_all(p);
    return p;
}

// A copy of a model in dir with one piece of text replaced; returns the copy's path.
fs::path edited_model(const fs::path& dir, const std::string& name, const std::string& from, const std::string& to) {
    fs::create_directories(dir);
    std::ifstream in(model("ring_elastic.toml"));
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    s.replace(s.find(from), from.size(), to);
    const fs::path path = dir / name;
    std::ofstream(path) << s;
    return path;
}

// The inelastic ring in 10 000 steps: long enough to be stopped mid-way.
void write_long_run(const fs::path& path) {
    std::ifstream in(model("ring_inelastic.toml"));
    std::stringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    s.replace(s.find("increment = 0.5"), 15, "increment = 0.002");
    s.replace(s.find("max_steps = 2000"), 16, "max_steps = 90000");
    std::ofstream(path) << s;
}

// Shell words that wait (up to 60 s) until a file exists.
std::string wait_for(const fs::path& file) {
    return "for i in $(seq 600); do [ -e '" + file.string() + "' ] && break; sleep 0.1; done; ";
}

} // namespace

TEST_CASE("plastica run solves the elastic ring and writes curve.csv, run.json and the series", "[cli]") {
    const fs::path out = scratch("ring");
    const Result r = command("run " + model("ring_elastic.toml") + " -o " + out.string() + " --no-render -q");
    CHECK(r.code == 0);
    // The curve: step 0 and 200 steps to δ = 100, ending on the stored load.
    const CsvTable curve = read_csv(out / "curve.csv");
    REQUIRE(curve.rows.size() == 201u);
    CHECK(curve.at(200, "step") == 200);
    CHECK(curve.at(200, "control_displacement") == Approx(100.0).epsilon(1e-12));
    CHECK(curve.at(200, "load") == Approx(elastic_ring_load_at_100).epsilon(1e-9));
    for (std::size_t k = 1; k < curve.rows.size(); ++k) CHECK(curve.at(k, "load") > curve.at(k - 1, "load"));
    // run.json says what ran and how it ended.
    const nlohmann::json run = read_json(out / "run.json");
    CHECK(run["status"] == "completed");
    CHECK(run["steps"] == 200);
    CHECK(run["final"]["load"].get<double>() == Approx(elastic_ring_load_at_100).epsilon(1e-9));
    // Where the time went: reading, the analysis, the writers; nothing was drawn.
    for (const char* stage : {"read", "analysis", "output"}) {
        CAPTURE(stage);
        REQUIRE(run["seconds"].contains(stage));
        CHECK(run["seconds"][stage].get<double>() > 0.0);
    }
    CHECK_FALSE(run["seconds"].contains("drawing"));
    // The series: one VTU per step, each listed once in the PVD.
    std::ifstream pvd(out / "ring_elastic.pvd");
    std::stringstream text;
    text << pvd.rdbuf();
    std::size_t listed = 0;
    for (std::size_t at = 0; (at = text.str().find("part=\"0\"", at)) != std::string::npos; ++at) ++listed;
    CHECK(listed == 201u);
    CHECK(fs::exists(out / "vtu" / "step_000200.vtu"));
    CHECK_FALSE(fs::exists(out / "vtu" / "step_000201.vtu"));
}

TEST_CASE("A run again into its folder rewrites the step files in place and removes the steps it no longer has", "[cli][output]") {
    const fs::path out = scratch("rerun");
    auto inode = [](const fs::path& file) {
        struct stat st {};
        REQUIRE(::stat(file.c_str(), &st) == 0);
        return st.st_ino;
    };
    auto vtu_files = [&out] {
        std::size_t n = 0;
        for (const auto& f : fs::directory_iterator(out / "vtu")) n += f.path().extension() == ".vtu";
        return n;
    };
    REQUIRE(command("run " + model("ring_elastic.toml") + " -o " + out.string() + " --no-render -q").code == 0);
    REQUIRE(vtu_files() == 201u);
    const auto first = inode(out / "vtu" / "step_000005.vtu");
    // Half the push, compressed (shorter files): steps 0–100 again, 101–200 gone.
    const std::string half = " --set analysis.target_displacement=50 --compression lz4 --no-render -q";
    REQUIRE(command("run " + model("ring_elastic.toml") + " -o " + out.string() + half).code == 0);
    CHECK(vtu_files() == 101u);
    CHECK(fs::exists(out / "vtu" / "step_000100.vtu"));
    CHECK_FALSE(fs::exists(out / "vtu" / "step_000101.vtu"));
    CHECK(inode(out / "vtu" / "step_000005.vtu") == first);
    // Each rewritten file is, byte for byte, the one a fresh run writes (no tail of the old one).
    const fs::path fresh = scratch("rerun_fresh");
    REQUIRE(command("run " + model("ring_elastic.toml") + " -o " + fresh.string() + half).code == 0);
    auto bytes = [](const fs::path& file) {
        std::ifstream in(file, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    for (const char* step : {"step_000000.vtu", "step_000005.vtu", "step_000100.vtu"}) {
        CAPTURE(step);
        CHECK(bytes(out / "vtu" / step) == bytes(fresh / "vtu" / step));
    }
}

TEST_CASE("A bad scene file exits with 2 and names file, line and key, creating no output", "[cli]") {
    const fs::path dir = scratch("bad");
    const fs::path bad = edited_model(dir, "bad.toml", "radius = 100.0", "radius = -100.0");
    const Result r = command("run " + bad.string() + " -o " + (dir / "out").string() + " --no-render");
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains("bad.toml:20: 'arc[1].radius': expected a positive number, got -100"));
    CHECK_FALSE(fs::exists(dir / "out"));
}

TEST_CASE("plastica schema --scene prints the key tables models/README.md carries", "[cli]") {
    const Result r = command("schema --scene");
    CHECK(r.code == 0);
    std::ifstream in(model("README.md"));
    std::stringstream readme;
    readme << in.rdbuf();
    // Each generated block printed is in models/README.md as printed (and no more of them).
    std::size_t blocks = 0;
    const std::string begin = "<!-- generated by", end = "<!-- end of generated keys -->\n";
    for (std::size_t at = r.output.find(begin); at != std::string::npos; at = r.output.find(begin, at + 1)) {
        const std::string block = r.output.substr(at, r.output.find(end, at) + end.size() - at);
        CHECK_THAT(readme.str(), Catch::Contains(block));
        ++blocks;
    }
    CHECK(blocks == 23u);
    CHECK_THAT(r.output, Catch::Contains("| `E` | number > 0, a stress, force/length² | needed; `concrete`: n·fc/eps_c2 | Young's modulus;"));
}

TEST_CASE("An analysis that stops early exits with 3 and keeps its converged steps", "[cli]") {
    const fs::path dir = scratch("early");
    const fs::path early = edited_model(dir, "early.toml", "max_steps = 2000", "max_steps = 5");
    const Result r = command("run " + early.string() + " -o " + (dir / "out").string() + " --no-render -q");
    CHECK(r.code == 3);
    CHECK_THAT(r.output, Catch::Contains("step limit reached"));
    CHECK(fs::exists(dir / "out" / "vtu" / "step_000005.vtu"));
    std::ifstream json(dir / "out" / "run.json");
    std::stringstream j;
    j << json.rdbuf();
    CHECK_THAT(j.str(), Catch::Contains("\"status\": \"step_limit\""));
}

TEST_CASE("An output folder holding another scene is refused without --force", "[cli]") {
    const fs::path out = scratch("mixed");
    REQUIRE(command("run " + model("ring_elastic.toml") + " -o " + out.string() + " --no-render -q").code == 0);
    const Result r = command("run " + model("ring_bilateral.toml") + " -o " + out.string() + " --no-render -q");
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains("holds results of scene 'ring_elastic'"));
    CHECK(command("run " + model("ring_bilateral.toml") + " -o " + out.string() + " --no-render -q --force").code == 0);
    CHECK_FALSE(fs::exists(out / "ring_elastic.pvd"));
}

TEST_CASE("Help is complete and unknown commands or options are bad input", "[cli]") {
    const Result help = command("--help");
    CHECK(help.code == 0);
    CHECK_THAT(help.output, Catch::Contains("run SCENE"));
    CHECK_THAT(command("run --help").output, Catch::Contains("--every"));
    CHECK(command("frobnicate").code == 2);
    CHECK(command("run " + model("ring_elastic.toml") + " --no-such-option").code == 2);
}

TEST_CASE("plastica section writes the capacity and moment-curvature curves", "[cli]") {
    const fs::path out = scratch("section");
    const Result r = command("section " + model("ring_inelastic.toml") + " -o " + out.string());
    CHECK(r.code == 0);
    // Mp of the ring's 10-fibre rectangle: fy·b·h²/4 = fy·A·h/4 = 10.0009 (exact for an even
    // fibre count), h = √(12 I/A).
    const double h = std::sqrt(12.0 * 1e-6 / 0.1), Mp = 36518.0 * 0.1 * h / 4.0;
    CHECK_THAT(r.output, Catch::Contains("Mp(0) = 10.0009"));
    const CsvTable capacity = read_csv(out / "ring_capacity.csv");
    REQUIRE(capacity.rows.size() == 101u);
    const std::size_t middle = 50; // N = 0
    CHECK(capacity.at(middle, "axial_force") == Approx(0.0).margin(1e-9));
    CHECK(capacity.at(middle, "moment_positive") == Approx(Mp).epsilon(1e-9));
    CHECK(capacity.at(middle, "moment_negative") == Approx(-Mp).epsilon(1e-9));
    // First yield at the outer face (h/2) of layers whose I is (1 − 1/n²) of the rectangle's:
    // 0.99 fy I / (h/2).
    CHECK(capacity.at(middle, "first_yield_moment") == Approx(0.99 * 36518.0 * 1e-6 / (h / 2.0)).epsilon(1e-9));
    // At the squash loads no moment is left.
    CHECK(capacity.at(0, "moment_positive") == Approx(0.0).margin(1e-9));
    CHECK(capacity.at(100, "moment_positive") == Approx(0.0).margin(1e-9));
    const CsvTable curvature = read_csv(out / "ring_moment_curvature.csv");
    REQUIRE(!curvature.rows.empty());
    // At N = 0 the moment rises toward Mp and never passes it.
    double largest = 0.0;
    for (std::size_t k = 0; k < curvature.rows.size(); ++k)
        if (curvature.at(k, "axial_ratio") == 0.0) largest = std::max(largest, curvature.at(k, "moment"));
    CHECK(largest > 0.95 * Mp);
    CHECK(largest <= Mp * (1.0 + 1e-10)); // the CSV holds 12 digits
    CHECK(ink(out / "ring_capacity.png") > 0.03);
    CHECK(ink(out / "ring_moment_curvature.png") > 0.03);
}

TEST_CASE("plastica section draws the most loaded end's path from a run, and refuses a missing one", "[cli][render]") {
    const fs::path run = scratch("section_run");
    REQUIRE(command("run " + model("ring_inelastic.toml") + " -o " + run.string() + " --every 50 --no-render -q").code == 0);
    const fs::path out = scratch("section_path");
    const Result r = command("section " + model("ring_inelastic.toml") + " -o " + out.string() + " --series " + run.string());
    CHECK(r.code == 0);
    CHECK(fs::exists(out / "ring_capacity.png"));
    const Result missing = command("section " + model("ring_inelastic.toml") + " -o " + out.string() + " --series " +
                                    (run / "nothing").string());
    CHECK(missing.code == 2);
    CHECK_THAT(missing.output, Catch::Contains("nothing: missing"));
}

TEST_CASE("plastica run draws the series and plastica render redraws it with overlays and a GIF", "[cli][render]") {
    const fs::path out = scratch("drawn");
    const Result run = command("run " + model("ring_inelastic.toml") + " -o " + out.string() +
                                " --every 40 --size 320x180 --no-animation -q");
    REQUIRE(run.code == 0);
    // Drawn, not blank: the pushed ring covers more of its frame than the unloaded one.
    CHECK(ink(out / "frames" / "frame_000000.png") > 0.05);
    CHECK(ink(out / "frames" / "frame_000200.png") > 0.05);
    CHECK(ink(out / "chart.png") > 0.02);
    CHECK(ink(out / "contact_sheet.png") > 0.05);
    CHECK_FALSE(fs::exists(out / "ring_inelastic.gif"));

    const fs::path other = scratch("drawn_elastic");
    REQUIRE(command("run " + model("ring_elastic.toml") + " -o " + other.string() + " --every 100 --no-render -q").code == 0);
    const fs::path pictures = scratch("drawn_again");
    const Result render = command("render " + (out / "ring_inelastic.pvd").string() + " -o " + pictures.string() +
                                   " --size 320x180 --overlay " + other.string() + " --field axial_force");
    CHECK(render.code == 0);
    CHECK_THAT(render.output, Catch::Contains("rendered 6 frames"));
    CHECK(ink(pictures / "chart.png") > 0.02);
    CHECK(ink(pictures / "frames" / "frame_000200.png") > 0.05);
    if (std::system("command -v ffmpeg > /dev/null") == 0)
        CHECK(fs::exists(pictures / "ring_inelastic.gif"));
    else
        CHECK_THAT(render.output, Catch::Contains("ffmpeg"));
}

TEST_CASE("plastica render refuses bad input with exit 2 and the reason", "[cli][render]") {
    const fs::path empty = scratch("render_empty");
    fs::create_directories(empty);
    const Result none = command("render " + empty.string());
    CHECK(none.code == 2);
    CHECK_THAT(none.output, Catch::Contains("expected one .pvd result series, found 0"));
    const Result size = command("render " + empty.string() + " --size 12by34");
    CHECK(size.code == 2);
    CHECK_THAT(size.output, Catch::Contains("--size takes WIDTHxHEIGHT"));
}

TEST_CASE("plastica compare: same pictures pass, a missing picture fails, a size mismatch is bad input", "[cli][compare]") {
    const fs::path references = fs::path(PLASTICA_SOURCE_DIR) / "tests" / "snapshots" / "ring_elastic";
    const Result same = command("compare " + references.string() + " " + references.string());
    CHECK(same.code == 0);
    CHECK_THAT(same.output, Catch::Contains("all 5 images match"));

    const fs::path copy = scratch("compare_copy");
    fs::copy(references, copy, fs::copy_options::recursive);
    fs::remove(copy / "frames" / "frame_000117.png");
    const Result missing = command("compare " + copy.string() + " " + references.string());
    CHECK(missing.code == 1);
    CHECK_THAT(missing.output, Catch::Contains("frames/frame_000117.png") && Catch::Contains("missing in"));

    const Result sizes = command("compare " + (references / "contact_sheet.png").string() + " " + (references / "chart.png").string());
    CHECK(sizes.code == 2);
    CHECK_THAT(sizes.output, Catch::Contains("size mismatch, 960x180 against the reference's 640x360"));

    const Result unreadable = command("compare " + (copy / "nothing.png").string() + " " + (references / "chart.png").string());
    CHECK(unreadable.code == 2);
    CHECK_THAT(unreadable.output, Catch::Contains("nothing.png: missing"));
}

TEST_CASE("plastica compare --region compares one part of each picture", "[cli][compare]") {
    // Two frames of the same run: the structure and the status line differ, the right end of
    // the title band (no text there) does not.
    const fs::path frames = fs::path(PLASTICA_SOURCE_DIR) / "tests" / "snapshots" / "ring_elastic" / "frames";
    const std::string pair = (frames / "frame_000200.png").string() + " " + (frames / "frame_000117.png").string();
    CHECK(command("compare " + pair).code == 1);
    const Result corner = command("compare " + pair + " --region 0.9,0,1,0.05");
    CHECK(corner.code == 0);
    CHECK_THAT(corner.output, Catch::Contains("all 1 images match"));
    CHECK(command("compare " + pair + " --region 0,0.11,0.43,1").code == 1);
    const Result bad = command("compare " + pair + " --region 0.5,0,0.2,1");
    CHECK(bad.code == 2);
    CHECK_THAT(bad.output, Catch::Contains("--region takes x0,y0,x1,y1"));
}

TEST_CASE("A model larger than the memory the process may have stops with exit 3 and says so", "[cli]") {
#ifdef PLASTICA_SANITIZED
    WARN("not under the sanitizers: their shadow memory needs more address space than the limit leaves");
    return;
#else
    // 300 000 elements need about 0.55 GB (200 000 fit since a chain factorises in node blocks);
    // the process may have 0.4 GB (virtual).
    const fs::path out = scratch("out_of_memory");
    const std::string cmd = "sh -c \"ulimit -v 400000; " + std::string(PLASTICA_BINARY) + " run " + model("cantilever_tip_load.toml") +
                            " --set 'line[1].elements=300000' --curves-only -q -o " + out.string() + "\" > " + out.string() +
                            ".log 2>&1";
    const int status = std::system(cmd.c_str());
    std::ifstream log(out.string() + ".log");
    std::stringstream message;
    message << log.rdbuf();
    CAPTURE(message.str());
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 3);
    CHECK_THAT(message.str(), Catch::Contains("out of memory") && Catch::Contains("300000 elements"));
    CHECK_THAT(message.str(), !Catch::Contains("terminate called"));
#endif
}

TEST_CASE("plastica study and plastica stability write their tables and charts", "[cli][study]") {
    const fs::path out = scratch("study");
    const Result study = command("study " + model("cantilever_tip_load.toml") + " --vary elements=4,8,16 -o " + out.string());
    CHECK(study.code == 0);
    CHECK_THAT(study.output, Catch::Contains("errors against exact: cantilever_tip_load"));
    CHECK_THAT(study.output, Catch::Contains("observed order of convergence in elements"));
    // Three levels whose error against the exact elastica falls with the mesh.
    const CsvTable levels = read_csv(out / "study.csv");
    REQUIRE(levels.rows.size() == 3u);
    CHECK(levels.at(1, "max_error") < levels.at(0, "max_error"));
    CHECK(levels.at(2, "max_error") < levels.at(1, "max_error"));
    CHECK(levels.at(2, "max_error") < 0.01);
    CHECK(ink(out / "study.png") > 0.02);
    const Result bad = command("study " + model("ring_elastic.toml") + " --vary elements=ten,20 -o " + out.string());
    CHECK(bad.code == 2);
    CHECK_THAT(bad.output, Catch::Contains("'ten' is not a number"));
    const Result method = command("study " + model("ring_inelastic.toml") + " --vary plasticity=hinges,zones --vary elements=10,20 -o " + out.string());
    CHECK(method.code == 2);
    CHECK_THAT(method.output, Catch::Contains("--vary plasticity: expected hinges, distributed or force_based, got 'zones'"));
    const Result elastic = command("study " + model("ring_elastic.toml") + " --vary plasticity=hinges,distributed --vary elements=10,20 -o " + out.string());
    CHECK(elastic.code == 2);
    CHECK_THAT(elastic.output, Catch::Contains("no inelastic section whose plasticity could be varied"));

    const fs::path table = scratch("stability");
    // The whole sweep is a test of its own (study_tests); here the command on a part of it.
    const Result stability = command("stability --case \"ring on a unilateral base\" -o " + table.string());
    CHECK(stability.code == 0);
    CHECK_THAT(stability.output, Catch::Contains("every case behaved as expected"));
    const CsvTable cases = read_csv(table / "stability.csv");
    REQUIRE(cases.rows.size() == 5u);
    for (std::size_t k = 0; k < cases.rows.size(); ++k) CHECK(cases.at(k, "expected_met") == 1);
}

TEST_CASE("A curves-only run writes curve.csv and run.json, no series, with the same exit codes", "[cli]") {
    const fs::path out = scratch("curves_only");
    const Result r = command("run " + model("ring_elastic.toml") + " -o " + out.string() + " --curves-only -q");
    CHECK(r.code == 0);
    CHECK(fs::exists(out / "run.json"));
    CHECK_FALSE(fs::exists(out / "vtu"));
    CHECK_FALSE(fs::exists(out / "ring_elastic.pvd"));
    CHECK_FALSE(fs::exists(out / "frames"));
    std::ifstream csv(out / "curve.csv");
    std::string line, last;
    int rows = 0;
    while (std::getline(csv, line)) last = line, ++rows;
    CHECK(rows == 202); // header, step 0 and 200 steps
    CHECK(last.rfind("200,", 0) == 0);
    CHECK(read_csv(out / "curve.csv").at(200, "load") == Approx(elastic_ring_load_at_100).epsilon(1e-9));
    // A run that stops early still exits 3, its converged steps kept.
    const fs::path dir = scratch("curves_only_short");
    const fs::path scene = edited_model(dir, "short.toml", "max_steps = 2000", "max_steps = 5");
    const Result stopped = command("run " + scene.string() + " -o " + (dir / "out").string() + " --curves-only -q");
    CHECK(stopped.code == 3);
    CHECK(fs::exists(dir / "out" / "curve.csv"));
}

TEST_CASE("Drawing options given to a run that draws nothing say so", "[cli]") {
    const fs::path out = scratch("unused_drawing_options");
    const Result r = command("run " + model("ring_elastic.toml") + " -o " + out.string() + " --curves-only -q --magnify 5 --size 800x600");
    CHECK(r.code == 0);
    CHECK_THAT(r.output, Catch::Contains("note: --size changes nothing: --curves-only draws nothing"));
    CHECK_THAT(r.output, Catch::Contains("note: --magnify changes nothing: --curves-only draws nothing"));
    CHECK(read_json(out / "run.json").at("drawing_notes").size() == 2);
    // Defaults given by nobody are no note.
    const Result plain = command("run " + model("ring_elastic.toml") + " -o " + out.string() + " --no-render -q --force");
    CHECK(plain.code == 0);
    CHECK_THAT(plain.output, !Catch::Contains("changes nothing"));
    CHECK_FALSE(read_json(out / "run.json").contains("drawing_notes"));
}

TEST_CASE("run --set overrides scene keys and run.json records them", "[cli][overrides]") {
    const fs::path out = scratch("overrides");
    const Result r = command("run " + model("ring_inelastic.toml") + " --set section[ring].plasticity=distributed" +
                              " --set analysis.target_displacement=10 -o " + out.string() + " --curves-only -q");
    CHECK(r.code == 0);
    std::ifstream in(out / "run.json");
    std::stringstream json;
    json << in.rdbuf();
    CHECK_THAT(json.str(), Catch::Contains("\"section[ring].plasticity\": \"distributed\""));
    CHECK_THAT(json.str(), Catch::Contains("\"analysis.target_displacement\": \"10\""));
    CHECK_THAT(json.str(), Catch::Contains("\"control_displacement\": 10"));
    const Result bad = command("run " + model("ring_inelastic.toml") + " --set material[steel].fy=-1 -o " + out.string() + " -q");
    CHECK(bad.code == 2);
    CHECK_THAT(bad.output, Catch::Contains("--set material[steel].fy: expected a positive number, got -1"));
}

TEST_CASE("A sweep runs its variants in a pool, survives a failing one, resumes, and matches GNU Parallel", "[cli][sweep]") {
    const fs::path dir = scratch("sweep");
    const std::string base = "sweep " + model("ring_inelastic.toml") + " --vary analysis.target_displacement=20" +
                             " --vary 'material[steel].fy=20000,30000,36518' --at 10,20 -j 2 -o ";
    // Values are checked before any run starts (a bad one refuses the sweep); a run can still
    // fail where it runs: here the second run's folder is a file, so that run exits 2 and is
    // reported as failed, with the first line of its log, while the others complete.
    const auto block_second_run = [&](const fs::path& sweep) {
        fs::create_directories(sweep / "runs");
        std::ofstream(sweep / "runs" / "r0002") << "in the way";
    };
    block_second_run(dir / "pool");
    const Result r = command(base + (dir / "pool").string());
    CHECK(r.code == 3);
    CHECK_THAT(r.output, Catch::Contains("3 runs, 2 completed, 0 stopped early, 1 failed, 0 missing"));
    auto rows = [](const fs::path& csv) {
        std::ifstream in(csv);
        std::vector<std::string> lines;
        for (std::string l; std::getline(in, l);) lines.push_back(l);
        return lines;
    };
    // The charts of the finished runs: the curve family and the peak against each key.
    for (const char* chart : {"curves.png", "peak_1.png", "peak_2.png"}) CHECK(fs::file_size(dir / "pool" / chart) > 20000);
    CHECK_FALSE(fs::exists(dir / "pool" / "peak_distribution.png")); // a grid, not a sample
    const std::vector<std::string> pool = rows(dir / "pool" / "sweep.csv");
    REQUIRE(pool.size() == 4u);
    CHECK(pool[0] == "id,analysis.target_displacement,material[steel].fy,status,reason,peak_load,peak_displacement,load_at_10,load_at_20,iterations,steps,seconds");
    CHECK(pool[1].rfind("r0001,20,20000,completed,target displacement reached,", 0) == 0);
    CHECK_THAT(pool[2], Catch::StartsWith("r0002,20,30000,failed,") && Catch::Contains("exists and is not a folder"));
    CHECK(pool[3].rfind("r0003,20,36518,completed,", 0) == 0);
    // Resume: a lost run is run again, the finished ones are kept.
    fs::remove_all(dir / "pool" / "runs" / "r0003");
    const Result again = command(base + (dir / "pool").string());
    CHECK_THAT(again.output, Catch::Contains("1 runs had finished before and were kept"));
    CHECK(rows(dir / "pool" / "sweep.csv")[3].rfind("r0003,20,36518,completed,", 0) == 0);
    // The same sweep as jobs for GNU Parallel, then merged: the same table but for the timings.
    CHECK(command(base + (dir / "jobs").string() + " --emit jobs").code == 0);
    block_second_run(dir / "jobs");
    CHECK(fs::exists(dir / "jobs" / "sweep.sbatch"));
    CHECK(std::system(("parallel --will-cite -j 2 < " + (dir / "jobs" / "jobs.txt").string() + " > /dev/null 2>&1").c_str()) != -1);
    const Result merged = command("merge " + (dir / "jobs").string() + " --at 10,20");
    CHECK_THAT(merged.output, Catch::Contains("3 runs, 2 completed, 0 stopped early, 1 failed, 0 missing"));
    const std::vector<std::string> jobs = rows(dir / "jobs" / "sweep.csv");
    REQUIRE(jobs.size() == 4u);
    for (std::size_t k : {1u, 3u}) {
        // Up to the iterations: the timings differ.
        const std::string a = pool[k].substr(0, pool[k].rfind(',', pool[k].rfind(',') - 1));
        const std::string b = jobs[k].substr(0, jobs[k].rfind(',', jobs[k].rfind(',') - 1));
        CHECK(a == b);
    }
    CHECK_THAT(jobs[2], Catch::StartsWith("r0002,20,30000,failed,") && Catch::Contains("exists and is not a folder"));
}

TEST_CASE("A sweep with a bad value anywhere in its lists starts no run and writes no job", "[cli][sweep]") {
    const fs::path dir = fs::temp_directory_path() / ("plastica_sweep_checked_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    for (const char* mode : {"", " --emit jobs"}) {
        const Result r = command("sweep " + model("ring_elastic.toml") + " --vary analysis.scheme=displacement_control,bogus" +
                                 " --vary analysis.increment=1,2 -o " + dir.string() + mode);
        CHECK(r.code == 2);
        CHECK_THAT(r.output, Catch::Contains("got 'bogus'"));
        // The key, the value and the runs it would have been (the grid's third and fourth).
        CHECK_THAT(r.output, Catch::Contains("analysis.scheme = bogus in runs r0003, r0004"));
        CHECK_FALSE(fs::exists(dir / "runs"));
        CHECK_FALSE(fs::exists(dir / "jobs.txt"));
    }
    // A sample's extremes are checked too: a lognormal fy can never be negative, a normal one can.
    const Result sampled = command("sweep " + model("ring_inelastic.toml") + " --sample 'material[steel].fy=normal:100:1000' --samples 50 --seed 1 -o " +
                                   dir.string() + " --emit jobs");
    CHECK(sampled.code == 2);
    CHECK_THAT(sampled.output, Catch::Contains("material[steel].fy"));
}

TEST_CASE("A sampled sweep draws the distribution of its peak load", "[cli][sweep]") {
    const fs::path dir = scratch("sample");
    const Result s = command("sweep " + model("ring_inelastic.toml") + " --sample material[steel].fy=uniform:30000:40000" +
                              " --samples 6 --seed 5 -o " + dir.string());
    CHECK(s.code == 0);
    CHECK(fs::exists(dir / "sample.txt"));
    CHECK(fs::file_size(dir / "peak_distribution.png") > 20000);
    // The plan follows from --seed: the same values again.
    std::ifstream plan(dir / "plan.csv");
    std::stringstream first;
    first << plan.rdbuf();
    const fs::path again = scratch("sample_again");
    CHECK(command("sweep " + model("ring_inelastic.toml") + " --sample material[steel].fy=uniform:30000:40000" +
                   " --samples 6 --seed 5 --emit jobs -o " + again.string()).code == 0);
    std::ifstream plan2(again / "plan.csv");
    std::stringstream second;
    second << plan2.rdbuf();
    CHECK(first.str() == second.str());
}

TEST_CASE("A series that would fill a disk is refused before the run, with the way out", "[cli]") {
    const fs::path dir = scratch("unbounded");
    // 10 000 000 steps of a fixed tiny increment: about 10 million files.
    const fs::path scene = edited_model(dir, "tiny.toml", "max_steps = 2000", "max_steps = 10000000");
    fs::path tiny = dir / "tinier.toml";
    {
        std::ifstream in(scene);
        std::stringstream text;
        text << in.rdbuf();
        std::string s = text.str();
        s.replace(s.find("increment = 0.5"), 15, "increment = 0.00001");
        std::ofstream(tiny) << s;
    }
    const Result r = command("run " + tiny.string() + " -o " + (dir / "out").string() + " -q");
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains("VTU files") && Catch::Contains("--every"));
    CHECK_FALSE(fs::exists(dir / "out"));
    // With --every large enough, or curves only, the same scene is accepted (not run here).
}

TEST_CASE("Progress goes to a log as plain lines, without a terminal's redrawing", "[cli]") {
    const fs::path out = scratch("progress");
    const Result r = command("run " + model("ring_elastic.toml") + " -o " + out.string() + " --no-render");
    CHECK(r.code == 0);
    // Step 20 of 200 to the target displacement of 100: 10 % done, with the time left.
    CHECK_THAT(r.output, Catch::Contains("solving:  10 %  step 20  P ") && Catch::Contains("top displacement 10"));
    CHECK_THAT(r.output, Catch::Contains(" left\n"));
    CHECK(r.output.find('\r') == std::string::npos);
    CHECK(r.output.find("\033[K") == std::string::npos);
}

TEST_CASE("After a SIGKILL the folder still names its scene, and the same run may use it again", "[cli][signal]") {
    const fs::path dir = scratch("sigkill");
    fs::create_directories(dir);
    write_long_run(dir / "long.toml");
    const fs::path out = dir / "out";
    // Killed without a chance to clean up: run.json is the one written at the start.
    const std::string cmd = "env -u DISPLAY " + std::string(PLASTICA_BINARY) + " run " + (dir / "long.toml").string() +
                            " -o " + out.string() + " -q --no-render > /dev/null 2>&1 & pid=$!; " +
                            wait_for(out / "vtu" / "step_000010.vtu") + "kill -KILL $pid; wait $pid";
    const int status = std::system(cmd.c_str());
    CHECK(WEXITSTATUS(status) == 128 + 9);
    std::ifstream report(out / "run.json");
    std::stringstream json;
    json << report.rdbuf();
    CHECK_THAT(json.str(), Catch::Contains("\"status\": \"running\""));
    CHECK_THAT(json.str(), Catch::Contains("\"scene\": \"ring_inelastic\""));
    // The same scene again into its own folder: accepted, not "files of another program".
    CHECK(command("run " + model("ring_inelastic.toml") + " -o " + out.string() + " --no-render -q").code == 0);
    // Another scene into it is still refused.
    const Result other = command("run " + model("ring_elastic.toml") + " -o " + out.string() + " --no-render -q");
    CHECK(other.code == 2);
    CHECK_THAT(other.output, Catch::Contains("holds results of scene 'ring_inelastic'"));
}

TEST_CASE("Ctrl-C and SIGTERM stop a run cleanly: exit 130, valid series, run.json says so", "[cli][signal]") {
    const fs::path dir = scratch("signal");
    fs::create_directories(dir);
    write_long_run(dir / "long.toml");
    for (const char* signal : {"INT", "TERM"}) {
        const fs::path out = dir / signal;
        // Started in the background, stopped once it has written 100 steps (not after a fixed
        // time, which a busy machine may spend starting up); the shell reports its exit code.
        const std::string cmd = "env -u DISPLAY " + std::string(PLASTICA_BINARY) + " run " + (dir / "long.toml").string() +
                                " -o " + out.string() + " -q > /dev/null 2>&1 & pid=$!; " + wait_for(out / "vtu" / "step_000100.vtu") +
                                "kill -" + signal + " $pid; wait $pid";
        const int status = std::system(cmd.c_str());
        CHECK(WEXITSTATUS(status) == 130);
        std::ifstream report(out / "run.json");
        std::stringstream json;
        json << report.rdbuf();
        CHECK_THAT(json.str(), Catch::Contains("\"interrupted\""));
        // Every step the PVD lists exists; no temporary file is left under any name.
        std::ifstream pvd(out / "ring_inelastic.pvd");
        std::stringstream listing;
        listing << pvd.rdbuf();
        const std::string l = listing.str();
        int listed = 0;
        for (std::size_t at = l.find("file=\"vtu/"); at != std::string::npos; at = l.find("file=\"vtu/", at + 1)) {
            const std::string file = l.substr(at + 6, l.find('"', at + 6) - at - 6);
            CHECK(fs::exists(out / file));
            ++listed;
        }
        CHECK(listed > 2);
        CHECK(listed < 50000);
        for (const auto& entry : fs::recursive_directory_iterator(out))
            CHECK(entry.path().filename().string().find(".tmp") == std::string::npos);
        // The stopped series is a valid input to the render stage.
        CHECK(command("render " + out.string() + " --every 1000 --size 320x180 --no-animation -q").code == 0);
    }
}

// A disk that fills up mid-run, as RLIMIT_FSIZE lets a test have one (the writes fail with
// EFBIG where a full disk gives ENOSPC; both are the same failed write to plastica).
TEST_CASE("A disk that fills mid-run stops it with exit 3: every output ends at the same step, no temporary files", "[cli][output]") {
    // 8 kB: the first VTU cannot be written; 24 kB: curve.csv fills first (inelastic ring, whose
    // VTU files are 20.5 kB); 20 kB: the PVD fills first (elastic ring with arc-length times,
    // whose entries are longer).
    struct Case {
        int kilobytes;
        std::string scene, extra, full_file;
    };
    for (const Case& c : {Case{8, "ring_inelastic", "", "step_000000.vtu"}, Case{24, "ring_inelastic", "", "curve.csv"},
                          Case{20, "ring_elastic", "--time arc_length", "ring_elastic.pvd"}}) {
        CAPTURE(c.kilobytes, c.scene);
        const fs::path out = scratch("full_disk_" + c.scene + std::to_string(c.kilobytes));
        // sh's ulimit -f counts 512-byte blocks; XFSZ ignored so that the write fails instead.
        const std::string cmd = "cd " + fs::temp_directory_path().string() + " && sh -c \"trap '' XFSZ; ulimit -f " +
                                std::to_string(2 * c.kilobytes) + "; exec env -u DISPLAY " + PLASTICA_BINARY + " run " +
                                model(c.scene + ".toml") + " -o " + out.string() + " --force --no-render -q " + c.extra +
                                "\" > " + (out.string() + ".log") + " 2>&1";
        fs::remove_all(out);
        const int status = std::system(cmd.c_str());
        std::ifstream log(out.string() + ".log");
        std::stringstream message;
        message << log.rdbuf();
        CAPTURE(message.str());
        CHECK(WEXITSTATUS(status) == 3);
        CHECK(message.str().find(c.full_file + ": File too large") != std::string::npos);
        std::ifstream json(out / "run.json");
        std::stringstream report;
        report << json.rdbuf();
        CHECK(report.str().find("\"output_failed\"") != std::string::npos);
        // The last step in curve.csv, in the PVD and on disk is the same one.
        std::ifstream csv(out / "curve.csv");
        std::string line, last_row;
        while (std::getline(csv, line)) last_row = line;
        const int rows_last_step = last_row.rfind("step", 0) == 0 ? -1 : std::stoi(last_row);
        int vtu_files = 0, pvd_entries = 0;
        if (fs::exists(out / "vtu"))
            for (const auto& f : fs::directory_iterator(out / "vtu")) vtu_files += f.path().extension() == ".vtu";
        std::ifstream pvd(out / (c.scene + ".pvd"));
        std::string pvd_last;
        while (std::getline(pvd, line)) {
            pvd_entries += line.find("part=\"0\"") != std::string::npos;
            pvd_last = line;
        }
        CHECK(vtu_files == rows_last_step + 1);
        CHECK(pvd_entries == rows_last_step + 1);
        if (fs::exists(out / (c.scene + ".pvd"))) CHECK(pvd_last == "</VTKFile>"); // a complete collection
        CHECK(report.str().find("\"steps\": " + std::to_string(std::max(rows_last_step, 0))) != std::string::npos);
        for (const auto& f : fs::recursive_directory_iterator(out)) CHECK(f.path().string().find(".tmp") == std::string::npos);
    }
}

TEST_CASE("The ring's fy × ky sweep gives the same rows in-process, through GNU Parallel and merged", "[cli][sweep]") {
    const fs::path dir = scratch("sweep_grid");
    const std::string base = "sweep " + model("ring_inelastic.toml") + " --vary 'material[steel].fy=30000,36518,43000'" +
                             " --vary 'foundation[1].ky=600,1200,2400' --at 50,100 --no-charts -j 2 -o ";
    REQUIRE(command(base + (dir / "pool").string()).code == 0);
    REQUIRE(command(base + (dir / "jobs").string() + " --emit jobs").code == 0);
    REQUIRE(std::system(("parallel --will-cite -j 2 < " + (dir / "jobs" / "jobs.txt").string() + " > /dev/null 2>&1").c_str()) == 0);
    const Result merged = command("merge " + (dir / "jobs").string() + " --at 50,100");
    CHECK_THAT(merged.output, Catch::Contains("9 runs, 9 completed, 0 stopped early, 0 failed, 0 missing"));
    auto rows = [](const fs::path& csv) {
        std::ifstream in(csv);
        std::vector<std::string> lines;
        // Each row up to its iterations: the last two columns (steps, seconds) hold the timing.
        for (std::string l; std::getline(in, l);) lines.push_back(l.substr(0, l.rfind(',')));
        return lines;
    };
    const std::vector<std::string> pool = rows(dir / "pool" / "sweep.csv"), jobs = rows(dir / "jobs" / "sweep.csv");
    REQUIRE(pool.size() == 10u);
    CHECK(pool == jobs);
    // The variants differ: nine distinct peak loads (the column after the reason).
    std::set<std::string> peaks;
    for (std::size_t k = 1; k < pool.size(); ++k) {
        const std::size_t at = pool[k].find("target displacement reached,");
        REQUIRE(at != std::string::npos);
        const std::string rest = pool[k].substr(at + 28);
        peaks.insert(rest.substr(0, rest.find(',')));
    }
    CHECK(peaks.size() == 9u);
}

TEST_CASE("A sweep's runs write curves by default, their series or their pictures on request", "[cli][sweep]") {
    const fs::path dir = scratch("sweep_output");
    const std::string base = "sweep " + model("ring_elastic.toml") + " --vary analysis.target_displacement=10,20 --no-charts -o ";
    REQUIRE(command(base + (dir / "curves").string()).code == 0);
    CHECK(fs::exists(dir / "curves" / "runs" / "r0001" / "curve.csv"));
    CHECK_FALSE(fs::exists(dir / "curves" / "runs" / "r0001" / "ring_elastic.pvd"));
    REQUIRE(command(base + (dir / "series").string() + " --run-output series").code == 0);
    CHECK(fs::exists(dir / "series" / "runs" / "r0002" / "ring_elastic.pvd"));
    CHECK_FALSE(fs::exists(dir / "series" / "runs" / "r0002" / "chart.png"));
    REQUIRE(command(base + (dir / "pictures").string() + " --run-output pictures").code == 0);
    CHECK(fs::exists(dir / "pictures" / "runs" / "r0002" / "chart.png"));
    const Result bad = command(base + (dir / "bad").string() + " --run-output frames");
    CHECK(bad.code == 2);
    CHECK_THAT(bad.output, Catch::Contains("--run-output takes curves, series or pictures, got 'frames'"));
}

namespace {

// The page as a real browser has it after loading: headless Chromium's DOM (scripts run).
std::string browser_dom(const fs::path& page) {
    const fs::path dom = page.string() + ".dom";
    const std::string cmd = "timeout 120 chromium --headless --no-sandbox --disable-gpu --dump-dom 'file://" + fs::absolute(page).string() +
                            "' > '" + dom.string() + "' 2>/dev/null";
    REQUIRE(std::system(cmd.c_str()) == 0);
    std::ifstream in(dom);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace

TEST_CASE("plastica report writes one page a browser shows whole, and compare --report shows each failing picture", "[cli][report]") {
    const fs::path out = scratch("report");
    REQUIRE(command("run " + model("ring_elastic.toml") + " -o " + out.string() + " --steps 0,100,200 -q").code == 0);
    CHECK(read_json(out / "run.json")["seconds"]["drawing"].get<double>() > 0.0);
    const Result r = command("report " + out.string());
    REQUIRE(r.code == 0);
    const fs::path page = out / "report.html";
    REQUIRE(fs::exists(page));
    // Chart, contact sheet, animation and the key frames named by what happens in them (the
    // elastic ring peaks at its last step), all embedded: the page stands alone.
    const fs::path moved = scratch("report_page") / "page.html";
    fs::create_directories(moved.parent_path());
    fs::copy_file(page, moved);
    const std::string dom = browser_dom(moved);
    CHECK_THAT(dom, Catch::Contains("5 of 5 images loaded"));
    CHECK_THAT(dom, Catch::Contains("start (frame_000000)"));
    CHECK_THAT(dom, Catch::Contains("peak P, last step (frame_000200)"));
    CHECK_THAT(dom, Catch::Contains("steps (converged, each written)"));
    CHECK_THAT(dom, Catch::Contains("Elastic ring on a unilateral base"));
    CHECK_THAT(dom, Catch::Contains("completed: target displacement reached"));
    CHECK_THAT(dom, Catch::Contains("Newton iterations"));
    CHECK_THAT(dom, Catch::Contains("peak P (at top displacement)"));
    // The model as the browser shows it: its section with the squash load, both supports, the
    // loads and the analysis settings.
    CHECK_THAT(dom, Catch::Contains("<h2>Model</h2>"));
    CHECK_THAT(dom, Catch::Contains("N_y (squash load)"));
    CHECK_THAT(dom, Catch::Contains("<h3>Supports</h3>"));
    CHECK_THAT(dom, Catch::Contains("(0, 200)"));
    CHECK_THAT(dom, Catch::Contains("<h3>Loads by pattern"));
    CHECK_THAT(dom, Catch::Contains("<h3>Analysis</h3>"));
    CHECK_THAT(dom, Catch::Contains("displacement_control"));
    // Drawn to pixels by the same browser.
    const fs::path shot = moved.parent_path() / "page.png";
    REQUIRE(std::system(("timeout 120 chromium --headless --no-sandbox --disable-gpu --window-size=1280,2000 --screenshot='" +
                         shot.string() + "' 'file://" + moved.string() + "' > /dev/null 2>&1").c_str()) == 0);
    CHECK(fs::file_size(shot) > 50000);

    // A comparison with one picture changed: that one beside its reference and its difference.
    const fs::path stored = scratch("report_stored");
    fs::copy(out / "frames", stored);
    fs::copy_file(out / "frames" / "frame_000200.png", stored / "frame_000100.png", fs::copy_options::overwrite_existing);
    const fs::path comparison = scratch("report_compare") / "compare.html";
    fs::create_directories(comparison.parent_path());
    const Result c = command("compare " + (out / "frames").string() + " " + stored.string() + " --report " + comparison.string());
    CHECK(c.code == 1);
    const std::string compared = browser_dom(comparison);
    CHECK_THAT(compared, Catch::Contains("1 of 3 images differ"));
    CHECK_THAT(compared, Catch::Contains("frame_000100.png"));
    CHECK_THAT(compared, Catch::Contains("3 of 3 images loaded"));

    const Result bad = command("report " + scratch("report_nothing").string());
    CHECK(bad.code == 2);
    CHECK_THAT(bad.output, Catch::Contains("holds no run.json"));
}

TEST_CASE("The report names the first yield and the peak among its key frames whatever --every skips", "[cli][report]") {
    // The gallery's portal, drawn every 8th step: it yields first at step 3 and peaks at step 29,
    // neither a multiple of 8; both are drawn and shown by name, and the counts add up.
    const fs::path out = scratch("report_keys");
    REQUIRE(command("run " + model("gallery/portal_frame.toml") + " -o " + out.string() + " --no-render -q").code == 0);
    REQUIRE(command("render " + out.string() + " --every 8 --size 640x360 --no-animation -q").code == 0);
    REQUIRE(command("report " + out.string()).code == 0);
    std::ifstream in(out / "report.html");
    const std::string page((std::istreambuf_iterator<char>(in)), {});
    CHECK_THAT(page, Catch::Contains("first yield (frame_000003)"));
    CHECK_THAT(page, Catch::Contains("peak load factor (frame_000029)"));
    CHECK_THAT(page, Catch::Contains("last step (frame_000056)"));
    CHECK(fs::exists(out / "frames" / "frame_000003.png"));
    CHECK(fs::exists(out / "frames" / "frame_000029.png"));
    CHECK_THAT(page, Catch::Contains("74 / 0 (56 steps kept + 18 refined)"));
    // The model: the HEB 300's capacities as `plastica section` gives them, both clamps, the loads.
    CHECK_THAT(page, Catch::Contains("<h2>Model</h2>"));
    CHECK_THAT(page, Catch::Contains("M_p at N = 0"));
    const nlohmann::json run = read_json(out / "run.json");
    const auto& section = run["model"]["sections"][0];
    CHECK(section["squash_load"].get<double>() == Approx(section["fy"].get<double>() * section["area"].get<double>()).epsilon(1e-3));
    CHECK(run["model"]["supports"].size() == 2);
    CHECK(run["model"]["load_patterns"][0]["sum_fy"].get<double>() == Approx(-5600.0));
    CHECK(run["model"]["load_patterns"][0]["sum_fx"].get<double>() == Approx(35.0));
}

TEST_CASE("A scene with [units] carries them into run.json and the VTU and its report page heads", "[cli][units]") {
    const fs::path out = scratch("units");
    REQUIRE(command("run " + std::string(PLASTICA_SOURCE_DIR) + "/tests/frames/portal_in_millimetres.toml -o " + out.string() +
                    " --no-render -q")
                .code == 0);
    REQUIRE(command("report " + out.string()).code == 0);
    const nlohmann::json run = read_json(out / "run.json");
    CHECK(run["model"]["units"]["length"] == "mm");
    CHECK(run["model"]["units"]["force"] == "kN");
    // 210 GPa = 210 kN/mm²; the HEB 200's M_p(0) 220.1 kN·m in kN·mm; its peak is the portal's in metres.
    CHECK(run["model"]["sections"][0]["E"].get<double>() == Approx(210.0));
    CHECK(run["model"]["sections"][0]["plastic_moment"].get<double>() == Approx(220108.9).epsilon(1e-5));
    CHECK(run["peak"]["load"].get<double>() == Approx(1.79834).epsilon(1e-5));
    std::ifstream in(out / "report.html");
    const std::string page((std::istreambuf_iterator<char>(in)), {});
    CHECK_THAT(page, Catch::Contains("E (kN/mm²)") && Catch::Contains("M_p at N = 0 (kN·mm)"));
    std::ifstream step(out / "vtu" / "step_000010.vtu");
    const std::string vtu((std::istreambuf_iterator<char>(step)), {});
    CHECK_THAT(vtu, Catch::Contains("Name=\"length_unit\""));
}

TEST_CASE("Likely unit mistakes are warned of on stderr and in run.json, and the run goes on", "[cli][warnings]") {
    // fy in MPa beside E in kN/m² (fy/E = 1.7e-6), and a section 200 deep on a frame in metres.
    const fs::path dir = scratch("warnings");
    fs::create_directories(dir);
    std::ifstream in(std::string(PLASTICA_SOURCE_DIR) + "/tests/frames/portal_weak_columns.toml");
    std::stringstream text;
    text << in.rdbuf();
    const std::string scene = text.str();
    const auto variant = [&](const std::string& from, const std::string& to, const std::string& name) {
        std::string s = scene;
        REQUIRE(s.find(from) != std::string::npos);
        s.replace(s.find(from), from.size(), to);
        const fs::path file = dir / (name + ".toml");
        std::ofstream(file) << s;
        return file.string();
    };
    const Result mpa = command("run " + variant("fy = 3.55e5", "fy = 355.0", "mpa") + " --curves-only -q -o " + (dir / "mpa").string());
    CHECK(mpa.code == 0);
    CHECK_THAT(mpa.output, Catch::Contains("warning: section 'HEB200': its material's fy/E is 1.69e-06, outside 1e-5 … 2e-2"));
    const nlohmann::json report = read_json(dir / "mpa" / "run.json");
    REQUIRE(report.contains("warnings"));
    CHECK(report["warnings"].size() == 2u);
    const Result mm = command("run " + variant("depth = 0.2\n", "depth = 200.0\n", "mm") + " --curves-only -q --set analysis.max_steps=3 -o " +
                              (dir / "mm").string());
    CHECK_THAT(mm.output, Catch::Contains("warning: section 'HEB200': 200 deep on a structure 7.21 across"));
    // The shipped scenes raise none.
    const Result ring = command("run " + model("ring_inelastic.toml") + " --curves-only -q --set analysis.max_steps=2 -o " + (dir / "ring").string());
    CHECK_THAT(ring.output, !Catch::Contains("warning"));
    CHECK_FALSE(read_json(dir / "ring" / "run.json").contains("warnings"));
}

TEST_CASE("plastica modes writes periods, effective masses and the shapes, at rest or at a step", "[cli][dynamics]") {
    const fs::path at_rest = scratch("modes_rest"), loaded = scratch("modes_loaded");
    const Result r = command("modes " + model("gallery/frame_shaken.toml") + " -n 3 -q -o " + at_rest.string());
    REQUIRE(r.code == 0);
    CHECK(fs::exists(at_rest / "contact_sheet.png"));
    CHECK(fs::exists(at_rest / "frame_shaken.pvd"));
    auto rows = [](const fs::path& folder) {
        std::ifstream in(folder / "modes.csv");
        std::string header, line;
        std::getline(in, header);
        CHECK(header == "mode,period,frequency,omega,effective_mass_x,effective_mass_y,share_x,share_y");
        std::vector<std::vector<double>> out;
        while (std::getline(in, line)) {
            std::vector<double> row;
            std::stringstream cells(line);
            for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
            out.push_back(row);
        }
        return out;
    };
    const auto rest = rows(at_rest);
    REQUIRE(rest.size() == 3u);
    // The first mode sways: it carries nearly all of the 100 t at the beam and the columns' share.
    CHECK(rest[0][6] > 0.99);
    CHECK(rest[0][1] * rest[0][2] == Approx(1.0));
    // Under its gravity (step 4) the frame sways more slowly: P-Δ takes stiffness away.
    REQUIRE(command("modes " + model("gallery/frame_shaken.toml") + " -n 1 -q --no-render --step 4 -o " + loaded.string()).code == 0);
    const auto held = rows(loaded);
    CHECK(held[0][1] > rest[0][1] * 1.005);
    CHECK(command("modes " + model("gallery/frame_shaken.toml") + " --step 100000 --no-render -o " + loaded.string()).code == 2);
}

TEST_CASE("A run in time writes its time and energies, a PVD in model time, and the drift and hysteresis charts", "[cli][dynamics]") {
    const fs::path out = scratch("frame_shaken");
    const Result r = command("run " + model("gallery/frame_shaken.toml") + " -q -o " + out.string());
    REQUIRE(r.code == 0);
    std::ifstream curve(out / "curve.csv");
    std::string header;
    std::getline(curve, header);
    CHECK_THAT(header, Catch::Contains(",time,kinetic_energy,strain_energy,plastic_dissipation,damping_work,contact_work,external_work,"
                                       "ground_motion_work,energy_error"));
    std::ifstream pvd(out / "frame_shaken.pvd");
    std::stringstream text;
    text << pvd.rdbuf();
    CHECK_THAT(text.str(), Catch::Contains("timestep=\"10\""));
    const nlohmann::json run = read_json(out / "run.json");
    CHECK(run["dynamics"]["time"] == 10.0);
    CHECK(run["dynamics"]["largest_energy_error"].get<double>() < 1e-6);
    CHECK(run["dynamics"]["damping"]["alpha_m"].get<double>() > 0.0);
    // Frames by model time, 12 to a second: the 10 s run in 10 s by default (121 frames), in 5 s
    // at twice the speed.
    auto frames = [](const fs::path& folder) {
        return std::distance(fs::directory_iterator(folder / "frames"), fs::directory_iterator{});
    };
    CHECK(frames(out) == 121);
    const fs::path faster = scratch("frame_shaken_faster");
    REQUIRE(command("render " + out.string() + " -o " + faster.string() + " --speed 2 --no-animation -q").code == 0);
    CHECK(frames(faster) == 61);
    CHECK(command("render " + out.string() + " -o " + faster.string() + " --speed -1 -q").code == 2);
    for (const char* picture : {"chart.png", "hysteresis.png", "energy.png", "contact_sheet.png"}) {
        CAPTURE(picture);
        REQUIRE(fs::exists(out / picture));
        CHECK(ink(out / picture) > 0.02);
    }
}

TEST_CASE("A flattening test reports the load at given travels and where its walls meet, apart from the crushing peak", "[cli][report]") {
    // models/gallery/steel_pipe_flattened.toml asks for the load at δ = 50, 100, 150 (δ/D =
    // 0.25, 0.5, 0.75) and has [[self_contact]]: the peak is the crushing curve's, before the
    // walls meet; the force beyond is the contact penalty's and is reported as such.
    const fs::path out = scratch("flattened");
    const Result r = command("run " + model("gallery/steel_pipe_flattened.toml") + " -o " + out.string() + " --no-render -q");
    REQUIRE(r.code == 0);
    const CsvTable curve = read_csv(out / "curve.csv");
    const nlohmann::json run = read_json(out / "run.json");
    REQUIRE(run["load_at"].size() == 3u);
    for (const nlohmann::json& at : run["load_at"]) {
        const double target = at["control_displacement"].get<double>();
        // The load between the two steps that straddle the travel, on their chord.
        std::size_t k = 1;
        while (k < curve.rows.size() && curve.at(k, "control_displacement") < target) ++k;
        REQUIRE(k < curve.rows.size());
        const double d0 = curve.at(k - 1, "control_displacement"), d1 = curve.at(k, "control_displacement");
        const double p0 = curve.at(k - 1, "load"), p1 = curve.at(k, "load");
        CAPTURE(target);
        CHECK(at["load"].get<double>() == Approx(p0 + (target - d0) / (d1 - d0) * (p1 - p0)).epsilon(1e-9));
    }
    const nlohmann::json& contact = run["self_contact"];
    REQUIRE(contact["closed"] == true);
    // The walls meet near a travel of 2R − h = 195 (the plates touch the walls' centre lines).
    CHECK(contact["control_displacement"].get<double>() > 185.0);
    CHECK(run["peak"]["control_displacement"].get<double>() < contact["control_displacement"].get<double>());
    CHECK(run["peak"]["load"].get<double>() < 0.2 * run["final"]["load"].get<double>());
    const double share = contact["final_share_of_load"].get<double>();
    CHECK(share > 0.0);
    CHECK(share <= 1.0);
}
