// One self-contained HTML page for CI artifacts (`plastica report`, `plastica compare --report`):
// text from run.json and every picture embedded as a data URI, so the page opens anywhere
// without the folder beside it. A script on the page counts the pictures that loaded into
// the element #images-loaded ("5 of 5 images loaded"), which a headless browser can read.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace plastica {

// Thrown for a folder that holds no run and for a file that cannot be read.
struct ReportError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The page of a result folder: scene, status and reason, the run's figures, chart, contact
// sheet, shapes, animation and the key frames (start, first yield, peak, last step), whichever the folder holds.
std::string run_page(const std::string& folder);

// One failing picture of a comparison: the three images (a missing one: empty path) and why.
struct FailedPicture {
    std::string name, why;
    std::string actual, reference, diff; // PNG paths
};
std::string comparison_page(const std::string& title, const std::string& summary, const std::vector<FailedPicture>& failed);

} // namespace plastica
