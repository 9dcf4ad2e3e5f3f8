#include "animation.hpp"

#include "atomic_file.hpp"

#include <cstdlib>
#include <filesystem>
#include <spawn.h>
#include <sys/wait.h>
#include <vector>

extern char** environ;

namespace plastica::render {

namespace {

bool on_path(const std::string& program) {
    const char* path = std::getenv("PATH");
    if (!path) return false;
    std::string dirs = path;
    for (std::size_t start = 0, end; start <= dirs.size(); start = end + 1) {
        end = dirs.find(':', start);
        if (end == std::string::npos) end = dirs.size();
        const std::filesystem::path candidate = std::filesystem::path(dirs.substr(start, end - start)) / program;
        std::error_code ec;
        if (std::filesystem::is_regular_file(candidate, ec)) return true;
    }
    return false;
}

// Runs a program without a shell (no quoting of paths) and returns its exit status.
int run(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    pid_t pid;
    if (posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) return -1;
    int status = 0;
    if (waitpid(pid, &status, 0) < 0) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace

AnimationResult write_gif(const std::string& frames_folder, const std::string& gif_path, int frames_per_second, int width) {
    if (!on_path("ffmpeg"))
        return {false, "no animation: the ffmpeg program is not installed (apt install ffmpeg); the PNG frames are complete"};
    // ffmpeg picks the format from the extension, so the temporary name keeps ".gif".
    const std::string temporary = temporary_name(gif_path) + ".gif";
    const std::string filter = "scale=" + std::to_string(width) +
                               ":-1:flags=lanczos,split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=none";
    const int status = run({"ffmpeg", "-v", "error", "-nostdin", "-y", "-framerate", std::to_string(frames_per_second),
                            "-pattern_type", "glob", "-i", (std::filesystem::path(frames_folder) / "frame_*.png").string(),
                            "-vf", filter, "-loop", "0", temporary});
    if (status != 0) {
        std::error_code ec;
        std::filesystem::remove(temporary, ec);
        return {false, "no animation: ffmpeg failed (exit " + std::to_string(status) + "); the PNG frames are complete"};
    }
    rename_into_place(temporary, gif_path);
    return {true, gif_path};
}

} // namespace plastica::render
