#include "line_load_shares.hpp"

#include "result_schema.hpp"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>

namespace plastica::render {

std::vector<double> line_load_shares(vtkUnstructuredGrid* step) {
    vtkDataArray* line = step->GetCellData()->GetArray(result::name::line_load);
    vtkDataArray* initial = step->GetPointData()->GetArray(result::name::initial_position);
    if (!line || !initial) return {};
    std::vector<double> shares(2 * static_cast<std::size_t>(step->GetNumberOfPoints()), 0.0);
    vtkNew<vtkIdList> ends;
    for (vtkIdType c = 0; c < step->GetNumberOfCells(); ++c) {
        const double wx = line->GetComponent(c, 0), wy = line->GetComponent(c, 1);
        if (wx == 0.0 && wy == 0.0) continue;
        step->GetCellPoints(c, ends);
        if (ends->GetNumberOfIds() != 2) continue;
        double a[3], b[3];
        initial->GetTuple(ends->GetId(0), a);
        initial->GetTuple(ends->GetId(1), b);
        const double half = 0.5 * std::hypot(b[0] - a[0], b[1] - a[1]);
        for (int k = 0; k < 2; ++k) {
            shares[2 * static_cast<std::size_t>(ends->GetId(k))] += half * wx;
            shares[2 * static_cast<std::size_t>(ends->GetId(k)) + 1] += half * wy;
        }
    }
    return shares;
}

} // namespace plastica::render
