// The headless OpenGL path itself: OSMesa, GLEW and VTK meeting without an X server.
#include "offscreen_window.hpp"

#include <catch2/catch.hpp>

#include <vtkActor.h>
#include <vtkImageData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <cstdlib>

using namespace plastica::render;

TEST_CASE("an OSMesa window draws a red disc on white without a DISPLAY", "[render]") {
    unsetenv("DISPLAY");
    OffscreenWindow window(160, 120);
    vtkNew<vtkSphereSource> sphere;
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(1, 0, 0);
    actor->GetProperty()->LightingOff();
    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(1, 1, 1);
    renderer->AddActor(actor);
    window.add(renderer);
    auto image = window.capture();
    CAPTURE(window.gl_renderer());
    int dims[3];
    image->GetDimensions(dims);
    REQUIRE(dims[0] == 160);
    REQUIRE(dims[1] == 120);
    const auto* centre = static_cast<unsigned char*>(image->GetScalarPointer(80, 60, 0));
    const auto* corner = static_cast<unsigned char*>(image->GetScalarPointer(2, 2, 0));
    CHECK(int(centre[0]) == 255);
    CHECK(int(centre[1]) == 0);
    CHECK(int(corner[1]) == 255);
    CHECK(window.gl_renderer().find("llvmpipe") != std::string::npos);
}
