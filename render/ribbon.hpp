// Members drawn as flat ribbons of a fixed world width in the drawing plane, unlit.
#pragma once

#include <vtkSmartPointer.h>

class vtkActor;
class vtkRibbonFilter;

namespace plastica::render {

void set_ribbon(vtkRibbonFilter* ribbon, double width);
vtkSmartPointer<vtkActor> ribbon_actor(vtkRibbonFilter* ribbon, double z);

} // namespace plastica::render
