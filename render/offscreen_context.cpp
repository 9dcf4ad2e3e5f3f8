#include "offscreen_context.hpp"
#include "render_error.hpp"

#include <GL/osmesa.h>

#include <atomic>

namespace plastica::render {

namespace {
std::atomic<bool> mesa_started{false};
}

bool mesa_started_in_this_process() { return mesa_started; }

OffscreenContext::OffscreenContext(int width, int height)
    : width_(width), height_(height), buffer_(static_cast<std::size_t>(width) * height * 4) {
    // Core profile 3.2 is what VTK's OpenGL2 backend needs; llvmpipe answers with 4.5.
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA,
                              OSMESA_DEPTH_BITS, 24,
                              OSMESA_STENCIL_BITS, 8,
                              OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 3,
                              OSMESA_CONTEXT_MINOR_VERSION, 2,
                              0};
    mesa_started = true;
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context_)
        throw RenderError("OSMesa could not create a core-profile 3.2 context (is libosmesa6 installed?)");
    make_current();
}

OffscreenContext::~OffscreenContext() {
    OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

void OffscreenContext::make_current() {
    if (!OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), buffer_.data(), GL_UNSIGNED_BYTE, width_, height_))
        throw RenderError("OSMesa could not make its context current");
}

std::string OffscreenContext::renderer() const {
    const auto* name = glGetString(GL_RENDERER);
    return name ? reinterpret_cast<const char*>(name) : "";
}

GlFunction osmesa_function(const char* name) {
    return reinterpret_cast<GlFunction>(OSMesaGetProcAddress(name));
}

} // namespace plastica::render
