#include "arrow_scale.hpp"
#include "flat_marks.hpp"
#include "result_schema.hpp"
#include "layers/layers.hpp"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>

namespace plastica::render {

namespace {

// Two walls pressed together each take a push away from the other. Drawn from each node along
// its push, the arrows of the two walls point apart and do not cover the contact itself.
class SurfaceContactLayer final : public Layer {
public:
    explicit SurfaceContactLayer(const SeriesSummary& summary)
        : largest_(summary.max_surface_contact_force), unit_(summary.force_unit) {}

    void reserve(double box[4], double size) override {
        // The longest arrow is a tenth of the structure's size; walls on the outline need room.
        scale_ = 0.1 * size / largest_;
        for (int k = 0; k < 4; ++k) box[k] += (k % 2 ? 0.1 : -0.1) * size;
    }

    void attach(const ViewGeometry& view, const AddProp& add) override {
        view_ = view;
        add(arrows_.prop(), true);
    }

    void show(vtkUnstructuredGrid* step) override {
        arrows_.clear();
        vtkDataArray* force = step->GetPointData()->GetArray(result::name::surface_contact_force);
        if (!force) return;
        for (vtkIdType i = 0; i < step->GetNumberOfPoints(); ++i) {
            const double fx = force->GetComponent(i, 0), fy = force->GetComponent(i, 1);
            const double magnitude = std::hypot(fx, fy);
            // Pushes below a thousandth of the largest are the penalty's round-off, not contact.
            if (magnitude <= 1e-3 * largest_) continue;
            double p[3];
            step->GetPoint(i, p);
            const double length = scale_ * magnitude;
            const double tail[2] = {p[0] + 0.5 * view_.ribbon_width * fx / magnitude, p[1] + 0.5 * view_.ribbon_width * fy / magnitude};
            const double tip[2] = {tail[0] + length * fx / magnitude, tail[1] + length * fy / magnitude};
            arrows_.arrow(tail, tip, view_.pixels(3.0), colour::surface_contact_force);
        }
    }

    std::vector<LegendEntry> legend() const override {
        return {{LegendEntry::Mark::arrow, colour::surface_contact_force, 0.0, "surface contact (push on each wall)"}};
    }

    std::string note() const override { return longest_arrow_note(largest_, unit_); }

private:
    double largest_;
    std::string unit_;
    double scale_ = 0.0;
    ViewGeometry view_;
    FlatMarks arrows_{3.0};
};

} // namespace

std::unique_ptr<Layer> surface_contact_layer(const SeriesSummary& summary) {
    return std::make_unique<SurfaceContactLayer>(summary);
}

// Drawn where surfaces press on each other.
LayerKind surface_contact_kind() {
    return {"surface_contact", [](const SeriesSummary& s, vtkUnstructuredGrid*, vtkPolyData*) -> std::unique_ptr<Layer> {
                return s.max_surface_contact_force > 0 ? surface_contact_layer(s) : nullptr;
            }};
}

} // namespace plastica::render
