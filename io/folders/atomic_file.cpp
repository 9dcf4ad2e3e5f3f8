#include "atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
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
    if (ec) throw WriteError("cannot rename " + temporary + " to " + path + ": " + ec.message());
}

namespace {
// Calls write_some(done) until `size` bytes are written: each call returns what it wrote, or −1.
template <class WriteSome>
void write_everything(std::size_t size, const std::string& path, WriteSome write_some) {
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = write_some(done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) throw WriteError("cannot write " + path + ": " + std::strerror(n < 0 ? errno : EIO));
        done += static_cast<std::size_t>(n);
    }
}
} // namespace

void write_all(int fd, const char* data, std::size_t size, const std::string& path) {
    write_everything(size, path, [&](std::size_t done) { return ::write(fd, data + done, size - done); });
}

void write_all_at(int fd, const std::string& text, long offset, const std::string& path) {
    write_everything(text.size(), path, [&](std::size_t done) {
        return ::pwrite(fd, text.data() + done, text.size() - done, offset + static_cast<long>(done));
    });
}

namespace {

// An open file descriptor, closed once (another thread may reuse its number after that).
class Descriptor {
public:
    // Never through a symbolic link: a link planted in an output folder must not carry a write out of it.
    Descriptor(const std::string& path, int flags)
        : path_(path), fd_(::open(path.c_str(), flags | O_WRONLY | O_CLOEXEC | O_NOFOLLOW, 0644)) {
        if (fd_ < 0) fail();
    }
    ~Descriptor() {
        if (fd_ >= 0) ::close(fd_);
    }
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    int get() const { return fd_; }
    void close() {
        const int fd = fd_;
        fd_ = -1;
        if (::close(fd) != 0) fail();
    }
    [[noreturn]] void fail() const { throw WriteError("cannot write " + path_ + ": " + std::strerror(errno)); }

private:
    std::string path_;
    int fd_;
};

} // namespace

void write_file_atomically(const std::string& path, const std::string& contents) {
    const std::string tmp = temporary_name(path);
    try {
        ::unlink(tmp.c_str()); // a leftover of a killed writer of this process id, or a planted link
        Descriptor file(tmp, O_CREAT | O_EXCL);
        write_all(file.get(), contents.data(), contents.size(), path);
        file.close();
        rename_into_place(tmp, path);
    } catch (...) {
        // A full disk leaves no half-written file behind, under either name.
        ::unlink(tmp.c_str());
        throw;
    }
}

void write_file_in_place(const std::string& path, const std::string& contents) {
    try {
        // Not truncated on opening: the new contents go over the old blocks, and only a tail
        // the new file no longer needs is cut off (freeing blocks can mean a synchronous discard;
        // even a cut to the file's own size invalidates its last page, so that is not asked for).
        Descriptor file(path, O_CREAT);
        struct stat before {};
        if (::fstat(file.get(), &before) != 0) file.fail();
        write_all(file.get(), contents.data(), contents.size(), path);
        if (before.st_size > static_cast<off_t>(contents.size()) && ::ftruncate(file.get(), static_cast<off_t>(contents.size())) != 0)
            file.fail();
        file.close();
    } catch (...) {
        ::unlink(path.c_str());
        throw;
    }
}

} // namespace plastica
