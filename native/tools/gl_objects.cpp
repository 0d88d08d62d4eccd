#include "gl_objects.hpp"

#include <algorithm>
#include <stdexcept>

namespace el_tools {
namespace {

GLuint compile(GLenum stage, const std::string& src, const std::string& program) {
    const GLuint s = gl::CreateShader(stage);
    const char* text = src.c_str();
    gl::ShaderSource(s, 1, &text, nullptr);
    gl::CompileShader(s);
    GLint ok = 0, len = 0;
    gl::GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        gl::GetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
        std::string log(size_t(std::max(len, 1)), '\0');
        gl::GetShaderInfoLog(s, len, nullptr, log.data());
        gl::DeleteShader(s);
        throw std::runtime_error("cannot compile the " + std::string(stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                                 " stage of program '" + program + "':\n" + log);
    }
    return s;
}

template <class List>
size_t slot_of(const List& list, const std::string& name, const char* what, const std::string& program) {
    for (size_t i = 0; i < list.size(); ++i) {
        if (list[i].name == name) return i;
    }
    throw std::runtime_error("program '" + program + "' declares no " + what + " '" + name + "'");
}

}  // namespace

Texture::Texture(int width, int height, GLenum internal_format, const float* data) : w_(width), h_(height) {
    GLenum format = GL_RGBA;
    if (internal_format == GL_R32F) format = GL_RED;
    if (internal_format == GL_DEPTH_COMPONENT32F) format = GL_DEPTH_COMPONENT;
    gl::GenTextures(1, &id_);
    gl::BindTexture(GL_TEXTURE_2D, id_);
    gl::TexImage2D(GL_TEXTURE_2D, 0, GLint(internal_format), width, height, 0, format, GL_FLOAT, data);
    // No mipmaps: the default minification filter would leave the texture incomplete, and an
    // incomplete texture reads as zero in texelFetch.
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl::TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl::check("creating a texture");
}

Texture::~Texture() { gl::DeleteTextures(1, &id_); }

Program::Program(const AssembledProgram& source) : src_(source) {
    const GLuint vs = compile(GL_VERTEX_SHADER, src_.vertex, src_.name);
    GLuint fs = 0;
    try {
        fs = compile(GL_FRAGMENT_SHADER, src_.fragment, src_.name);
    } catch (...) {
        gl::DeleteShader(vs);
        throw;
    }
    id_ = gl::CreateProgram();
    gl::AttachShader(id_, vs);
    gl::AttachShader(id_, fs);
    gl::LinkProgram(id_);
    gl::DeleteShader(vs);
    gl::DeleteShader(fs);
    GLint ok = 0, len = 0;
    gl::GetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (!ok) {
        gl::GetProgramiv(id_, GL_INFO_LOG_LENGTH, &len);
        std::string log(size_t(std::max(len, 1)), '\0');
        gl::GetProgramInfoLog(id_, len, nullptr, log.data());
        gl::DeleteProgram(id_);
        throw std::runtime_error("cannot link program '" + src_.name + "':\n" + log);
    }
}

Program::~Program() { gl::DeleteProgram(id_); }

void Program::use() const { gl::UseProgram(id_); }

GLint Program::location(const std::string& name) const {
    slot_of(src_.iface.push_constants, name, "push constant", src_.name);
    return gl::GetUniformLocation(id_, name.c_str());  // -1 if the compiler dropped it: harmless
}

void Program::set(const std::string& name, float v) const {
    const GLint l = location(name);
    if (l >= 0) gl::Uniform1f(l, v);
}

void Program::set(const std::string& name, const glm::vec4& v) const {
    const GLint l = location(name);
    if (l >= 0) gl::Uniform4fv(l, 1, &v[0]);
}

void Program::set(const std::string& name, const glm::mat4& v) const {
    const GLint l = location(name);
    if (l >= 0) gl::UniformMatrix4fv(l, 1, GL_FALSE, &v[0][0]);
}

void Program::texture(const std::string& sampler, const Texture& t) const {
    const size_t unit = slot_of(src_.iface.samplers, sampler, "sampler", src_.name);
    gl::ActiveTexture(GLenum(GL_TEXTURE0 + unit));
    gl::BindTexture(GL_TEXTURE_2D, t.id());
}

void Program::uniform_buf(const std::string& name, GLuint buffer) const {
    for (const auto& b : src_.iface.uniform_bufs) {
        if (b.name == name) {
            gl::BindBufferBase(GL_UNIFORM_BUFFER, GLuint(b.binding), buffer);
            return;
        }
    }
    throw std::runtime_error("program '" + src_.name + "' declares no uniform buffer '" + name + "'");
}

Framebuffer::Framebuffer(std::vector<const Texture*> colors, const Texture* depth)
    : w_(colors.at(0)->width()), h_(colors.at(0)->height()) {
    gl::GenFramebuffers(1, &id_);
    gl::BindFramebuffer(GL_FRAMEBUFFER, id_);
    std::vector<GLenum> draw;
    for (size_t i = 0; i < colors.size(); ++i) {
        gl::FramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + i), GL_TEXTURE_2D, colors[i]->id(), 0);
        draw.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
    }
    if (depth) gl::FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth->id(), 0);
    gl::DrawBuffers(GLsizei(draw.size()), draw.data());
    if (gl::CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw std::runtime_error("incomplete framebuffer");
    }
}

Framebuffer::~Framebuffer() { gl::DeleteFramebuffers(1, &id_); }

void Framebuffer::bind() const {
    gl::BindFramebuffer(GL_FRAMEBUFFER, id_);
    gl::Viewport(0, 0, w_, h_);
}

void Framebuffer::clear_color(int attachment, const glm::vec4& c) const {
    bind();
    gl::ClearBufferfv(GL_COLOR, attachment, &c[0]);
}

void Framebuffer::clear_depth(float d) const {
    bind();
    gl::DepthMask(GL_TRUE);
    gl::ClearBufferfv(GL_DEPTH, 0, &d);
}

std::vector<float> Framebuffer::read(int attachment, int channels) const {
    bind();
    std::vector<float> out(size_t(w_) * size_t(h_) * size_t(channels));
    gl::ReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + attachment));
    gl::PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl::ReadPixels(0, 0, w_, h_, channels == 1 ? GL_RED : GL_RGBA, GL_FLOAT, out.data());
    gl::check("reading a render target");
    return out;
}

VertexArray::VertexArray(const Program& program, const std::vector<Attr>& attrs, const std::vector<uint32_t>* indices) {
    const auto& declared = program.iface().vertex_in;
    if (attrs.size() != declared.size()) throw std::runtime_error("vertex attributes do not match the program's vertex_in");
    gl::GenVertexArrays(1, &vao_);
    gl::BindVertexArray(vao_);
    size_t vertices = 0;
    for (const auto& a : attrs) {
        const size_t loc = slot_of(declared, a.name, "vertex input", "?");
        GLuint vbo = 0;
        gl::GenBuffers(1, &vbo);
        vbos_.push_back(vbo);
        gl::BindBuffer(GL_ARRAY_BUFFER, vbo);
        gl::BufferData(GL_ARRAY_BUFFER, GLsizeiptr(a.data->size() * sizeof(float)), a.data->data(), GL_STATIC_DRAW);
        gl::EnableVertexAttribArray(GLuint(loc));
        gl::VertexAttribPointer(GLuint(loc), a.components, GL_FLOAT, GL_FALSE, 0, nullptr);
        vertices = a.data->size() / size_t(a.components);
    }
    count_ = GLsizei(vertices);
    if (indices) {
        gl::GenBuffers(1, &ibo_);
        gl::BindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);
        gl::BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices->size() * sizeof(uint32_t)), indices->data(),
                       GL_STATIC_DRAW);
        count_ = GLsizei(indices->size());
        indexed_ = true;
    }
    gl::BindVertexArray(0);
    gl::check("creating vertex buffers");
}

VertexArray::~VertexArray() {
    gl::DeleteVertexArrays(1, &vao_);
    gl::DeleteBuffers(GLsizei(vbos_.size()), vbos_.data());
    if (ibo_) gl::DeleteBuffers(1, &ibo_);
}

void VertexArray::draw_triangles() const {
    if (count_ == 0) return;
    gl::BindVertexArray(vao_);
    if (indexed_) {
        gl::DrawElements(GL_TRIANGLES, count_, GL_UNSIGNED_INT, nullptr);
    } else {
        gl::DrawArrays(GL_TRIANGLES, 0, count_);
    }
    gl::BindVertexArray(0);
}

UniformBuffer::UniformBuffer() { gl::GenBuffers(1, &id_); }
UniformBuffer::~UniformBuffer() { gl::DeleteBuffers(1, &id_); }

void UniformBuffer::upload(const std::vector<float>& data) const {
    gl::BindBuffer(GL_UNIFORM_BUFFER, id_);
    gl::BufferData(GL_UNIFORM_BUFFER, GLsizeiptr(data.size() * sizeof(float)), data.data(), GL_DYNAMIC_DRAW);
}

}  // namespace el_tools
