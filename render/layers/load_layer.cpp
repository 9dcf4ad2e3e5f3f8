#include "arrow_scale.hpp"
#include "flat_marks.hpp"
#include "line_load_shares.hpp"
#include "result_schema.hpp"
#include "layers/layers.hpp"

#include <vtkActor.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>

namespace plastica::render {

namespace {

// Arrows at nodes from a point array of forces and one of moments: the applied loads, or the
// reactions of the supports (forces on the structure, drawn the same way).
struct ArrowKind {
    const char* force_array;
    const char* moment_array;
    Rgb colour;
    const char* force_label;
    const char* moment_label;
    bool takes_off_line_loads; // the applied loads: line loads are drawn along their members
};

class LoadLayer final : public Layer {
public:
    LoadLayer(const SeriesSummary& summary, const SeriesSummary::NodalArrows& stats, double reference, ArrowKind kind)
        : summary_(summary), stats_(stats), kind_(kind) {
        scale_.reference = reference;
    }

    void reserve(double box[4], double size) override {
        // The longest arrow is 12 % of the structure's size; its tail lies beyond the node on
        // the side the force comes from.
        length_ = 0.12 * size;
        scale_.full_length = length_;
        widen_for_arrows(box, stats_.sides, length_);
    }

    void attach(const ViewGeometry& view, const AddProp& add) override {
        view_ = view;
        add(arrows_.prop(), true);
        labels_.attach(view, add, kind_.colour);
    }

    void show(vtkUnstructuredGrid* step) override {
        arrows_.clear();
        labels_.clear();
        vtkDataArray* load = step->GetPointData()->GetArray(kind_.force_array);
        vtkDataArray* moment = step->GetPointData()->GetArray(kind_.moment_array);
        vtkDataArray* initial = step->GetPointData()->GetArray(result::name::initial_position);
        if (!load || !moment || !initial) return;
        // Line loads are drawn along their members (line_load_layer.cpp), not at the nodes.
        const std::vector<double> shares = kind_.takes_off_line_loads ? line_load_shares(step) : std::vector<double>();
        for (vtkIdType i = 0; i < step->GetNumberOfPoints(); ++i) {
            double p[3];
            step->GetPoint(i, p);
            // A half model carries half of a load on its mirror line: the arrow shows the whole.
            const double whole = on_mirror_line(summary_, initial->GetTuple3(i)) ? 2.0 : 1.0;
            const double share_x = shares.empty() ? 0.0 : shares[2 * static_cast<std::size_t>(i)];
            const double share_y = shares.empty() ? 0.0 : shares[2 * static_cast<std::size_t>(i) + 1];
            const double fx = whole * (load->GetComponent(i, 0) - share_x), fy = whole * (load->GetComponent(i, 1) - share_y),
                         m = whole * moment->GetComponent(i, 0);
            const double f = std::hypot(fx, fy);
            if (stats_.max_force > 0 && f > 1e-9 * stats_.max_force) {
                if (stats_.by_components) {
                    if (std::abs(fx) > 1e-9 * stats_.max_force) force_arrow(p, fx, 0.0);
                    if (std::abs(fy) > 1e-9 * stats_.max_force) force_arrow(p, 0.0, fy);
                } else {
                    force_arrow(p, fx, fy);
                }
            }
            if (stats_.max_moment > 0 && std::abs(m) > 1e-9 * stats_.max_moment) moment_arrow(p, m > 0);
        }
    }

    std::vector<LegendEntry> legend() const override {
        return {{LegendEntry::Mark::arrow, kind_.colour, 0.0, stats_.max_force > 0 ? kind_.force_label : kind_.moment_label}};
    }

    std::string note() const override {
        std::string text;
        if (stats_.max_force > 0) text = "longest " + force_text(scale_.reference, summary_.force_unit);
        if (stats_.max_moment > 0)
            text += (text.empty() ? "" : "\n") + std::string("moment ") +
                    force_text(stats_.max_moment, array_unit(summary_, result::name::moment_i));
        // Arrows off the scale (ArrowScale) are cut at the longest and carry their value.
        if (stats_.max_force > 0 && scale_.reference < stats_.max_force) text += "\nlonger ones cut, valued";
        return text;
    }

private:
    // The tip touches the ribbon's edge; an arrow off the scale says its value.
    void force_arrow(const double p[3], double fx, double fy) {
        const double f = std::hypot(fx, fy);
        const double length = std::max(scale_.length(f), view_.pixels(8));
        const double tip[2] = {p[0] - 0.5 * view_.ribbon_width * fx / f, p[1] - 0.5 * view_.ribbon_width * fy / f};
        const double tail[2] = {tip[0] - length * fx / f, tip[1] - length * fy / f};
        arrows_.arrow(tail, tip, view_.pixels(3), kind_.colour);
        if (!scale_.to_scale(f)) labels_.add(tail, fx, fy, force_text(f, summary_.force_unit));
    }

    // A three-quarter circle round the node, its head showing the sense of the moment.
    void moment_arrow(const double p[3], bool counter_clockwise) {
        const double r = view_.pixels(16), sense = counter_clockwise ? 1.0 : -1.0;
        constexpr int pieces = 14;
        const double start = -0.75 * M_PI, sweep = 1.5 * M_PI;
        double previous[2] = {p[0] + r * std::cos(start), p[1] + r * std::sin(start)};
        double end = start;
        for (int k = 1; k <= pieces; ++k) {
            end = start + sense * sweep * k / pieces;
            const double next[2] = {p[0] + r * std::cos(end), p[1] + r * std::sin(end)};
            arrows_.bar(previous, next, view_.pixels(3), kind_.colour);
            previous[0] = next[0], previous[1] = next[1];
        }
        // The head along the circle's tangent at its end.
        const double tangent[2] = {-sense * std::sin(end), sense * std::cos(end)};
        const double tail[2] = {previous[0] - view_.pixels(10) * tangent[0], previous[1] - view_.pixels(10) * tangent[1]};
        const double tip[2] = {previous[0] + view_.pixels(3) * tangent[0], previous[1] + view_.pixels(3) * tangent[1]};
        arrows_.arrow(tail, tip, view_.pixels(3), kind_.colour);
    }

    const SeriesSummary& summary_;
    const SeriesSummary::NodalArrows& stats_;
    ArrowKind kind_;
    double length_ = 0.0;
    ArrowScale scale_;
    ViewGeometry view_;
    FlatMarks arrows_{6.5}; // above the hinge markers: a load at a hinged joint stays visible
    ArrowLabels labels_;
};

} // namespace

std::unique_ptr<Layer> load_layer(const SeriesSummary& summary) {
    return std::make_unique<LoadLayer>(summary, summary.loads, summary.load_arrow_reference, ArrowKind{result::name::applied_load, result::name::applied_moment, colour::load, "applied load", "applied moment", true});
}

std::unique_ptr<Layer> reaction_layer(const SeriesSummary& summary) {
    return std::make_unique<LoadLayer>(summary, summary.reactions, summary.reactions.max_force, ArrowKind{result::name::reaction, result::name::reaction_moment, colour::reaction, "support reaction", "support moment", false});
}

// Drawn where the series has loads.
LayerKind load_kind() {
    return {"loads", [](const SeriesSummary& s, vtkUnstructuredGrid*, vtkPolyData*) -> std::unique_ptr<Layer> {
                return s.loads.max_force > 0 || s.loads.max_moment > 0 ? load_layer(s) : nullptr;
            }};
}

// Drawn when --show reactions asks and the series has reactions.
LayerKind reaction_kind() {
    return {"reactions",
            [](const SeriesSummary& s, vtkUnstructuredGrid*, vtkPolyData*) -> std::unique_ptr<Layer> {
                return s.reactions.max_force > 0 || s.reactions.max_moment > 0 ? reaction_layer(s) : nullptr;
            },
            true};
}

} // namespace plastica::render
