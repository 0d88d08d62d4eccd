// What the edge pass does to run its fragment shader on fewer pixels (shaders/
// edge_highlight.vert.glsl) must not change what it draws:
// - the early depth test: its quads are depth-tested against the surface pass so that hidden
//   pixels never run the fragment shader, with their depth pulled toward the eye past that
//   shader's own visibility bias. It must reject nothing the shader keeps: the highlight buffer
//   is the same with the test on and off, on real meshes that hide edges behind themselves. And
//   since the quads' depth is no longer the edge's, the near plane must still clip the edge line
//   itself (the fragment shader does it now);
// - the quads fitted to the side of the line where the band lies leave out nothing;
// - the benchmarks' shading-free variant of the pass draws the same quads and shows nothing.
#include "mesh_batches.hpp"
#include "mesh_io.hpp"
#include "offscreen_gl.hpp"
#include "render_passes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

namespace {

using glm::dvec3;

class EdgeCulling : public OffscreenGlTest {};

struct Framed {
    el_tools::Scene scene;
    dvec3 centre{0.0};
    double diag = 0.0;
};

Framed load(const std::string& name, double radius_of_diag) {
    const auto mesh = el_tools::load_mesh(std::string(EDGELIGHT_TEST_MESH_DIR) + "/" + name + ".off");
    Framed f;
    f.scene.surface = el_tools::surface_corners(mesh, 30.0f);
    f.scene.edges = el_tools::choose_edges(mesh, 30.0f);
    const el_tools::Box box = el_tools::bounding_box(mesh.positions);
    f.centre = box.centre();
    f.diag = box.diagonal();
    f.scene.material.radius = float(radius_of_diag * f.diag);
    f.scene.suns.push_back({glm::normalize(dvec3(-0.4, -0.7, 0.6)), dvec3(3.0)});
    return f;
}

el_tools::Camera camera(const Framed& f, const dvec3& from, double distance_of_diag) {
    el_tools::Camera c;
    c.target = f.centre;
    c.eye = f.centre + distance_of_diag * f.diag * glm::normalize(from);
    c.width = 480;
    c.height = 360;
    const double dist = glm::length(c.eye - f.centre);
    c.clip_end = dist + f.diag;
    c.clip_start = std::max(c.clip_end * 1e-4, dist - f.diag);
    return c;
}

el_tools::Images render(el_tools::Scene scene, const el_tools::Camera& cam, bool depth_test, bool tight_quads = true) {
    scene.edge_depth_test = depth_test;
    scene.tight_edge_quads = tight_quads;
    el_tools::Renderer renderer(EDGELIGHT_SHADER_DIR);
    return renderer.render(scene, cam, 1);
}

struct Case {
    const char* mesh;
    double radius;    // of the bounding-box diagonal: sub-pixel and several-pixel bands
    dvec3 from;       // camera direction from the centre
    double distance;  // of the diagonal
};
const Case kCases[] = {
    {"fandisk", 0.002, {1.0, -0.85, 0.7}, 1.6}, {"fandisk", 0.02, {-0.3, 1.0, 0.2}, 1.2},
    {"fandisk", 0.01, {0.05, 0.1, 1.0}, 0.9},   {"fandisk", 0.05, {0.7, 0.6, -0.4}, 0.7},
    {"cow", 0.003, {1.0, -0.85, 0.7}, 1.5},     {"cow", 0.02, {-1.0, 0.1, -0.05}, 1.0},
    {"cube", 0.05, {5.2, -4.4, 3.6}, 2.0},      {"cube", 0.2, {0.3, -4.4, 0.2}, 1.0},
};

// Two ways of drawing on every case: a view that shows edges, and the same highlight buffer but
// for at most `flips` pixels (any difference) and rounding (1e-4) elsewhere.
template <class Render>
void expect_same(const char* what, int flips, Render render_both) {
    for (const Case& c : kCases) {
        const Framed f = load(c.mesh, c.radius);
        const el_tools::Camera cam = camera(f, c.from, c.distance);
        const auto [on, off] = render_both(f.scene, cam);
        ASSERT_EQ(on.highlight.size(), off.highlight.size());
        int lit = 0, differ = 0;
        double worst = 0.0, worst_rounding = 0.0;
        for (size_t i = 0; i < on.highlight.size(); i += 4) {
            double d = 0.0;
            for (int k = 0; k < 4; ++k) d = std::max(d, double(std::abs(on.highlight[i + k] - off.highlight[i + k])));
            worst = std::max(worst, d);
            if (d > 1e-4) ++differ;
            else worst_rounding = std::max(worst_rounding, d);
            lit += off.highlight[i + 3] > 1e-3f;
        }
        std::cout << what << ", " << c.mesh << " radius " << c.radius << ": " << lit << " highlight pixels, " << differ
                  << " differ by more than 1e-4 (worst " << worst << ")\n";
        EXPECT_GT(lit, 300) << c.mesh << ": the view shows rounded edges";
        EXPECT_LE(differ, flips) << what << ", " << c.mesh << ", radius " << c.radius << ": worst difference " << worst;
    }
}

TEST_F(EdgeCulling, RejectsNothingTheShaderKeeps) {
    expect_same("depth test on / off", 0, [](const el_tools::Scene& s, const el_tools::Camera& cam) {
        return std::pair{render(s, cam, true), render(s, cam, false)};
    });
}

// The quads fitted to where the band lies (edge_highlight.vert) leave out no pixel that the
// quads symmetric about the line light. Both are parallelograms with the same edge_point along
// each pixel's perpendicular, but interpolated over other triangles its last bits differ, and a
// few pixels right at a threshold of the shader's visibility or coverage tests flip (0-8 here;
// a fit without its margin leaves out 50-6000 per view).
TEST_F(EdgeCulling, FittedQuadsLeaveOutNothing) {
    expect_same("fitted / symmetric quads", 16, [](const el_tools::Scene& s, const el_tools::Camera& cam) {
        return std::pair{render(s, cam, true, true), render(s, cam, true, false)};
    });
}

TEST_F(EdgeCulling, TheNearPlaneStillClipsTheEdgeLine) {
    // The unit cube's corner nearest the eye cut off by the near plane: its three edges must show
    // no highlight in front of the plane and show it behind (the back faces seen through the cut
    // are farther than the edges, so only the clipping can hide those parts).
    Framed f = load("cube", 0.03);
    const dvec3 corner(1.0, -1.0, 1.0);
    el_tools::Camera cam = camera(f, {5.2, -4.4, 3.6}, 1.6);
    const dvec3 ahead = cam.view_dir();
    const double corner_depth = glm::dot(corner - cam.eye, ahead);
    cam.clip_start = corner_depth + 0.4;
    const el_tools::Images img = render(f.scene, cam, true);
    const dvec3 others[] = {{-1.0, -1.0, 1.0}, {1.0, 1.0, 1.0}, {1.0, -1.0, -1.0}};
    int clipped = 0, kept = 0;
    for (const dvec3& other : others) {
        for (double t = 0.02; t < 0.8; t += 0.01) {
            const dvec3 X = corner + t * (other - corner);
            const double depth = glm::dot(X - cam.eye, ahead);
            if (std::abs(depth - cam.clip_start) < 0.1) continue;  // the pixels the plane crosses
            const glm::dvec4 clip = cam.projection() * cam.view() * glm::dvec4(X, 1.0);
            const int x = int(std::floor((clip.x / clip.w * 0.5 + 0.5) * cam.width));
            const int y = int(std::floor((clip.y / clip.w * 0.5 + 0.5) * cam.height));
            ASSERT_TRUE(x >= 0 && x < cam.width && y >= 0 && y < cam.height);
            const float W = img.highlight[4 * (size_t(y) * cam.width + x) + 3];
            if (depth < cam.clip_start) {
                EXPECT_EQ(W, 0.0f) << "in front of the near plane, t = " << t;
                ++clipped;
            } else {
                EXPECT_GT(W, 0.05f) << "behind the near plane, t = " << t;
                ++kept;
            }
        }
    }
    std::cout << clipped << " edge points in front of the near plane, " << kept << " behind\n";
    EXPECT_GT(clipped, 20);
    EXPECT_GT(kept, 20);
}

// The benchmarks' floor variant (EL_EDGE_FLOOR, Scene::edge_floor: the same quads with a fragment
// shader that does next to nothing) builds, draws the same quads, and shows nothing: the
// benchmark's "quads alone" column is the pass's cost with the shading left out, not a broken
// program's. Its writes (1e-20 of its inputs, never 0) must land on every pixel the real pass
// lights: the floor skips the visibility test, so it covers those and more.
TEST_F(EdgeCulling, FloorVariantDrawsTheQuadsAndShowsNothing) {
    const Framed f = load("fandisk", 0.01);
    const el_tools::Camera cam = camera(f, {1.0, -0.85, 0.7}, 1.6);
    el_tools::Scene floor = f.scene;
    floor.edge_floor = true;
    el_tools::Renderer renderer(EDGELIGHT_SHADER_DIR);
    const el_tools::Images real = renderer.render(f.scene, cam, 1), quads = renderer.render(floor, cam, 1);
    int lit = 0, lit_written = 0;
    float brightest = 0.0f;
    for (size_t i = 0; i < quads.highlight.size(); i += 4) {
        for (int k = 0; k < 4; ++k) brightest = std::max(brightest, std::abs(quads.highlight[i + k]));
        if (real.highlight[i + 3] > 1e-3f) {
            ++lit;
            lit_written += quads.highlight[i + 3] != 0.0f;
        }
    }
    EXPECT_GT(lit, 300);
    EXPECT_LT(brightest, 1e-12f) << "the floor variant must not show";
    EXPECT_EQ(lit_written, lit) << "the floor variant must draw the same quads";
}

}  // namespace
