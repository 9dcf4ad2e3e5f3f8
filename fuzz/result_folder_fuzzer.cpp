// libFuzzer target: a result folder of someone else's making. The input is split at NUL bytes
// into a run.json, a curve.csv and a plan.csv (with a run folder of its own); `plastica report`'s
// page and `plastica merge`'s sweep.csv are made from it. Each must give a page or a message —
// never a crash, an uncaught exception or a read outside the folder.
#include "report_page.hpp"
#include "study_error.hpp"
#include "sweep.hpp"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace fs = std::filesystem;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const fs::path dir = fs::temp_directory_path() / ("plastica_result_fuzz_" + std::to_string(::getpid()));
    const std::string input(reinterpret_cast<const char*>(data), size);
    std::string parts[3];
    for (std::size_t at = 0, k = 0; k < 3 && at <= input.size(); ++k) {
        const std::size_t end = std::min(input.find('\0', at), input.size());
        parts[k] = input.substr(at, end - at);
        at = end + 1;
    }
    fs::remove_all(dir);
    fs::create_directories(dir / "runs" / "r0001");
    for (const fs::path& folder : {dir, dir / "runs" / "r0001"}) {
        std::ofstream(folder / "run.json", std::ios::binary) << parts[0];
        std::ofstream(folder / "curve.csv", std::ios::binary) << parts[1];
    }
    std::ofstream(dir / "plan.csv", std::ios::binary) << parts[2];
    try {
        (void)plastica::run_page(dir.string());
    } catch (const plastica::ReportError&) {
    }
    try {
        (void)plastica::write_sweep_csv(dir.string(), {1.0, 50.0});
    } catch (const plastica::StudyError&) {
    } catch (const std::runtime_error&) {
        // A file over its limit or unreadable: said with the file's name.
    }
    return 0;
}
