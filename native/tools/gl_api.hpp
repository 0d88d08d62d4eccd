// The OpenGL 4.5 core entry points the renderer uses, as function pointers loaded from the
// current context (OSMesaGetProcAddress): no GL loader library, and no GL symbol linked
// directly, so nothing here depends on which libGL the process loaded. Called as gl::Name(...).
#pragma once

#include <GL/glcorearb.h>

#define EL_GL_FUNCTIONS(X)                                                                           \
    X(PFNGLGETSTRINGPROC, GetString)                                                                 \
    X(PFNGLGETERRORPROC, GetError)                                                                   \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                                                             \
    X(PFNGLCREATESHADERPROC, CreateShader)                                                           \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                                                           \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                                                         \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                                                             \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                                                   \
    X(PFNGLDELETESHADERPROC, DeleteShader)                                                           \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                                                         \
    X(PFNGLATTACHSHADERPROC, AttachShader)                                                           \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                                                             \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                                                           \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                                                 \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                                                         \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                                                               \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                                               \
    X(PFNGLGETATTRIBLOCATIONPROC, GetAttribLocation)                                                 \
    X(PFNGLUNIFORM1FPROC, Uniform1f)                                                                 \
    X(PFNGLUNIFORM2FVPROC, Uniform2fv)                                                               \
    X(PFNGLUNIFORM3FVPROC, Uniform3fv)                                                               \
    X(PFNGLUNIFORM4FVPROC, Uniform4fv)                                                               \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                                                   \
    X(PFNGLGENBUFFERSPROC, GenBuffers)                                                               \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                                                               \
    X(PFNGLBUFFERDATAPROC, BufferData)                                                               \
    X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                                                       \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                                                         \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                                                     \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                                                     \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                                               \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)                                     \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                                             \
    X(PFNGLGENTEXTURESPROC, GenTextures)                                                             \
    X(PFNGLBINDTEXTUREPROC, BindTexture)                                                             \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                                                         \
    X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                                               \
    X(PFNGLTEXPARAMETERIPROC, TexParameteri)                                                         \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                                                       \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                                                     \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                                                     \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)                                           \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)                                       \
    X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                                                             \
    X(PFNGLREADBUFFERPROC, ReadBuffer)                                                               \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                                               \
    X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                                                         \
    X(PFNGLVIEWPORTPROC, Viewport)                                                                   \
    X(PFNGLENABLEPROC, Enable)                                                                       \
    X(PFNGLDISABLEPROC, Disable)                                                                     \
    X(PFNGLDEPTHFUNCPROC, DepthFunc)                                                                 \
    X(PFNGLDEPTHMASKPROC, DepthMask)                                                                 \
    X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate)                                                 \
    X(PFNGLBLENDEQUATIONPROC, BlendEquation)                                                         \
    X(PFNGLPROVOKINGVERTEXPROC, ProvokingVertex)                                                     \
    X(PFNGLDRAWARRAYSPROC, DrawArrays)                                                               \
    X(PFNGLDRAWELEMENTSPROC, DrawElements)                                                           \
    X(PFNGLPIXELSTOREIPROC, PixelStorei)                                                             \
    X(PFNGLREADPIXELSPROC, ReadPixels)                                                               \
    X(PFNGLFINISHPROC, Finish)

namespace gl {

#define EL_GL_DECLARE(type, name) extern type name;
EL_GL_FUNCTIONS(EL_GL_DECLARE)
#undef EL_GL_DECLARE

// Loads every pointer through `get` ("glName" -> address). Throws std::runtime_error naming the
// first entry point the context lacks.
void load(void* (*get)(const char* name));

// Throws std::runtime_error("GL error 0x... after <what>") if the context recorded an error.
void check(const char* what);

}  // namespace gl
