#include "section_path.hpp"
#include "result_schema.hpp"
#include "render_error.hpp"

#include <string>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

namespace plastica::render {

namespace {

// ", member 'left column'" for an element of a named member, else "".
std::string member_of(vtkUnstructuredGrid* step, vtkIdType element) {
    vtkDataArray* member = step->GetCellData()->GetArray(result::name::member);
    auto* names = vtkStringArray::SafeDownCast(step->GetFieldData()->GetAbstractArray(result::name::member_names));
    if (!member || !names || element >= member->GetNumberOfTuples()) return "";
    const auto index = static_cast<vtkIdType>(member->GetComponent(element, 0));
    if (index < 0 || index >= names->GetNumberOfValues()) return "";
    return ", member '" + names->GetValue(index) + "'";
}

} // namespace

SectionPath most_loaded_end(const ResultSeries& series) {
    auto last = read_step(series.steps.back().file);
    vtkDataArray* use[2] = {last->GetCellData()->GetArray(result::name::utilisation_i), last->GetCellData()->GetArray(result::name::utilisation_j)};
    if (!use[0] || !use[1]) throw RenderError(series.steps.back().file + ": no plastic hinges (an elastic scene)");
    vtkIdType element = 0;
    int end = 0;
    double most = -1.0;
    for (vtkIdType e = 0; e < last->GetNumberOfCells(); ++e)
        for (int k = 0; k < 2; ++k)
            if (use[k]->GetComponent(e, 0) > most) most = use[k]->GetComponent(e, 0), element = e, end = k;
    SectionPath path;
    // Counted from 0, as ParaView's cell ids and Python's arrays count.
    path.where = "element " + std::to_string(element) + " (from 0), end " + (end == 0 ? "i" : "j") + member_of(last, element);
    const char* moment = end == 0 ? result::name::moment_i : result::name::moment_j;
    for (const SeriesStep& step : series.steps) {
        auto grid = read_step(step.file);
        vtkDataArray* n = grid->GetCellData()->GetArray(result::name::axial_force);
        vtkDataArray* m = grid->GetCellData()->GetArray(moment);
        if (!n || !m || element >= n->GetNumberOfTuples())
            throw RenderError(step.file + ": no 'axial_force' or '" + moment + "' for element " + std::to_string(element) + " (from 0)");
        path.axial_force.push_back(n->GetComponent(element, 0));
        path.moment.push_back(m->GetComponent(element, 0));
    }
    return path;
}

} // namespace plastica::render
