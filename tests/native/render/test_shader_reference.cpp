// The edge highlight shader, drawn by edgelight-render's passes on OSMesa (llvmpipe), against
// the library's double-precision reference integral (el_highlight_reference) at every pixel of
// one edge: tests/blender/test_reference.py without Blender. The scene is the cube sample
// (blend_samples/make_samples.py): a unit cube under one sun mirrored from the view about the
// bisector of the top and front faces, so that edge's arc holds the half vector and glints.
#include "mesh_batches.hpp"
#include "mesh_io.hpp"
#include "offscreen_gl.hpp"
#include "render_passes.hpp"

#include <edgelight/edgelight.h>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

namespace {

using glm::dvec3;

const dvec3 kA(-1.0, -1.0, 1.0), kB(1.0, -1.0, 1.0);  // the glinting edge (top and front faces)
const dvec3 kN1(0.0, 0.0, 1.0), kN2(0.0, -1.0, 0.0);

// Stated tolerances, as in test_reference.py. Colour: the float32 shader path (table lookup,
// closed form, 8-point Gauss-Legendre) against adaptive double quadrature, relative to the
// pixel's highlight colour; the table's own error is below 1e-5 (docs/highlight_math.md) and
// float32 rounding of the arc frame a few 1e-7. Weight: the band's coverage of the pixel, from
// the shader's float projected width against the reference's r_max.
constexpr double kRelativeTolerance = 1e-4;
constexpr double kWeightTolerance = 1e-3;

struct CubeScene {
    el_tools::Scene scene;
    el_tools::Camera camera;
};

CubeScene cube(int width, int height, float radius) {
    CubeScene s;
    const auto mesh = el_tools::load_mesh(std::string(EDGELIGHT_TEST_MESH_DIR) + "/cube.off");
    s.scene.surface = el_tools::surface_corners(mesh, 30.0f);
    s.scene.edges = el_tools::choose_edges(mesh, 30.0f);
    // el_highlight_reference integrates the whole visible arc at one point, as the edge pass's
    // "whole" method does for every pixel of the band (per-pixel parts of the arc are checked
    // against the bevel ground truth in tests/blender/test_wide_edges.py).
    s.scene.edge_method = 1;
    s.camera.eye = dvec3(5.2, -4.4, 3.6);
    s.camera.target = dvec3(0.0);
    s.camera.width = width;
    s.camera.height = height;
    s.camera.fov_deg = glm::degrees(2.0 * std::atan(18.0 / 50.0));  // 50 mm lens, 36 mm sensor
    const dvec3 v = glm::normalize(s.camera.eye), h = glm::normalize(dvec3(0.0, -1.0, 1.0));
    s.scene.suns.push_back({2.0 * glm::dot(h, v) * h - v, dvec3(4.0)});
    auto& m = s.scene.material;
    m.base_color = {0.55f, 0.05f, 0.04f};
    m.spec_color = glm::vec3(0.04f);
    m.shininess = float(2.0 / std::pow(0.3, 4.0) - 2.0);  // roughness 0.3 (addon/extract/materials.py)
    m.radius = radius;
    return s;
}

el_tools::Images render(const CubeScene& s) {
    offscreen_context();
    el_tools::Renderer renderer(EDGELIGHT_SHADER_DIR);
    return renderer.render(s.scene, s.camera, 1);
}

// Pixel coordinates (x right, y up, pixel centres at .5) and clip w of a world point.
glm::dvec3 project(const el_tools::Camera& c, const dvec3& p) {
    const glm::dvec4 clip = c.projection() * c.view() * glm::dvec4(p, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return {(ndc.x * 0.5 + 0.5) * c.width, (ndc.y * 0.5 + 0.5) * c.height, clip.w};
}

struct Reference {
    el_highlight_result r{};
    dvec3 colour{0.0};
};

// lighting.glsl's el_env_specular: what a uniform world of radiance 1 puts into the specular lobe.
dvec3 env_specular(const dvec3& spec, double n, double nv) {
    const double rough = std::pow(2.0 / (std::max(n, 0.0) + 2.0), 0.25);
    const glm::dvec4 r = rough * glm::dvec4(-1.0, -0.0275, -0.572, 0.022) + glm::dvec4(1.0, 0.0425, 1.04, -0.04);
    const double a004 = std::min(r.x * r.x, std::exp2(-9.28 * std::clamp(nv, 0.0, 1.0))) * r.x + r.y;
    const double a = -1.04 * a004 + r.z, b = 1.04 * a004 + r.w;
    const double e = std::max(a + b, 1e-4);
    return glm::max((spec * a + b) * (1.0 + spec * (1.0 / e - 1.0)), dvec3(0.0));
}

// The reference colour of the rounded edge at X, as the shader's el_edge_colour() composes it.
Reference reference(const CubeScene& s, const dvec3& X, float shininess, float radius) {
    el_highlight_input in{};
    for (int k = 0; k < 3; ++k) {
        in.point[k] = float(X[k]);
        in.edge_dir[k] = float(kB[k] - kA[k]);
        in.n1[k] = float(kN1[k]);
        in.n2[k] = float(kN2[k]);
        in.eye[k] = float(s.camera.eye[k]);
        in.light[k] = float(glm::normalize(s.scene.suns[0].to_light)[k]);
    }
    in.projection = EL_PERSPECTIVE;
    in.shininess = shininess;
    in.radius = radius;
    in.K = float(s.camera.px_per_unit());
    Reference out;
    EXPECT_EQ(el_highlight_reference(&in, &out.r), EL_OK) << el_last_error();
    // The world's light takes the arc's mean cosine to the eye: its diffuse mean with the eye
    // as the light.
    el_highlight_input to_eye = in;
    const dvec3 V = glm::normalize(s.camera.eye - X);
    for (int k = 0; k < 3; ++k) to_eye.light[k] = float(V[k]);
    el_highlight_result seen{};
    EXPECT_EQ(el_highlight_reference(&to_eye, &seen), EL_OK) << el_last_error();
    const auto& m = s.scene.material;
    const dvec3 base(m.base_color), spec(m.spec_color), tint(m.tint);
    const double n = shininess, blinn_norm = (n + 8.0) / (8.0 * M_PI);
    out.colour = s.scene.ambient * (base + tint * env_specular(spec, n, double(seen.diffuse))) +
                 s.scene.suns[0].color * (base * double(out.r.diffuse) / M_PI + tint * spec * blinn_norm * double(out.r.specular));
    return out;
}

// A sharp face's colour at X (unit normal N), as the surface pass shades it (Blinn-Phong).
dvec3 face_colour(const CubeScene& s, const dvec3& X, const dvec3& N) {
    const auto& m = s.scene.material;
    const dvec3 base(m.base_color), spec(m.spec_color);
    const dvec3 V = glm::normalize(s.camera.eye - X), L = glm::normalize(s.scene.suns[0].to_light);
    const double n = m.shininess, nl = glm::dot(N, L);
    const dvec3 lit = nl > 0.0 ? s.scene.suns[0].color * (base * nl / M_PI +
                                                          spec * (n + 8.0) / (8.0 * M_PI) *
                                                              std::pow(std::max(glm::dot(N, glm::normalize(L + V)), 0.0), n))
                               : dvec3(0.0);
    return s.scene.ambient * (base + env_specular(spec, n, glm::dot(N, V))) + lit;
}

// What the band's blend gets wrong about the faces it replaces, per unit of weight
// (docs/highlight_math.md, "The faces under the band"): (f1 - s1) (I1 - I2), with f1 the pixel's
// share on the top face's side of the line and s1 the band's (a band of w_px centred on the line,
// the whole-arc method's), `side1` the side the top face lies on.
dvec3 faces_under(const CubeScene& s, const dvec3& X, double across, double w_px, double side1) {
    const double pa = std::max(across - 0.5, -0.5 * w_px), pb = std::min(across + 0.5, 0.5 * w_px);
    if (!(pb > pa)) return dvec3(0.0);
    const double on1 = side1 >= 0.0 ? pb - std::max(pa, 0.0) : std::min(pb, 0.0) - pa;
    const double s1 = std::clamp(on1 / (pb - pa), 0.0, 1.0), f1 = std::clamp(0.5 + across * side1, 0.0, 1.0);
    return (f1 - s1) * (face_colour(s, X, kN1) - face_colour(s, X, kN2));
}

// Which side of the edge's image (along nrm) the top face (N1's) lies on.
double top_side(const CubeScene& s, const glm::dvec2& s0, const glm::dvec2& nrm) {
    const glm::dvec2 inside(project(s.camera, 0.5 * (kA + kB) + dvec3(0.0, 0.2, 0.0)));
    return glm::dot(inside - s0, nrm) < 0.0 ? -1.0 : 1.0;
}

struct Agreement {
    int checked = 0;
    double worst_rel = 0.0, worst_weight = 0.0;
    double worst_faces_under = 0.0;  // the largest faces-under term met, relative to the band's colour
};

// Every pixel of the edge's band with W > 0.2, away from the corners, against the reference at
// the edge point the rasteriser interpolates there (perspective-correct).
Agreement compare(const CubeScene& s, const el_tools::Images& img, float shininess, float radius) {
    const dvec3 a = project(s.camera, kA), b = project(s.camera, kB);
    const glm::dvec2 s0(a), s1(b);
    const double len = glm::length(s1 - s0);
    const glm::dvec2 d = (s1 - s0) / len, nrm(-d.y, d.x);
    const double side1 = top_side(s, s0, nrm);
    Agreement out;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            const float* hl = &img.highlight[4 * (size_t(y) * img.width + x)];
            if (!(hl[3] > 0.2f)) continue;
            const glm::dvec2 pc(x + 0.5, y + 0.5);
            const double u = glm::dot(pc - s0, d) / len, across = glm::dot(pc - s0, nrm);
            if (!(u > 0.1 && u < 0.9) || std::abs(across) > 8.0) continue;  // this edge, not the corners
            const double t = (u / b.z) / ((1.0 - u) / a.z + u / b.z);
            const dvec3 X = kA + t * (kB - kA);
            const Reference ref = reference(s, X, shininess, radius);
            // Unclamped W of the paper, K r_e / (d r_max): the band's width in pixels.
            const double w_px = s.camera.px_per_unit() * radius / (glm::length(s.camera.eye - X) * ref.r.r_max);
            const dvec3 want = ref.colour + faces_under(s, X, across, w_px, side1);
            const dvec3 got = dvec3(hl[0], hl[1], hl[2]) / double(hl[3]);
            const dvec3 err = glm::abs(got - want);
            const double rel = std::max({err.x, err.y, err.z}) / std::max({ref.colour.x, ref.colour.y, ref.colour.z, 1e-6});
            out.worst_rel = std::max(out.worst_rel, rel);
            out.worst_faces_under = std::max(out.worst_faces_under, glm::length(want - ref.colour) / glm::length(ref.colour));
            const double cover = std::clamp(std::min(across + 0.5, 0.5 * w_px) - std::max(across - 0.5, -0.5 * w_px), 0.0, 1.0);
            out.worst_weight = std::max(out.worst_weight, std::abs(double(hl[3]) - cover));
            ++out.checked;
        }
    }
    return out;
}

class ShaderReference : public OffscreenGlTest {};

TEST_F(ShaderReference, HighlightColourAndWeightMatchTheDoubleReference) {
    const CubeScene s = cube(640, 480, 0.05f);  // a few pixels wide: many pixels to compare
    ASSERT_EQ(s.scene.edges.size(), 12u);
    const el_tools::Images img = render(s);
    const Agreement got = compare(s, img, s.scene.material.shininess, s.scene.material.radius);
    std::cout << "checked " << got.checked << " pixels on " << offscreen_context().description() << ": worst colour error "
              << got.worst_rel << " (relative), worst weight error " << got.worst_weight << "; faces-under term up to "
              << got.worst_faces_under << " of the band's colour\n";
    EXPECT_GT(got.checked, 100);
    EXPECT_LT(got.worst_rel, kRelativeTolerance);
    EXPECT_LT(got.worst_weight, kWeightTolerance);

    // The comparison can tell: a reference for a 2 % larger radius or exponent is out of
    // tolerance (the colour does not depend on the radius, the weight does not on n).
    const Agreement radius = compare(s, img, s.scene.material.shininess, s.scene.material.radius * 1.02f);
    EXPECT_GT(radius.worst_weight, kWeightTolerance);
    const Agreement shininess = compare(s, img, s.scene.material.shininess * 1.02f, s.scene.material.radius);
    EXPECT_GT(shininess.worst_rel, kRelativeTolerance);
    std::cout << "against a 2 % larger radius: worst weight error " << radius.worst_weight
              << "; a 2 % larger exponent: worst colour error " << shininess.worst_rel << "\n";
}

TEST_F(ShaderReference, ANarrowBandReplacesTheFacesUnderIt) {
    // Under a pixel wide, the band covers part of the pixels the line crosses, centred on the
    // line, while the pixel's faces split by where the line crosses it: the faces-under term.
    const CubeScene s = cube(640, 480, 0.006f);
    const el_tools::Images img = render(s);
    const Agreement got = compare(s, img, s.scene.material.shininess, s.scene.material.radius);
    std::cout << "checked " << got.checked << " pixels: worst colour error " << got.worst_rel << " (relative), worst weight error "
              << got.worst_weight << "; faces-under term up to " << got.worst_faces_under << " of the band's colour\n";
    EXPECT_GT(got.checked, 50);
    EXPECT_GT(got.worst_faces_under, 50.0 * kRelativeTolerance);  // the term is there to be checked
    EXPECT_LT(got.worst_rel, kRelativeTolerance);
    EXPECT_LT(got.worst_weight, kWeightTolerance);
}

TEST_F(ShaderReference, EdgesUnder16PxCarryTheMidpointColour) {
    // Short edges are shaded once, in the vertex shader, by the quad's shading vertex; its flat
    // outputs reach both triangles only under the provoking-vertex convention the quads were
    // ordered for.
    const CubeScene s = cube(48, 36, 0.2f);  // wide enough to cover whole pixels
    const dvec3 a = project(s.camera, kA), b = project(s.camera, kB);
    const glm::dvec2 s0(a), s1(b);
    ASSERT_LT(glm::length(s1 - s0), 16.0) << "the edge is short on screen";
    const el_tools::Images img = render(s);
    const Reference ref = reference(s, 0.5 * (kA + kB), s.scene.material.shininess, s.scene.material.radius);
    const glm::dvec2 d = glm::normalize(s1 - s0), nrm(-d.y, d.x);
    const double side1 = top_side(s, s0, nrm);
    const dvec3 X = 0.5 * (kA + kB);
    const double w_px = s.camera.px_per_unit() * s.scene.material.radius / (glm::length(s.camera.eye - X) * ref.r.r_max);
    int checked = 0;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            const float* hl = &img.highlight[4 * (size_t(y) * img.width + x)];
            const glm::dvec2 pc(x + 0.5, y + 0.5);
            const double u = glm::dot(pc - s0, d) / glm::length(s1 - s0);
            const double across = glm::dot(pc - s0, nrm);
            if (!(hl[3] > 0.5f) || !(u > 0.3 && u < 0.7) || std::abs(across) >= 0.5) continue;
            const dvec3 got = dvec3(hl[0], hl[1], hl[2]) / double(hl[3]);
            const dvec3 err = glm::abs(got - (ref.colour + faces_under(s, X, across, w_px, side1)));
            EXPECT_LT(std::max({err.x, err.y, err.z}) / std::max({ref.colour.x, ref.colour.y, ref.colour.z}),
                      kRelativeTolerance)
                << "pixel " << x << ", " << y;
            ++checked;
        }
    }
    std::cout << "checked " << checked << " pixels of a " << glm::length(s1 - s0) << " px edge\n";
    EXPECT_GT(checked, 2);
}

}  // namespace
