#include "pass_state.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace el_tools {
namespace {

using nlohmann::json;

// Blender's names (gpu.types.GPUTexture formats, gpu.state) in GL terms.
template <class T>
T named(const std::map<std::string, T>& names, const std::string& name, const char* what) {
    const auto it = names.find(name);
    if (it == names.end()) throw std::runtime_error(std::string("passes.json: unknown ") + what + " " + name);
    return it->second;
}

const std::map<std::string, GLenum> kFormats = {
    {"RGBA32F", GL_RGBA32F}, {"RG32F", GL_RG32F}, {"R32F", GL_R32F}, {"DEPTH_COMPONENT32F", GL_DEPTH_COMPONENT32F}};
const std::map<std::string, GLenum> kDepthTests = {
    {"NONE", 0},
    {"ALWAYS", GL_ALWAYS},
    {"LESS", GL_LESS},
    {"LESS_EQUAL", GL_LEQUAL},
    {"EQUAL", GL_EQUAL},
    {"GREATER", GL_GREATER},
    {"GREATER_EQUAL", GL_GEQUAL},
};
// BACK: GL culls back faces unless told otherwise, and nothing here tells it.
const std::map<std::string, GLenum> kCullFaces = {{"NONE", 0}, {"BACK", GL_BACK}};
// Blender's blend states as (source, destination) factors for colour and alpha, added.
struct BlendFactors {
    GLenum src_rgb, dst_rgb, src_alpha, dst_alpha;
};
const std::map<std::string, BlendFactors> kBlends = {
    {"ALPHA_PREMULT", {GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA}},
    {"ADDITIVE_PREMULT", {GL_ONE, GL_ONE, GL_ONE, GL_ONE}},
    {"MULTIPLY", {GL_DST_COLOR, GL_ZERO, GL_DST_ALPHA, GL_ZERO}}};

std::map<std::string, std::string> string_map(const json& j) {
    std::map<std::string, std::string> out;
    for (const auto& [k, v] : j.items()) out[k] = v.get<std::string>();
    return out;
}

PassSpec read_pass(const json& p) {
    PassSpec s;
    s.program = p.at("program").get<std::string>();
    s.inputs = string_map(p.at("inputs"));
    s.outputs = string_map(p.at("outputs"));
    s.depth_target = p.value("depth_target", "");
    if (p.contains("clear")) {
        const json& c = p.at("clear");
        if (c.contains("color")) {
            const auto v = c.at("color").get<std::vector<float>>();
            if (v.size() != 4) throw std::runtime_error("passes.json: a clear colour is not 4 numbers");
            s.clear_color = glm::vec4(v[0], v[1], v[2], v[3]);
        }
        if (c.contains("depth")) s.clear_depth = c["depth"].get<float>();
    }
    const json& st = p.at("state");
    s.depth_func = named(kDepthTests, st.at("depth_test").get<std::string>(), "depth test");
    s.depth_write = st.at("depth_write").get<bool>();
    s.blend = st.at("blend").get<std::string>();
    if (s.blend != "NONE") named(kBlends, s.blend, "blend");
    s.cull_face = named(kCullFaces, st.at("face_culling").get<std::string>(), "face culling");
    if (p.contains("table")) {
        const json& t = p.at("table");
        s.table_sampler = t.at("sampler").get<std::string>();
        for (const auto& [define, field] : t.at("defines").items()) {
            s.table_defines.emplace_back(define, field.get<std::string>());
        }
        if (t.contains("float_defines")) {
            for (const auto& [define, field] : t.at("float_defines").items()) {
                s.table_float_defines.emplace_back(define, field.get<std::string>());
            }
        }
    }
    return s;
}

// An el_table_info field by its name in the C header (as addon/bridge/native.py's TableInfo has it).
double table_field(const el_table_info& info, const std::string& field) {
    const std::map<std::string, double> fields = {
        {"layout", double(info.layout)},
        {"phi_count", double(info.phi_count)},
        {"m_count", double(info.m_count)},
        {"m_max", double(info.m_max)},
        {"warp_c", double(info.warp_c)},
    };
    return named(fields, field, "el_table_info field");
}

void blend(const std::string& name) {
    if (name == "NONE") {
        gl::Disable(GL_BLEND);
        return;
    }
    const BlendFactors f = named(kBlends, name, "blend");
    gl::Enable(GL_BLEND);
    gl::BlendEquation(GL_FUNC_ADD);
    gl::BlendFuncSeparate(f.src_rgb, f.dst_rgb, f.src_alpha, f.dst_alpha);
}

}  // namespace

const PassSpec& PassSpecs::pass(const std::string& name) const {
    const auto it = passes.find(name);
    if (it == passes.end()) throw std::runtime_error("passes.json has no pass '" + name + "'");
    return it->second;
}

PassSpecs read_pass_specs(const std::string& shader_dir) {
    const std::string path = shader_dir + "/passes.json";
    std::ifstream f(path, std::ios::binary);
    if (!f) throw std::runtime_error("cannot read " + path);
    PassSpecs specs;
    try {
        const json j = json::parse(f);
        for (const auto& [name, format] : j.at("targets").items()) {
            specs.targets[name] = named(kFormats, format.get<std::string>(), "format");
        }
        for (const auto& [name, p] : j.at("passes").items()) specs.passes[name] = read_pass(p);
    } catch (const json::exception& e) {
        throw std::runtime_error(path + ": " + e.what());
    }
    return specs;
}

std::vector<std::pair<std::string, std::string>> table_defines(const PassSpec& pass, const el_table_info& info) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& [define, field] : pass.table_defines) {
        out.emplace_back(define, std::to_string(int(table_field(info, field))));
    }
    for (const auto& [define, field] : pass.table_float_defines) {
        char text[64];
        std::snprintf(text, sizeof text, "%.9e", table_field(info, field));
        out.emplace_back(define, text);
    }
    return out;
}

const Texture& Targets::target(const std::string& name) {
    auto& t = textures_[name];
    if (!t) t = std::make_unique<Texture>(w, h, named(specs_.targets, name, "target"));
    return *t;
}

const Framebuffer& Targets::framebuffer(const std::string& pass, const Program& program) {
    auto& fb = framebuffers_[{pass, program.id()}];
    if (!fb) {
        const PassSpec& p = specs_.pass(pass);
        std::vector<const Texture*> colors;
        for (const auto& out : program.iface().fragment_out) colors.push_back(&target(named(p.outputs, out.name, "output")));
        fb = std::make_unique<Framebuffer>(colors, p.depth_target.empty() ? nullptr : &target(p.depth_target));
    }
    return *fb;
}

void Targets::clear(const std::string& name) {
    auto& fb = single_[name];
    if (!fb) fb = std::make_unique<Framebuffer>(std::vector<const Texture*>{&target(name)});
    fb->clear_color(0, glm::vec4(0.0f));
}

std::vector<float> Targets::read(const std::string& name, int channels) {
    auto& fb = single_[name];
    if (!fb) fb = std::make_unique<Framebuffer>(std::vector<const Texture*>{&target(name)});
    return fb->read(0, channels);
}

void begin_pass(const PassSpecs& specs, const std::string& pass, Targets& targets, const Program& program) {
    const PassSpec& p = specs.pass(pass);
    const Framebuffer& fb = targets.framebuffer(pass, program);
    if (p.clear_color) {
        for (size_t i = 0; i < program.iface().fragment_out.size(); ++i) fb.clear_color(int(i), *p.clear_color);
    }
    if (p.clear_depth) fb.clear_depth(*p.clear_depth);
    fb.bind();
    if (p.depth_func) {
        gl::Enable(GL_DEPTH_TEST);
        gl::DepthFunc(p.depth_func);
    } else {
        gl::Disable(GL_DEPTH_TEST);
    }
    gl::DepthMask(p.depth_write ? GL_TRUE : GL_FALSE);
    blend(p.blend);
    if (p.cull_face) {
        gl::Enable(GL_CULL_FACE);
    } else {
        gl::Disable(GL_CULL_FACE);
    }
    program.use();
    for (const auto& [sampler, target] : p.inputs) {
        bool declared = false;
        for (const auto& s : program.iface().samplers) declared = declared || s.name == sampler;
        if (!declared) throw std::runtime_error("passes.json: program '" + p.program + "' has no sampler " + sampler);
        // A sampler the variant's compiler dropped reads nothing: its target is not even made.
        if (gl::GetUniformLocation(program.id(), sampler.c_str()) >= 0) program.texture(sampler, targets.target(target));
    }
}

void end_pass() {
    gl::Disable(GL_DEPTH_TEST);
    gl::DepthMask(GL_FALSE);
    gl::Disable(GL_BLEND);
}

}  // namespace el_tools
