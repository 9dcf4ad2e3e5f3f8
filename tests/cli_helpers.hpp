// Running the plastica program from a test: its exit code and everything it printed.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace cli_test {

struct Result {
    int code;
    std::string output;
};

// Runs `plastica ARGS` through the shell (ARGS is shell text) with no DISPLAY: drawing must not
// need an X server.
inline Result command(const std::string& args) {
    namespace fs = std::filesystem;
    // One log per test process: CTest runs the test cases in parallel.
    const fs::path log = fs::temp_directory_path() / ("plastica_cli_" + std::to_string(::getpid()) + ".log");
    const std::string cmd = "env -u DISPLAY " + std::string(PLASTICA_BINARY) + " " + args + " > " + log.string() + " 2>&1";
    const int status = std::system(cmd.c_str());
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), text.str()};
}

inline std::string model(const std::string& name) { return std::string(PLASTICA_SOURCE_DIR) + "/models/" + name; }

} // namespace cli_test
