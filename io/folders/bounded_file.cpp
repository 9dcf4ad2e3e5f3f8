#include "bounded_file.hpp"

#include "safe_names.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace plastica {

namespace {

class OpenFile {
public:
    explicit OpenFile(int fd) : fd_(fd) {}
    ~OpenFile() {
        if (fd_ >= 0) ::close(fd_);
    }
    OpenFile(const OpenFile&) = delete;
    OpenFile& operator=(const OpenFile&) = delete;
    int get() const { return fd_; }

private:
    int fd_;
};

std::string megabytes(std::size_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

// O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused as not a regular file.
constexpr int read_flags = O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY;

std::string read_open_file(OpenFile& file, const std::string& name, std::size_t max_bytes) {
    struct stat st {};
    if (::fstat(file.get(), &st) != 0) throw FileReadError("cannot read " + name + ": " + std::strerror(errno));
    if (!S_ISREG(st.st_mode)) throw FileReadError(name + " is not a regular file");
    if (static_cast<unsigned long long>(st.st_size) > max_bytes)
        throw FileReadError(name + " is " + std::to_string(st.st_size) + " bytes, more than the " + megabytes(max_bytes) +
                            " such a file may have");
    std::string bytes;
    bytes.resize(static_cast<std::size_t>(st.st_size));
    std::size_t done = 0;
    // A file that grows while it is read is cut at the size it had: the limit holds either way.
    while (done < bytes.size()) {
        const ssize_t n = ::read(file.get(), bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw FileReadError("cannot read " + name + ": " + std::strerror(errno));
        if (n == 0) break;
        done += static_cast<std::size_t>(n);
    }
    bytes.resize(done);
    return bytes;
}

} // namespace

std::string read_bounded_file(const std::string& path, std::size_t max_bytes) {
    if (path.find('\0') != std::string::npos) throw FileReadError("a file name may not hold a NUL character");
    OpenFile file(::open(path.c_str(), read_flags));
    if (file.get() < 0) throw FileReadError("cannot open " + path + ": " + std::strerror(errno));
    return read_open_file(file, path, max_bytes);
}

namespace {

// The descriptor of `relative` inside `folder`, each component opened without following links.
int open_inside(const std::string& folder, const std::string& relative) {
    const std::string name = folder + "/" + relative;
    if (!is_plain_relative_path(relative))
        throw FileReadError("'" + relative + "' is not a plain file name inside " + folder + " (no '..', no absolute path)");
    int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir < 0) throw FileReadError("cannot open the folder " + folder + ": " + std::strerror(errno));
    std::size_t start = 0;
    while (true) {
        const std::size_t slash = relative.find('/', start);
        const bool last = slash == std::string::npos;
        const std::string part = relative.substr(start, last ? std::string::npos : slash - start);
        const int fd = ::openat(dir, part.c_str(), (last ? read_flags : O_RDONLY | O_DIRECTORY | O_CLOEXEC) | O_NOFOLLOW);
        const int error = errno;
        ::close(dir);
        if (fd < 0)
            throw FileReadError(error == ELOOP || error == ENOTDIR
                                    ? name + " is reached through a symbolic link or is no folder: only files inside the folder are read"
                                    : "cannot open " + name + ": " + std::strerror(error));
        if (last) return fd;
        dir = fd;
        start = slash + 1;
    }
}

} // namespace

std::string read_file_inside(const std::string& folder, const std::string& relative, std::size_t max_bytes) {
    OpenFile file(open_inside(folder, relative));
    return read_open_file(file, folder + "/" + relative, max_bytes);
}

bool is_file_inside(const std::string& folder, const std::string& relative) {
    try {
        OpenFile file(open_inside(folder, relative));
        struct stat st {};
        return ::fstat(file.get(), &st) == 0 && S_ISREG(st.st_mode);
    } catch (const FileReadError&) {
        return false;
    }
}

} // namespace plastica
