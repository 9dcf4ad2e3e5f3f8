#include "section_charts.hpp"

#include "figure_text.hpp"
#include "palette.hpp"
#include "result_schema.hpp"
#include "series_summary.hpp"

#include <cmath>

namespace plastica::render {

namespace {

std::string unit_of(const char* array, const SectionUnits& units) {
    return result::unit(result::find(array), units.length, units.force);
}

} // namespace

ChartFigure capacity_chart(const std::string& section_name, const std::vector<CapacityRow>& rows, const SectionUnits& units,
                           const std::optional<SectionPath>& path, bool strain_limits) {
    ChartFigure chart{section_name + ": N-M capacity of the fibre section",
                      with_unit("bending moment M", unit_of(result::name::moment_i, units)),
                      with_unit("axial force N", unit_of(result::name::axial_force, units)), {}, true};
    // Both signs of the capacity and of first yield; one legend entry each.
    chart.series = {{"fully plastic Mp(N)", {}, {}, colour::curve_progress, 3.0f},
                    {"", {}, {}, colour::curve_progress, 3.0f},
                    {"first yield", {}, {}, colour::hinge_yielding_high, 2.0f},
                    {"", {}, {}, colour::hinge_yielding_high, 2.0f}};
    for (const CapacityRow& r : rows) {
        chart.series[0].x.push_back(r.moment_positive);
        chart.series[1].x.push_back(r.moment_negative);
        chart.series[0].y.push_back(r.axial_force);
        chart.series[1].y.push_back(r.axial_force);
        if (std::isnan(r.first_yield_moment)) continue; // no elastic range at this N
        chart.series[2].x.push_back(r.first_yield_moment);
        chart.series[3].x.push_back(r.first_yield_moment_negative);
        chart.series[2].y.push_back(r.axial_force);
        chart.series[3].y.push_back(r.axial_force);
    }
    if (strain_limits) {
        ChartSeries positive{"strain limits (EN 1992-1-1): the hinges' capacity", {}, {}, colour::hinge_plastic, 2.5f};
        ChartSeries negative{"", {}, {}, colour::hinge_plastic, 2.5f};
        for (const CapacityRow& r : rows) {
            if (r.hinge_moment_positive == 0.0 && r.hinge_moment_negative == 0.0) continue;
            positive.x.push_back(r.hinge_moment_positive);
            negative.x.push_back(r.hinge_moment_negative);
            positive.y.push_back(r.axial_force);
            negative.y.push_back(r.axial_force);
        }
        chart.series.push_back(positive);
        chart.series.push_back(negative);
    }
    if (path) chart.series.push_back({"path of " + path->where, path->moment, path->axial_force, colour::current_point, 2.0f});
    return chart;
}

ChartFigure moment_curvature_chart(const std::string& section_name, const std::vector<MomentCurvatureCurve>& curves,
                                   const SectionUnits& units) {
    ChartFigure chart{section_name + ": moment-curvature at constant axial force",
                      with_unit("curvature κ", unit_of(result::name::section_curvature, units)),
                      with_unit("bending moment M", unit_of(result::name::moment_i, units)), {}, true};
    const Rgb shades[] = {{31, 90, 180}, {40, 150, 70}, {230, 120, 20}, {150, 30, 170}, {90, 90, 90}};
    int shade = 0;
    // A section with concrete: where it cracks, where its steel yields and where it crushes.
    ChartSeries cracking{"cracking", {}, {}, {120, 120, 120}, 9.0f, true};
    ChartSeries yielding{"steel yields", {}, {}, colour::hinge_yielding_high, 9.0f, true};
    ChartSeries crushing{"concrete at eps_cu2", {}, {}, {20, 20, 20}, 9.0f, true};
    for (const MomentCurvatureCurve& c : curves) {
        const std::string ratio = (c.of_compression && c.axial_ratio > 0.0 ? "-" : "") + number(c.axial_ratio);
        ChartSeries line{(c.of_compression ? "N/Nc = " : "N/Ny = ") + ratio, {}, {}, shades[shade++ % 5], 2.5f};
        for (std::size_t k = 0; k < c.points.size(); ++k) {
            const MomentCurvaturePoint& p = c.points[k];
            line.x.push_back(p.curvature);
            line.y.push_back(p.moment);
            if (!c.of_compression) continue;
            const MomentCurvaturePoint* before = k > 0 ? &c.points[k - 1] : nullptr;
            const auto first = [&](bool now, bool then, ChartSeries& marks) {
                if (now && !then) marks.x.push_back(p.curvature), marks.y.push_back(p.moment);
            };
            first(p.cracked, before && before->cracked, cracking);
            first(p.yielded, before && before->yielded, yielding);
            first(p.crushed, before && before->crushed, crushing);
        }
        chart.series.push_back(line);
    }
    for (ChartSeries* marks : {&cracking, &yielding, &crushing})
        if (!marks->x.empty()) chart.series.push_back(*marks);
    return chart;
}

} // namespace plastica::render
