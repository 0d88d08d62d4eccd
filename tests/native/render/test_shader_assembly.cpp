// Every program of shaders/programs.json compiles and links in a plain GL 4.5 core context with
// the declarations shader_assembly.cpp generates: the bodies need nothing of Blender's own
// preamble, and a declaration added to programs.json without its use (or the reverse) fails here.
#include "gl_objects.hpp"
#include "offscreen_gl.hpp"
#include "shader_assembly.hpp"

#include <gtest/gtest.h>

namespace {

class ShaderAssembly : public OffscreenGlTest {};

TEST_F(ShaderAssembly, EveryProgramCompilesAndLinks) {
    const auto names = el_tools::program_names(EDGELIGHT_SHADER_DIR);
    ASSERT_GE(names.size(), 4u);  // surface, edge_highlight, composite, line
    for (const auto& name : names) {
        EXPECT_NO_THROW({ el_tools::Program p(el_tools::assemble_program(EDGELIGHT_SHADER_DIR, name)); }) << name;
    }
}

TEST_F(ShaderAssembly, InterfaceFollowsProgramsJson) {
    const auto p = el_tools::assemble_program(EDGELIGHT_SHADER_DIR, "edge_highlight");
    // Flat outputs stay flat (the short-edge colour comes from one vertex), slots in list order.
    EXPECT_NE(p.vertex.find("flat vec4 edge_color;"), std::string::npos);
    EXPECT_NE(p.fragment.find("smooth vec3 edge_point;"), std::string::npos);
    EXPECT_NE(p.vertex.find("layout(location = 4) in vec4 corner;"), std::string::npos);
    EXPECT_NE(p.fragment.find("layout(binding = 1) uniform sampler2D surface_depth;"), std::string::npos);
    EXPECT_NE(p.fragment.find("layout(std140, binding = 0) uniform FrameData_frame_block { FrameData frame; };"),
              std::string::npos);
    EXPECT_THROW(el_tools::assemble_program(EDGELIGHT_SHADER_DIR, "no_such_program"), std::runtime_error);
}

}  // namespace
