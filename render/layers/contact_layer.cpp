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
#include <vector>

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
        struct Arrow {
            double magnitude, fx, fy, at[2];
        };
        std::vector<Arrow> pressed;
        for (vtkIdType i = 0; i < step->GetNumberOfPoints(); ++i) {
            if (state && state->GetComponent(i, 0) <= 0) continue;
            const double fx = force->GetComponent(i, 0), fy = force->GetComponent(i, 1);
            const double magnitude = std::hypot(fx, fy);
            if (magnitude <= 0) continue;
            double p[3];
            step->GetPoint(i, p);
            pressed.push_back({magnitude, fx, fy, {p[0], p[1]}});
        }
        // Thinned where many nodes press: the largest forces first, each arrow at least 10 px
        // from those drawn, so that a flattened wall's row of arrows stays a row, not a block.
        std::sort(pressed.begin(), pressed.end(), [](const Arrow& a, const Arrow& b) { return a.magnitude > b.magnitude; });
        std::vector<const Arrow*> drawn;
        const double spacing = view_.pixels(10.0);
        for (const Arrow& a : pressed) {
            const bool crowded = std::any_of(drawn.begin(), drawn.end(), [&](const Arrow* d) {
                return std::hypot(d->at[0] - a.at[0], d->at[1] - a.at[1]) < spacing;
            });
            if (crowded) continue;
            drawn.push_back(&a);
            // A force beyond the reference (a base's penalty holding the load after landing) ends
            // at full length and says its value.
            const double length = scale_ * std::min(a.magnitude, reference_);
            const double ux = a.fx / a.magnitude, uy = a.fy / a.magnitude;
            const double tip[2] = {a.at[0] - 0.5 * view_.ribbon_width * ux, a.at[1] - 0.5 * view_.ribbon_width * uy};
            const double tail[2] = {tip[0] - length * ux, tip[1] - length * uy};
            arrows_.arrow(tail, tip, view_.pixels(3.5), colour::contact_force);
            if (a.magnitude > reference_ && a.magnitude > valued.force) valued = {a.magnitude, a.fx, a.fy, {tail[0], tail[1]}};
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
