// An output folder that is one writer's own while it writes: a lock refuses a second writer
// (another process or another thread); symbolic links where results go are refused; a rerun
// removes only the files an earlier run listed in the folder's manifest (never the inputs it is
// given, never a file of the user's); and a folder removed during the run is noticed.
#pragma once

#include <ctime>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace plastica {

// The folder may not be used (held by another writer, holds another scene's results or a
// symbolic link where results go): the message says why and what to do.
class OutputFolderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct OutputFolderOptions {
    std::string scene_name;          // results of another scene are not mixed in without `force`
    bool force = false;              // use a folder of another scene or of another program
    bool keep_step_files = false;    // an earlier series' step files stay, to be rewritten in place
    bool clear_results = true;       // false: only take the lock (drawing into a run's folder)
    std::vector<std::string> inputs; // files this run reads: never removed
    std::string holder;              // who holds the lock, for the message a second writer gets
};

class OutputFolder {
public:
    // Creates the folder and takes its lock, then clears what an earlier run of the same scene
    // wrote. Throws OutputFolderError.
    OutputFolder(std::string path, OutputFolderOptions options);
    ~OutputFolder(); // records the manifest and releases the lock
    OutputFolder(const OutputFolder&) = delete;
    OutputFolder& operator=(const OutputFolder&) = delete;

    const std::string& path() const { return path_; }
    // Whether the folder is still the one the run began in: not removed, not replaced.
    bool still_there() const;
    // Lists in the manifest every file Plastica has written here: those it listed before and
    // still there, and those written or rewritten since this object was made.
    void record_manifest() const;

private:
    void prepare();
    void release() noexcept;

    std::string path_;
    OutputFolderOptions options_;
    int lock_fd_ = -1;
    int folder_fd_ = -1;
    std::timespec started_{};
    std::set<std::string> foreign_; // files that were here before and are not Plastica's
};

// The files of the folder's manifest (relative paths; empty when there is none).
std::vector<std::string> read_manifest(const std::string& folder);
// Temporary files (NAME.tmpPID…) that a killed writer left below the folder: removed. Only
// safe while the folder's lock is held.
void remove_stale_temporaries(const std::string& folder);

inline constexpr const char* manifest_file_name = ".plastica-manifest";
inline constexpr const char* lock_file_name = ".plastica-lock";

} // namespace plastica
