// The command line given hostile or careless input, end to end: no command runs from a value, no
// file outside the folders asked for is written or read, no crash, one writer a folder, and the
// documented exit codes (2 bad input, 3 stopped early or output not written, 130 interrupted).
#include "cli_helpers.hpp"

#include "scratch_files.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <sys/mount.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fs = std::filesystem;
using cli_test::command;
using cli_test::model;
using cli_test::Result;

namespace {

fs::path fresh_folder(const std::string& name) { return scratch::fresh_folder("hostile_" + name); }
using scratch::read;
using scratch::write;

// Shell text with $PLASTICA set to the program: for runs side by side and signals.
cli_test::Result shell(const std::string& script) {
    const fs::path file = fs::temp_directory_path() / ("plastica_hostile_" + std::to_string(::getpid()) + ".sh");
    write(file, "PLASTICA='" + std::string(PLASTICA_BINARY) + "'\n" + script);
    const std::string log = file.string() + ".log";
    const int status = std::system(("env -u DISPLAY sh " + file.string() + " > " + log + " 2>&1").c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read(log)};
}

bool any_temporary_below(const fs::path& dir) {
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.path().filename().string().find(".tmp") != std::string::npos) return true;
    return false;
}

// A run slow enough to be caught in the middle on a loaded machine (400 steps of hinges of 3000
// fibres, about 4 s in Release): a second command started after its fifth step finds it running.
const std::string slow_ring = model("ring_inelastic.toml") + " --set 'section[1].fibres=3000' --set analysis.increment=0.25 --no-render -q";

} // namespace

TEST_CASE("A sweep value or output folder holding a newline is refused before any job is written", "[untrusted]") {
    const fs::path dir = fresh_folder("newline");
    const Result value = command("sweep " + model("ring_elastic.toml") + " --vary \"$(printf 'analysis.increment=1\\nrm -rf x')\" --emit jobs -o " +
                                 (dir / "sweep").string());
    CHECK(value.code == 2);
    CHECK_THAT(value.output, Catch::Contains("newline"));
    CHECK_FALSE(fs::exists(dir / "sweep" / "jobs.txt"));
    const Result folder = command("sweep " + model("ring_elastic.toml") + " --vary analysis.increment=1,2 --emit jobs -o \"" + dir.string() +
                                  "/$(printf 'a\\nb')\"");
    CHECK(folder.code == 2);
    CHECK_THAT(folder.output, Catch::Contains("output folder may not hold a newline"));
}

TEST_CASE("Emitted jobs run each value as one argument under GNU Parallel and as a Slurm array task", "[untrusted]") {
    const fs::path dir = fresh_folder("jobs");
    const fs::path sweep = dir / "it's a sweep";
    // Values a shell would run, were they not quoted; and a folder with a space and a quote.
    const std::string marker = (dir / "ran").string();
    const std::string values = "\"$(touch " + marker + "1)\",\"; touch " + marker + "2\",\"`touch " + marker + "3`\"";
    const Result emitted = command("sweep " + model("ring_elastic.toml") + " --vary 'scene.title=" + values + "' --emit jobs -o \"" +
                                   sweep.string() + "\"");
    REQUIRE(emitted.code == 0);
    std::ifstream jobs(sweep / "jobs.txt");
    int lines = 0;
    for (std::string line; std::getline(jobs, line);) ++lines;
    CHECK(lines == 3);
    const Result parallel = shell("cd \"" + sweep.string() + "\" && parallel --will-cite < jobs.txt");
    CHECK(parallel.code == 0);
    // The array task as Slurm starts it: the script with its task number.
    const Result task = shell("cd \"" + sweep.string() + "\" && rm -rf runs/r0002 && SLURM_ARRAY_TASK_ID=2 bash sweep.sbatch");
    CHECK(task.code == 0);
    for (const char* n : {"1", "2", "3"}) CHECK_FALSE(fs::exists(marker + n));
    const auto title = [&](const char* id) {
        return nlohmann::json::parse(read(sweep / "runs" / id / "run.json")).value("title", "");
    };
    CHECK(title("r0001") == "$(touch " + marker + "1)");
    CHECK(title("r0002") == "; touch " + marker + "2");
    CHECK(title("r0003") == "`touch " + marker + "3`");
}

TEST_CASE("A sweep whose lists multiply past a million runs is refused, however long they are", "[untrusted]") {
    std::string vary;
    std::string values = "1";
    for (int k = 2; k <= 65536; k *= 2) values += "," + std::to_string(k); // 17 values
    for (int k = 0; k < 16; ++k) vary += " --vary 'analysis.increment=" + values + "'";
    const Result r = command("sweep " + model("ring_elastic.toml") + vary + " --emit jobs -o " + fresh_folder("grid").string());
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains("more than 1000000 runs"));
}

TEST_CASE("Section names become file names inside the output folder", "[untrusted]") {
    const fs::path dir = fresh_folder("section_names");
    std::string scene = read(model("gallery/portal_frame.toml"));
    const std::string name = "name = \"";
    const auto at = scene.find(name, scene.find("[[section]]"));
    REQUIRE(at != std::string::npos);
    const auto end = scene.find('"', at + name.size());
    const std::string old_name = scene.substr(at + name.size(), end - at - name.size());
    for (std::size_t p; (p = scene.find("\"" + old_name + "\"")) != std::string::npos;)
        scene.replace(p, old_name.size() + 2, "\"../../escaped\"");
    write(dir / "scene.toml", scene);
    const Result r = command("section " + (dir / "scene.toml").string() + " -o " + (dir / "sections").string() + " --no-charts");
    CHECK(r.code == 0);
    CHECK(fs::exists(dir / "sections" / "______escaped_capacity.csv"));
    CHECK_FALSE(fs::exists(dir.parent_path().parent_path() / "escaped_capacity.csv"));
    CHECK_FALSE(fs::exists(fs::temp_directory_path().parent_path() / "escaped_capacity.csv"));
}

TEST_CASE("Section curves of millions of fibres are announced, and refused where they would take many minutes", "[untrusted]") {
    const fs::path dir = fresh_folder("section_work");
    std::string scene = read(model("gallery/portal_frame.toml"));
    const std::string anchor = "residual_stress = 0.3\n";
    REQUIRE(scene.find(anchor) != std::string::npos);
    scene.replace(scene.find(anchor), anchor.size(), anchor + "flange_strips = 1000\nflange_layers = 1000\nweb_fibres = 10000\n");
    write(dir / "fine.toml", scene);
    const Result r = command("section " + (dir / "fine.toml").string() + " --points 1000 --no-charts -o " + (dir / "sections").string());
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains("2010000 fibres × 1000 points would take about 15 min"));
    CHECK_FALSE(fs::exists(dir / "sections" / "HEB300_capacity.csv"));
}

TEST_CASE("A link planted in an output folder is refused and what it points to is untouched", "[untrusted]") {
    const fs::path dir = fresh_folder("links");
    write(dir / "outside.txt", "keep me");
    const fs::path out = dir / "out";
    REQUIRE(command("run " + model("ring_elastic.toml") + " -o " + out.string() + " --no-render -q").code == 0);
    fs::remove(out / "vtu" / "step_000003.vtu");
    fs::create_symlink(dir / "outside.txt", out / "vtu" / "step_000003.vtu");
    const Result r = command("run " + model("ring_elastic.toml") + " -o " + out.string() + " --no-render -q");
    CHECK(r.code == 2);
    CHECK_THAT(r.output, Catch::Contains("step_000003.vtu is a symbolic link"));
    CHECK(read(dir / "outside.txt") == "keep me");
    CHECK(fs::exists(out / "vtu" / "step_000004.vtu")); // the earlier results are still there
}

TEST_CASE("A rerun keeps the user's files and the measured curve it is given", "[untrusted]") {
    const fs::path out = fresh_folder("rerun") / "out";
    REQUIRE(command("run " + model("ring_elastic.toml") + " -o " + out.string() + " --no-render -q").code == 0);
    write(out / "measured.csv", "displacement,load\n0,0\n50,0.3\n100,0.45\n");
    write(out / "notes.json", "{\"mine\": true}");
    write(out / "photo.png", "not really a PNG");
    const Result r = command("run " + model("ring_elastic.toml") + " -o " + out.string() + " -q --every 50 --no-animation --overlay-csv " +
                             (out / "measured.csv").string());
    CHECK(r.code == 0);
    CHECK(fs::exists(out / "measured.csv"));
    CHECK(read(out / "notes.json") == "{\"mine\": true}");
    CHECK(read(out / "photo.png") == "not really a PNG");
    CHECK(fs::exists(out / "chart.png"));
}

TEST_CASE("A second writer into a folder in use is refused naming the holder, and a folder removed mid-run stops it", "[untrusted]") {
    const fs::path out = fresh_folder("concurrent") / "out";
    const Result both = shell("$PLASTICA run " + slow_ring + " -o " + out.string() + " & first=$!\n"
                              "while [ ! -f " + out.string() + "/vtu/step_000005.vtu ]; do sleep 0.02; done\n"
                              "$PLASTICA run " + slow_ring + " -o " + out.string() + "; echo \"second exit $?\"\n"
                              "wait $first; echo \"first exit $?\"\n");
    CHECK_THAT(both.output, Catch::Contains("second exit 2") && Catch::Contains("first exit 0"));
    CHECK_THAT(both.output, Catch::Contains("is in use by process") && Catch::Contains("(plastica run"));
    // Every step once, from the one run that wrote.
    const nlohmann::json run = nlohmann::json::parse(read(out / "run.json"));
    std::ifstream curve(out / "curve.csv");
    int rows = -1;
    for (std::string line; std::getline(curve, line);) rows += line.empty() || line[0] == '#' ? 0 : 1;
    CHECK(rows == run.value("steps", 0) + 1);

    const Result removed = shell("rm -rf " + out.string() + "\n$PLASTICA run " + slow_ring + " -o " + out.string() + " & first=$!\n"
                                 "while [ ! -f " + out.string() + "/vtu/step_000005.vtu ]; do sleep 0.02; done\n"
                                 // rm -r can lose the race with a step being written into vtu/
                                 // ("Directory not empty"): it is repeated until the folder is gone.
                                 "while [ -e " + out.string() + " ]; do rm -rf " + out.string() + " 2>/dev/null; done\n"
                                 "wait $first; echo \"exit $?\"\n");
    CHECK_THAT(removed.output, Catch::Contains("exit 3") && Catch::Contains("was removed or replaced during the run"));
}

TEST_CASE("A crafted result folder cannot make the report read outside it", "[untrusted]") {
    const fs::path dir = fresh_folder("report");
    write(dir / "secret.gif", "SECRET-BYTES");
    const fs::path folder = dir / "result";
    const auto page_of = [&](const std::string& run_json) {
        write(folder / "run.json", run_json);
        const Result r = command("report " + folder.string() + " -o " + (dir / "page.html").string());
        return std::pair{r.code, read(dir / "page.html")};
    };
    // "SECRET-BYTES" in base64, and /etc/passwd's first line.
    for (const char* scene : {R"(/etc/passwd\u0000)", R"(/proc/self/environ\u0000)", "../secret", "/etc/passwd"}) {
        const auto [code, page] = page_of(std::string(R"({"program": "plastica", "status": "completed", "scene": ")") + scene + "\"}");
        CHECK(code == 0);
        CHECK_THAT(page, !Catch::Contains("U0VDUkVULUJZVEVT") && !Catch::Contains("cm9vdDp4OjA6MD"));
    }
    fs::create_symlink("/etc/passwd", folder / "chart.png");
    fs::create_directories(folder / "frames");
    fs::create_symlink("/etc/passwd", folder / "frames" / "frame_000001.png");
    const auto [code, page] = page_of(R"({"program": "plastica", "status": "completed", "scene": "x"})");
    CHECK(code == 0);
    CHECK_THAT(page, !Catch::Contains("cm9vdDp4OjA6MD"));
    write(folder / "run.json", R"({"program": "plastica", "status": 7, "steps": "abc"})");
    const Result wrong = command("report " + folder.string());
    CHECK(wrong.code == 2);
    CHECK_THAT(wrong.output, Catch::Contains("run.json: a value of the wrong type"));
}

TEST_CASE("compare refuses broken and oversized PNGs with a message, without crashing", "[untrusted]") {
    const fs::path dir = fresh_folder("png");
    const std::string good = read(std::string(PLASTICA_SOURCE_DIR) + "/docs/ring_chart.png");
    write(dir / "truncated.png", good.substr(0, good.size() / 2));
    write(dir / "header_only.png", good.substr(0, 100));
    // A header claiming 100000 × 100000 pixels, and one with a bad bit depth (valid checksums).
    const auto chunk = [](const std::string& type, const std::string& data) {
        std::string c;
        for (int s = 24; s >= 0; s -= 8) c += static_cast<char>((data.size() >> s) & 0xff);
        c += type + data;
        unsigned long crc = 0xffffffffUL;
        for (char ch : type + data) {
            crc ^= static_cast<unsigned char>(ch);
            for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320UL & (0UL - (crc & 1)));
        }
        crc ^= 0xffffffffUL;
        for (int s = 24; s >= 0; s -= 8) c += static_cast<char>((crc >> s) & 0xff);
        return c;
    };
    const auto header = [&](unsigned side, char depth) {
        std::string ihdr;
        for (int s = 0; s < 2; ++s)
            for (int b = 24; b >= 0; b -= 8) ihdr += static_cast<char>((side >> b) & 0xff);
        ihdr += std::string{depth, 2, 0, 0, 0};
        return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IEND", "");
    };
    write(dir / "huge.png", header(100000, 8));
    write(dir / "bad_ihdr.png", header(100, 7));
    for (const char* name : {"truncated.png", "header_only.png", "huge.png", "bad_ihdr.png"}) {
        const Result r = command("compare " + (dir / name).string() + " " + std::string(PLASTICA_SOURCE_DIR) + "/docs/ring_chart.png");
        INFO(name << ": " << r.output);
        CHECK(r.code == 2);
        CHECK_THAT(r.output, Catch::Contains(name));
    }
    CHECK_THAT(command("compare " + (dir / "huge.png").string() + " " + (dir / "huge.png").string()).output,
               Catch::Contains("pixels a side"));
}

TEST_CASE("merge reads crafted run folders as failed runs, not a crash", "[untrusted]") {
    const fs::path sweep = fresh_folder("merge") / "sweep";
    REQUIRE(command("sweep " + model("ring_elastic.toml") + " --vary analysis.increment=1,2,4 -o " + sweep.string() + " -j 2 --no-charts").code == 0);
    write(sweep / "runs" / "r0001" / "curve.csv", "step,load,control_displacement\nabc,def,ghi\n1,2\n\"unclosed\n");
    write(sweep / "runs" / "r0002" / "run.json", R"({"status": 5, "peak": "x", "steps": "abc"})");
    write(sweep / "runs" / "r0003" / "run.json", R"({"status": "completed", "peak": {"load": "high"}})");
    const Result r = command("merge " + sweep.string());
    CHECK(r.code == 3); // two runs failed
    const std::string csv = read(sweep / "sweep.csv");
    CHECK_THAT(csv, Catch::Contains("r0002,2,failed,run.json: 'status' is not a text"));
    CHECK_THAT(csv, Catch::Contains("r0003,4,failed,run.json: 'peak' is not an object of numbers"));
    CHECK_THAT(csv, Catch::Contains("r0001,1,completed"));
    // A plan whose ids would name folders elsewhere is refused.
    write(sweep / "plan.csv", "id,analysis.increment\n../../etc,1\n");
    const Result crafted = command("merge " + sweep.string());
    CHECK(crafted.code == 2);
    CHECK_THAT(crafted.output, Catch::Contains("is not a plain name"));
}

TEST_CASE("Device files and overflowing indices are refused as bad input", "[untrusted]") {
    const Result zero = command("run /dev/zero");
    CHECK(zero.code == 2);
    CHECK_THAT(zero.output, Catch::Contains("/dev/zero is not a regular file"));
    const Result index = command("run " + model("ring_elastic.toml") + " --set 'material[18446744073709551617].E=1' --curves-only");
    CHECK(index.code == 2);
    CHECK_THAT(index.output, Catch::Contains("not 18446744073709551617"));
}

TEST_CASE("SIGTERM while drawing exits 130 and leaves no temporary file, and a stale one goes at the next drawing", "[untrusted]") {
    const fs::path out = fresh_folder("sigterm") / "out";
    const Result r = shell("$PLASTICA run " + model("ring_inelastic.toml") + " -o " + out.string() + " -q & run=$!\n"
                           "while [ ! -d " + out.string() + "/frames ]; do sleep 0.02; done\nsleep 0.3\n"
                           "kill -TERM $run; wait $run; echo \"exit $?\"\n");
    CHECK_THAT(r.output, Catch::Contains("exit 130"));
    CHECK_FALSE(any_temporary_below(out));
    const nlohmann::json run = nlohmann::json::parse(read(out / "run.json"));
    CHECK_THAT(run.dump(), Catch::Contains("drawing interrupted"));
    write(out / "ring_inelastic.gif.tmp99999.rgb", std::string(4096, 'x'));
    write(out / "frames" / "frame_000001.png.tmp99999", "half a frame");
    CHECK(command("render " + out.string() + " -q --every 100 --no-animation").code == 0);
    CHECK_FALSE(any_temporary_below(out));
}

TEST_CASE("A full disk while drawing exits 3 and run.json says so", "[untrusted]") {
    const fs::path disk = fresh_folder("full_disk");
    // A small file system of its own (needs root, as CI has); elsewhere the case says why it ran not.
    if (::mount("tmpfs", disk.c_str(), "tmpfs", 0, "size=8m") != 0) {
        WARN("no tmpfs could be mounted here (not root?): the full-disk case was not run");
        return;
    }
    const Result r = command("run " + model("ring_inelastic.toml") + " -o " + (disk / "out").string() + " -q");
    const nlohmann::json run = nlohmann::json::parse(read(disk / "out" / "run.json"));
    ::umount(disk.c_str());
    CHECK(r.code == 3);
    CHECK_THAT(r.output, Catch::Contains("No space left on device"));
    CHECK(run.value("status", "") == "output_failed");
}

TEST_CASE("A step file whose data header claims 2^63 bytes or 1e12 points is refused by render, naming the file", "[untrusted]") {
    // VTK's reader trusted the appended data's size header and died with SIGSEGV; Plastica's own
    // reader checks every offset and size against the file before VTK sees it.
    const fs::path dir = fresh_folder("vtu_header");
    const Result run = command("run " + model("ring_elastic.toml") + " -o " + (dir / "ring").string() + " --no-render -q");
    REQUIRE(run.code == 0);
    const fs::path step = dir / "ring" / "vtu" / "step_000005.vtu";
    const std::string original = read(step);
    const std::size_t data = original.find('_', original.find("<AppendedData")) + 1;
    std::string huge = original;
    for (int b = 0; b < 8; ++b) huge[data + static_cast<std::size_t>(b)] = static_cast<char>(b == 7 ? 0x7f : 0xff);
    std::string many = original;
    const std::size_t points = many.find("NumberOfPoints=\"") + 16;
    many.replace(points, many.find('"', points) - points, "1000000000000");
    for (const std::string& crafted : {huge, many}) {
        write(step, crafted);
        const Result drawn = command("render " + (dir / "ring").string() + " --steps 5 -q -o " + (dir / "pictures").string());
        CHECK(drawn.code == 2);
        CHECK_THAT(drawn.output, Catch::Contains("step_000005.vtu"));
    }
}
