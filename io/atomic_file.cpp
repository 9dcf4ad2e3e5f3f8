#include "atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace plastica {

std::string temporary_name(const std::string& path) {
    return path + ".tmp" + std::to_string(::getpid());
}

void rename_into_place(const std::string& temporary, const std::string& path) {
    std::error_code ec;
    std::filesystem::rename(temporary, path, ec);
    if (ec) throw std::runtime_error("cannot rename " + temporary + " to " + path + ": " + ec.message());
}

void write_all(int fd, const char* data, std::size_t size, const std::string& path) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw std::runtime_error("cannot write " + path + ": " + std::strerror(n < 0 ? errno : EIO));
        data += n;
        size -= static_cast<std::size_t>(n);
    }
}

void write_file_atomically(const std::string& path, const std::string& contents) {
    const std::string tmp = temporary_name(path);
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    try {
        write_all(fd, contents.data(), contents.size(), path);
        if (::close(fd) != 0) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
    } catch (...) {
        // A full disk leaves no half-written file behind, under either name.
        ::close(fd);
        ::unlink(tmp.c_str());
        throw;
    }
    try {
        rename_into_place(tmp, path);
    } catch (...) {
        ::unlink(tmp.c_str());
        throw;
    }
}

} // namespace plastica
