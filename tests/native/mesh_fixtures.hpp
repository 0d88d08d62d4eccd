// Small meshes with known answers, shared by the native tests.
#pragma once

#include <edgelight/edgelight.h>

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace fixtures {

struct TestMesh {
    std::vector<float> positions;    // xyz
    std::vector<uint32_t> triangles; // 3 per triangle

    uint32_t vertex_count() const { return uint32_t(positions.size() / 3); }
    uint32_t triangle_count() const { return uint32_t(triangles.size() / 3); }
    uint32_t add_vertex(float x, float y, float z);
    void add_triangle(uint32_t a, uint32_t b, uint32_t c);
    void add_quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d);  // a-b-c, a-c-d
    el_mesh_desc desc() const;
};

TestMesh cube();                          // [0,1]^3, 12 outward triangles
TestMesh open_box();                      // cube without its top (z = 1) face
TestMesh tetrahedron();
TestMesh icosphere(int subdivisions);     // unit radius
TestMesh uv_sphere(int segments, int rings);  // unit radius, poles on z, rings even -> equator ring
TestMesh hinge(float opening_deg);        // two triangles sharing the edge x=0..1, y=z=0
TestMesh fin();                           // three triangles sharing one edge
TestMesh open_cylinder(int segments);     // radius 1, z in [0, 1], no caps
TestMesh grid(uint32_t n);                // n x n quads in the xy plane, wavy z

struct MeshDeleter { void operator()(el_mesh* m) const { el_mesh_destroy(m); } };
struct ViewDeleter { void operator()(el_view* v) const { el_view_destroy(v); } };
using MeshPtr = std::unique_ptr<el_mesh, MeshDeleter>;
using ViewPtr = std::unique_ptr<el_view, ViewDeleter>;

// Creates the mesh through the C API; fails the current test on error.
MeshPtr create(const el_mesh_desc& desc);
el_mesh_info info(const el_mesh* mesh);
std::vector<uint32_t> edge_flags(const el_mesh* mesh);
std::vector<uint32_t> edges(const el_mesh* mesh);

// An undirected edge key by value (std::minmax returns references).
inline std::pair<uint32_t, uint32_t> ordered(uint32_t a, uint32_t b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); }

el_camera perspective(float ex, float ey, float ez);
el_camera orthographic(float dx, float dy, float dz);

}  // namespace fixtures
