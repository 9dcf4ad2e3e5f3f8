// Files and names from someone else: texts without control characters, names that stay inside
// a folder, reads that are bounded and never follow a link out, and output folders that are one
// writer's own (lock, manifest, links refused, removal noticed).
#include "bounded_file.hpp"
#include "model_building.hpp"
#include "output_folder.hpp"
#include "safe_names.hpp"
#include "scene_error.hpp"
#include "scene_overrides.hpp"
#include "scene_reader.hpp"

#include "scratch_files.hpp"

#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <thread>

using namespace plastica;
namespace fs = std::filesystem;

namespace {

fs::path fresh_folder(const std::string& name) { return scratch::fresh_folder("untrusted_" + name); }
using scratch::read;
using scratch::write;

std::string scene_message(const std::string& text) {
    try {
        read_scene_text(text, "bad.toml");
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

// The shipped cantilever, its title replaced.
const std::string bar = [] {
    std::ifstream in(std::string(PLASTICA_SOURCE_DIR) + "/models/cantilever_tip_load.toml");
    return std::string(std::istreambuf_iterator<char>(in), {});
}();

std::string with_title(const std::string& title) {
    std::string text = bar;
    const std::string line = "title = \"Cantilever under a tip load (exact elastica)\"";
    return text.replace(text.find(line), line.size(), "title = \"" + title + "\"");
}

} // namespace

TEST_CASE("Names from a scene become file names that stay inside their folder", "[untrusted]") {
    CHECK(is_plain_name("ring_elastic-2"));
    CHECK_FALSE(is_plain_name("../x"));
    CHECK_FALSE(is_plain_name(""));
    CHECK_FALSE(is_plain_name(std::string(65, 'a')));
    CHECK(file_stem_for("HEB 200") == "HEB_200");
    CHECK(file_stem_for("../../x") == "______x");
    CHECK(file_stem_for("/etc/passwd") == "_etc_passwd");
    CHECK(file_stem_for("") == "_");
    CHECK(file_stem_for(std::string(100, 'a')).size() == 64);
    CHECK(is_plain_relative_path("frames/frame_000001.png"));
    for (const char* bad : {"../x", "/etc/passwd", "a/../b", "a//b", "./a", "a/", "", "a\nb"})
        CHECK_FALSE(is_plain_relative_path(bad));
}

TEST_CASE("A text with a NUL or a control character, or longer than 1024 bytes, is refused at its line", "[untrusted]") {
    CHECK(scene_message(with_title("a plain title, with tab\\t")).empty());
    CHECK_THAT(scene_message(with_title("a\\u0000b")), Catch::Contains("bad.toml:6") && Catch::Contains("NUL character at position 2"));
    CHECK_THAT(scene_message(with_title("line\\nbreak")), Catch::Contains("bad.toml:6") && Catch::Contains("control character"));
    CHECK_THAT(scene_message(with_title(std::string(1025, 'x'))), Catch::Contains("1025 bytes long, more than the 1024"));
    CHECK(scene_message(with_title(std::string(1024, 'x'))).empty());
}

TEST_CASE("A misspelt required key is named at its own line, not reported as missing", "[scene]") {
    std::string text = bar;
    const std::string key = "I = 1.0";
    text.replace(text.find(key), key.size(), "I_ = 1.0");
    CHECK_THAT(scene_message(text), Catch::Contains("bad.toml:16") && Catch::Contains("'section[1].I_': unknown key; did you mean 'I'?"));
}

TEST_CASE("An override's index of any length is refused without overflow", "[untrusted]") {
    for (const char* index : {"18446744073709551617", "99999999999999999999999999", "0"}) {
        try {
            read_scene_text(bar, "cantilever.toml", {parse_override(std::string("material[") + index + "].E=1")});
            FAIL("accepted material[" << index << "]");
        } catch (const SceneError& e) {
            CHECK_THAT(e.what(), Catch::Contains("the scene has 1 [[material]] table(s), not " + std::string(index)));
        }
    }
}

TEST_CASE("Reading is bounded: devices, FIFOs and files over the limit are refused by name", "[untrusted]") {
    const fs::path dir = fresh_folder("bounded");
    CHECK_THROWS_WITH(read_bounded_file("/dev/zero", 1024), Catch::Contains("/dev/zero is not a regular file"));
    const fs::path fifo = dir / "fifo";
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    CHECK_THROWS_WITH(read_bounded_file(fifo.string(), 1024), Catch::Contains("is not a regular file"));
    write(dir / "big.txt", std::string(2000, 'x'));
    CHECK_THROWS_WITH(read_bounded_file((dir / "big.txt").string(), 1024), Catch::Contains("2000 bytes"));
    CHECK(read_bounded_file((dir / "big.txt").string(), 2000).size() == 2000);
    try {
        read_scene("/dev/zero");
        FAIL("read /dev/zero as a scene");
    } catch (const SceneError& e) {
        CHECK_THAT(e.what(), Catch::Contains("not a regular file"));
    }
}

TEST_CASE("A file a folder names is read only inside it, never through a symbolic link", "[untrusted]") {
    const fs::path dir = fresh_folder("inside");
    write(dir / "outside" / "secret.txt", "secret");
    const fs::path folder = dir / "results";
    write(folder / "run.json", "{}");
    write(folder / "frames" / "frame_000001.png", "png");
    fs::create_symlink(dir / "outside" / "secret.txt", folder / "chart.png");
    fs::create_symlink(dir / "outside", folder / "vtu");
    CHECK(read_file_inside(folder.string(), "run.json", 100) == "{}");
    CHECK(read_file_inside(folder.string(), "frames/frame_000001.png", 100) == "png");
    CHECK(is_file_inside(folder.string(), "run.json"));
    CHECK_FALSE(is_file_inside(folder.string(), "chart.png"));
    CHECK_FALSE(is_file_inside(folder.string(), "vtu/secret.txt"));
    CHECK_FALSE(is_file_inside(folder.string(), "../outside/secret.txt"));
    CHECK_FALSE(is_file_inside(folder.string(), "/etc/passwd"));
    CHECK_THROWS_WITH(read_file_inside(folder.string(), "chart.png", 100), Catch::Contains("symbolic link"));
    CHECK_THROWS_WITH(read_file_inside(folder.string(), "vtu/secret.txt", 100), Catch::Contains("symbolic link"));
    CHECK_THROWS_WITH(read_file_inside(folder.string(), "../outside/secret.txt", 100), Catch::Contains("not a plain file name"));
}

TEST_CASE("An output folder takes one writer at a time, a process's thread included, and names the holder", "[untrusted]") {
    const fs::path dir = fresh_folder("lock");
    OutputFolderOptions o;
    o.scene_name = "bar";
    o.holder = "the first writer";
    const OutputFolder first(dir.string(), o);
    std::string refused;
    std::thread other([&] {
        try {
            OutputFolderOptions again;
            again.scene_name = "bar";
            const OutputFolder second(dir.string(), again);
        } catch (const OutputFolderError& e) {
            refused = e.what();
        }
    });
    other.join();
    CHECK_THAT(refused, Catch::Contains("is in use by process " + std::to_string(::getpid()) + " (the first writer)"));
}

TEST_CASE("A rerun removes only what the run before wrote, never the user's files or its own inputs", "[untrusted]") {
    const fs::path dir = fresh_folder("manifest");
    OutputFolderOptions o;
    o.scene_name = "bar";
    {
        const OutputFolder run(dir.string(), o);
        write(dir / "run.json", R"({"program": "plastica", "scene": "bar", "status": "completed"})");
        write(dir / "curve.csv", "step,load\n");
        write(dir / "frames" / "frame_000007.png", "old frame");
        write(dir / "measured.csv", "written by this run too");
    }
    CHECK_THAT(read(dir / manifest_file_name), Catch::Contains("frames/frame_000007.png") && Catch::Contains("measured.csv"));
    write(dir / "notes.txt", "the user's notes");
    write(dir / "photo.png", "the user's photo");
    o.inputs = {(dir / "measured.csv").string()};
    {
        const OutputFolder rerun(dir.string(), o);
        CHECK_FALSE(fs::exists(dir / "curve.csv"));
        CHECK_FALSE(fs::exists(dir / "frames" / "frame_000007.png"));
        CHECK(read(dir / "notes.txt") == "the user's notes");
        CHECK(read(dir / "photo.png") == "the user's photo");
        CHECK(fs::exists(dir / "measured.csv")); // an input of this run
        write(dir / "curve.csv", "step,load\n");
    }
    const std::string manifest = read(dir / manifest_file_name);
    CHECK_THAT(manifest, Catch::Contains("curve.csv"));
    CHECK_THAT(manifest, !Catch::Contains("notes.txt") && !Catch::Contains("photo.png"));
}

TEST_CASE("A folder of an earlier version without a manifest loses only the files a run writes", "[untrusted]") {
    const fs::path dir = fresh_folder("legacy");
    write(dir / "run.json", R"({"program": "plastica", "scene": "bar", "status": "completed"})");
    write(dir / "chart.png", "old chart");
    write(dir / "bar.gif", "old animation");
    write(dir / "frames" / "frame_000001.png", "old frame");
    write(dir / "measured.csv", "the user's curve");
    write(dir / "notes.json", "{}");
    OutputFolderOptions o;
    o.scene_name = "bar";
    const OutputFolder rerun(dir.string(), o);
    CHECK_FALSE(fs::exists(dir / "chart.png"));
    CHECK_FALSE(fs::exists(dir / "bar.gif"));
    CHECK_FALSE(fs::exists(dir / "frames" / "frame_000001.png"));
    CHECK(read(dir / "measured.csv") == "the user's curve");
    CHECK(fs::exists(dir / "notes.json"));
}

TEST_CASE("Symbolic links where results go are refused before anything is written", "[untrusted]") {
    const fs::path dir = fresh_folder("links");
    write(dir / "outside.txt", "keep me");
    OutputFolderOptions o;
    o.scene_name = "bar";
    for (const char* link : {"vtu/step_000003.vtu", "frames", "curve.csv", "bar.pvd"}) {
        const fs::path folder = dir / ("run_" + file_stem_for(link));
        fs::create_directories((folder / link).parent_path());
        fs::create_symlink(dir / "outside.txt", folder / link);
        CHECK_THROWS_WITH(OutputFolder(folder.string(), o), Catch::Contains(link) && Catch::Contains("is a symbolic link"));
    }
    CHECK(read(dir / "outside.txt") == "keep me");
}

TEST_CASE("A removed output folder is noticed, and stale temporaries are cleared", "[untrusted]") {
    const fs::path dir = fresh_folder("removed");
    write(dir / "run" / "frames" / "frame_000001.png.tmp12345", "left by a killed drawing");
    write(dir / "run" / "bar.gif.tmp999.rgb", std::string(1000, 'x'));
    write(dir / "run" / "measurements.tmp2024", "the user's, named like a temporary");
    OutputFolderOptions o;
    o.scene_name = "bar";
    o.force = true;
    const OutputFolder run((dir / "run").string(), o);
    CHECK_FALSE(fs::exists(dir / "run" / "frames" / "frame_000001.png.tmp12345"));
    CHECK_FALSE(fs::exists(dir / "run" / "bar.gif.tmp999.rgb"));
    CHECK(fs::exists(dir / "run" / "measurements.tmp2024"));
    CHECK(run.still_there());
    fs::remove_all(dir / "run");
    CHECK_FALSE(run.still_there());
    fs::create_directories(dir / "run"); // a new folder of the same name is not the run's
    CHECK_FALSE(run.still_there());
}

TEST_CASE("Fibre set-up beyond the machine's memory is refused with the estimate", "[untrusted]") {
    Model model = read_scene_text(bar, "cantilever.toml");
    CHECK_FALSE(setup_too_large(model));
    // Hinges of 100 fibres at both ends of 10⁶ elements: 2·10⁸ fibre states, 60 GB.
    model.elements.resize(1);
    model.sections[0].steel.emplace();
    model.sections[0].plasticity = Plasticity::hinges;
    model.sections[0].fibres.resize(100);
    model.elements.resize(1'000'000, model.elements.front());
    CHECK(fibre_states(model) == Approx(2e8));
    const std::optional<std::string> why = setup_too_large(model);
    REQUIRE(why);
    CHECK_THAT(*why, Catch::Contains("about 60 GB") && Catch::Contains("2e+08 fibre states"));
}
