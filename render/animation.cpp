#include "animation.hpp"

#include "atomic_file.hpp"

#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <filesystem>
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

} // namespace

int animation_shrink(int width) { return std::max(1, (width + 320) / 640); }

std::string animation_pixels(vtkImageData* frame, int factor) {
    int dims[3];
    frame->GetDimensions(dims);
    auto* scalars = vtkUnsignedCharArray::SafeDownCast(frame->GetPointData()->GetScalars());
    const int c = scalars ? scalars->GetNumberOfComponents() : 0;
    const int w = dims[0] / factor, h = dims[1] / factor;
    std::string out(static_cast<std::size_t>(w) * h * 3, '\0');
    if (c < 3) return out;
    const unsigned char* p = scalars->GetPointer(0);
    if (factor == 2 && c == 3) {
        // The common case (1280 × 720 frames), written out: a quarter of the general loop's time.
        for (int y = 0; y < h; ++y) {
            const unsigned char* a = p + static_cast<std::size_t>(2 * y) * dims[0] * 3;
            const unsigned char* b = a + static_cast<std::size_t>(dims[0]) * 3;
            unsigned char* row = reinterpret_cast<unsigned char*>(&out[static_cast<std::size_t>(h - 1 - y) * w * 3]);
            for (int i = 0; i < w * 3; ++i) {
                const int x = i / 3 * 6 + i % 3;
                row[i] = static_cast<unsigned char>((a[x] + a[x + 3] + b[x] + b[x + 3] + 2) / 4);
            }
        }
        return out;
    }
    const int area = factor * factor;
    std::vector<int> sums(static_cast<std::size_t>(w) * 3);
    for (int y = 0; y < h; ++y) {
        std::fill(sums.begin(), sums.end(), 0);
        for (int dy = 0; dy < factor; ++dy) {
            const unsigned char* source = p + static_cast<std::size_t>(y * factor + dy) * dims[0] * c;
            for (int x = 0; x < w; ++x)
                for (int dx = 0; dx < factor; ++dx, source += c)
                    for (int k = 0; k < 3; ++k) sums[static_cast<std::size_t>(x) * 3 + k] += source[k];
        }
        // VTK's rows run from the bottom up.
        char* row = &out[static_cast<std::size_t>(h - 1 - y) * w * 3];
        for (std::size_t i = 0; i < sums.size(); ++i) row[i] = static_cast<char>((sums[i] + area / 2) / area);
    }
    return out;
}

namespace {

// Runs ffmpeg with `args` (after "ffmpeg -v error -y"), its standard input from `input`
// (or none); returns the process, or -1.
pid_t start_ffmpeg(const std::vector<std::string>& args, int input) {
    std::vector<std::string> words{"ffmpeg", "-v", "error", "-y"};
    words.insert(words.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (const std::string& a : words) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (input >= 0) posix_spawn_file_actions_adddup2(&actions, input, STDIN_FILENO);
    else posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    pid_t pid = -1;
    const int spawned = posix_spawnp(&pid, "ffmpeg", &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    return spawned == 0 ? pid : -1;
}

int wait_for(pid_t pid) {
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void remove_quietly(const std::string& path) {
    std::error_code ec;
    std::filesystem::remove(path, ec);
}

} // namespace

GifWriter::GifWriter(std::string gif_path, int width, int height, int frames_per_second)
    : gif_path_(std::move(gif_path)), width_(width), height_(height), frames_per_second_(frames_per_second),
      frame_bytes_(static_cast<std::size_t>(width) * height * 3) {
    if (!on_path("ffmpeg")) {
        failure_ = "no animation: the ffmpeg program is not installed (apt install ffmpeg); the PNG frames are complete";
        return;
    }
    // ffmpeg picks the format from the extension, so the temporary names keep theirs.
    const std::string stem = temporary_name(gif_path_);
    temporary_ = stem + ".gif";
    palette_ = stem + ".palette.png";
    frames_ = stem + ".rgb";
    const int fd = open(frames_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) failure_ = "no animation: cannot write " + frames_;
    else close(fd);
}

GifWriter::~GifWriter() {
    if (palette_pass_ > 0) {
        close(palette_input_);
        kill(palette_pass_, SIGTERM);
        waitpid(palette_pass_, nullptr, 0);
    }
    if (previous_sigpipe_) signal(SIGPIPE, previous_sigpipe_);
    for (const std::string& file : {temporary_, palette_, frames_})
        if (!file.empty()) remove_quietly(file);
}

void GifWriter::start() {
    if (!failure_.empty()) return;
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) {
        failure_ = "no animation: no pipe to ffmpeg";
        return;
    }
    const std::string size = std::to_string(width_) + "x" + std::to_string(height_);
    palette_pass_ = start_ffmpeg({"-f", "rawvideo", "-pix_fmt", "rgb24", "-s", size, "-i", "pipe:0",
                                  "-vf", "palettegen=stats_mode=diff", palette_}, fds[0]);
    close(fds[0]);
    if (palette_pass_ < 0) {
        close(fds[1]);
        failure_ = "no animation: ffmpeg could not be started";
        return;
    }
    palette_input_ = fds[1];
    // A failing ffmpeg closes its end: the write then fails with EPIPE instead of ending us.
    previous_sigpipe_ = signal(SIGPIPE, SIG_IGN);
}

void GifWriter::add(std::size_t k) {
    if (palette_pass_ < 0 || !failure_.empty()) return;
    std::string frame(frame_bytes_, '\0');
    const int fd = open(frames_.c_str(), O_RDONLY | O_CLOEXEC);
    const ssize_t got = fd < 0 ? -1 : pread(fd, frame.data(), frame.size(), static_cast<off_t>(k * frame_bytes_));
    if (fd >= 0) close(fd);
    if (got != static_cast<ssize_t>(frame.size())) {
        failure_ = "no animation: frame " + std::to_string(k) + " is missing";
        return;
    }
    try {
        write_all(palette_input_, frame.data(), frame.size(), "ffmpeg's input");
    } catch (const std::exception&) {
        failure_ = "no animation: ffmpeg stopped reading frames";
    }
}

AnimationResult GifWriter::finish(std::size_t count) {
    if (palette_pass_ > 0) {
        close(palette_input_);
        const int status = wait_for(palette_pass_);
        palette_pass_ = -1;
        if (status != 0 && failure_.empty())
            failure_ = "no animation: ffmpeg could not gather a palette (exit " + std::to_string(status) + ")";
    }
    if (failure_.empty() && count == 0) failure_ = "no animation: no frames";
    if (failure_.empty()) {
        // The frame file may be longer (an earlier, longer sequence): read exactly `count` frames.
        const std::string size = std::to_string(width_) + "x" + std::to_string(height_);
        const pid_t gif = start_ffmpeg({"-f", "rawvideo", "-pix_fmt", "rgb24", "-s", size,
                                        "-framerate", std::to_string(frames_per_second_), "-i", frames_, "-i", palette_,
                                        "-frames:v", std::to_string(count),
                                        "-lavfi", "[0][1]paletteuse=dither=none:diff_mode=rectangle", "-loop", "0", temporary_},
                                       -1);
        const int status = gif < 0 ? -1 : wait_for(gif);
        if (status != 0)
            failure_ = "no animation: ffmpeg failed (exit " + std::to_string(status) + "); the PNG frames are complete";
    }
    if (!failure_.empty()) return {false, failure_};
    rename_into_place(temporary_, gif_path_);
    return {true, gif_path_};
}

void write_animation_frame(const std::string& frame_file, std::size_t k, const std::string& rgb) {
    const int fd = open(frame_file.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) return; // the animation then reports the frame missing
    try {
        write_all_at(fd, rgb, static_cast<long>(k * rgb.size()), frame_file);
    } catch (const std::exception&) {
        // As above: a frame not written is reported missing when the animation reads it.
    }
    close(fd);
}

} // namespace plastica::render
