#include "flat_marks.hpp"
#include "result_schema.hpp"
#include "layers/layers.hpp"
#include "result_series.hpp"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>

namespace plastica::render {

namespace {

class BaseLayer final : public Layer {
public:
    BaseLayer(const SeriesSummary& summary, vtkPolyData* base)
        : summary_(summary), base_data_(base), has_line_(base->GetNumberOfLines() > 0),
          has_anchors_(base->GetNumberOfVerts() > 0) {}

    void reserve(double box[4], double size) override {
        if (has_line_) box[2] -= 0.05 * size; // the hatching under the line
    }

    void attach(const ViewGeometry& view, const AddProp& add) override {
        view_ = view;
        draw_lines(view, nullptr);
        vtkCellArray* verts = base_data_->GetVerts();
        verts->InitTraversal();
        vtkIdType n;
        const vtkIdType* ids;
        while (verts->GetNextCell(n, ids)) {
            double p[3];
            base_data_->GetPoint(ids[0], p);
            anchors_.disc(p[0], p[1], view.pixels(4), colour::spring_anchor);
        }
        add(line_.prop(), false); // the base line already spans both halves
        add(anchors_.prop(), true);
    }

    // A platen is drawn where the step has moved it (its travel magnified as the structure's
    // displacements are, so that what it presses stays on it).
    void show(vtkUnstructuredGrid* step) override {
        if (!base_data_->GetCellData()->GetArray(result::name::base_motion)) return;
        line_.clear();
        draw_lines(view_, step);
    }

    std::vector<LegendEntry> legend() const override {
        if (!has_anchors_) return {};
        return {{LegendEntry::Mark::disc, colour::spring_anchor, 4.0, "spring anchor"}};
    }

private:
    // Each base line as a bar with hatching on the far side from the structure, clipped to the
    // drawing so the legend column stays clear.
    // step: where platens stand (none: at the start).
    void draw_lines(const ViewGeometry& view, vtkUnstructuredGrid* step) {
        vtkDataArray* kind = base_data_->GetCellData()->GetArray(result::name::base_kind);
        vtkDataArray* motion = base_data_->GetCellData()->GetArray(result::name::base_motion);
        vtkDataArray* pattern = base_data_->GetCellData()->GetArray(result::name::base_pattern);
        vtkDataArray* factors = step ? step->GetFieldData()->GetArray(result::name::pattern_factors) : nullptr;
        vtkCellArray* lines = base_data_->GetLines();
        lines->InitTraversal();
        vtkIdType n;
        const vtkIdType* ids;
        const double cx = 0.5 * (summary_.bounds[0] + summary_.bounds[1]);
        const double cy = 0.5 * (summary_.bounds[2] + summary_.bounds[3]);
        const vtkIdType first_line = base_data_->GetNumberOfVerts();
        for (vtkIdType c = 0; lines->GetNextCell(n, ids); ++c) {
            if (n < 2 || (kind && kind->GetComponent(first_line + c, 0) != static_cast<int>(result::BaseKind::rigid_line))) continue;
            double a[3], b[3];
            base_data_->GetPoint(ids[0], a);
            base_data_->GetPoint(ids[n - 1], b);
            // The factor of the pattern that moves the line: the step's λ with one pattern.
            double load_factor = step ? field_value(step, result::name::load_factor) : 0.0;
            if (step && pattern && factors) {
                const vtkIdType p = static_cast<vtkIdType>(pattern->GetComponent(first_line + c, 0));
                load_factor = p >= 0 && p < factors->GetNumberOfTuples() ? factors->GetComponent(p, 0) : 0.0;
            }
            if (motion && step)
                for (int k = 0; k < 2; ++k) {
                    a[k] += summary_.magnify * load_factor * motion->GetComponent(first_line + c, k);
                    b[k] += summary_.magnify * load_factor * motion->GetComponent(first_line + c, k);
                }
            const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
            const double tx = (b[0] - a[0]) / length, ty = (b[1] - a[1]) / length;
            double nx = -ty, ny = tx;
            if ((cx - a[0]) * nx + (cy - a[1]) * ny < 0) nx = -nx, ny = -ny;
            double s0 = 0.0, s1 = length;
            if (std::abs(tx) > 1e-12) {
                const double sa = (view.view[0] - a[0]) / tx, sb = (view.drawing_right - a[0]) / tx;
                s0 = std::max(s0, std::min(sa, sb));
                s1 = std::min(s1, std::max(sa, sb));
            }
            if (s1 <= s0) continue;
            const double from[2] = {a[0] + s0 * tx, a[1] + s0 * ty}, to[2] = {a[0] + s1 * tx, a[1] + s1 * ty};
            line_.bar(from, to, view.pixels(3), colour::base);
            // Hatching on the far side, every 14 pixels.
            const double step = view.pixels(14), tick = view.pixels(12);
            for (double s = s0 + 0.5 * step; s <= s1; s += step) {
                const double p[2] = {a[0] + s * tx, a[1] + s * ty};
                if (p[1] < view.view[2] - tick || p[1] > view.view[3] + tick) continue;
                const double q[2] = {p[0] - tick * (nx + tx) * M_SQRT1_2, p[1] - tick * (ny + ty) * M_SQRT1_2};
                line_.bar(p, q, view.pixels(1.5), colour::hatching);
            }
        }
    }

    const SeriesSummary& summary_;
    ViewGeometry view_;
    vtkSmartPointer<vtkPolyData> base_data_;
    bool has_line_, has_anchors_;
    FlatMarks line_{-3.0}, anchors_{2.5};
};

} // namespace

std::unique_ptr<Layer> base_layer(const SeriesSummary& summary, vtkPolyData* base) {
    return std::make_unique<BaseLayer>(summary, base);
}

// Drawn where the series has a base line or spring anchors (base.vtp).
LayerKind base_kind() {
    return {"base", [](const SeriesSummary& s, vtkUnstructuredGrid*, vtkPolyData* base) -> std::unique_ptr<Layer> {
                if (!base || (base->GetNumberOfLines() == 0 && base->GetNumberOfVerts() == 0)) return nullptr;
                return base_layer(s, base);
            }};
}

} // namespace plastica::render
