// An OpenGL context drawn by Mesa's software rasteriser (llvmpipe) through OSMesa, on a pixel
// buffer this object owns: no X server, no DISPLAY. Only offscreen_context.cpp
// includes GL/osmesa.h, because GLEW's header (used elsewhere) breaks it.
#pragma once

#include <string>
#include <vector>

namespace plastica::render {

class OffscreenContext {
public:
    OffscreenContext(int width, int height); // throws RenderError when OSMesa refuses
    ~OffscreenContext();
    OffscreenContext(const OffscreenContext&) = delete;
    OffscreenContext& operator=(const OffscreenContext&) = delete;

    void make_current();
    // The GL_RENDERER string of the current context ("llvmpipe (LLVM 15.0.6, 256 bits)").
    std::string renderer() const;

private:
    void* context_ = nullptr; // OSMesaContext
    int width_, height_;
    std::vector<unsigned char> buffer_;
};

// Whether this process has created an OSMesa context. Mesa then keeps threads of its own (the
// shader cache's, the compiler's queue) that a forked child would lack: only a process that has
// drawn nothing yet may fork drawing processes.
bool mesa_started_in_this_process();

// OSMesa's entry point for a GL function by name (nullptr when unknown).
using GlFunction = void (*)();
GlFunction osmesa_function(const char* name);

} // namespace plastica::render
