// Line loads drawn along the members they act on: a row of arrows against each loaded element
// between its nodes, their tails joined, and each member's intensity written once ("30 kN/m"). The arrows keep the
// load's direction; their length is the intensity over the largest in the run.
#include "arrow_scale.hpp"
#include "flat_marks.hpp"
#include "result_schema.hpp"
#include "layers/layers.hpp"

#include <vtkActor.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>
#include <map>

namespace plastica::render {

namespace {

class LineLoadLayer final : public Layer {
public:
    explicit LineLoadLayer(const SeriesSummary& summary)
        : summary_(summary),
          unit_(summary.force_unit.empty() || summary.length_unit.empty() ? "" : summary.force_unit + "/" + summary.length_unit) {}

    void reserve(double box[4], double size) override {
        // The longest arrow is 6 % of the structure's size, its tail beyond the member on the
        // side the load comes from.
        length_ = 0.06 * size;
        widen_for_arrows(box, summary_.line_loads.sides, length_);
    }

    void attach(const ViewGeometry& view, const AddProp& add) override {
        view_ = view;
        add(marks_.prop(), true);
        labels_.attach(view, add, colour::load);
    }

    void show(vtkUnstructuredGrid* step) override {
        marks_.clear();
        labels_.clear();
        vtkDataArray* line = step->GetCellData()->GetArray(result::name::line_load);
        vtkDataArray* member = step->GetCellData()->GetArray(result::name::member);
        const double largest = summary_.line_loads.max_intensity;
        if (!line || largest <= 0.0) return;
        // Per member: the loaded element nearest its middle carries the label.
        std::map<long, vtkIdType> labelled;
        std::map<long, std::vector<vtkIdType>> loaded;
        for (vtkIdType c = 0; c < step->GetNumberOfCells(); ++c) {
            const double wx = line->GetComponent(c, 0), wy = line->GetComponent(c, 1);
            const double w = std::hypot(wx, wy);
            if (w <= 1e-9 * largest) continue;
            double a[3], b[3];
            if (!member_ends(step, c, a, b)) continue;
            const double length = std::max(length_ * w / largest, view_.pixels(10));
            const double ux = wx / w, uy = wy / w;
            // Tips on the ribbon's edge between the nodes, never at them: a point load at a node
            // keeps its own arrow there. The tails' bar runs the element's whole length.
            const double span = std::hypot(b[0] - a[0], b[1] - a[1]);
            const int pieces = std::max(1, static_cast<int>(span / view_.pixels(28)));
            const auto tail_at = [&](double t, double tail[2]) {
                tail[0] = a[0] + t * (b[0] - a[0]) - (0.5 * view_.ribbon_width + length) * ux;
                tail[1] = a[1] + t * (b[1] - a[1]) - (0.5 * view_.ribbon_width + length) * uy;
            };
            for (int k = 0; k < pieces; ++k) {
                double tail[2];
                tail_at((k + 0.5) / pieces, tail);
                const double tip[2] = {tail[0] + length * ux, tail[1] + length * uy};
                marks_.arrow(tail, tip, view_.pixels(2), colour::load);
            }
            double start[2], end[2];
            tail_at(0.0, start);
            tail_at(1.0, end);
            marks_.bar(start, end, view_.pixels(2), colour::load);
            loaded[member ? static_cast<long>(member->GetComponent(c, 0)) : static_cast<long>(c)].push_back(c);
        }
        for (const auto& [m, cells] : loaded) labelled[m] = cells[cells.size() / 2];
        for (const auto& [m, c] : labelled) {
            double a[3], b[3];
            member_ends(step, c, a, b);
            const double wx = line->GetComponent(c, 0), wy = line->GetComponent(c, 1), w = std::hypot(wx, wy);
            const double length = std::max(length_ * w / largest, view_.pixels(10));
            const double tail[2] = {0.5 * (a[0] + b[0]) - (0.5 * view_.ribbon_width + length) * wx / w,
                                    0.5 * (a[1] + b[1]) - (0.5 * view_.ribbon_width + length) * wy / w};
            labels_.add(tail, wx, wy, force_text(w, unit_), true);
        }
    }

    std::vector<LegendEntry> legend() const override { return {{LegendEntry::Mark::arrow, colour::load, 0.0, "line load"}}; }

private:
    const SeriesSummary& summary_;
    std::string unit_;
    double length_ = 0.0;
    ViewGeometry view_;
    FlatMarks marks_{6.4};
    ArrowLabels labels_;
};

} // namespace

// Drawn where the series has line loads; `--hide loads` leaves them out with the point loads.
LayerKind line_load_kind() {
    return {"loads", [](const SeriesSummary& s, vtkUnstructuredGrid*, vtkPolyData*) -> std::unique_ptr<Layer> {
                return s.line_loads.max_intensity > 0 ? std::make_unique<LineLoadLayer>(s) : nullptr;
            }};
}

} // namespace plastica::render
