#include "mesh_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

namespace fixtures {

uint32_t TestMesh::add_vertex(float x, float y, float z) {
    positions.insert(positions.end(), {x, y, z});
    return vertex_count() - 1;
}

void TestMesh::add_triangle(uint32_t a, uint32_t b, uint32_t c) { triangles.insert(triangles.end(), {a, b, c}); }

void TestMesh::add_quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    add_triangle(a, b, c);
    add_triangle(a, c, d);
}

el_mesh_desc TestMesh::desc() const {
    el_mesh_desc d{};
    d.positions = positions.data();
    d.vertex_count = vertex_count();
    d.triangles = triangles.data();
    d.triangle_count = triangle_count();
    return d;
}

TestMesh cube() {
    TestMesh m;
    for (int i = 0; i < 8; ++i) m.add_vertex(float(i & 1), float((i >> 1) & 1), float((i >> 2) & 1));
    // Vertex i = (x, y, z) bits; quads counter-clockwise seen from outside.
    m.add_quad(0, 2, 3, 1);  // z = 0
    m.add_quad(4, 5, 7, 6);  // z = 1
    m.add_quad(0, 1, 5, 4);  // y = 0
    m.add_quad(2, 6, 7, 3);  // y = 1
    m.add_quad(0, 4, 6, 2);  // x = 0
    m.add_quad(1, 3, 7, 5);  // x = 1
    return m;
}

TestMesh open_box() {
    TestMesh m = cube();
    m.triangles.erase(m.triangles.begin() + 6, m.triangles.begin() + 12);  // drop z = 1
    return m;
}

TestMesh tetrahedron() {
    TestMesh m;
    m.add_vertex(1, 1, 1);
    m.add_vertex(1, -1, -1);
    m.add_vertex(-1, 1, -1);
    m.add_vertex(-1, -1, 1);
    m.add_triangle(0, 1, 2);
    m.add_triangle(0, 3, 1);
    m.add_triangle(0, 2, 3);
    m.add_triangle(1, 3, 2);
    return m;
}

TestMesh icosphere(int subdivisions) {
    TestMesh m;
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    const float v[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                            {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    auto push = [&](float x, float y, float z) {
        const float l = std::sqrt(x * x + y * y + z * z);
        return m.add_vertex(x / l, y / l, z / l);
    };
    for (auto& p : v) push(p[0], p[1], p[2]);
    std::vector<uint32_t> f = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2,
                               10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5,
                               2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            const float* pa = &m.positions[3 * a];
            const float* pb = &m.positions[3 * b];
            const uint32_t i = push(pa[0] + pb[0], pa[1] + pb[1], pa[2] + pb[2]);
            mid[key] = i;
            return i;
        };
        std::vector<uint32_t> next;
        for (size_t i = 0; i < f.size(); i += 3) {
            const uint32_t a = f[i], b = f[i + 1], c = f[i + 2];
            const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        f.swap(next);
    }
    m.triangles = f;
    return m;
}

TestMesh uv_sphere(int segments, int rings) {
    TestMesh m;
    const float pi = 3.14159265358979f;
    const uint32_t north = m.add_vertex(0, 0, 1);
    for (int r = 1; r < rings; ++r) {
        const float theta = pi * float(r) / float(rings);
        for (int s = 0; s < segments; ++s) {
            const float phi = 2.0f * pi * float(s) / float(segments);
            m.add_vertex(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
        }
    }
    const uint32_t south = m.add_vertex(0, 0, -1);
    auto ring = [&](int r, int s) { return uint32_t(1 + (r - 1) * segments + (s % segments)); };
    for (int s = 0; s < segments; ++s) m.add_triangle(north, ring(1, s), ring(1, s + 1));
    for (int r = 1; r < rings - 1; ++r)
        for (int s = 0; s < segments; ++s) m.add_quad(ring(r, s), ring(r + 1, s), ring(r + 1, s + 1), ring(r, s + 1));
    for (int s = 0; s < segments; ++s) m.add_triangle(south, ring(rings - 1, s + 1), ring(rings - 1, s));
    return m;
}

TestMesh hinge(float opening_deg) {
    // Face A in the xy plane (y >= 0), face B rotated about the x axis so the angle between the
    // two faces' planes is opening_deg (180 = flat).
    TestMesh m;
    const float a = opening_deg * 3.14159265358979f / 180.0f;
    m.add_vertex(0, 0, 0);
    m.add_vertex(1, 0, 0);
    m.add_vertex(0.5f, 1, 0);
    m.add_vertex(0.5f, std::cos(a), std::sin(a));
    m.add_triangle(0, 1, 2);  // normal +z
    m.add_triangle(1, 0, 3);
    return m;
}

TestMesh fin() {
    TestMesh m;
    m.add_vertex(0, 0, 0);
    m.add_vertex(1, 0, 0);
    m.add_vertex(0.5f, 1, 0);
    m.add_vertex(0.5f, -1, 0);
    m.add_vertex(0.5f, 0, 1);
    m.add_triangle(0, 1, 2);
    m.add_triangle(1, 0, 3);
    m.add_triangle(0, 1, 4);
    return m;
}

TestMesh open_cylinder(int segments) {
    TestMesh m;
    const float pi = 3.14159265358979f;
    for (int s = 0; s < segments; ++s) {
        const float phi = 2.0f * pi * float(s) / float(segments);
        m.add_vertex(std::cos(phi), std::sin(phi), 0);
        m.add_vertex(std::cos(phi), std::sin(phi), 1);
    }
    for (int s = 0; s < segments; ++s) {
        const uint32_t a = 2 * s, b = 2 * ((s + 1) % segments);
        m.add_quad(a, b, b + 1, a + 1);
    }
    return m;
}

TestMesh grid(uint32_t n) {
    TestMesh m;
    for (uint32_t j = 0; j <= n; ++j)
        for (uint32_t i = 0; i <= n; ++i)
            m.add_vertex(float(i), float(j), 0.3f * std::sin(0.7f * float(i)) * std::cos(0.5f * float(j)));
    for (uint32_t j = 0; j < n; ++j)
        for (uint32_t i = 0; i < n; ++i) {
            const uint32_t a = j * (n + 1) + i;
            m.add_quad(a, a + 1, a + n + 2, a + n + 1);
        }
    return m;
}

MeshPtr create(const el_mesh_desc& desc) {
    el_mesh* m = nullptr;
    const el_status s = el_mesh_create(&desc, &m);
    EXPECT_EQ(s, EL_OK) << el_last_error();
    return MeshPtr(m);
}

el_mesh_info info(const el_mesh* mesh) {
    el_mesh_info i{};
    EXPECT_EQ(el_mesh_get_info(mesh, &i), EL_OK) << el_last_error();
    return i;
}

std::vector<uint32_t> edge_flags(const el_mesh* mesh) {
    std::vector<uint32_t> f(info(mesh).edge_count);
    EXPECT_EQ(el_mesh_get_edge_flags(mesh, f.data(), uint32_t(f.size())), EL_OK) << el_last_error();
    return f;
}

std::vector<uint32_t> edges(const el_mesh* mesh) {
    std::vector<uint32_t> e(2 * size_t(info(mesh).edge_count));
    EXPECT_EQ(el_mesh_get_edges(mesh, e.data(), uint32_t(e.size() / 2)), EL_OK) << el_last_error();
    return e;
}

static void identity(float* m) {
    for (int i = 0; i < 16; ++i) m[i] = (i % 5 == 0) ? 1.0f : 0.0f;
}

el_camera perspective(float ex, float ey, float ez) {
    el_camera c{};
    c.projection = EL_PERSPECTIVE;
    c.eye[0] = ex;
    c.eye[1] = ey;
    c.eye[2] = ez;
    identity(c.object_to_world);
    return c;
}

el_camera orthographic(float dx, float dy, float dz) {
    el_camera c{};
    c.projection = EL_ORTHOGRAPHIC;
    c.view_dir[0] = dx;
    c.view_dir[1] = dy;
    c.view_dir[2] = dz;
    identity(c.object_to_world);
    return c;
}

}  // namespace fixtures
