// Two GL entry points that every rendering executable must define itself. They are
// linked as object code with ENABLE_EXPORTS so that the dynamic linker resolves GLEW's and VTK's
// calls to them rather than to glvnd's:
//  - glXGetProcAddress[ARB]: Debian's GLEW asks GLX for every GL function; glvnd would answer with
//    a dispatch stub OSMesa never fills. GLX names go to the real GLX, all others to OSMesa.
//  - glewInit: without a GLX display GLEW reports "no GLX display" (4) or "GLX 1.1 only" (3) after
//    it has loaded every GL function; VTK 9.1 would treat that as fatal.
#include "offscreen_context.hpp"

#include <GL/glew.h>
#include <cstring>
#include <dlfcn.h>

namespace {

using plastica::render::GlFunction;

GlFunction find_function(const unsigned char* name, const char* glx_resolver) {
    const char* text = reinterpret_cast<const char*>(name);
    if (std::strncmp(text, "glX", 3) == 0) {
        using Resolver = GlFunction (*)(const unsigned char*);
        const auto real = reinterpret_cast<Resolver>(dlsym(RTLD_NEXT, glx_resolver));
        return real ? real(name) : nullptr;
    }
    return plastica::render::osmesa_function(text);
}

} // namespace

extern "C" {

__attribute__((visibility("default"))) GlFunction glXGetProcAddressARB(const unsigned char* name) {
    return find_function(name, "glXGetProcAddressARB");
}

__attribute__((visibility("default"))) GlFunction glXGetProcAddress(const unsigned char* name) {
    return find_function(name, "glXGetProcAddress");
}

__attribute__((visibility("default"))) GLenum GLEWAPIENTRY glewInit(void) {
    using Init = GLenum (*)();
    const auto real = reinterpret_cast<Init>(dlsym(RTLD_NEXT, "glewInit"));
    if (!real) return GLEW_ERROR_NO_GL_VERSION;
    const GLenum status = real();
    return (status == GLEW_ERROR_NO_GLX_DISPLAY || status == GLEW_ERROR_GLX_VERSION_11_ONLY) ? GLEW_OK : status;
}

} // extern "C"
