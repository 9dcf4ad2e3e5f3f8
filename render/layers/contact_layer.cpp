#include "arrow_scale.hpp"
#include "flat_marks.hpp"
#include "result_schema.hpp"
#include "layers/layers.hpp"

#include <vtkActor.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>

namespace plastica::render {

namespace {

class ContactLayer final : public Layer {
public:
    explicit ContactLayer(const SeriesSummary& summary)
        : largest_(summary.max_contact_force), reference_(summary.contact_arrow_reference), unit_(summary.force_unit) {}

    void reserve(double box[4], double size) override {
        // Room under the base for the arrows: the longest is 14 % of the structure's size.
        if (reference_ <= 0) return;
        scale_ = 0.14 * size / reference_;
        box[2] -= 0.14 * size;
    }

    void attach(const ViewGeometry& view, const AddProp& add) override {
        view_ = view;
        add(arrows_.prop(), true);
        labels_.attach(view, add, colour::contact_force);
    }

    void show(vtkUnstructuredGrid* step) override {
        arrows_.clear();
        labels_.clear();
        vtkDataArray* force = step->GetPointData()->GetArray(result::name::contact_force);
        vtkDataArray* state = step->GetPointData()->GetArray(result::name::contact);
        if (!force) return;
        struct {
            double force = 0, fx = 0, fy = 0, tail[2] = {0, 0};
        } valued; // the largest force beyond the reference
        for (vtkIdType i = 0; i < step->GetNumberOfPoints(); ++i) {
            if (state && state->GetComponent(i, 0) <= 0) continue;
            const double fx = force->GetComponent(i, 0), fy = force->GetComponent(i, 1);
            const double magnitude = std::hypot(fx, fy);
            if (magnitude <= 0) continue;
            double p[3];
            step->GetPoint(i, p);
            // A force beyond the reference (a base's penalty holding the load after landing) ends
            // at full length and says its value.
            const double length = scale_ * std::min(magnitude, reference_);
            const double tip[2] = {p[0] - 0.5 * view_.ribbon_width * fx / magnitude, p[1] - 0.5 * view_.ribbon_width * fy / magnitude};
            const double tail[2] = {tip[0] - length * fx / magnitude, tip[1] - length * fy / magnitude};
            arrows_.arrow(tail, tip, view_.pixels(3.5), colour::contact_force);
            if (magnitude > reference_ && magnitude > valued.force) valued = {magnitude, fx, fy, {tail[0], tail[1]}};
        }
        // One value, the largest: a row of pressed nodes would write a row of numbers.
        if (valued.force > 0) labels_.add(valued.tail, valued.fx, valued.fy, force_text(valued.force, unit_));
    }

    std::vector<LegendEntry> legend() const override {
        return {{LegendEntry::Mark::arrow, colour::contact_force, 0.0, "contact force"}};
    }

    std::string note() const override {
        if (reference_ >= largest_) return longest_arrow_note(largest_, unit_);
        return "longest " + force_text(reference_, unit_) + "\nlonger ones cut, largest valued";
    }

private:
    double largest_, reference_;
    std::string unit_;
    double scale_ = 0.0; // world length per unit force
    ViewGeometry view_;
    FlatMarks arrows_{3.0};
    ArrowLabels labels_;
};

} // namespace

std::unique_ptr<Layer> contact_layer(const SeriesSummary& summary) { return std::make_unique<ContactLayer>(summary); }

// Drawn where something touches a base.
LayerKind contact_kind() {
    return {"contact", [](const SeriesSummary& s, vtkUnstructuredGrid*, vtkPolyData*) -> std::unique_ptr<Layer> {
                return s.any_contact ? contact_layer(s) : nullptr;
            }};
}

} // namespace plastica::render
