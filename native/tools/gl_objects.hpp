// Small owners of GL objects (program, texture, framebuffer, vertex array) that speak the
// names of shaders/programs.json: uniforms, samplers and attributes are set by the name the
// bodies use, and a name the program does not declare is an error, not a silent no-op.
#pragma once

#include "gl_api.hpp"
#include "shader_assembly.hpp"

#include <glm/glm.hpp>

#include <string>
#include <utility>
#include <vector>

namespace el_tools {

class Texture {
public:
    // internal_format: GL_RGBA32F, GL_R32F or GL_DEPTH_COMPONENT32F; data (optional) matches it.
    Texture(int width, int height, GLenum internal_format, const float* data = nullptr);
    ~Texture();
    Texture(const Texture&) = delete;
    Texture& operator=(const Texture&) = delete;
    GLuint id() const { return id_; }
    int width() const { return w_; }
    int height() const { return h_; }

private:
    GLuint id_ = 0;
    int w_, h_;
};

class Program {
public:
    // Compiles and links; throws std::runtime_error with the info log and the program's name.
    explicit Program(const AssembledProgram& source);
    ~Program();
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;

    void use() const;
    void set(const std::string& push_constant, float v) const;
    void set(const std::string& push_constant, const glm::vec4& v) const;
    void set(const std::string& push_constant, const glm::mat4& v) const;
    void texture(const std::string& sampler, const Texture& t) const;  // unit = its slot
    void uniform_buf(const std::string& name, GLuint buffer) const;    // binding = its slot
    const ProgramInterface& iface() const { return src_.iface; }
    GLuint id() const { return id_; }

private:
    GLint location(const std::string& push_constant) const;
    AssembledProgram src_;
    GLuint id_ = 0;
};

class Framebuffer {
public:
    Framebuffer(std::vector<const Texture*> colors, const Texture* depth = nullptr);
    ~Framebuffer();
    Framebuffer(const Framebuffer&) = delete;
    Framebuffer& operator=(const Framebuffer&) = delete;
    void bind() const;  // and sets the viewport to its size
    void clear_color(int attachment, const glm::vec4& c) const;
    void clear_depth(float d) const;
    // Bottom-up rows, `channels` floats per pixel (4 for RGBA targets, 1 for R32F).
    std::vector<float> read(int attachment, int channels) const;

private:
    GLuint id_ = 0;
    int w_, h_;
};

// Float vertex attributes in the order of the program's vertex_in (location = slot), with an
// optional index buffer.
class VertexArray {
public:
    struct Attr {
        std::string name;
        const std::vector<float>* data;
        int components;
    };
    VertexArray(const Program& program, const std::vector<Attr>& attrs, const std::vector<uint32_t>* indices = nullptr);
    ~VertexArray();
    VertexArray(const VertexArray&) = delete;
    VertexArray& operator=(const VertexArray&) = delete;
    void draw_triangles() const;

private:
    GLuint vao_ = 0, ibo_ = 0;
    std::vector<GLuint> vbos_;
    GLsizei count_ = 0;
    bool indexed_ = false;
};

class UniformBuffer {
public:
    UniformBuffer();
    ~UniformBuffer();
    UniformBuffer(const UniformBuffer&) = delete;
    UniformBuffer& operator=(const UniformBuffer&) = delete;
    void upload(const std::vector<float>& data) const;
    GLuint id() const { return id_; }

private:
    GLuint id_ = 0;
};

}  // namespace el_tools
