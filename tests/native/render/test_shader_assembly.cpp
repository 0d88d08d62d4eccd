// Every program of shaders/programs.json compiles and links in a plain GL 4.5 core context with
// the declarations shader_assembly.cpp generates: the bodies need nothing of Blender's own
// preamble, and a declaration added to programs.json without its use (or the reverse) fails here.
#include "gl_objects.hpp"
#include "offscreen_gl.hpp"
#include "pass_state.hpp"
#include "shader_assembly.hpp"

#include <edgelight/edgelight.h>
#include <gtest/gtest.h>

namespace {

class ShaderAssembly : public OffscreenGlTest {};

// The defines a program is built with from the library's default table, where a pass of
// shaders/passes.json reads the table with it (the edge program: its m_max and warp_c).
std::vector<std::pair<std::string, std::string>> table_defines_of(const std::string& program) {
    const auto specs = el_tools::read_pass_specs(EDGELIGHT_SHADER_DIR);
    for (const auto& [name, pass] : specs.passes) {
        if (pass.program != program || pass.table_sampler.empty()) continue;
        const el_table_desc desc = EL_TABLE_DEFAULT_DESC;
        el_highlight_table* t = nullptr;
        el_table_info info{};
        if (el_highlight_table_create(&desc, &t) != EL_OK || el_highlight_table_get_info(t, &info) != EL_OK) {
            ADD_FAILURE() << "the default table";
        }
        el_highlight_table_destroy(t);
        return el_tools::table_defines(pass, info);
    }
    return {};
}

TEST_F(ShaderAssembly, EveryProgramCompilesAndLinks) {
    const auto names = el_tools::program_names(EDGELIGHT_SHADER_DIR);
    ASSERT_GE(names.size(), 4u);  // surface, edge_highlight, composite, line
    for (const auto& name : names) {
        EXPECT_NO_THROW({ el_tools::Program p(el_tools::assemble_program(EDGELIGHT_SHADER_DIR, name, table_defines_of(name))); })
            << name;
    }
}

// The surface program's variant that leaves out the strips and corners a rounded outline moves
// in (the add-on builds it with highlights on, the layout from rounded_outline.py's constants):
// compiles and links, its distances interpolated without perspective.
TEST_F(ShaderAssembly, RoundedOutlineVariantCompilesAndLinks) {
    const std::vector<std::pair<std::string, std::string>> defines = {
        {"EL_ROUNDED_OUTLINE", "1"},
        {"EL_OUTLINE_EDGE_TEXELS", "6"},
        {"EL_OUTLINE_EDGES_PER_ROW", "1024"},
        {"EL_OUTLINE_CORNER_TEXELS", "5"},
        {"EL_OUTLINE_CORNERS_PER_ROW", "1024"},
        {"EL_OUTLINE_TRIANGLE_TEXELS", "3"},
        {"EL_OUTLINE_EDGES_PER_TRIANGLE", "8"},
        {"EL_OUTLINE_TRIANGLES_PER_ROW", "2048"},
    };
    const auto p = el_tools::assemble_program(EDGELIGHT_SHADER_DIR, "surface", defines);
    EXPECT_NE(p.vertex.find("noperspective vec4 outline_dist;"), std::string::npos);
    EXPECT_NO_THROW({ el_tools::Program program(p); });
}

TEST_F(ShaderAssembly, InterfaceFollowsProgramsJson) {
    const auto p = el_tools::assemble_program(EDGELIGHT_SHADER_DIR, "edge_highlight");
    // Flat outputs stay flat (each quad carries its edge's), slots in list order.
    EXPECT_NE(p.vertex.find("flat vec4 edge_cut0;"), std::string::npos);
    EXPECT_NE(p.fragment.find("smooth vec3 edge_point;"), std::string::npos);
    EXPECT_NE(p.vertex.find("layout(location = 4) in vec4 corner;"), std::string::npos);
    EXPECT_NE(p.fragment.find("layout(binding = 1) uniform sampler2D surface_depth;"), std::string::npos);
    EXPECT_NE(p.fragment.find("layout(std140, binding = 0) uniform FrameData_frame_block { FrameData frame; };"),
              std::string::npos);
    EXPECT_THROW(el_tools::assemble_program(EDGELIGHT_SHADER_DIR, "no_such_program"), std::runtime_error);
}

// The edge pass's benchmark and test variants (bench/shaders/edge_methods.json) build on the
// add-on's program: every method, with and without fitted quads and the floor, compiles and links,
// with the flat outputs the variant adds; the add-on's program has none of them.
TEST_F(ShaderAssembly, BenchVariantsCompileAndLink) {
    const std::string variants = EDGELIGHT_BENCH_SHADER_DIR "/edge_methods.json";
    for (const char* method : {"0", "1", "2", "3"}) {
        for (const char* tight : {"true", "false"}) {
            for (bool floor : {false, true}) {
                auto defines = table_defines_of("edge_highlight");
                defines.emplace_back("EL_EDGE_METHOD", method);
                defines.emplace_back("EL_TIGHT_QUADS", tight);
                if (floor) defines.emplace_back("EL_EDGE_FLOOR", "1");
                el_tools::AssembledProgram p;
                ASSERT_NO_THROW(p = el_tools::assemble_variant(EDGELIGHT_SHADER_DIR, variants, defines));
                EXPECT_NO_THROW({ el_tools::Program compiled(p); }) << method << " " << tight << " " << floor;
                EXPECT_NE(p.vertex.find("flat vec4 edge_color;"), std::string::npos);
            }
        }
    }
    const auto product = el_tools::assemble_program(EDGELIGHT_SHADER_DIR, "edge_highlight", table_defines_of("edge_highlight"));
    for (const char* variant_only : {"edge_color", "EL_EDGE_METHOD", "EL_TIGHT_QUADS", "EL_EDGE_FLOOR", "quadrature"}) {
        EXPECT_EQ(product.vertex.find(variant_only), std::string::npos) << variant_only;
        EXPECT_EQ(product.fragment.find(variant_only), std::string::npos) << variant_only;
    }
}

}  // namespace
