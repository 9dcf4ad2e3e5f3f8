// A VTK render window on an OSMesa context: renderers are added as usual, capture() draws and
// returns the pixels. The first capture checks that Mesa's llvmpipe drew a picture that is not a
// single colour, and fails clearly otherwise (a wrong link order gives a black image silently).
#pragma once

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <memory>
#include <string>

class vtkGenericOpenGLRenderWindow;
class vtkImageData;
class vtkRenderer;
class vtkWindowToImageFilter;

namespace plastica::render {

class OffscreenContext;

class OffscreenWindow {
public:
    OffscreenWindow(int width, int height);
    ~OffscreenWindow();

    void add(vtkRenderer* renderer);
    // Draws every renderer and returns a copy of the pixels (RGB, origin bottom left).
    vtkSmartPointer<vtkImageData> capture();

    const std::string& gl_renderer() const { return gl_renderer_; }

private:
    std::unique_ptr<OffscreenContext> context_;
    vtkSmartPointer<vtkGenericOpenGLRenderWindow> window_;
    vtkSmartPointer<vtkWindowToImageFilter> grabber_;
    std::string gl_renderer_;
    bool checked_ = false;
};

// True when every pixel of the image has the same colour.
bool is_uniform(vtkImageData* image);

} // namespace plastica::render
