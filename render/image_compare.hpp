// Rendered pictures against stored references. Per image: the fraction of pixels whose colour
// differs by more than a threshold in any channel (the verdict), the RMS difference over all
// channels, and VTK's vtkImageDifference thresholded error (which forgives 2-pixel shifts and
// anti-aliasing noise; reported so users can compare with VTK's own tests). A diff image shows
// the differing pixels in red over a dimmed copy of the reference.
#pragma once

#include <string>
#include <vector>

namespace plastica::render {

struct CompareOptions {
    int threshold = 16;             // per channel, 0–255: below it a pixel counts as equal
    double max_fraction = 0.001;    // an image passes when at most this share of pixels differ
    std::string diff_folder;        // where to write <name>_diff.png for failing images; empty: none
    // Only pixels in [x0, x1) × [y0, y1) are compared (fractions of width and height, y from
    // the top): a check of what one part of a picture shows, e.g. the structure without its
    // legend. The differing fraction is of the region's pixels.
    double region[4] = {0.0, 0.0, 1.0, 1.0};
};

struct ImageVerdict {
    std::string name;               // path relative to the compared folders
    bool passed = false;
    double differing_fraction = 0.0;
    double rms = 0.0;               // over all channels, 0–255
    double vtk_error = 0.0;         // vtkImageDifference::GetThresholdedError()
    std::string problem;            // "missing in actual", "extra in actual", …; empty when compared
};

// Two PNGs, or two folders of PNGs matched by relative path (a missing or extra file fails).
// Throws RenderError for an unreadable PNG or a size mismatch (bad input, not a difference).
std::vector<ImageVerdict> compare_pictures(const std::string& actual, const std::string& reference,
                                           const CompareOptions& options);

} // namespace plastica::render
