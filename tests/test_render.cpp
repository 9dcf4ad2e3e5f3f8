// The render stage drawn for real (OSMesa, no DISPLAY) from series the engine wrote, checked by
// the pixels of the PNGs: sizes, layers present or left out, and a chart that follows the data.
#include "render_helpers.hpp"

#include "arrow_scale.hpp"
#include "charts.hpp"
#include "contact_sheet.hpp"
#include "figure_text.hpp"
#include "frame_layout.hpp"
#include "layer_list.hpp"
#include "legend_corner.hpp"
#include "palette.hpp"
#include "png_file.hpp"
#include "render_error.hpp"
#include "render_series.hpp"
#include "result_series.hpp"
#include "series_summary.hpp"

#include <catch2/catch.hpp>
#include <vtkPolyData.h>
#include <vtkTextActor.h>
#include <vtkUnstructuredGrid.h>

#include <cstdlib>
#include <fstream>

using namespace plastica;
using namespace plastica::testing;
using namespace plastica::render;

namespace {

// The bytes of a file that must exist: two missing files would otherwise compare equal.
std::string file_bytes(const fs::path& p) {
    REQUIRE(fs::is_regular_file(p));
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

RenderOptions small(const fs::path& out, int every = 1);

// A frame's full size, 1280 × 720, where pixel positions are checked against a frame's layout.
RenderOptions full_size(const fs::path& out) {
    RenderOptions o = small(out);
    o.width = 1280;
    o.height = 720;
    return o;
}

RenderOptions small(const fs::path& out, int every) {
    RenderOptions o;
    o.output = out.string();
    o.width = 640;
    o.height = 360;
    o.every = every;
    o.animation = false;
    o.quiet = true;
    return o;
}

bool is(Pixel p, Rgb c) { return p.r == c.r && p.g == c.g && p.b == c.b; }

// Yielding markers blend gold into orange; no colour of the cool–warm map has so little blue
// with so much red.
bool yielding_marker(Pixel p) { return p.r >= 240 && p.g >= 120 && p.g <= 220 && p.b <= 45; }

// The structure view: left of the chart, under the title band.
constexpr double structure_right = 0.57 * (1 - 0.25), band_bottom = 0.11;

} // namespace

TEST_CASE("An inelastic ring renders headless: sizes, colours, hinges, contact arrows", "[render]") {
    unsetenv("DISPLAY");
    const fs::path series = solved_series("ring_inelastic", 50, "inelastic");
    const fs::path out = series / "pictures";
    const RenderReport report = render_series(series.string(), small(out));
    CHECK(report.frames == 5);
    CHECK(report.gl_renderer.find("llvmpipe") != std::string::npos);
    for (const char* name : {"frame_000000.png", "frame_000100.png", "frame_000200.png"})
        REQUIRE(fs::exists(out / "frames" / name));
    auto last = read_png((out / "frames" / "frame_000200.png").string());
    int d[3];
    last->GetDimensions(d);
    CHECK(d[0] == 640);
    CHECK(d[1] == 360);
    // Not blank: white background, the title band and many structure colours.
    CHECK(count_pixels(last, [](Pixel p) { return is(p, colour::background); }) > 640 * 360 / 3);
    CHECK(count_pixels(last, [](Pixel p) { return is(p, colour::title_band); }, 0, 1, 0, band_bottom) > 640 * 30);
    // The last step has a fully plastic hinge under the load and yielding ends elsewhere.
    CHECK(count_pixels(last, [](Pixel p) { return is(p, colour::hinge_plastic); }, 0, structure_right, band_bottom, 1) > 20);
    CHECK(count_pixels(last, yielding_marker, 0, structure_right, band_bottom, 1) > 20);
    // Contact arrows sit at the base: in the lowest fifth of the picture.
    const auto green = [](Pixel p) { return is(p, colour::contact_force); };
    CHECK(count_pixels(last, green, 0, structure_right, 0.8, 1) > 30);
    CHECK(count_pixels(last, green, 0, structure_right, band_bottom, 0.6) == 0);
    // The first frame is unloaded: no hinge and no arrow.
    auto first = read_png((out / "frames" / "frame_000000.png").string());
    CHECK(count_pixels(first, [](Pixel p) { return is(p, colour::hinge_plastic); }, 0, structure_right, band_bottom, 1) == 0);
    CHECK(count_pixels(first, green, 0, structure_right, band_bottom, 1) == 0);
    // The contact sheet: its 5 frames in a 3 × 2 grid of half-size frames.
    auto sheet = read_png((out / "contact_sheet.png").string());
    sheet->GetDimensions(d);
    CHECK(d[0] == 3 * 320);
    CHECK(d[1] == 2 * 180);
}

TEST_CASE("An elastic ring has no hinge layer and a scene without a base has no contact arrows", "[render]") {
    unsetenv("DISPLAY");
    const fs::path elastic = solved_series("ring_elastic", 100, "elastic");
    render_series(elastic.string(), small(elastic / "pictures"));
    auto frame = read_png((elastic / "pictures" / "frames" / "frame_000200.png").string());
    CHECK(count_pixels(frame, [](Pixel p) { return is(p, colour::hinge_plastic); }) == 0);
    CHECK(count_pixels(frame, yielding_marker) == 0);
    CHECK(count_pixels(frame, [](Pixel p) { return is(p, colour::contact_force); }, 0, structure_right, 0.8, 1) > 30);

    const fs::path bilateral = solved_series("ring_bilateral", 100, "bilateral");
    render_series(bilateral.string(), small(bilateral / "pictures"));
    frame = read_png((bilateral / "pictures" / "frames" / "frame_000200.png").string());
    CHECK(count_pixels(frame, [](Pixel p) { return is(p, colour::contact_force); }) == 0);
    CHECK(count_pixels(frame, [](Pixel p) { return is(p, colour::hinge_plastic); }) == 0);
    CHECK(count_pixels(frame, [](Pixel p) { return is(p, colour::spring_anchor); }, 0, structure_right, band_bottom, 1) > 20);
}

TEST_CASE("A distributed-plasticity ring is shaded by the yielded share, without hinge markers", "[render][distributed]") {
    unsetenv("DISPLAY");
    const fs::path series = solved_series("ring_distributed", 50, "distributed");
    render_series(series.string(), small(series / "pictures"));
    // The warm end of the cool–warm map (a section yielded through): strong red, little green.
    const auto yielded_through = [](Pixel p) { return p.r >= 150 && p.g <= 60 && p.b <= 70; };
    auto last = read_png((series / "pictures" / "frames" / "frame_000200.png").string());
    // At δ = 100 the sections under the load have yielded through: red at the top of the ring
    // (upper half of the structure view), and no hinge colours anywhere.
    CHECK(count_pixels(last, yielded_through, 0, structure_right, band_bottom, 0.6) > 10);
    CHECK(count_pixels(last, [](Pixel p) { return is(p, colour::hinge_plastic); }) == 0);
    CHECK(count_pixels(last, yielding_marker) == 0);
    // Unloaded: nothing has yielded.
    auto first = read_png((series / "pictures" / "frames" / "frame_000000.png").string());
    CHECK(count_pixels(first, yielded_through, 0, structure_right, band_bottom, 1) == 0);
}

TEST_CASE("Charts keep a structure's own response in view when a base takes over the load", "[render]") {
    unsetenv("DISPLAY");
    // The shallow arch snaps through (peak near 172) and lands on the floor, whose penalty
    // then carries 1.5e6: the load axis spans the arch's own range and says where it is cut.
    const fs::path arch = solved_series("gallery/arch_on_floor", 1, "arch_cut");
    const SeriesSummary landed = summarise(open_series(arch.string()), "", 1.0);
    double before = 0.0, low = 0.0;
    for (const CurvePoint& c : landed.curve) {
        if (c.contact_count > 0) break;
        before = std::max(before, c.load), low = std::min(low, c.load);
    }
    CHECK(before == Approx(172.5).margin(1.0));
    CHECK(low < 0.0); // past the snap the arch pulls back before it lands
    CHECK(landed.load_axis_cut[1] == Approx(2.0 * before));
    CHECK(landed.load_axis_cut[0] < low);
    CHECK(landed.largest_load > 1e6);
    RenderOptions o = small(arch / "pictures", 1000);
    render_series(arch.string(), o);
    // The chart's curve climbs to the arch's peak and falls past the snap: its blue (drawn
    // thin and blended at this size) fills the chart's middle, where with the whole range
    // (to 1.5e6) only the vertical landing line would stand.
    auto chart = read_png((arch / "pictures" / "chart.png").string());
    const auto blue = [](Pixel p) { return p.b > p.r + 60 && p.b > p.g + 40; };
    CHECK(count_pixels(chart, blue, 0.1, 0.7, 0.3, 0.75) > 200);
    // A ring whose contact spreads with a modest rise of the load keeps its whole range.
    const fs::path ring = solved_series("ring_elastic", 50, "ring_uncut");
    const SeriesSummary spread = summarise(open_series(ring.string()), "", 1.0);
    CHECK(spread.load_axis_cut[0] == 0.0);
    CHECK(spread.load_axis_cut[1] == 0.0);
}

TEST_CASE("Contact arrows are scaled to the forces while the load is in view", "[render]") {
    unsetenv("DISPLAY");
    // The cantilever bent down onto a floor: the floor's penalty then holds the load (200 against
    // the cantilever's own 1.5), and its contact forces would shrink the arrows of the first
    // touches to dots; they are drawn to the largest force while the load is in view instead.
    const fs::path floor = solved_series("gallery/cantilever_onto_floor", 1, "contact_scale");
    const SeriesSummary landed = summarise(open_series(floor.string()), "", 1.0);
    REQUIRE(landed.load_axis_cut[1] > 0.0);
    CHECK(landed.contact_arrow_reference > 0.0);
    CHECK(landed.contact_arrow_reference < 0.1 * landed.max_contact_force);
    const ResultSeries series = open_series(floor.string());
    const auto layers = make_layers(landed, read_step(series.steps.front().file), read_base(series.base_file), {});
    const auto contact = std::find_if(layers.begin(), layers.end(), [](const auto& l) {
        return !l->legend().empty() && l->legend().front().text == "contact force";
    });
    REQUIRE(contact != layers.end());
    CHECK_THAT((*contact)->note(), Catch::Contains("longer ones cut"));
    // A ring whose contact spreads as its load rises keeps the largest in the run.
    const fs::path ring = solved_series("ring_elastic", 50, "contact_scale_ring");
    const SeriesSummary spread = summarise(open_series(ring.string()), "", 1.0);
    CHECK(spread.contact_arrow_reference == spread.max_contact_force);
}

TEST_CASE("Supports and loads are drawn where the scene has them, and --hide leaves them out", "[render]") {
    unsetenv("DISPLAY");
    // The portal frame: two clamped feet at the bottom, gravity loads on the column heads and a
    // sway load, drawn as arrows above the frame.
    const fs::path portal = solved_series("gallery/portal_frame", 1000, "portal");
    render_series(portal.string(), small(portal / "pictures"));
    // Its first and last steps: the sway load at its largest in the last.
    const std::string last = last_frame(portal / "pictures").filename().string();
    REQUIRE(last != "frame_000000.png");
    auto frame = read_png((portal / "pictures" / "frames" / last).string());
    const auto support = [](Pixel p) { return is(p, colour::support); };
    const auto load = [](Pixel p) { return is(p, colour::load); };
    const double middle = 0.5 * (band_bottom + 1.0);
    CHECK(count_pixels(frame, support, 0, structure_right, middle, 1) > 40);
    CHECK(count_pixels(frame, support, 0, structure_right, band_bottom, middle) == 0);
    CHECK(count_pixels(frame, load, 0, structure_right, band_bottom, middle) > 40);
    CHECK(count_pixels(frame, load, 0, structure_right, middle, 1) == 0);
    // Unloaded, the load arrows are gone; the supports stay.
    auto first = read_png((portal / "pictures" / "frames" / "frame_000000.png").string());
    CHECK(count_pixels(first, load, 0, structure_right, band_bottom, 1) == 0);
    CHECK(count_pixels(first, support, 0, structure_right, band_bottom, 1) > 40);

    // Its scene names its units: the displacement in m, moments in kN·m, the load factor none.
    const SeriesSummary units = summarise(open_series(portal.string()), "", 1.0);
    CHECK(units.displacement_unit == "m");
    CHECK(units.load_unit.empty());
    CHECK(array_unit(units, "bending_moment") == "kN·m");
    CHECK(array_unit(units, "reaction") == "kN");
    CHECK(array_unit(units, "yielded_share").empty());
    CHECK(with_unit(units.displacement_label, units.displacement_unit) == "sway at the beam (m)");

    RenderOptions hidden = small(portal / "hidden");
    hidden.hide = {"supports", "loads"};
    render_series(portal.string(), hidden);
    frame = read_png((portal / "hidden" / "frames" / last).string());
    CHECK(count_pixels(frame, support) == 0);
    CHECK(count_pixels(frame, load, 0, structure_right, band_bottom, 1) == 0);
    hidden.hide = {"suports"};
    CHECK_THROWS_WITH(render_series(portal.string(), hidden),
                      Catch::Contains("--hide takes initial, base, hinges, releases, contact, surface_contact, supports, loads (got 'suports')"));
    // A refused option leaves the pictures drawn before.
    CHECK(fs::exists(portal / "hidden" / "frames" / last));

    // Reactions only on request: at the clamps, in the lower half, where no reaction colour is otherwise.
    const auto reaction = [](Pixel p) { return is(p, colour::reaction); };
    CHECK(count_pixels(read_png((portal / "pictures" / "frames" / last).string()), reaction) == 0);
    RenderOptions shown = small(portal / "reactions");
    shown.show = {"reactions"};
    render_series(portal.string(), shown);
    frame = read_png((portal / "reactions" / "frames" / last).string());
    CHECK(count_pixels(frame, reaction, 0, structure_right, middle, 1) > 40);
    CHECK(count_pixels(frame, reaction, 0, structure_right, band_bottom, middle) == 0);
    shown.show = {"loads"};
    CHECK_THROWS_WITH(render_series(portal.string(), shown), Catch::Contains("--show takes reactions (got 'loads')"));

    // The half ring's supports state symmetry on its mirror line: no symbols; its load at the
    // top is drawn, in the upper half of the view.
    const fs::path ring = solved_series("ring_elastic", 100, "ring_loads");
    render_series(ring.string(), small(ring / "pictures"));
    frame = read_png((ring / "pictures" / "frames" / "frame_000200.png").string());
    CHECK(count_pixels(frame, support) == 0);
    CHECK(count_pixels(frame, load, 0, structure_right, band_bottom, middle) > 20);
}

TEST_CASE("A support on a symmetric structure's centre line is drawn on one side, wherever round-off puts its node", "[render]") {
    unsetenv("DISPLAY");
    // A pinned triangle whose apex is held sideways only: the guide's ground stands beside the
    // apex, on the side away from the structure, which on the centre line is the left. Its
    // node 1e-12 left or right of the centre must not turn the symbol round.
    auto drawn = [](const std::string& x, const std::string& tag) {
        const Model model = read_scene_text(
            "[scene]\nname = \"apex\"\n[[material]]\nname = \"m\"\nE = 1.0e6\n[[section]]\nname = \"s\"\nmaterial = \"m\"\n"
            "A = 1.0\nI = 1.0\n[[line]]\nstart = [-5.0, 0.0]\nend = [" + x + ", 5.0]\nelements = 2\nsection = \"s\"\n"
            "[[line]]\nstart = [" + x + ", 5.0]\nend = [5.0, 0.0]\nelements = 2\nsection = \"s\"\n"
            "[[support]]\nat = [-5.0, 0.0]\nfix = [\"ux\", \"uy\"]\n[[support]]\nat = [5.0, 0.0]\nfix = [\"ux\", \"uy\"]\n"
            "[[support]]\nat = [" + x + ", 5.0]\nfix = [\"ux\"]\n[[load]]\nat = [" + x + ", 5.0]\nfy = -1.0\n"
            "[analysis]\nscheme = \"load_control\"\nincrement = 1.0\ntarget_load_factor = 1.0\n",
            "apex.toml");
        const fs::path series = solved_series_of(model, 1, tag);
        render_series(series.string(), small(series / "pictures"));
        return read_png((series / "pictures" / "frames" / "frame_000000.png").string());
    };
    const auto left = drawn("-1e-12", "apex_left"), right = drawn("1e-12", "apex_right");
    const auto support = [](Pixel p) { return is(p, colour::support); };
    // Both pictures alike, and the guide's symbol in the left half of the structure view.
    CHECK(count_pixels(left, support) == count_pixels(right, support));
    const double top = band_bottom + 0.5 * (1 - band_bottom); // above the pins
    const long guide_left = count_pixels(right, support, 0, 0.5 * structure_right, band_bottom, top);
    const long guide_right = count_pixels(right, support, 0.5 * structure_right, structure_right, band_bottom, top);
    CHECK(guide_left > 40);
    CHECK(guide_right < guide_left / 4);
    CHECK(count_pixels(left, support, 0, 0.5 * structure_right, band_bottom, top) == guide_left);
}

TEST_CASE("A stiff structure drawn with --magnify shows its displacements enlarged", "[render]") {
    unsetenv("DISPLAY");
    // A cantilever of length 10 whose tip moves down by 0.01 (PL³/3EI): 0.1 % of its length.
    const Model model = read_scene_text(
        "[scene]\nname = \"stiff\"\n[[material]]\nname = \"m\"\nE = 1.0e6\n[[section]]\nname = \"s\"\nmaterial = \"m\"\n"
        "A = 1.0\nI = 1.0\n[[line]]\nstart = [0.0, 0.0]\nend = [10.0, 0.0]\nelements = 10\nsection = \"s\"\n"
        "[[support]]\nat = [0.0, 0.0]\nfix = [\"ux\", \"uy\", \"rz\"]\n[[load]]\nat = [10.0, 0.0]\nfy = -30.0\n"
        "[analysis]\nscheme = \"load_control\"\nincrement = 1.0\ntarget_load_factor = 1.0\n",
        "stiff.toml");
    const fs::path series = solved_series_of(model, 1, "stiff");
    const SeriesSummary true_scale = summarise(open_series(series.string()), "", 1.0);
    const SeriesSummary chosen = summarise(open_series(series.string()), "", 0.0);
    // The tip deflection 0.01 becomes about 10 % of the size: × 100.
    CHECK(true_scale.magnify == 1.0);
    CHECK(chosen.magnify == 100.0);
    CHECK(chosen.bounds[2] == Approx(-1.0).epsilon(1e-3));
    CHECK(true_scale.bounds[2] == Approx(-0.01).epsilon(1e-3));
    // Drawn at true scale the deformed ribbon hides the initial shape; magnified, it shows.
    const auto initial = [](Pixel p) { return is(p, colour::initial_shape); };
    render_series(series.string(), small(series / "true"));
    RenderOptions enlarged = small(series / "enlarged");
    enlarged.magnify = 0.0;
    render_series(series.string(), enlarged);
    auto flat = read_png((series / "true" / "frames" / "frame_000001.png").string());
    auto bent = read_png((series / "enlarged" / "frames" / "frame_000001.png").string());
    CHECK(count_pixels(bent, initial, 0, structure_right, band_bottom, 1) > 3 * count_pixels(flat, initial, 0, structure_right, band_bottom, 1) + 100);
    // A scene on a rigid base keeps its true scale: magnified, it would seem to pass through.
    const fs::path ring = solved_series("ring_elastic", 100, "magnify_ring");
    CHECK(summarise(open_series(ring.string()), "", 0.0).magnify == 1.0);
}

TEST_CASE("Reference points from a CSV join the chart as markers, and a bad line is named", "[render]") {
    unsetenv("DISPLAY");
    const fs::path series = solved_series("ring_elastic", 200, "reference_points");
    const fs::path csv = series / "table.csv";
    std::ofstream(csv) << "# points of the README's table\ndisplacement,P\n10, 0.0626\n40, 0.2117\n80, 0.3786\n";
    RenderOptions plain = small(series / "plain"), with = small(series / "with");
    with.reference_points = {csv.string() + ":README table"};
    render_series(series.string(), plain);
    render_series(series.string(), with);
    const auto black = [](Pixel p) { return p.r == 0 && p.g == 0 && p.b == 0; };
    auto before = read_png((series / "plain" / "chart.png").string());
    auto after = read_png((series / "with" / "chart.png").string());
    CHECK(count_pixels(before, black) == 0);
    CHECK(count_pixels(after, black) > 3 * 20); // three markers and the legend's
    std::ofstream(series / "bad.csv") << "displacement,P\n10, 0.06\n40, none\n";
    with.reference_points = {(series / "bad.csv").string()};
    CHECK_THROWS_WITH(render_series(series.string(), with), Catch::Contains("bad.csv:3: expected 'displacement, load'"));
}

TEST_CASE("Shapes at several displacements, two runs side by side at one scale", "[render]") {
    unsetenv("DISPLAY");
    const fs::path elastic = solved_series("ring_elastic", 10, "shapes_elastic");
    const fs::path inelastic = solved_series("ring_inelastic", 10, "shapes_inelastic");
    RenderOptions o = small(elastic / "pictures");
    o.steps = {0};
    o.overlays = {inelastic.string()};
    o.shapes = {50.0, 100.0};
    render_series(elastic.string(), o);
    auto shapes = read_png((elastic / "pictures" / "shapes.png").string());
    int d[3];
    shapes->GetDimensions(d);
    CHECK(d[0] == 640);
    // The last shape in the darkest blue, the unloaded ring in grey, in each half.
    const auto dark = [](Pixel p) { return p.r == 10 && p.g == 40 && p.b == 110; };
    const auto grey = [](Pixel p) { return is(p, colour::initial_shape); };
    for (double x0 : {0.0, 0.5}) {
        CHECK(count_pixels(shapes, dark, x0, x0 + 0.35, band_bottom, 1) > 100);
        CHECK(count_pixels(shapes, grey, x0, x0 + 0.35, band_bottom, 1) > 100);
    }
    o.shapes = {150.0};
    CHECK_THROWS_WITH(render_series(elastic.string(), o), Catch::Contains("the run does not reach top displacement = 150"));
}

TEST_CASE("The chart's curve rises where the load rises", "[render]") {
    unsetenv("DISPLAY");
    const fs::path series = solved_series("ring_elastic", 10, "chart");
    render_series(series.string(), small(series / "pictures", 200));
    auto chart = read_png((series / "pictures" / "chart.png").string());
    int d[3];
    chart->GetDimensions(d);
    // Height of the curve's highest pixel in each column where the curve is drawn.
    std::vector<int> heights;
    for (int x = 0; x < d[0]; ++x) {
        for (int y = d[1] - 1; y >= 0; --y) {
            const auto* p = static_cast<unsigned char*>(chart->GetScalarPointer(x, y, 0));
            if (is({p[0], p[1], p[2]}, colour::curve_progress)) {
                heights.push_back(y);
                break;
            }
        }
    }
    REQUIRE(heights.size() > 300u);
    // The elastic ring's load grows with the displacement: the curve climbs over most of the
    // chart's height and never drops by more than its own line width.
    CHECK(heights.back() - heights.front() > d[1] / 2);
    for (std::size_t i = 1; i < heights.size(); ++i) CHECK(heights[i] >= heights[i - 1] - 3);
}

TEST_CASE("The same frame drawn twice is the same PNG, byte for byte", "[render]") {
    unsetenv("DISPLAY");
    const fs::path series = solved_series("ring_inelastic", 100, "twice");
    render_series(series.string(), small(series / "a"));
    render_series(series.string(), small(series / "b"));
    for (const char* name : {"frames/frame_000100.png", "frames/frame_000200.png", "chart.png"})
        CHECK(file_bytes(series / "a" / name) == file_bytes(series / "b" / name));
}

TEST_CASE("Frames drawn by several processes are the bytes one process draws", "[render]") {
    unsetenv("DISPLAY");
    const fs::path series = solved_series("ring_inelastic", 10, "workers");
    RenderOptions serial = small(series / "serial"), parallel = small(series / "parallel");
    serial.workers = 1;
    parallel.workers = 3;
    serial.animation = parallel.animation = std::system("command -v ffmpeg > /dev/null") == 0;
    // Processes are forked only before this process has drawn anything: the parallel render first.
    const RenderReport report = render_series(series.string(), parallel);
    CHECK(report.workers == 3);
    CHECK(render_series(series.string(), serial).workers == 1);
    const auto bytes = file_bytes;
    int frames = 0;
    for (const auto& entry : fs::directory_iterator(series / "serial" / "frames")) {
        ++frames;
        CHECK(bytes(entry.path()) == bytes(series / "parallel" / "frames" / entry.path().filename()));
    }
    CHECK(frames == report.frames);
    CHECK(frames == 21);
    CHECK(bytes(series / "serial" / "contact_sheet.png") == bytes(series / "parallel" / "contact_sheet.png"));
    if (serial.animation) {
        const std::string gif = bytes(series / "parallel" / "ring_inelastic.gif");
        CHECK(gif.rfind("GIF89a", 0) == 0);
        CHECK(gif == bytes(series / "serial" / "ring_inelastic.gif"));
        // The frame file and the palette, kept only while the animation is made, are gone.
        for (const auto& entry : fs::directory_iterator(series / "parallel"))
            CHECK(entry.path().extension() != ".rgb");
    }
}

TEST_CASE("Every load shows by its components and the legend names only the supports there are", "[render][legend]") {
    unsetenv("DISPLAY");
    // The gallery's portal: 35 kN sideways beside 2 800 kN down at the left column's head. The
    // sway load is drawn as its own arrow, pointing right, left of the frame at the beam's height,
    // not folded into a near-vertical resultant.
    const fs::path portal = solved_series("gallery/portal_frame", 1000, "components");
    render_series(portal.string(), full_size(portal / "pictures"));
    auto frame = read_png(last_frame(portal / "pictures").string());
    const auto load = [](Pixel p) { return is(p, colour::load); };
    CHECK(count_pixels(frame, load, 0.0, 0.085, 0.19, 0.26) > 40);
    // Clamps only: the legend's support mark is a wall (a few rows high), not a pin's triangle.
    const auto support = [](Pixel p) { return is(p, colour::support); };
    int rows = 0;
    for (int y = 100; y < 720; ++y)
        rows += count_pixels(frame, support, 0.445, 0.47, y / 720.0, (y + 1) / 720.0) > 0;
    CHECK(rows > 0);
    CHECK(rows <= 6);
}

TEST_CASE("A signed field is coloured about zero: a column in compression is blue", "[render][legend]") {
    unsetenv("DISPLAY");
    // Axial force alone, all of it compression: on a scale diverging about the middle of its
    // range half the column would be red, as if in tension.
    const fs::path column = solved_series_of(read_scene_text(R"(
[scene]
name = "column_in_compression"
[[material]]
name = "steel"
E = 2.1e8
fy = 3.55e5
[[section]]
name = "box"
material = "steel"
shape = "rectangle"
b = 0.2
h = 0.2
[[line]]
name = "column"
start = [0.0, 0.0]
end = [0.0, 4.0]
elements = 8
section = "box"
[[support]]
at = [0.0, 0.0]
fix = ["ux", "uy", "rz"]
[[load]]
at = [0.0, 4.0]
fy = -100.0
[[distributed_load]]
on = "column"
wy = -50.0
[analysis]
scheme = "load_control"
increment = 0.25
target_load_factor = 1.0
)", "column.toml"), 1, "compression");
    RenderOptions o = small(column / "pictures");
    o.field = "axial_force";
    o.hide = {"loads"}; // red arrows of their own
    render_series(column.string(), o);
    auto frame = read_png(last_frame(column / "pictures").string());
    const auto warm = [](Pixel p) { return p.r > p.b + 40; };
    const auto cool = [](Pixel p) { return p.b > p.r + 40 && p.g < 200; };
    CHECK(count_pixels(frame, cool, 0, structure_right, band_bottom, 1) > 100);
    CHECK(count_pixels(frame, warm, 0, structure_right, band_bottom, 1) == 0);
}

TEST_CASE("An option that cannot act says why and a chart mark that would sit on the origin is left out", "[render]") {
    unsetenv("DISPLAY");
    // A pipe on a tensionless bed: contact grows from the first loaded step, and enlarged
    // displacements would push the pipe through its bed.
    const fs::path pipe = solved_series("gallery/pipe_on_soil", 1, "notes");
    RenderOptions o = small(pipe / "pictures", 1000);
    o.magnify = 0.0; // auto
    const RenderReport report = render_series(pipe.string(), o);
    REQUIRE(report.notes.size() == 1);
    CHECK_THAT(report.notes.front(), Catch::Contains("--magnify auto draws at true scale") && Catch::Contains("rests on a base"));
    auto chart = read_png((pipe / "pictures" / "chart.png").string());
    CHECK(count_pixels(chart, [](Pixel p) { return is(p, colour::contact_force); }) == 0);
    CHECK(count_pixels(chart, [](Pixel p) { return is(p, colour::hinge_yielding_high); }) > 10); // first yield stays
    // A factor is taken, and the note says how the bed is drawn beside the enlarged pipe.
    o.magnify = 5.0;
    const RenderReport enlarged = render_series(pipe.string(), o);
    REQUIRE(enlarged.notes.size() == 1);
    CHECK_THAT(enlarged.notes.front(), Catch::Contains("--magnify 5") && Catch::Contains("may seem to pass through it"));
}

TEST_CASE("Options that change nothing in a series say so", "[render]") {
    unsetenv("DISPLAY");
    // The elastic ring has no hinges and no moments at its supports' reactions to speak of,
    // and --steps names the steps, so --every has nothing to choose.
    const fs::path ring = solved_series("ring_elastic", 50, "no_ops");
    RenderOptions o = small(ring / "pictures", 1);
    o.hide = {"hinges", "loads"};
    o.steps = {0, 200};
    o.every = 7;
    const RenderReport report = render_series(ring.string(), o);
    REQUIRE(report.notes.size() == 2);
    CHECK(report.notes[0] == "--hide hinges changes nothing: this series has no hinges to draw");
    CHECK(report.notes[1] == "--every 7 changes nothing: --steps names the steps to draw");
    // Without them: no note.
    o.hide = {"loads"};
    o.every = 1;
    CHECK(render_series(ring.string(), o).notes.empty());
}

TEST_CASE("Labels of values keep every value apart", "[render][legend]") {
    CHECK(distinct_numbers({235e3, 275e3, 355e3}) == std::vector<std::string>{"235000", "275000", "355000"});
    CHECK(distinct_numbers({2.35e5, 2.351e5}) == std::vector<std::string>{"235000", "235100"});
    CHECK(distinct_numbers({1.0, 1.0001, 1.0}) == std::vector<std::string>{"1", "1.0001", "1"});
    CHECK(distinct_numbers({0.5, 0.25, 0.125}) == std::vector<std::string>{"0.5", "0.25", "0.125"});
    CHECK(distinct_numbers({2e-7, 3e-7}) == std::vector<std::string>{"2e-07", "3e-07"});
}

TEST_CASE("A bad series is refused with the file and the reason", "[render]") {
    unsetenv("DISPLAY");
    const fs::path series = solved_series("ring_elastic", 100, "bad");
    auto message = [&](const fs::path& target, RenderOptions o) {
        try {
            render_series(target.string(), o);
        } catch (const RenderError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const RenderOptions o = small(series / "pictures");
    SECTION("no series in the folder") {
        CHECK_THAT(message(series / "vtu", o), Catch::Contains("expected one .pvd result series, found 0"));
    }
    SECTION("a colour field the series does not have") {
        RenderOptions f = o;
        f.field = "temperature";
        CHECK_THAT(message(series, f), Catch::Contains("no array 'temperature'") && Catch::Contains("bending_moment"));
    }
    SECTION("a step file missing") {
        fs::remove(series / "vtu" / "step_000100.vtu");
        CHECK_THAT(message(series, o), Catch::Contains("step_000100.vtu: missing (listed in"));
    }
    SECTION("a truncated step file") {
        const fs::path step = series / "vtu" / "step_000100.vtu";
        fs::resize_file(step, fs::file_size(step) / 2);
        CHECK_THAT(message(series, o), Catch::Contains("step_000100.vtu: an array runs past the end of the file"));
    }
    SECTION("a foreign VTU") {
        std::ofstream(series / "vtu" / "step_000100.vtu")
            << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\"><UnstructuredGrid>"
               "<Piece NumberOfPoints=\"1\" NumberOfCells=\"0\"><Points><DataArray type=\"Float32\" "
               "NumberOfComponents=\"3\" format=\"ascii\">0 0 0</DataArray></Points><Cells>"
               "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\"></DataArray>"
               "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\"></DataArray>"
               "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\"></DataArray></Cells>"
               "</Piece></UnstructuredGrid></VTKFile>\n";
        CHECK_THAT(message(series, o), Catch::Contains("step_000100.vtu: no appended data (not a step file as Plastica writes it)"));
    }
    SECTION("a PVD that is not a collection") {
        std::ofstream(series / "ring_elastic.pvd") << "<html>not a series</html>\n";
        CHECK_THAT(message(series, o), Catch::Contains("ring_elastic.pvd: not a ParaView collection"));
    }
    SECTION("an absurd picture size") {
        RenderOptions big = o;
        big.width = 100000;
        CHECK_THAT(message(series, big), Catch::Contains("outside 64x64"));
    }
}

TEST_CASE("Greek letters in labels are drawn, not dropped", "[render]") {
    unsetenv("DISPLAY");
    // The same run twice, its displacement label with and without Greek letters: the title
    // band's status line draws more dark pixels for Greek letters only if their glyphs exist
    // (VTK's own Arial has none: they vanished).
    auto band_ink = [](const std::string& label, const std::string& tag) {
        Model model = read_scene(std::string(PLASTICA_SOURCE_DIR) + "/models/ring_elastic.toml");
        model.analysis.max_steps = 4;
        model.report.displacement_label = label;
        const fs::path series = solved_series_of(model, 1, tag);
        RenderOptions o = small(series / "pictures");
        o.steps = {4};
        render_series(series.string(), o);
        auto frame = read_png((series / "pictures" / "frames" / "frame_000004.png").string());
        return count_pixels(frame, [](Pixel p) { return p.r < 90 && p.g < 90 && p.b < 90; }, 0, 1, 0, band_bottom);
    };
    const long plain = band_ink("top displacement", "greek_plain");
    const long greek = band_ink("top displacement δσθδσθδσθ", "greek_letters");
    const long latin = band_ink("top displacement abcabcabc", "greek_latin");
    CAPTURE(plain, greek, latin);
    // Nine Greek letters add ink about as much as nine Latin ones.
    CHECK(greek - plain > 0.7 * (latin - plain));
}

TEST_CASE("The legend goes to the corner the curves leave free", "[render]") {
    // A frame's curve: up at once to its peak, then falling away to the right.
    ChartSeries falling{"a curve", {0.0, 0.02, 0.05, 0.25}, {0.0, 1.05, 0.95, 0.6}, {31, 119, 180}};
    const auto corner = [](const std::vector<ChartSeries>& s) { return clearest_corner(s, 0.0, 0.26, 0.0, 1.1, 0.3, 0.15); };
    CHECK(corner({falling}).right);
    CHECK(!corner({falling}).bottom);
    // Rising to the top right, the curve leaves the top left free: it keeps the legend.
    ChartSeries rising{"a curve", {0.0, 0.25}, {0.0, 1.05}, {31, 119, 180}};
    CHECK(!corner({rising}).right);
    CHECK(!corner({rising}).bottom);
    // A plateau across the top: a bottom corner, the right one first.
    ChartSeries plateau{"a curve", {0.0, 0.01, 0.25}, {0.0, 1.05, 1.05}, {31, 119, 180}};
    CHECK(corner({plateau}).bottom);
    CHECK(corner({plateau}).right);

    // Drawn: the legend's dark text and frame in the top right, none in the top left, where the
    // curve peaks (the vertical axis' labels lie left of both boxes).
    unsetenv("DISPLAY");
    ChartFigure f;
    f.title = "legend placement";
    f.x_label = "x";
    f.y_label = "y";
    f.series = {falling};
    f.legend = true;
    f.width = 640;
    f.height = 360;
    vtkSmartPointer<vtkImageData> chart = draw_chart(f);
    const auto dark = [](Pixel p) { return p.r < 60 && p.g < 60 && p.b < 60; };
    CHECK(count_pixels(chart, dark, 0.6, 0.98, band_bottom + 0.01, 0.4) > 50);
    CHECK(count_pixels(chart, dark, 0.15, 0.45, band_bottom + 0.01, 0.4) == 0);
}

TEST_CASE("A chart on log axes draws its lines", "[render]") {
    // An error against run time, one decade each way: the line and its markers must be on the
    // picture (a log axis becomes active only while a frame is painted).
    unsetenv("DISPLAY");
    ChartFigure f;
    f.title = "log axes";
    f.x_label = "time";
    f.y_label = "error";
    f.series = {{"a ladder", {0.001, 0.01, 0.1}, {0.1, 0.03, 0.01}, {230, 120, 20}, 3.0f}};
    f.legend = false;
    f.log_scale = true;
    f.width = 640;
    f.height = 360;
    vtkSmartPointer<vtkImageData> chart = draw_chart(f);
    const auto orange = [](Pixel p) { return p.r > 200 && p.g > 90 && p.g < 150 && p.b < 60; };
    // The line runs from the left third to the right third of the plot.
    CHECK(count_pixels(chart, orange, 0.15, 0.35, band_bottom, 1) > 100);
    CHECK(count_pixels(chart, orange, 0.65, 0.9, band_bottom, 1) > 100);
}

TEST_CASE("A contact sheet's grid is no larger than its frames", "[render]") {
    auto tile = [] {
        auto image = vtkSmartPointer<vtkImageData>::New();
        image->SetDimensions(40, 20, 1);
        image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
        return image;
    };
    // frames → expected columns × rows of 40 × 20 tiles (3 × 3 at most).
    const int cases[][3] = {{1, 1, 1}, {2, 2, 1}, {3, 3, 1}, {4, 2, 2}, {5, 3, 2}, {6, 3, 2}, {7, 3, 3}, {30, 3, 3}};
    for (const auto& c : cases) {
        CAPTURE(c[0]);
        ContactSheet sheet(static_cast<std::size_t>(c[0]), 3, 3, 1.0);
        for (int k = 0; k < c[0]; ++k)
            if (sheet.wants(static_cast<std::size_t>(k))) sheet.keep(static_cast<std::size_t>(k), tile());
        int dims[3];
        sheet.compose()->GetDimensions(dims);
        CHECK(dims[0] == 40 * c[1]);
        CHECK(dims[1] == 20 * c[2]);
    }
}

TEST_CASE("A frame's layout draws a wide structure across the picture and a compact one beside the chart", "[render][layout]") {
    // A box about as tall as wide (the ring with its base and load) keeps the chart beside it.
    const FrameLayout ring = choose_frame_layout(2.4, 2.6, 1280, 720);
    CHECK_FALSE(ring.legend);
    CHECK(ring.structure.x1 == Approx(0.57));
    CHECK(ring.chart[0] == Approx(0.57));
    // So does a frame 1.4 times as wide as tall: across the picture, under a band that leaves the
    // chart room, it would be drawn smaller.
    const FrameLayout portal = choose_frame_layout(9.9, 7.1, 1280, 720);
    CHECK_FALSE(portal.legend);
    // A flat beam goes across the whole width, its legend and the chart beneath it, in three
    // viewports that do not overlap; it is drawn more than twice as large as beside the chart.
    const FrameLayout beam = choose_frame_layout(10.8, 2.0, 1280, 720);
    REQUIRE(beam.legend);
    CHECK(beam.structure.x0 == 0.0);
    CHECK(beam.structure.x1 == 1.0);
    CHECK(beam.structure.y1 == Approx(1.0 - band));
    CHECK(beam.legend->y1 == Approx(beam.structure.y0));
    CHECK(beam.chart[3] == Approx(beam.structure.y0));
    CHECK(beam.legend->x1 == Approx(beam.chart[0]));
    CHECK(structure_scale(beam, 10.8, 2.0) > 2.0 * structure_scale(choose_frame_layout(2.0, 2.0, 1280, 720), 10.8, 2.0));
    // However flat, the chart keeps close to half the height under the title band.
    const FrameLayout strip = choose_frame_layout(100.0, 1.0, 1280, 720);
    CHECK(strip.structure.y0 >= 0.3 * (1.0 - band) - 1e-12);
    CHECK(strip.structure.y1 - strip.structure.y0 >= 0.3 * (1.0 - band) - 1e-12);
}

TEST_CASE("A flat beam's drawing spans the picture's width, above its legend and chart", "[render][layout]") {
    unsetenv("DISPLAY");
    const fs::path beam = solved_series("gallery/beam_large_deflection", 1000, "wide");
    render_series(beam.string(), full_size(beam / "pictures"));
    auto frame = read_png(last_frame(beam / "pictures").string());
    // The ribbon's dark outline: the columns it reaches.
    const auto outline = [](Pixel p) { return is(p, colour::outline); };
    int first = -1, last = -1;
    for (int x = 0; x < 1280; ++x)
        if (count_pixels(frame, outline, x / 1280.0, (x + 1) / 1280.0, band_bottom, 0.6) > 0) {
            if (first < 0) first = x;
            last = x;
        }
    // Beside the chart the beam spanned 500 of 1280 pixels.
    CHECK(last - first > 0.7 * 1280);
}

TEST_CASE("Values beside arrows stay inside the drawing and never cover one another", "[render][legend]") {
    ViewGeometry view;
    view.view[0] = 0.0, view.view[1] = 12.8, view.view[2] = 0.0, view.view[3] = 7.2;
    view.drawing_right = 10.0;
    view.world_per_pixel = 0.01;
    std::vector<vtkTextActor*> written;
    ArrowLabels labels;
    labels.attach(view, [&](vtkProp* prop, bool) { written.push_back(vtkTextActor::SafeDownCast(prop)); }, colour::load);
    const auto shown = [&] {
        return std::count_if(written.begin(), written.end(), [](vtkTextActor* a) { return a->GetVisibility(); });
    };
    // Downward arrows at the drawing's left edge and 0.1 (10 pixels) beside it: the first value is
    // moved in from the edge, the second, which would cover it, is left out; one further along is
    // written.
    const double at_edge[2] = {0.0, 5.0}, beside[2] = {0.1, 5.0}, further[2] = {5.0, 5.0};
    labels.add(at_edge, 0.0, -1.0, "0.625");
    labels.add(beside, 0.0, -1.0, "1.25");
    CHECK(shown() == 1);
    REQUIRE(!written.empty());
    CHECK(written[0]->GetPosition()[0] > 0.1);
    labels.add(further, 0.0, -1.0, "1.25");
    CHECK(shown() == 2);
    // A new frame starts afresh.
    labels.clear();
    labels.add(beside, 0.0, -1.0, "1.25");
    CHECK(shown() == 1);
}
