#include "flat_marks.hpp"
#include "result_schema.hpp"
#include "layers/layers.hpp"

#include <vtkActor.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>

namespace plastica::render {

namespace {

// A released member end as a small open circle on the member, just off the node: the member is
// pinned there, the others at the node may go on rigidly.
class ReleaseLayer final : public Layer {
public:
    void attach(const ViewGeometry& view, const AddProp& add) override {
        view_ = view;
        for (FlatMarks* m : {&rim_, &hole_}) add(m->prop(), true);
    }

    void show(vtkUnstructuredGrid* step) override {
        rim_.clear();
        hole_.clear();
        vtkDataArray* released = step->GetCellData()->GetArray(result::name::released);
        if (!released) return;
        const double r = view_.pixels(6.0);
        for (vtkIdType c = 0; c < step->GetNumberOfCells(); ++c) {
            const int ends = static_cast<int>(released->GetComponent(c, 0));
            if (ends == 0) continue;
            double a[3], b[3];
            if (!member_ends(step, c, a, b)) continue;
            const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
            if (!(length > 0.0)) continue;
            // The circle's centre a radius and a half in from the node, at most half the element.
            const double t = std::min(0.5, 1.5 * r / length);
            for (int end = 0; end < 2; ++end) {
                if (!(ends & (1 << end))) continue;
                double x, y;
                along_member(a, b, end, t, x, y);
                rim_.disc(x, y, r, colour::outline);
                hole_.disc(x, y, 0.6 * r, colour::background);
            }
        }
    }

    std::vector<LegendEntry> legend() const override {
        return {{LegendEntry::Mark::outlined_disc, colour::background, 3.5, "released end (pin)"}};
    }

private:
    ViewGeometry view_;
    FlatMarks rim_{5.5}, hole_{6.5};
};

} // namespace

std::unique_ptr<Layer> release_layer() { return std::make_unique<ReleaseLayer>(); }

// Drawn where member ends are released.
LayerKind release_kind() {
    return {"releases", [](const SeriesSummary&, vtkUnstructuredGrid* first, vtkPolyData*) -> std::unique_ptr<Layer> {
                return first && first->GetCellData()->GetArray(result::name::released) ? release_layer() : nullptr;
            }};
}

} // namespace plastica::render
