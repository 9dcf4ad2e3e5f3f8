#include "ribbon.hpp"

#include <vtkActor.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRibbonFilter.h>

namespace plastica::render {

void set_ribbon(vtkRibbonFilter* ribbon, double width) {
    ribbon->SetWidth(width / 2); // VTK's width is the half width
    ribbon->UseDefaultNormalOn();
    ribbon->SetDefaultNormal(0, 0, 1); // the ribbon lies in the drawing plane
    ribbon->VaryWidthOff();
}

vtkSmartPointer<vtkActor> ribbon_actor(vtkRibbonFilter* ribbon, double z) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(ribbon->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->LightingOff();
    actor->SetPosition(0, 0, z);
    return actor;
}

} // namespace plastica::render
