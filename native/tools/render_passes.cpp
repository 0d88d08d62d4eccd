#include "render_passes.hpp"

#include "pass_state.hpp"
#include "typedef_spec.hpp"

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

// The edge pass's benchmark and test variants (Scene::edge_method, tight_edge_quads, edge_floor).
constexpr const char* kEdgeVariants = EDGELIGHT_BENCH_SHADER_DIR "/edge_methods.json";

void check(el_status s) {
    if (s != EL_OK) throw std::runtime_error(std::string(el_status_name(s)) + ": " + el_last_error());
}

// The library's recommended F(phi, m) table as an R32F texture, and its el_table_info (the edge
// pass's table defines and push constants are made of its fields: shaders/passes.json).
std::unique_ptr<Texture> highlight_table(el_table_info& info) {
    const el_table_desc desc = EL_TABLE_DEFAULT_DESC;
    el_highlight_table* t = nullptr;
    check(el_highlight_table_create(&desc, &t));
    std::unique_ptr<el_highlight_table, void (*)(el_highlight_table*)> owner(t, el_highlight_table_destroy);
    check(el_highlight_table_get_info(t, &info));
    std::vector<float> data(size_t(info.phi_count) * info.m_count);
    check(el_highlight_table_copy(t, data.data(), data.size()));
    return std::make_unique<Texture>(int(info.phi_count), int(info.m_count), GL_R32F, data.data());
}

}  // namespace

struct Renderer::Impl {
    std::string dir;
    PassSpecs passes;   // shaders/passes.json: targets, pass state, the table's use
    Block frame_block;  // shaders/frame_data.json: FrameData's layout
    Block material_block;  // shaders/material_data.json: a material's block, zeros here (no emission)
    Program surface, composite;
    std::map<std::tuple<int, bool, bool>, std::unique_ptr<Program>> edge_programs;  // method, quad fit, floor
    el_table_info table_info{};
    std::unique_ptr<Texture> table = highlight_table(table_info);
    UniformBuffer ubo;
    UniformBuffer material_ubo;
    std::vector<float> fullscreen = {-1.0f, -1.0f, 3.0f, -1.0f, -1.0f, 3.0f};
    VertexArray fullscreen_vao{composite, {{"pos", &fullscreen, 2}}};

    explicit Impl(const std::string& shader_dir)
        : dir(shader_dir), passes(read_pass_specs(dir)), frame_block(dir, "frame_data.json"),
          material_block(dir, "material_data.json"), surface(assemble_program(dir, "surface")),
          composite(assemble_program(dir, "composite")) {
        material_ubo.upload(material_block.zeros());
    }

    // The edge program with the table's defines of shaders/passes.json: the add-on's (method 0,
    // fitted quads, shaded), else the test and benchmark variant of bench/shaders/edge_methods.json
    // (another method, quads symmetric about the line, the shading-free floor).
    const Program& edge(int method, bool tight_quads, bool floor) {
        auto& p = edge_programs[{method, tight_quads, floor}];
        if (!p) {
            auto defines = table_defines(passes.pass("edge_highlight"), table_info);
            defines.emplace_back("EL_FACES_UNDER", "1");  // Blinn-Phong only: bands replace the faces under them
            if (method == 0 && tight_quads && !floor) {
                p = std::make_unique<Program>(assemble_program(dir, "edge_highlight", defines));
            } else {
                defines.emplace_back("EL_EDGE_METHOD", std::to_string(method));
                defines.emplace_back("EL_TIGHT_QUADS", tight_quads ? "true" : "false");
                if (floor) defines.emplace_back("EL_EDGE_FLOOR", "1");
                p = std::make_unique<Program>(assemble_variant(dir, kEdgeVariants, defines));
            }
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

class Renderer::Uploaded {
public:
    Uploaded(const Scene& s, const Program& surface, const Program& edge)
        : scene(s), quads(edge_quads(s.edges, s.material.radius, kProvoking)),
          surface_vao(surface, {{"pos", &s.surface.pos, 3}, {"nor", &s.surface.nor, 3}, {"uv", &s.surface.uv, 2},
                                {"col", &s.surface.col, 4}, {"tan", &s.surface.tan, 4}}),
          edge_vao(edge,
                   {{"p0", &quads.p0, 3}, {"p1", &quads.p1, 3}, {"n1", &quads.n1, 3}, {"n2", &quads.n2, 3},
                    {"corner", &quads.corner, 4}, {"faces", &quads.faces, 2}, {"ends", &quads.ends, 4},
                    {"turn1", &quads.turn1, 3}, {"turn2", &quads.turn2, 3}, {"uv", &quads.uv, 4},
                    {"col0", &quads.col0, 4}, {"col1", &quads.col1, 4}},
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
    Targets& t = *up->targets;
    Images out;
    out.width = t.w;
    out.height = t.h;
    out.result = t.read("result", 4);
    out.surface = t.read("surface_color", 4);
    out.inv_depth = t.read("surface_depth", 1);
    out.highlight = t.read("highlight", 4);
    return out;
}

void Renderer::draw(Uploaded& up, const Camera& camera, int samples) {
    Impl& r = *impl_;
    const Scene& scene = up.scene;
    const int w = camera.width, h = camera.height;
    if (!up.targets || up.targets->w != w || up.targets->h != h) up.targets = std::make_unique<Targets>(r.passes, w, h);
    Targets& t = *up.targets;
    const Program& edge = r.edge(scene.edge_method, scene.tight_edge_quads, scene.edge_floor);
    const PassSpec& edge_pass = r.passes.pass("edge_highlight");
    const Material& m = scene.material;

    samples = std::max(samples, 1);
    t.clear("result");
    t.clear("lines");  // no ink lines here: the composite reads a clear layer
    for (int s = 0; s < samples; ++s) {
        const glm::dmat4 proj = jittered_projection(camera.projection(), w, h, jitter(s));
        r.ubo.upload(frame_data(r.frame_block, camera, proj, scene.suns, scene.ambient));

        // Surface: colour and 1 / view depth. Blinn-Phong: the program built without
        // EL_SURFACE_MODE has no toon inputs.
        begin_pass(r.passes, "surface", t, r.surface);
        r.surface.uniform_buf("frame", r.ubo.id());
        r.surface.uniform_buf("material", r.material_ubo.id());
        r.shading(r.surface, m);
        up.surface_vao.draw_triangles();
        end_pass();
        gl::check("the surface pass");

        // Edge highlights once, on the unjittered sample: their coverage is box-filtered
        // analytically across the band (docs/addon.md), later samples reuse them.
        if (s == 0) {
            begin_pass(r.passes, "edge_highlight", t, edge);
            if (!scene.edge_depth_test) gl::Disable(GL_DEPTH_TEST);  // a test's check of the depth test
            edge.uniform_buf("frame", r.ubo.id());
            edge.uniform_buf("material", r.material_ubo.id());
            edge.texture(edge_pass.table_sampler, *r.table);
            r.shading(edge, m);
            edge.set("tint", glm::vec4(m.tint, m.K));
            up.edge_vao.draw_triangles();
            end_pass();
            gl::check("the edge highlight pass");
        }

        begin_pass(r.passes, "composite", t, r.composite);
        r.composite.uniform_buf("frame", r.ubo.id());  // declared by the program; no environment here
        r.composite.set("background", glm::vec4(glm::vec3(scene.ambient), 1.0f));  // an opaque world
        r.composite.set("weight", 1.0f / float(samples));
        r.fullscreen_vao.draw_triangles();
        end_pass();
        gl::check("the composite pass");
    }
    gl::Finish();
}

}  // namespace el_tools
