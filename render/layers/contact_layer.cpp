#include "arrow_scale.hpp"
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

class ContactLayer final : public Layer {
public:
    explicit ContactLayer(const SeriesSummary& summary) : largest_(summary.max_contact_force), unit_(summary.force_unit) {}

    void reserve(double box[4], double size) override {
        // Room under the base for the arrows: the largest is 14 % of the structure's size.
        if (largest_ <= 0) return;
        scale_ = 0.14 * size / largest_;
        box[2] -= 0.14 * size;
    }

    void attach(const ViewGeometry& view, const AddProp& add) override {
        view_ = view;
        add(arrows_.prop(), true);
    }

    void show(vtkUnstructuredGrid* step) override {
        arrows_.clear();
        vtkDataArray* force = step->GetPointData()->GetArray(result::name::contact_force);
        vtkDataArray* state = step->GetPointData()->GetArray(result::name::contact);
        if (!force) return;
        for (vtkIdType i = 0; i < step->GetNumberOfPoints(); ++i) {
            if (state && state->GetComponent(i, 0) <= 0) continue;
            const double fx = force->GetComponent(i, 0), fy = force->GetComponent(i, 1);
            const double magnitude = std::hypot(fx, fy);
            if (magnitude <= 0) continue;
            double p[3];
            step->GetPoint(i, p);
            const double length = scale_ * magnitude;
            const double tip[2] = {p[0] - 0.5 * view_.ribbon_width * fx / magnitude, p[1] - 0.5 * view_.ribbon_width * fy / magnitude};
            const double tail[2] = {tip[0] - length * fx / magnitude, tip[1] - length * fy / magnitude};
            arrows_.arrow(tail, tip, view_.pixels(3.5), colour::contact_force);
        }
    }

    std::vector<LegendEntry> legend() const override {
        return {{LegendEntry::Mark::arrow, colour::contact_force, 0.0, "contact force"}};
    }

    std::string note() const override { return longest_arrow_note(largest_, unit_); }

private:
    double largest_;
    std::string unit_;
    double scale_ = 0.0; // world length per unit force
    ViewGeometry view_;
    FlatMarks arrows_{3.0};
};

} // namespace

std::unique_ptr<Layer> contact_layer(const SeriesSummary& summary) { return std::make_unique<ContactLayer>(summary); }

} // namespace plastica::render
