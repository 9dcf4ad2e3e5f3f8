#include "progress.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iostream>

namespace plastica::cli {

std::string duration_text(double seconds) {
    char text[32];
    if (seconds < 10.0) std::snprintf(text, sizeof text, "%.1f s", seconds);
    else if (seconds < 60.0) std::snprintf(text, sizeof text, "%.0f s", seconds);
    else std::snprintf(text, sizeof text, "%d min %02d s", static_cast<int>(seconds) / 60, static_cast<int>(seconds) % 60);
    return text;
}

Progress::Progress(std::string what, int every, std::string unit)
    : what_(std::move(what)), every_(every), unit_(std::move(unit)), terminal_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

Progress::~Progress() { finish(); }

void Progress::update(int count, double done, const std::string& status) {
    const auto now = std::chrono::steady_clock::now();
    // Redrawn at most ten times a second: a fast run is not slowed by its own display.
    if (terminal_ && open_ && done < 1.0 && now - last_ < std::chrono::milliseconds(100)) return;
    if (!terminal_ && (every_ <= 0 || count % every_ != 0)) return;
    last_ = now;
    const double share = std::fmax(0.0, std::fmin(done, 1.0));
    std::string line = what_ + (terminal_ ? " " : ": ");
    if (done >= 0.0 && terminal_) {
        constexpr int width = 24;
        const int filled = static_cast<int>(std::lround(share * width));
        line += "[" + std::string(filled, '#') + std::string(width - filled, '-') + "] ";
    }
    if (done >= 0.0) {
        char percent[16];
        std::snprintf(percent, sizeof percent, "%3.0f %%  ", 100.0 * share);
        line += percent;
    }
    line += status;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    // An early rate is noise; the last one always shows, however quick the run.
    if (terminal_ && !unit_.empty() && elapsed > 0.0 && (elapsed > 0.05 || done >= 1.0)) {
        char rate[48];
        std::snprintf(rate, sizeof rate, "  %.3g %s/s", count / elapsed, unit_.c_str());
        line += rate;
    }
    if (done > 0.02 && done < 1.0) line += "  about " + duration_text(elapsed * (1.0 - done) / done) + " left";
    // In a log each update is a line of its own, with the same share and estimate.
    if (!terminal_) {
        std::cerr << line << "\n";
        return;
    }
    std::cerr << "\r\033[K" << line << std::flush;
    open_ = true;
}

void Progress::finish() {
    if (open_) std::cerr << "\n";
    open_ = false;
}

} // namespace plastica::cli
