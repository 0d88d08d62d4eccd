#include "render_passes.hpp"

#include <edgelight/edgelight.h>

#include <algorithm>
#include <map>
#include <memory>
#include <stdexcept>

namespace el_tools {
namespace {

// Flat outputs come from each triangle's last vertex, as on Blender's OpenGL backend (see
// addon/passes/provoking.py, which measures it there); edge_quads() orders the triangles to
// match, so the edge's shading vertex provides them.
constexpr GLenum kProvokingGl = GL_LAST_VERTEX_CONVENTION;
constexpr Provoking kProvoking = Provoking::last;

void check(el_status s) {
    if (s != EL_OK) throw std::runtime_error(std::string(el_status_name(s)) + ": " + el_last_error());
}

// The library's recommended F(phi, m) table as an R32F texture, with the shader's
// table_params = (layout, m_max, warp_c, unused), as addon/passes/frame.py sets it.
std::unique_ptr<Texture> highlight_table(glm::vec4& params) {
    const el_table_desc desc = EL_TABLE_DEFAULT_DESC;
    el_highlight_table* t = nullptr;
    check(el_highlight_table_create(&desc, &t));
    std::unique_ptr<el_highlight_table, void (*)(el_highlight_table*)> owner(t, el_highlight_table_destroy);
    el_table_info info{};
    check(el_highlight_table_get_info(t, &info));
    std::vector<float> data(size_t(info.phi_count) * info.m_count);
    check(el_highlight_table_copy(t, data.data(), data.size()));
    params = {float(info.layout), info.m_max, info.warp_c, 0.0f};
    return std::make_unique<Texture>(int(info.phi_count), int(info.m_count), GL_R32F, data.data());
}

void blend_none() { gl::Disable(GL_BLEND); }

// Blender's ALPHA_PREMULT and ADDITIVE_PREMULT blend states.
void blend_alpha_premult() {
    gl::Enable(GL_BLEND);
    gl::BlendEquation(GL_FUNC_ADD);
    gl::BlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
}

void blend_additive_premult() {
    gl::Enable(GL_BLEND);
    gl::BlendEquation(GL_FUNC_ADD);
    gl::BlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
}

}  // namespace

struct Renderer::Impl {
    std::string dir;
    Program surface, composite;
    std::map<std::tuple<int, bool, bool>, std::unique_ptr<Program>> edge_programs;  // method, quad fit, floor
    glm::vec4 table_params{0.0f};
    std::unique_ptr<Texture> table = highlight_table(table_params);
    UniformBuffer ubo;
    std::vector<float> fullscreen = {-1.0f, -1.0f, 3.0f, -1.0f, -1.0f, 3.0f};
    VertexArray fullscreen_vao{composite, {{"pos", &fullscreen, 2}}};

    explicit Impl(const std::string& shader_dir)
        : dir(shader_dir), surface(assemble_program(dir, "surface")), composite(assemble_program(dir, "composite")) {}

    // The edge program of one method, with the table layout fixed as the add-on fixes it
    // (passes/frame.py: defines, not uniforms). tight_quads false: the test variant; floor: the
    // benchmark's shading-free variant.
    const Program& edge(int method, bool tight_quads, bool floor) {
        auto& p = edge_programs[{method, tight_quads, floor}];
        if (!p) {
            std::vector<std::pair<std::string, std::string>> defines = {
                {"EL_TABLE_LAYOUT", std::to_string(int(table_params.x))},
                {"EL_EDGE_METHOD", std::to_string(method)},
                {"EL_TIGHT_QUADS", tight_quads ? "true" : "false"}};
            if (floor) defines.emplace_back("EL_EDGE_FLOOR", "1");
            p = std::make_unique<Program>(assemble_program(dir, "edge_highlight", defines));
        }
        return *p;
    }

    void shading(const Program& p, const Material& m) const {
        p.set("model", glm::mat4(1.0f));
        p.set("base_color", glm::vec4(m.base_color, m.alpha));
        p.set("spec_color", glm::vec4(m.spec_color, m.shininess));
    }
};

Renderer::Renderer(const std::string& shader_dir) : impl_(std::make_unique<Impl>(shader_dir)) {
    gl::ProvokingVertex(kProvokingGl);
    gl::check("creating the renderer");
}

Renderer::~Renderer() = default;

// The render targets of one size.
struct Targets {
    Targets(int width, int height) : w(width), h(height) {}
    int w, h;
    Texture surface_color{w, h, GL_RGBA32F}, surface_depth{w, h, GL_R32F}, depth{w, h, GL_DEPTH_COMPONENT32F},
        highlight{w, h, GL_RGBA32F}, lines{w, h, GL_RGBA32F}, result{w, h, GL_RGBA32F};
    // The edge pass depth-tests against the surface pass's depth (read only).
    Framebuffer surface_fb{{&surface_color, &surface_depth}, &depth}, highlight_fb{{&highlight}, &depth},
        line_fb{{&lines}}, result_fb{{&result}};
};

class Renderer::Uploaded {
public:
    Uploaded(const Scene& s, const Program& surface, const Program& edge)
        : scene(s), quads(edge_quads(s.edges, s.material.radius, kProvoking)),
          surface_vao(surface, {{"pos", &s.surface.pos, 3}, {"nor", &s.surface.nor, 3}}),
          edge_vao(edge,
                   {{"p0", &quads.p0, 3}, {"p1", &quads.p1, 3}, {"n1", &quads.n1, 3}, {"n2", &quads.n2, 3},
                    {"corner", &quads.corner, 4}, {"faces", &quads.faces, 2}},
                   &quads.indices) {}

    const Scene& scene;
    const EdgeQuads quads;
    VertexArray surface_vao, edge_vao;
    std::unique_ptr<Targets> targets;
};

void Renderer::UploadedDelete::operator()(Uploaded* u) const { delete u; }

Renderer::UploadedPtr Renderer::upload(const Scene& scene) {
    return UploadedPtr(new Uploaded(scene, impl_->surface, impl_->edge(scene.edge_method, scene.tight_edge_quads, scene.edge_floor)));
}

Images Renderer::render(const Scene& scene, const Camera& camera, int samples) {
    const auto up = upload(scene);
    draw(*up, camera, samples);
    const Targets& t = *up->targets;
    Images out;
    out.width = t.w;
    out.height = t.h;
    out.result = t.result_fb.read(0, 4);
    out.surface = t.surface_fb.read(0, 4);
    out.inv_depth = t.surface_fb.read(1, 1);
    out.highlight = t.highlight_fb.read(0, 4);
    return out;
}

void Renderer::draw(Uploaded& up, const Camera& camera, int samples) {
    Impl& r = *impl_;
    const Scene& scene = up.scene;
    const int w = camera.width, h = camera.height;
    if (!up.targets || up.targets->w != w || up.targets->h != h) up.targets = std::make_unique<Targets>(w, h);
    Targets& t = *up.targets;
    auto &surface_fb = t.surface_fb, &highlight_fb = t.highlight_fb, &line_fb = t.line_fb, &result_fb = t.result_fb;
    auto &surface_color = t.surface_color, &surface_depth = t.surface_depth, &highlight = t.highlight,
         &lines = t.lines;
    const Program& edge = r.edge(scene.edge_method, scene.tight_edge_quads, scene.edge_floor);
    const Material& m = scene.material;
    gl::Disable(GL_CULL_FACE);  // Blender shows both sides; the surface shader flips back faces

    samples = std::max(samples, 1);
    result_fb.clear_color(0, glm::vec4(0.0f));
    line_fb.clear_color(0, glm::vec4(0.0f));  // no ink lines here: the composite reads a clear layer
    for (int s = 0; s < samples; ++s) {
        const glm::dmat4 proj = jittered_projection(camera.projection(), w, h, jitter(s));
        r.ubo.upload(frame_data(camera, proj, scene.suns, scene.ambient));

        // Surface: colour and 1 / view depth, depth-tested.
        surface_fb.clear_color(0, glm::vec4(0.0f));
        surface_fb.clear_color(1, glm::vec4(0.0f));
        surface_fb.clear_depth(1.0f);
        surface_fb.bind();
        gl::Enable(GL_DEPTH_TEST);
        gl::DepthFunc(GL_LEQUAL);
        gl::DepthMask(GL_TRUE);
        blend_none();
        r.surface.use();
        r.surface.uniform_buf("frame", r.ubo.id());
        r.shading(r.surface, m);
        // Blinn-Phong: the surface program built without EL_SURFACE_MODE has no toon inputs.
        up.surface_vao.draw_triangles();
        gl::Disable(GL_DEPTH_TEST);
        gl::DepthMask(GL_FALSE);
        gl::check("the surface pass");

        // Edge highlights once, on the unjittered sample: their coverage is box-filtered
        // analytically across the band (docs/addon.md), later samples reuse them.
        if (s == 0) {
            highlight_fb.clear_color(0, glm::vec4(0.0f));
            highlight_fb.bind();
            blend_alpha_premult();
            // Depth-tested against the surface (read only), as the add-on does: the vertex
            // shader pulls the quads toward the eye past the fragment shader's own bias.
            if (scene.edge_depth_test) {
                gl::Enable(GL_DEPTH_TEST);
                gl::DepthFunc(GL_LEQUAL);
            }
            edge.use();
            edge.uniform_buf("frame", r.ubo.id());
            edge.texture("cos_power_table", *r.table);
            edge.texture("surface_depth", surface_depth);
            edge.set("table_params", r.table_params);
            r.shading(edge, m);
            edge.set("tint", glm::vec4(m.tint, m.K));
            up.edge_vao.draw_triangles();
            gl::Disable(GL_DEPTH_TEST);
            blend_none();
            gl::check("the edge highlight pass");
        }

        result_fb.bind();
        blend_additive_premult();
        r.composite.use();
        r.composite.texture("surface_color", surface_color);
        r.composite.texture("highlight_color", highlight);
        r.composite.texture("line_color", lines);
        r.composite.set("background", glm::vec4(glm::vec3(scene.ambient), 1.0f));  // an opaque world
        r.composite.set("weight", 1.0f / float(samples));
        r.fullscreen_vao.draw_triangles();
        blend_none();
        gl::check("the composite pass");
    }
    gl::Finish();
}

}  // namespace el_tools
