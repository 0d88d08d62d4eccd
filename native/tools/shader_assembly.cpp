// programs.json -> GLSL, mapping each GPUShaderCreateInfo call of addon/passes/shader_lib.py to
// the declaration Blender's GL backend generates for it:
//   typedef_source       -> the typedef files, verbatim, before any resource; a JSON typedef
//                           spec (frame_data.json) as the GLSL typedef_spec.cpp writes from it
//   uniform_buf(s, T, v) -> layout(std140, binding = s) uniform T_v_block { T v; };
//   push_constant(T, v)  -> uniform T v;           (Blender's GL backend does the same)
//   vertex_in(i, T, v)   -> layout(location = i) in T v;
//   vertex_out(iface)    -> out NAME { smooth|flat T v; ... };  and  in NAME { ... }; unnamed
//                           blocks, so the bodies use the members by their own names
//   sampler(i, T, v)     -> layout(binding = i) uniform sampler2D v;   (texture unit i)
//   fragment_out(i, T, v)-> layout(location = i) out T v;
#include "shader_assembly.hpp"

#include "typedef_spec.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace el_tools {
namespace {

using nlohmann::json;

std::string read_text(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw std::runtime_error("cannot read " + path);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

json read_programs(const std::string& shader_dir) {
    const std::string path = shader_dir + "/programs.json";
    try {
        return json::parse(read_text(path));
    } catch (const json::exception& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}

// Blender's eGPUType / ImageType names used in programs.json, as GLSL types.
const std::string& glsl_type(const std::string& t, const std::string& program) {
    static const std::map<std::string, std::string> types = {
        {"FLOAT", "float"}, {"VEC2", "vec2"},   {"VEC3", "vec3"},   {"VEC4", "vec4"},
        {"MAT3", "mat3"},   {"MAT4", "mat4"},   {"INT", "int"},     {"IVEC2", "ivec2"},
        {"IVEC3", "ivec3"}, {"IVEC4", "ivec4"}, {"UINT", "uint"},   {"UVEC2", "uvec2"},
        {"UVEC3", "uvec3"}, {"UVEC4", "uvec4"}, {"BOOL", "bool"},
        {"FLOAT_2D", "sampler2D"}, {"FLOAT_1D", "sampler1D"}, {"FLOAT_3D", "sampler3D"},
        {"INT_2D", "isampler2D"},  {"UINT_2D", "usampler2D"}, {"FLOAT_2D_ARRAY", "sampler2DArray"},
    };
    const auto it = types.find(t);
    if (it == types.end()) throw std::runtime_error("program '" + program + "': unknown type " + t);
    return it->second;
}

// An optional list of a program's description; absent means empty.
const json& list_of(const json& d, const char* key) {
    static const json empty = json::array();
    const auto it = d.find(key);
    return it == d.end() ? empty : *it;
}

std::vector<ProgramInterface::Var> vars(const json& list) {
    std::vector<ProgramInterface::Var> out;
    for (const auto& v : list) out.push_back({v.at(0).get<std::string>(), v.at(1).get<std::string>()});
    return out;
}

bool ends_with(const std::string& s, const std::string& end) {
    return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

bool is_file(const std::string& path) { return std::ifstream(path).good(); }

// The files' texts, each read from `first_dir` when it is there (a variant's folder) and from
// `dir` (shaders/) otherwise.
std::string join_files(const std::string& dir, const json& files, const std::string& first_dir = "") {
    std::string out;
    for (const auto& f : files) {
        const std::string name = f.get<std::string>();
        const std::string path = !first_dir.empty() && is_file(first_dir + "/" + name) ? first_dir + "/" + name : dir + "/" + name;
        const std::string text = ends_with(name, ".json") ? typedef_glsl(dir, name) : read_text(path);
        out += "/* ---- " + name + " ---- */\n" + text + "\n";
    }
    return out;
}

// fragment_out, then the outputs of each fragment_out_if whose define is set, in the defines'
// sorted order (as addon/bridge/shader_specs.py's fragment_outputs).
std::vector<ProgramInterface::Var> fragment_outputs(const json& d, const std::vector<std::pair<std::string, std::string>>& defines) {
    auto out = vars(list_of(d, "fragment_out"));
    const auto it = d.find("fragment_out_if");
    if (it == d.end()) return out;
    for (const auto& [define, extra] : it->items()) {  // nlohmann::json objects iterate sorted by key
        for (const auto& [name, value] : defines) {
            if (name == define) {
                for (auto& v : vars(extra)) out.push_back(v);
                break;
            }
        }
    }
    return out;
}

// The declarations both stages share: typedefs, uniform blocks, push constants, samplers.
std::string resources(const std::string& dir, const json& d, const ProgramInterface& iface, const std::string& program) {
    std::ostringstream s;
    s << join_files(dir, list_of(d, "typedefs"));
    for (const auto& b : iface.uniform_bufs) {
        s << "layout(std140, binding = " << b.binding << ") uniform " << b.type_name << "_" << b.name << "_block { "
          << b.type_name << " " << b.name << "; };\n";
    }
    for (const auto& p : iface.push_constants) s << "uniform " << glsl_type(p.type, program) << " " << p.name << ";\n";
    for (size_t i = 0; i < iface.samplers.size(); ++i) {
        s << "layout(binding = " << i << ") uniform " << glsl_type(iface.samplers[i].type, program) << " "
          << iface.samplers[i].name << ";\n";
    }
    return s.str();
}

std::string interface_block(const json& out, const char* direction, const std::string& program) {
    std::ostringstream s;
    s << direction << " " << out.at("name").get<std::string>() << " {\n";
    size_t members = 0;
    // programs.json's key, the GLSL qualifier
    const std::pair<const char*, const char*> quals[] = {
        {"smooth", "smooth"}, {"flat", "flat"}, {"no_perspective", "noperspective"}};
    for (const auto& [key, qual] : quals) {
        for (const auto& v : vars(list_of(out, key))) {
            s << "  " << qual << " " << glsl_type(v.type, program) << " " << v.name << ";\n";
            ++members;
        }
    }
    s << "};\n";
    return members ? s.str() : std::string();  // GLSL forbids an empty block
}

}  // namespace

std::vector<std::string> program_names(const std::string& shader_dir) {
    std::vector<std::string> names;
    const json all = read_programs(shader_dir);  // items() refers into it: keep it alive
    for (const auto& [key, value] : all.items()) {
        if (!key.empty() && key[0] != '_') names.push_back(key);
    }
    return names;
}

namespace {

// GLSL's layout qualifier for a programs.json depth_write value.
std::string depth_layout(const std::string& mode, const std::string& program) {
    if (mode == "ANY") return "depth_any";
    if (mode == "GREATER") return "depth_greater";
    if (mode == "LESS") return "depth_less";
    throw std::runtime_error("programs.json, program '" + program + "': depth_write " + mode + " is none of ANY, GREATER, LESS");
}

// A program from its description `d` (a programs.json entry); files are read from `first_dir`
// when they are there, else from `shader_dir`.
AssembledProgram assemble(const std::string& shader_dir, const std::string& first_dir, const std::string& program,
                          const json& d, const std::vector<std::pair<std::string, std::string>>& defines) {
    AssembledProgram p;
    p.name = program;
    try {
        for (const auto& b : list_of(d, "uniform_bufs")) {
            p.iface.uniform_bufs.push_back({b.at(0).get<int>(), b.at(1).get<std::string>(), b.at(2).get<std::string>()});
        }
        p.iface.push_constants = vars(list_of(d, "push_constants"));
        p.iface.vertex_in = vars(list_of(d, "vertex_in"));
        p.iface.samplers = vars(list_of(d, "samplers"));
        p.iface.fragment_out = fragment_outputs(d, defines);

        std::string define_lines;
        for (const auto& [name, value] : defines) define_lines += "#define " + name + " " + value + "\n";
        const std::string head = std::string(kGlslVersion) + "\n" + define_lines + "/* EdgeLight program '" +
                                 program + "': declarations generated from shaders/programs.json */\n" +
                                 resources(shader_dir, d, p.iface, program);
        std::ostringstream v;
        v << head;
        for (size_t i = 0; i < p.iface.vertex_in.size(); ++i) {
            v << "layout(location = " << i << ") in " << glsl_type(p.iface.vertex_in[i].type, program) << " "
              << p.iface.vertex_in[i].name << ";\n";
        }
        v << interface_block(d.at("vertex_out"), "out", program) << join_files(shader_dir, d.at("vertex"), first_dir);
        p.vertex = v.str();

        std::ostringstream f;
        f << head << interface_block(d.at("vertex_out"), "in", program);
        for (size_t i = 0; i < p.iface.fragment_out.size(); ++i) {
            f << "layout(location = " << i << ") out " << glsl_type(p.iface.fragment_out[i].type, program) << " "
              << p.iface.fragment_out[i].name << ";\n";
        }
        // A program that writes gl_FragDepth says how (programs.json depth_write), as the add-on
        // declares it to Blender: a driver may otherwise keep the rasterised depth.
        if (d.contains("depth_write")) f << "layout(" << depth_layout(d.at("depth_write").get<std::string>(), program) << ") out float gl_FragDepth;\n";
        f << join_files(shader_dir, d.at("fragment"), first_dir);
        p.fragment = f.str();
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error("programs.json, program '" + program + "': " + e.what());
    }
    return p;
}

json read_json(const std::string& path) {
    try {
        return json::parse(read_text(path));
    } catch (const json::exception& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
}

}  // namespace

AssembledProgram assemble_program(const std::string& shader_dir, const std::string& program,
                                  const std::vector<std::pair<std::string, std::string>>& defines) {
    const json all = read_programs(shader_dir);
    if (!all.contains(program)) throw std::runtime_error("programs.json has no program '" + program + "'");
    return assemble(shader_dir, "", program, all.at(program), defines);
}

// As bench/edge_methods.py's variant(): the flat outputs added, each named file of a stage
// replaced by its list; a file the program does not have is an error (the variant would
// silently be the add-on's program).
AssembledProgram assemble_variant(const std::string& shader_dir, const std::string& variant_file,
                                  const std::vector<std::pair<std::string, std::string>>& defines) {
    const json v = read_json(variant_file);
    const std::string variant_dir = variant_file.substr(0, variant_file.find_last_of('/'));
    const std::string program = v.at("program").get<std::string>();
    const json all = read_programs(shader_dir);
    if (!all.contains(program)) throw std::runtime_error(variant_file + ": programs.json has no program '" + program + "'");
    json d = all.at(program);
    for (const auto& member : list_of(v, "vertex_out_flat")) d["vertex_out"]["flat"].push_back(member);
    for (const char* stage : {"vertex", "fragment"}) {
        const auto swaps = v.find(stage);
        if (swaps == v.end()) continue;
        for (const auto& [name, files] : swaps->items()) {
            bool found = false;
            for (const auto& f : d.at(stage)) found = found || f.get<std::string>() == name;
            if (!found) throw std::runtime_error(variant_file + ": the " + stage + " stage of '" + program + "' has no " + name);
        }
        json replaced = json::array();
        for (const auto& f : d.at(stage)) {
            const auto swap = swaps->find(f.get<std::string>());
            for (const auto& g : swap == swaps->end() ? json::array({f}) : *swap) replaced.push_back(g);
        }
        d[stage] = replaced;
    }
    return assemble(shader_dir, variant_dir, program, d, defines);
}

}  // namespace el_tools
