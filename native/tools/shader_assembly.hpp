// GLSL sources of one EdgeLight program for a plain OpenGL 4.5 core context, assembled from
// shaders/programs.json and the same body files the add-on hands to Blender's
// GPUShaderCreateInfo (addon/passes/shader_lib.py): one source of truth for both hosts.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace el_tools {

// The interface of a program as programs.json states it, in declaration order (the order gives
// the slots: vertex attribute locations, sampler texture units, fragment output locations).
struct ProgramInterface {
    struct Var {
        std::string type;  // programs.json's type name: "VEC3", "MAT4", "FLOAT_2D", ...
        std::string name;
    };
    struct Block {
        int binding = 0;
        std::string type_name;  // the struct declared by a typedef file ("FrameData")
        std::string name;       // the variable the bodies use ("frame")
    };
    std::vector<Block> uniform_bufs;
    std::vector<Var> push_constants, vertex_in, samplers, fragment_out;
};

struct AssembledProgram {
    std::string name;
    ProgramInterface iface;
    std::string vertex;  // complete sources, #version line first
    std::string fragment;
};

// The GLSL version the preamble declares. 4.30 is what Blender's GL backend asks for on Mesa;
// the bodies need 4.00 at least (frexp, ldexp, fma in highlight_arc.glsl) and the preamble uses
// 4.20's layout(binding = ...) for samplers and uniform blocks.
inline constexpr const char* kGlslVersion = "#version 430 core";

// Reads `shader_dir`/programs.json and the program's files. `defines` become #define lines after
// the version, as GPUShaderCreateInfo.define() does in the add-on (EL_TABLE_LAYOUT:
// shaders/highlight_arc.glsl), and a define named in the program's fragment_out_if adds its
// outputs. Throws std::runtime_error naming the program, file or type that is missing or unknown.
AssembledProgram assemble_program(const std::string& shader_dir, const std::string& program,
                                  const std::vector<std::pair<std::string, std::string>>& defines = {});

// A variant of a program kept outside shaders/ for tests and benchmarks, described by
// `variant_file` (bench/shaders/edge_methods.json: the edge pass's earlier methods and its floor):
// the program it names, with the flat outputs it adds and, per stage, each file it names replaced
// by its list (looked up beside `variant_file` first, then in `shader_dir`); as
// bench/edge_methods.py builds it in Blender.
AssembledProgram assemble_variant(const std::string& shader_dir, const std::string& variant_file,
                                  const std::vector<std::pair<std::string, std::string>>& defines = {});

// Every program name in programs.json (keys not starting with '_').
std::vector<std::string> program_names(const std::string& shader_dir);

}  // namespace el_tools
