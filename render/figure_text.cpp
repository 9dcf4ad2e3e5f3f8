#include "figure_text.hpp"
#include "text_and_mirror.hpp"

#include <vtkTextActor.h>

#include <algorithm>
#include <cmath>
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

std::vector<double> chart_x(const SeriesSummary& s, std::size_t count) {
    if (!s.in_time) return curve_column(s.curve, count, false);
    std::vector<double> v;
    for (std::size_t i = 0; i < count && i < s.curve.size(); ++i) v.push_back(s.curve[i].time);
    return v;
}

std::vector<double> chart_y(const SeriesSummary& s, std::size_t count) { return curve_column(s.curve, count, !s.in_time); }

std::string chart_x_title(const SeriesSummary& s) {
    return s.in_time ? std::string("time (s)") : with_unit(s.displacement_label, s.displacement_unit);
}

std::string chart_y_title(const SeriesSummary& s) {
    return s.in_time ? with_unit(s.displacement_label, s.displacement_unit) : load_axis_title(s);
}

namespace {

std::string with_digits(double value, int digits) {
    char text[64];
    const double size = std::abs(value);
    if (value == 0.0) return "0";
    if (size >= 1e-3 && size < 1e7) {
        const int decimals = std::max(0, digits - 1 - static_cast<int>(std::floor(std::log10(size))));
        std::snprintf(text, sizeof text, "%.*f", decimals, value);
        std::string t = text;
        if (t.find('.') != std::string::npos) {
            t.erase(t.find_last_not_of('0') + 1);
            if (t.back() == '.') t.pop_back();
        }
        return t;
    }
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    return text;
}

} // namespace

std::vector<std::string> distinct_numbers(const std::vector<double>& values) {
    std::vector<std::string> labels;
    for (int digits = 3; digits <= 17; ++digits) {
        labels.clear();
        for (double v : values) labels.push_back(with_digits(v, digits));
        bool apart = true;
        for (std::size_t i = 0; i < values.size() && apart; ++i)
            for (std::size_t j = i + 1; j < values.size() && apart; ++j)
                apart = values[i] == values[j] || labels[i] != labels[j];
        if (apart) break;
    }
    return labels;
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value == 0.0 ? 0.0 : value); // no "-0"
    return text;
}

} // namespace plastica::render
