#include "osmesa_context.hpp"

#include "gl_api.hpp"

#include <GL/osmesa.h>

#include <stdexcept>

namespace el_tools {
namespace {

void* proc(const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }

}  // namespace

OsmesaContext::OsmesaContext() {
    // 4.5 core: llvmpipe offers it, and the bodies need GLSL 4.00+ (shader_assembly.hpp).
    const int attrs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
    OSMesaContext c = OSMesaCreateContextAttribs(attrs, nullptr);
    if (!c) {
        throw std::runtime_error(
            "OSMesa could not create an OpenGL 4.5 core context (needs Mesa's llvmpipe; "
            "Debian: libosmesa6, scripts/setup.sh installs it)");
    }
    ctx_ = c;
    if (!OSMesaMakeCurrent(c, placeholder_, GL_UNSIGNED_BYTE, 1, 1)) {
        OSMesaDestroyContext(c);
        throw std::runtime_error("OSMesaMakeCurrent failed");
    }
    try {
        gl::load(proc);
    } catch (...) {
        OSMesaDestroyContext(c);
        throw;
    }
}

OsmesaContext::~OsmesaContext() { OSMesaDestroyContext(static_cast<OSMesaContext>(ctx_)); }

std::string OsmesaContext::description() const {
    auto str = [](GLenum e) {
        const GLubyte* s = gl::GetString(e);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    return str(GL_VERSION) + " | " + str(GL_RENDERER);
}

}  // namespace el_tools
