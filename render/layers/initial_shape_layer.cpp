#include "layers/layers.hpp"
#include "result_schema.hpp"
#include "ribbon.hpp"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRibbonFilter.h>
#include <vtkUnstructuredGrid.h>

namespace plastica::render {

namespace {

class InitialShapeLayer final : public Layer {
public:
    explicit InitialShapeLayer(vtkUnstructuredGrid* first_step) {
        vtkNew<vtkPoints> points;
        vtkDataArray* positions = first_step->GetPointData()->GetArray(result::name::initial_position);
        points->SetNumberOfPoints(first_step->GetNumberOfPoints());
        for (vtkIdType i = 0; i < first_step->GetNumberOfPoints(); ++i) points->SetPoint(i, positions->GetTuple3(i));
        vtkNew<vtkCellArray> lines;
        for (vtkIdType c = 0; c < first_step->GetNumberOfCells(); ++c) {
            vtkIdType n;
            const vtkIdType* ids;
            first_step->GetCellPoints(c, n, ids);
            lines->InsertNextCell(n, ids);
        }
        shape_->SetPoints(points);
        shape_->SetLines(lines);
    }

    void attach(const ViewGeometry& view, const AddProp& add) override {
        ribbon_->SetInputData(shape_);
        set_ribbon(ribbon_, 0.6 * view.ribbon_width);
        auto actor = ribbon_actor(ribbon_, -2.0);
        actor->GetProperty()->SetColor(colour::initial_shape.red(), colour::initial_shape.green(), colour::initial_shape.blue());
        add(actor, true);
    }

    std::vector<LegendEntry> legend() const override {
        return {{LegendEntry::Mark::bar, colour::initial_shape, 0.0, "initial shape"}};
    }

private:
    vtkNew<vtkPolyData> shape_;
    vtkNew<vtkRibbonFilter> ribbon_;
};

} // namespace

std::unique_ptr<Layer> initial_shape_layer(vtkUnstructuredGrid* first_step) {
    return std::make_unique<InitialShapeLayer>(first_step);
}

// The undeformed members, faint behind the deformed ones: drawn always.
LayerKind initial_shape_kind() {
    return {"initial", [](const SeriesSummary&, vtkUnstructuredGrid* first, vtkPolyData*) { return initial_shape_layer(first); }};
}

} // namespace plastica::render
