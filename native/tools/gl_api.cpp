#include "gl_api.hpp"

#include <cstdio>
#include <stdexcept>
#include <string>

namespace gl {

#define EL_GL_DEFINE(type, name) type name = nullptr;
EL_GL_FUNCTIONS(EL_GL_DEFINE)
#undef EL_GL_DEFINE

void load(void* (*get)(const char* name)) {
#define EL_GL_LOAD(type, name)                      \
    name = reinterpret_cast<type>(get("gl" #name)); \
    if (!name) throw std::runtime_error("the GL context has no gl" #name);
    EL_GL_FUNCTIONS(EL_GL_LOAD)
#undef EL_GL_LOAD
}

void check(const char* what) {
    const GLenum e = GetError();
    if (e != GL_NO_ERROR) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04x", e);
        throw std::runtime_error(std::string("GL error ") + code + " after " + what);
    }
}

}  // namespace gl
