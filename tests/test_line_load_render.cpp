// Line loads drawn as loads along their members: both beams of a two-storey frame carry a row of
// arrows joined at their tails across their span, each labelled with its intensity, and the
// nodal arrows keep the point loads alone.
#include "render_helpers.hpp"
#include "palette.hpp"
#include "png_file.hpp"
#include "render_series.hpp"
#include "result_series.hpp"
#include "series_summary.hpp"

#include <catch2/catch.hpp>

#include <vtkImageData.h>

#include <cstdlib>
#include <set>

using namespace plastica;
using namespace plastica::testing;
using namespace plastica::render;

namespace {

bool load_colour(Pixel p) { return p.r == colour::load.r && p.g == colour::load.g && p.b == colour::load.b; }

// Columns of x ∈ [0, x1) holding a load-coloured pixel between rows y0 and y1 (fractions).
int load_columns(vtkImageData* image, double x1, double y0, double y1) {
    int d[3];
    image->GetDimensions(d);
    int columns = 0;
    for (int x = 0; x < static_cast<int>(x1 * d[0]); ++x)
        columns += count_pixels(image, load_colour, static_cast<double>(x) / d[0], static_cast<double>(x + 1) / d[0], y0, y1) > 0;
    return columns;
}

} // namespace

TEST_CASE("Line loads on two beams are drawn along both, and leave the nodal arrows to the point loads", "[render][loads]") {
    unsetenv("DISPLAY");
    const Model model = read_scene(std::string(PLASTICA_SOURCE_DIR) + "/tests/frames/two_storey_line_loads.toml");
    const fs::path series = solved_series_of(model, 1, "two_storey_line_loads");
    const SeriesSummary summary = summarise(open_series(series.string()), "", 1.0);
    // 30 kN/m, and of the nodal loads only the 20 kN side load: the beams' nodal shares (up to
    // 30 × 0.75 = 22.5 kN) are not drawn at the nodes.
    CHECK(summary.line_loads.max_intensity == Approx(30.0));
    CHECK(summary.loads.max_force == Approx(20.0));
    RenderOptions o;
    o.output = (series / "pictures").string();
    o.width = 1280, o.height = 720, o.animation = false, o.quiet = true;
    render_series(series.string(), o);
    auto frame = read_png((last_frame(series / "pictures")).string());
    // The structure's view spans the picture's left 43 %: the roof's arrows in its upper band,
    // the floor's in the middle, each a row joined across the 6 m span (over 300 of the ~450
    // pixel columns the beam spans; the nodes' arrows alone would fill some 30).
    const double structure_right = 0.43;
    CHECK(load_columns(frame, structure_right, 0.12, 0.22) > 300);
    CHECK(load_columns(frame, structure_right, 0.45, 0.56) > 300);
    // `--hide loads` leaves out line loads with the point loads.
    o.output = (series / "hidden").string();
    o.hide = {"loads"};
    render_series(series.string(), o);
    frame = read_png((last_frame(series / "hidden")).string());
    CHECK(load_columns(frame, structure_right, 0.12, 0.22) == 0);
    CHECK(load_columns(frame, structure_right, 0.45, 0.56) == 0);
}
