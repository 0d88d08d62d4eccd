// FrameData's layout as both hosts derive it from shaders/frame_data.json (native/tools/
// typedef_spec.cpp here; addon/bridge/shader_specs.py agrees with it, tests/addon) is the one the
// GL compiler gives the block: every member's offset and stride, and the block's size.
#include "gl_objects.hpp"
#include "offscreen_gl.hpp"
#include "shader_assembly.hpp"
#include "typedef_spec.hpp"

#include <GL/osmesa.h>
#include <gtest/gtest.h>

#include <string>

namespace {

class TypedefSpec : public OffscreenGlTest {};

template <class F>
F gl_function(const char* name) {
    return reinterpret_cast<F>(OSMesaGetProcAddress(name));
}

TEST_F(TypedefSpec, FrameDataLayoutIsTheCompilers) {
    const el_tools::Block block(EDGELIGHT_SHADER_DIR, "frame_data.json");
    const el_tools::Program program(el_tools::assemble_program(EDGELIGHT_SHADER_DIR, "surface"));
    const auto block_index = gl_function<PFNGLGETUNIFORMBLOCKINDEXPROC>("glGetUniformBlockIndex");
    const auto block_param = gl_function<PFNGLGETACTIVEUNIFORMBLOCKIVPROC>("glGetActiveUniformBlockiv");
    const auto uniform_indices = gl_function<PFNGLGETUNIFORMINDICESPROC>("glGetUniformIndices");
    const auto uniform_param = gl_function<PFNGLGETACTIVEUNIFORMSIVPROC>("glGetActiveUniformsiv");
    ASSERT_TRUE(block_index && block_param && uniform_indices && uniform_param);

    const GLuint b = block_index(program.id(), "FrameData_frame_block");
    ASSERT_NE(b, GL_INVALID_INDEX);
    GLint bytes = 0;
    block_param(program.id(), b, GL_UNIFORM_BLOCK_DATA_SIZE, &bytes);
    EXPECT_EQ(size_t(bytes), 4 * block.size());

    ASSERT_EQ(block.members().size(), 21u);  // the lights, the world's image, then the shadows (docs/shadows.md)
    for (const auto& [name, m] : block.members()) {
        // std140 blocks keep every member active, read or not.
        const std::string gl_name = "frame." + name + (m.count > 1 ? "[0]" : "");
        const char* names[] = {gl_name.c_str()};
        GLuint index = GL_INVALID_INDEX;
        uniform_indices(program.id(), 1, names, &index);
        ASSERT_NE(index, GL_INVALID_INDEX) << gl_name;
        GLint offset = -1, array_stride = -1, matrix_stride = -1;
        uniform_param(program.id(), 1, &index, GL_UNIFORM_OFFSET, &offset);
        uniform_param(program.id(), 1, &index, GL_UNIFORM_ARRAY_STRIDE, &array_stride);
        uniform_param(program.id(), 1, &index, GL_UNIFORM_MATRIX_STRIDE, &matrix_stride);
        EXPECT_EQ(size_t(offset), 4 * m.offset) << name;
        if (m.count > 1) EXPECT_EQ(size_t(array_stride), 4 * m.floats) << name;
        if (m.floats == 16) EXPECT_EQ(matrix_stride, 16) << name;  // column-major vec4 columns
    }
}

TEST_F(TypedefSpec, DefinesReachTheGlsl) {
    const el_tools::Block block(EDGELIGHT_SHADER_DIR, "frame_data.json");
    const auto p = el_tools::assemble_program(EDGELIGHT_SHADER_DIR, "surface");
    EXPECT_NE(p.fragment.find("#define EL_MAX_LIGHTS " + std::to_string(block.define("EL_MAX_LIGHTS"))), std::string::npos);
    EXPECT_NE(p.fragment.find("#define EL_LIGHT_SPOT " + std::to_string(block.define("EL_LIGHT_SPOT"))), std::string::npos);
    EXPECT_NE(p.fragment.find("vec4 light_color[EL_MAX_LIGHTS];"), std::string::npos);
    EXPECT_NE(p.fragment.find("#define EL_SURFACE_MODE_WHITEOUT 3"), std::string::npos);
    EXPECT_THROW(block.define("EL_NO_SUCH_NAME"), std::runtime_error);
}

}  // namespace
