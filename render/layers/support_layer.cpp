#include "flat_marks.hpp"
#include "result_schema.hpp"
#include "layers/layers.hpp"

#include <vtkActor.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>

namespace plastica::render {

namespace {

using result::fixes_ux, result::fixes_uy, result::fixes_rz;

struct SupportedNode {
    vtkIdType point;
    int fixed;
    double into[2]; // unit direction from the node into its members (initial shape)
};

class SupportLayer final : public Layer {
public:
    SupportLayer(const SeriesSummary& summary, vtkUnstructuredGrid* first_step) : summary_(summary) {
        vtkDataArray* fixed = first_step->GetPointData()->GetArray(result::name::support);
        vtkDataArray* initial = first_step->GetPointData()->GetArray(result::name::initial_position);
        if (!fixed || !initial) return;
        for (vtkIdType i = 0; i < fixed->GetNumberOfTuples(); ++i) {
            const int bits = static_cast<int>(fixed->GetComponent(i, 0));
            if (bits == 0) continue;
            const double* p = initial->GetTuple3(i);
            // On the mirror line of a half model a support states symmetry, not a real support.
            if (on_mirror_line(summary, p)) continue;
            supported_.push_back({i, bits, {0.0, 0.0}});
        }
        // The direction into the members: the sum of unit vectors to the neighbours.
        for (vtkIdType c = 0; c < first_step->GetNumberOfCells(); ++c) {
            vtkIdType n;
            const vtkIdType* ids;
            first_step->GetCellPoints(c, n, ids);
            if (n != 2) continue;
            for (SupportedNode& s : supported_)
                for (int end = 0; end < 2; ++end)
                    if (ids[end] == s.point) {
                        const double* a = initial->GetTuple3(ids[end]);
                        const double ax = a[0], ay = a[1];
                        const double* b = initial->GetTuple3(ids[1 - end]);
                        const double length = std::hypot(b[0] - ax, b[1] - ay);
                        if (length > 0) s.into[0] += (b[0] - ax) / length, s.into[1] += (b[1] - ay) / length;
                    }
        }
        for (SupportedNode& s : supported_) {
            const double length = std::hypot(s.into[0], s.into[1]);
            if (length > 1e-12) s.into[0] /= length, s.into[1] /= length;
            else s.into[0] = 0.0, s.into[1] = 1.0;
        }
    }

    bool any() const { return !supported_.empty(); }

    void reserve(double box[4], double size) override {
        // Symbols stand under (or beside) their nodes, about 30 pixels: 6 % of the size.
        if (!supported_.empty()) box[2] -= 0.06 * size;
    }

    void attach(const ViewGeometry& view, const AddProp& add) override {
        view_ = view;
        add(marks_.prop(), true);
    }

    void show(vtkUnstructuredGrid* step) override {
        marks_.clear();
        for (const SupportedNode& s : supported_) {
            double p[3];
            step->GetPoint(s.point, p);
            draw(s, p);
        }
    }

    // One entry per kind of support the scene has, in a fixed order.
    std::vector<LegendEntry> legend() const override {
        bool clamp = false, pin = false, roller = false, guide = false, rotation = false;
        for (const SupportedNode& s : supported_) {
            const bool ux = s.fixed & fixes_ux, uy = s.fixed & fixes_uy, rz = s.fixed & fixes_rz;
            if (ux && uy && rz) clamp = true;
            else if (!ux && !uy) rotation = true;
            else if (rz) guide = true;
            else if (ux && uy) pin = true;
            else roller = true;
        }
        std::vector<LegendEntry> entries;
        using Mark = LegendEntry::Mark;
        if (clamp) entries.push_back({Mark::clamp, colour::support, 0.0, "clamped support"});
        if (pin) entries.push_back({Mark::triangle, colour::support, 0.0, "pinned support"});
        if (roller) entries.push_back({Mark::roller, colour::support, 0.0, "roller"});
        if (guide) entries.push_back({Mark::square, colour::support, 0.0, "guided support (slides, cannot turn)"});
        if (rotation) entries.push_back({Mark::square, colour::support, 0.0, "rotation held"});
        return entries;
    }

private:
    // A ground line across `u` at `at`, hatched on the far side.
    void ground(const double at[2], const double u[2], double half_width) {
        const double t[2] = {-u[1], u[0]};
        const double a[2] = {at[0] - half_width * t[0], at[1] - half_width * t[1]};
        const double b[2] = {at[0] + half_width * t[0], at[1] + half_width * t[1]};
        marks_.bar(a, b, view_.pixels(2.5), colour::support);
        const double tick = view_.pixels(7);
        for (int k = 0; k < 4; ++k) {
            const double s = -half_width + (k + 0.75) * 2.0 * half_width / 4.0;
            const double q[2] = {at[0] + s * t[0], at[1] + s * t[1]};
            const double r[2] = {q[0] - tick * (u[0] + t[0]) * M_SQRT1_2, q[1] - tick * (u[1] + t[1]) * M_SQRT1_2};
            marks_.bar(q, r, view_.pixels(1.5), colour::hatching);
        }
    }

    void draw(const SupportedNode& s, const double p[3]) {
        const double px = view_.pixels(1);
        const bool ux = s.fixed & fixes_ux, uy = s.fixed & fixes_uy, rz = s.fixed & fixes_rz;
        if (ux && uy && rz) { // clamp: a wall across the member, hatched behind it
            const double back[2] = {-s.into[0], -s.into[1]};
            const double at[2] = {p[0] + 0.5 * view_.ribbon_width * back[0], p[1] + 0.5 * view_.ribbon_width * back[1]};
            const double u[2] = {s.into[0], s.into[1]};
            const double t[2] = {-u[1], u[0]};
            const double a[2] = {at[0] - 14 * px * t[0], at[1] - 14 * px * t[1]}, b[2] = {at[0] + 14 * px * t[0], at[1] + 14 * px * t[1]};
            marks_.bar(a, b, 4 * px, colour::support);
            ground(at, u, 14 * px);
            return;
        }
        if (!ux && !uy) { // rotation only: a square on the node
            const double h = 5 * px;
            const double xy[8] = {p[0] - h, p[1] - h, p[0] + h, p[1] - h, p[0] + h, p[1] + h, p[0] - h, p[1] + h};
            marks_.polygon(xy, 4, colour::support);
            return;
        }
        // Pin, roller or guide: the ground under the node (beside it when only ux is held,
        // on the side away from the structure).
        double u[2] = {0.0, 1.0};
        if (!uy) {
            // A node on the centre line (a symmetric structure's top) has no side away from
            // the structure: the left, whichever side round-off puts it on.
            const double cx = 0.5 * (summary_.bounds[0] + summary_.bounds[1]);
            const double on_centre = 1e-6 * (summary_.bounds[1] - summary_.bounds[0]);
            u[0] = p[0] < cx + on_centre ? 1.0 : -1.0, u[1] = 0.0;
        }
        const double t[2] = {-u[1], u[0]};
        const double h = 15 * px, w = 9 * px;
        const double base[2] = {p[0] - h * u[0], p[1] - h * u[1]};
        if (rz) { // a guide: a block that slides but does not turn
            const double xy[8] = {base[0] - w * t[0], base[1] - w * t[1], base[0] + w * t[0], base[1] + w * t[1],
                                  p[0] + w * t[0], p[1] + w * t[1], p[0] - w * t[0], p[1] - w * t[1]};
            marks_.polygon(xy, 4, colour::support);
        } else {
            const double xy[6] = {p[0], p[1], base[0] - w * t[0], base[1] - w * t[1], base[0] + w * t[0], base[1] + w * t[1]};
            marks_.polygon(xy, 3, colour::support);
        }
        const bool rolls = !(ux && uy);
        double at[2] = {base[0], base[1]};
        if (rolls) {
            const double r = 2.8 * px;
            for (double side : {-0.5, 0.5})
                marks_.disc(base[0] - r * u[0] + side * w * t[0], base[1] - r * u[1] + side * w * t[1], r, colour::support);
            at[0] -= 2 * r * u[0] + px * u[0], at[1] -= 2 * r * u[1] + px * u[1];
        }
        ground(at, u, 13 * px);
    }

    const SeriesSummary& summary_;
    std::vector<SupportedNode> supported_;
    ViewGeometry view_;
    FlatMarks marks_{1.0};
};

} // namespace

std::unique_ptr<Layer> support_layer(const SeriesSummary& summary, vtkUnstructuredGrid* first_step) {
    auto layer = std::make_unique<SupportLayer>(summary, first_step);
    if (!layer->any()) return nullptr;
    return layer;
}

// Drawn always (nothing where nothing is supported).
LayerKind support_kind() {
    return {"supports", [](const SeriesSummary& s, vtkUnstructuredGrid* first, vtkPolyData*) { return support_layer(s, first); }};
}

} // namespace plastica::render
