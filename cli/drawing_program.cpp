#include "drawing_program.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <vector>

namespace plastica::cli {

namespace fs = std::filesystem;

std::string drawing_program() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    return ((ec ? fs::path(".") : self.parent_path()) / "plastica-draw").string();
}

int hand_over_to_drawing(const std::string& command, const Args& args) {
    const std::string program = drawing_program();
    std::vector<std::string> words{"plastica", command};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    std::cout.flush();
    execv(program.c_str(), argv.data());
    std::cerr << "plastica: '" << command << "' draws pictures, which " << program << " does; it cannot be started ("
              << std::strerror(errno) << "). It is built beside plastica: run make build.\n";
    return bad_input;
}

bool can_draw() {
#ifdef PLASTICA_DRAWING
    return true;
#else
    return false;
#endif
}

} // namespace plastica::cli
