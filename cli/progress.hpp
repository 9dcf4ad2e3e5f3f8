// Progress of a long run, render or sweep on stderr. On a terminal: one line redrawn in place (a
// bar when the share done is known, the step, what it is doing, the rate of its units and an
// estimate of the time left), ended by a newline.
// Elsewhere (CI logs, files): a plain line every `every` updates with the share done and the
// estimate, nothing redrawn.
#pragma once

#include <chrono>
#include <string>

namespace plastica::cli {

class Progress {
public:
    // what: "solving", "drawing"; every: the plain-line interval when stderr is not a terminal
    // (0: none there);
    // unit: what a count counts, for the rate ("steps", "frames", "runs").
    Progress(std::string what, int every, std::string unit = "");
    ~Progress();

    // done: the share finished in [0, 1], or negative when unknown; status: the numbers to show.
    void update(int count, double done, const std::string& status);
    // Ends the line on a terminal (before other messages).
    void finish();

private:
    std::string what_;
    int every_;
    std::string unit_;
    bool terminal_;
    bool open_ = false; // a redrawn line is on the terminal
    std::chrono::steady_clock::time_point start_, last_;
};

// "1 min 05 s", "12 s", "0.4 s".
std::string duration_text(double seconds);

} // namespace plastica::cli
