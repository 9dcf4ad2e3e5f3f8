#include "atomic_file.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

namespace plastica {

std::string temporary_name(const std::string& path) {
    return path + ".tmp" + std::to_string(::getpid());
}

void rename_into_place(const std::string& temporary, const std::string& path) {
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) throw std::runtime_error("cannot rename " + temporary + " to " + path + ": " + ec.message());
}

void write_file_atomically(const std::string& path, const std::string& contents) {
    const std::string tmp = temporary_name(path);
    {
        std::ofstream out(tmp, std::ios::binary);
        out << contents;
        if (!out) throw std::runtime_error("cannot write " + tmp);
    }
    rename_into_place(tmp, path);
}

} // namespace plastica
