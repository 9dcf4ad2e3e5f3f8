#include "figure_text.hpp"
#include "text_and_mirror.hpp"

#include <vtkTextActor.h>

#include <algorithm>
#include <cstdio>

namespace plastica::render {

double text_scale(int width, int height) { return std::min(height / 720.0, width / 1280.0); }

void style(vtkTextActor* text, double size, bool bold) { style_text(text->GetTextProperty(), size, bold); }

std::string scene_heading(const SeriesSummary& s) { return s.title.empty() ? s.scene : s.title + "  (" + s.scene + ")"; }

std::string load_axis_title(const SeriesSummary& s) {
    const std::string title = with_unit(s.load_label, s.load_unit);
    if (!(s.load_axis_cut[1] > s.load_axis_cut[0])) return title;
    char note[96];
    std::snprintf(note, sizeof note, " (axis cut: rises to %.3g on the base)", s.largest_load);
    return title + note;
}

std::vector<double> curve_column(const std::vector<CurvePoint>& curve, std::size_t count, bool load) {
    std::vector<double> v;
    for (std::size_t i = 0; i < count && i < curve.size(); ++i) v.push_back(load ? curve[i].load : curve[i].displacement);
    return v;
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value == 0.0 ? 0.0 : value); // no "-0"
    return text;
}

} // namespace plastica::render
