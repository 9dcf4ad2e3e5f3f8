#include "flat_marks.hpp"
#include "result_schema.hpp"
#include "layers/layers.hpp"

#include <vtkActor.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>

namespace plastica::render {

namespace {

class HingeLayer final : public Layer {
public:
    explicit HingeLayer(const SeriesSummary& summary) : summary_(summary) {}

    void attach(const ViewGeometry& view, const AddProp& add) override {
        view_ = view;
        for (FlatMarks* m : {&under_, &markers_, &failed_}) add(m->prop(), true);
    }

    void show(vtkUnstructuredGrid* step) override {
        markers_.clear();
        under_.clear();
        failed_.clear();
        vtkCellData* cd = step->GetCellData();
        vtkDataArray* states[2] = {cd->GetArray(result::name::hinge_state_i), cd->GetArray(result::name::hinge_state_j)};
        vtkDataArray* use[2] = {cd->GetArray(result::name::utilisation_i), cd->GetArray(result::name::utilisation_j)};
        if (!states[0] || !states[1] || !use[0] || !use[1]) return;
        const double r = view_.pixels(4.5);
        for (vtkIdType c = 0; c < step->GetNumberOfCells(); ++c) {
            double a[3], b[3];
            if (!member_ends(step, c, a, b)) continue;
            for (int end = 0; end < 2; ++end) {
                const auto state = static_cast<result::HingeCode>(states[end]->GetComponent(c, 0));
                if (state == result::HingeCode::elastic) continue;
                const double u = std::clamp(use[end]->GetComponent(c, 0), 0.0, 1.0);
                // A quarter of the element in from its end, so the two ends meeting at a node stay apart.
                double x, y;
                along_member(a, b, end, 0.25, x, y);
                if (state == result::HingeCode::yielding) {
                    markers_.disc(x, y, r * (0.5 + 0.6 * u), mix(colour::hinge_yielding_low, colour::hinge_yielding_high, u));
                } else {
                    under_.disc(x, y, 1.55 * r, colour::outline);
                    markers_.disc(x, y, 1.3 * r, colour::hinge_plastic);
                    if (state == result::HingeCode::failed) failed_.cross(x, y, 2.2 * r, view_.pixels(2), colour::hinge_failed);
                }
            }
        }
    }

    std::vector<LegendEntry> legend() const override {
        std::vector<LegendEntry> entries;
        if (summary_.any_yielding) entries.push_back({LegendEntry::Mark::disc, colour::hinge_yielding_high, 5.0, "yielding end"});
        if (summary_.any_plastic) entries.push_back({LegendEntry::Mark::outlined_disc, colour::hinge_plastic, 6.0, "fully plastic end"});
        if (summary_.any_failed) entries.push_back({LegendEntry::Mark::cross, colour::hinge_failed, 6.0, "failed fibres"});
        return entries;
    }

private:
    const SeriesSummary& summary_;
    ViewGeometry view_;
    FlatMarks under_{4.0}, markers_{5.0}, failed_{6.0};
};

} // namespace

std::unique_ptr<Layer> hinge_layer(const SeriesSummary& summary) { return std::make_unique<HingeLayer>(summary); }

bool member_ends(vtkUnstructuredGrid* step, vtkIdType c, double a[3], double b[3]) {
    vtkIdType n;
    const vtkIdType* ids;
    step->GetCellPoints(c, n, ids);
    if (n != 2) return false;
    step->GetPoint(ids[0], a);
    step->GetPoint(ids[1], b);
    return true;
}

void along_member(const double a[3], const double b[3], int end, double t, double& x, double& y) {
    const double* from = end == 0 ? a : b;
    const double* to = end == 0 ? b : a;
    x = from[0] + t * (to[0] - from[0]);
    y = from[1] + t * (to[1] - from[1]);
}

// Drawn where members are inelastic.
LayerKind hinge_kind() {
    return {"hinges", [](const SeriesSummary& s, vtkUnstructuredGrid*, vtkPolyData*) -> std::unique_ptr<Layer> {
                return s.inelastic ? hinge_layer(s) : nullptr;
            }};
}

} // namespace plastica::render
