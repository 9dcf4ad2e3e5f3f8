// Helpers for the render tests: solve a stored scene into a temporary result folder, and count
// pixels of a PNG by colour and region.
#pragma once

#include "analysis/path_following.hpp"
#include "scene_reader.hpp"
#include "vtu_series_writer.hpp"

#include <vtkImageData.h>

#include <filesystem>
#include <functional>
#include <string>

namespace plastica::testing {

namespace fs = std::filesystem;

// Runs models/<scene>.toml writing every k-th step into a folder named by `tag` (test cases run
// in parallel processes, each needs its own folder).
inline fs::path solved_series_of(Model model, int every, const std::string& tag);

inline fs::path solved_series(const std::string& scene, int every, const std::string& tag) {
    return solved_series_of(read_scene(std::string(PLASTICA_SOURCE_DIR) + "/models/" + scene + ".toml"), every, tag);
}

inline fs::path solved_series_of(Model model, int every, const std::string& tag) {
    const fs::path folder = fs::temp_directory_path() / ("plastica_render_" + tag);
    fs::remove_all(folder);
    VtuSeriesWriter writer(model, folder.string(), {every, SeriesTime::step});
    PathFollowing analysis(model);
    analysis.run({std::ref(writer)});
    writer.finish();
    return folder;
}

// The last of the frames drawn into `pictures` (frames are numbered by step).
inline fs::path last_frame(const fs::path& pictures) {
    fs::path last;
    for (const fs::directory_entry& f : fs::directory_iterator(pictures / "frames"))
        if (f.path().extension() == ".png" && f.path().filename() > last.filename()) last = f.path();
    return last;
}

struct Pixel {
    int r, g, b;
};

// Pixels satisfying `is` inside [x0, x1) × [y0, y1), as fractions of the image, y from the top.
inline long count_pixels(vtkImageData* image, const std::function<bool(Pixel)>& is, double x0 = 0, double x1 = 1,
                         double y0 = 0, double y1 = 1) {
    int d[3];
    image->GetDimensions(d);
    const int c = image->GetNumberOfScalarComponents();
    long n = 0;
    for (int y = static_cast<int>(y0 * d[1]); y < static_cast<int>(y1 * d[1]); ++y)
        for (int x = static_cast<int>(x0 * d[0]); x < static_cast<int>(x1 * d[0]); ++x) {
            // VTK images start at the bottom row.
            const auto* p = static_cast<unsigned char*>(image->GetScalarPointer(x, d[1] - 1 - y, 0));
            n += is({p[0], c > 1 ? p[1] : p[0], c > 2 ? p[2] : p[0]});
        }
    return n;
}

inline std::function<bool(Pixel)> exactly(int r, int g, int b) {
    return [=](Pixel p) { return p.r == r && p.g == g && p.b == b; };
}

} // namespace plastica::testing
