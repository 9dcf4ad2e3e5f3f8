#include "output_folder.hpp"

#include "atomic_file.hpp"
#include "bounded_file.hpp"
#include "run_report.hpp"
#include "safe_names.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

namespace plastica {

namespace fs = std::filesystem;

namespace {

// What a run of `scene` writes, for a folder an earlier version wrote without a manifest.
bool is_known_result(const std::string& relative, const std::string& scene) {
    static const std::set<std::string> fixed{"run.json", "curve.csv", "base.vtp", "chart.png", "contact_sheet.png", "shapes.png", "report.html"};
    static const std::regex step(R"(vtu/step_\d+\.vtu)"), frame(R"(frames/frame_\d+\.png)");
    return fixed.count(relative) || relative == scene + ".pvd" || relative == scene + ".gif" || std::regex_match(relative, step) ||
           std::regex_match(relative, frame);
}

bool is_temporary(const std::string& name) {
    static const std::regex temporary(R"(.+\.tmp\d+(\..*)?)");
    return std::regex_match(name, temporary);
}

// A manifest or a lock, of this folder or of a folder inside it (plastica section's own).
bool is_bookkeeping(const std::string& relative) {
    const std::string name = fs::path(relative).filename().string();
    return name == manifest_file_name || name == lock_file_name;
}

// A temporary file Plastica makes: NAME.tmpPID… of a file it writes (a result of any scene's
// name, a section's table or chart, a file its manifest lists). A user's "data.tmp2024" is not one.
bool is_our_temporary(const std::string& relative, const std::set<std::string>& listed) {
    const fs::path path(relative);
    const std::string name = path.filename().string();
    if (!is_temporary(name)) return false;
    const std::string stem = name.substr(0, name.rfind(".tmp"));
    const std::string of = (path.parent_path() / stem).generic_string();
    static const std::regex any_scene(R"([A-Za-z0-9_-]+\.(pvd|gif)|[A-Za-z0-9_-]+_(capacity|moment_curvature)\.(csv|png))");
    return listed.count(of) || is_known_result(of, "") || is_bookkeeping(of) || std::regex_match(of, any_scene);
}

// Every entry below the folder (symbolic links listed, never followed), as relative paths.
std::vector<std::pair<std::string, fs::file_status>> entries_below(const std::string& folder) {
    std::vector<std::pair<std::string, fs::file_status>> out;
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(folder, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
        out.emplace_back(it->path().lexically_relative(folder).string(), it->symlink_status());
    return out;
}

bool modified_since(const fs::path& file, const std::timespec& since) {
    struct stat st {};
    if (::lstat(file.c_str(), &st) != 0) return false;
    // Strictly later: a file the user left just as the run began stays the user's.
    return st.st_mtim.tv_sec > since.tv_sec || (st.st_mtim.tv_sec == since.tv_sec && st.st_mtim.tv_nsec > since.tv_nsec);
}

std::string lock_holder(int fd) {
    char text[512] = {};
    const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
    std::string holder = n > 0 ? std::string(text, static_cast<std::size_t>(n)) : "another writer";
    return has_control_character(holder) ? "another writer" : holder;
}

} // namespace

std::vector<std::string> read_manifest(const std::string& folder) {
    std::vector<std::string> files;
    if (!is_file_inside(folder, manifest_file_name)) return files;
    std::istringstream in(read_file_inside(folder, manifest_file_name, result_file_limit));
    for (std::string line; std::getline(in, line);)
        if (is_plain_relative_path(line) && !is_bookkeeping(line)) files.push_back(line);
    return files;
}

void remove_stale_temporaries(const std::string& folder) {
    const std::vector<std::string> manifest = read_manifest(folder);
    const std::set<std::string> listed(manifest.begin(), manifest.end());
    for (const auto& [relative, status] : entries_below(folder))
        if ((fs::is_regular_file(status) || fs::is_symlink(status)) && is_our_temporary(relative, listed)) {
            std::error_code ec;
            fs::remove(fs::path(folder) / relative, ec);
        }
}

OutputFolder::OutputFolder(std::string path, OutputFolderOptions options) : path_(std::move(path)), options_(std::move(options)) {
    std::error_code ec;
    if (fs::exists(path_, ec) && !fs::is_directory(path_, ec))
        throw OutputFolderError("output path " + path_ + " exists and is not a folder");
    fs::create_directories(path_, ec);
    if (ec) throw OutputFolderError("cannot make the output folder " + path_ + ": " + ec.message());
    folder_fd_ = ::open(path_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (folder_fd_ < 0) throw OutputFolderError("cannot open the output folder " + path_ + ": " + std::strerror(errno));
    // flock belongs to an open file description: a second open of the lock, by another process
    // or by another thread of this one, is refused while this one is held.
    lock_fd_ = ::openat(folder_fd_, lock_file_name, O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (lock_fd_ < 0 || ::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
        const int error = errno;
        std::string holder = lock_fd_ >= 0 ? lock_holder(lock_fd_) : std::string();
        // The holder writes its name just after it locks (and empties the file first): a refusal
        // in between waits for it, up to a tenth of a second.
        for (int wait = 0; lock_fd_ >= 0 && error == EWOULDBLOCK && holder == "another writer" && wait < 50; ++wait) {
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
            holder = lock_holder(lock_fd_);
        }
        release();
        if (error == EWOULDBLOCK)
            throw OutputFolderError("output folder " + path_ + " is in use by " + holder +
                                    ": wait until it ends, or write to another folder");
        throw OutputFolderError("cannot lock the output folder " + path_ + ": " + std::strerror(error));
    }
    const std::string holder = "process " + std::to_string(::getpid()) + " (" + options_.holder + ")";
    if (::ftruncate(lock_fd_, 0) != 0) {} // the holder's text is a courtesy; the lock is what counts
    try {
        write_all_at(lock_fd_, holder, 0, path_ + "/" + lock_file_name);
    } catch (const std::exception&) {
    }
    // The fine clock: a file written before this moment has a time no later than it, whatever
    // the file system's own granularity.
    ::clock_gettime(CLOCK_REALTIME, &started_);
    try {
        prepare();
    } catch (...) {
        release();
        throw;
    }
}

void OutputFolder::prepare() {
    const std::vector<std::string> manifest = read_manifest(path_);
    const std::set<std::string> listed(manifest.begin(), manifest.end());
    const std::string scene = options_.scene_name;
    const auto below = entries_below(path_);
    // Symbolic links where results go would carry writes out of the folder: refused.
    for (const auto& [relative, status] : below) {
        const std::string top = relative.substr(0, relative.find('/'));
        if (fs::is_symlink(status) && (listed.count(relative) || is_known_result(relative, scene) || top == "vtu" || top == "frames"))
            throw OutputFolderError(path_ + "/" + relative + " is a symbolic link where results go; Plastica writes only inside its "
                                    "folder and never through a link: remove the link or choose another folder with -o");
    }
    if (options_.clear_results) {
        const std::string other = recorded_scene((fs::path(path_) / "run.json").string());
        const bool foreign = !other.empty() && other != scene;
        const bool unknown = other.empty() && manifest.empty() &&
                             std::any_of(below.begin(), below.end(), [](const auto& e) { return !is_bookkeeping(e.first); });
        if ((foreign || unknown) && !options_.force)
            throw OutputFolderError("output folder " + path_ + " holds " +
                                    (foreign ? "results of scene '" + other + "'" : "files of another program") +
                                    "; choose another folder with -o or pass --force to replace them");
        // What an earlier run wrote goes (by its manifest, or by name where it left none); the
        // user's own files and this run's inputs stay.
        std::vector<fs::path> inputs;
        for (const std::string& input : options_.inputs) {
            std::error_code ec;
            if (fs::exists(input, ec)) inputs.push_back(fs::canonical(input, ec));
        }
        for (const auto& [relative, status] : below) {
            const bool ours = manifest.empty() ? !other.empty() && is_known_result(relative, scene) : listed.count(relative) > 0;
            const bool step_file = relative.rfind("vtu/", 0) == 0;
            if (!ours || !fs::is_regular_file(status) || (step_file && options_.keep_step_files)) continue;
            const fs::path file = fs::path(path_) / relative;
            std::error_code ec;
            const fs::path real = fs::canonical(file, ec);
            if (std::find(inputs.begin(), inputs.end(), real) != inputs.end()) continue;
            fs::remove(file, ec);
        }
    }
    remove_stale_temporaries(path_);
    for (const auto& [relative, status] : entries_below(path_))
        if (!fs::is_directory(status) && !is_bookkeeping(relative) && !listed.count(relative)) foreign_.insert(relative);
}

OutputFolder::~OutputFolder() {
    // The manifest is what lets the next run remove exactly this run's files.
    if (lock_fd_ >= 0 && still_there()) try {
            record_manifest();
        } catch (const std::exception&) {
        }
    release();
}

void OutputFolder::release() noexcept {
    if (lock_fd_ >= 0) ::close(lock_fd_); // closing releases the lock
    if (folder_fd_ >= 0) ::close(folder_fd_);
    lock_fd_ = folder_fd_ = -1;
}

bool OutputFolder::still_there() const {
    struct stat open_folder {}, named {};
    return ::fstat(folder_fd_, &open_folder) == 0 && open_folder.st_nlink > 0 && ::stat(path_.c_str(), &named) == 0 &&
           named.st_ino == open_folder.st_ino && named.st_dev == open_folder.st_dev;
}

void OutputFolder::record_manifest() const {
    const std::vector<std::string> manifest = read_manifest(path_);
    const std::set<std::string> before(manifest.begin(), manifest.end());
    std::string text;
    for (const auto& [relative, status] : entries_below(path_)) {
        if (!fs::is_regular_file(status) || is_bookkeeping(relative) || is_temporary(fs::path(relative).filename().string())) continue;
        if (before.count(relative) || !foreign_.count(relative) || modified_since(fs::path(path_) / relative, started_)) text += relative + "\n";
    }
    write_file_atomically((fs::path(path_) / manifest_file_name).string(), text);
}

} // namespace plastica
