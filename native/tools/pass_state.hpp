// shaders/passes.json for plain OpenGL: the render targets, and per pass its program, the targets
// its samplers read and its outputs write, what it clears, its fixed-function state and the
// table it reads. The add-on draws from the same file (addon/passes/pass_state.py), so a change
// to a pass is made there once. Needs a current GL context from Targets on.
#pragma once

#include "gl_objects.hpp"

#include <edgelight/edgelight.h>
#include <glm/glm.hpp>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace el_tools {

struct PassSpec {
    std::string program;
    std::map<std::string, std::string> inputs;   // sampler -> target
    std::map<std::string, std::string> outputs;  // fragment output -> target
    std::string depth_target;                    // empty: none
    std::optional<glm::vec4> clear_color;        // every colour slot
    std::optional<float> clear_depth;
    // Fixed-function state, from Blender's gpu.state names.
    GLenum depth_func = 0;  // 0: no depth test
    bool depth_write = false;
    std::string blend;     // NONE, ALPHA_PREMULT, ADDITIVE_PREMULT
    GLenum cull_face = 0;  // 0: both faces drawn
    // The F(phi, m) table, if the pass reads it: its sampler, and defines fixed from el_table_info
    // fields (define -> field), written as integers or as float literals.
    std::string table_sampler;
    std::vector<std::pair<std::string, std::string>> table_defines;
    std::vector<std::pair<std::string, std::string>> table_float_defines;
};

struct PassSpecs {
    std::map<std::string, GLenum> targets;  // name -> internal format
    std::map<std::string, PassSpec> passes;
    const PassSpec& pass(const std::string& name) const;
};

// Reads `shader_dir`/passes.json; throws std::runtime_error naming what is missing or unknown.
PassSpecs read_pass_specs(const std::string& shader_dir);

// The table's defines for a pass, from the table's el_table_info: integers, then float literals
// (%.9e, as the add-on writes them: addon/passes/pass_state.py).
std::vector<std::pair<std::string, std::string>> table_defines(const PassSpec& pass, const el_table_info& info);

// The targets of one size, each made on first use in its passes.json format, and a framebuffer
// per pass and program.
class Targets {
public:
    Targets(const PassSpecs& specs, int width, int height) : w(width), h(height), specs_(specs) {}
    const int w, h;

    const Texture& target(const std::string& name);
    // The pass's framebuffer for `program`: a colour slot per output of the program in slot order,
    // on the target the pass names for it, and the pass's depth target.
    const Framebuffer& framebuffer(const std::string& pass, const Program& program);
    // Clears one colour target to zero.
    void clear(const std::string& target);
    // Reads a colour target back, `channels` floats per pixel, rows bottom-up.
    std::vector<float> read(const std::string& target, int channels);

private:
    const PassSpecs& specs_;
    std::map<std::string, std::unique_ptr<Texture>> textures_;
    std::map<std::pair<std::string, GLuint>, std::unique_ptr<Framebuffer>> framebuffers_;
    std::map<std::string, std::unique_ptr<Framebuffer>> single_;  // one target each
};

// Binds the pass's framebuffer, clears what the pass clears, sets its state and binds its inputs
// (the samplers `program` kept); end_pass() puts depth test, depth writes and blending back off.
void begin_pass(const PassSpecs& specs, const std::string& pass, Targets& targets, const Program& program);
void end_pass();

}  // namespace el_tools
