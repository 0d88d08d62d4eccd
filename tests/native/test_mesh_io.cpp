// The tools' mesh reader (native/tools/mesh_io.cpp): equal positions welded across corners that
// carry their own normals and across a file's meshes, and what it must refuse: a face index
// that a loader clamped, a position past EL_MAX_COORDINATE, a PLY header claiming more than the
// caps or the file allow.
#include "mesh_io.hpp"
#include "off_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace {

std::string write_file(const std::string& name, const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() / ("edgelight_mesh_io_" + name);
    std::ofstream(path) << text;
    return path.string();
}

// A unit cube as an OBJ with a normal per face corner and its faces in two materials.
const char* kCubeObj =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 1 0 0\nvn 0 1 0\nvn -1 0 0\n"
    "usemtl a\nf 1//1 4//1 3//1 2//1\nf 5//2 6//2 7//2 8//2\nf 1//3 2//3 6//3 5//3\n"
    "usemtl b\nf 2//4 3//4 7//4 6//4\nf 3//5 4//5 8//5 7//5\nf 4//6 1//6 5//6 8//6\n";

TEST(MeshIo, EqualPositionsAreWeldedAcrossNormalsAndMaterials) {
    const el_tools::LoadedMesh m = el_tools::load_mesh(write_file("cube.obj", kCubeObj));
    EXPECT_EQ(m.positions.size(), 8u * 3u);  // 24 corners with their own normals, two meshes
    EXPECT_EQ(m.triangles.size(), 12u * 3u);
}

TEST(MeshIo, AClampedFaceIndexIsRefused) {
    // assimp's OFF reader clamps the 5 to 2 and says so only in its log.
    const std::string path = write_file("badidx.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n");
    try {
        el_tools::load_mesh(path);
        FAIL() << "read";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("OFF: Vertex index is out of range"), std::string::npos) << e.what();
    }
    // The same file with the index in range is read.
    EXPECT_NO_THROW(el_tools::load_mesh(write_file("goodidx.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")));
}

TEST(MeshIo, APositionPastTheLargestCoordinateIsRefused) {
    const std::string tetra = "f 1 2 3\nf 1 2 4\nf 2 3 4\nf 1 3 4\n";
    try {
        el_tools::load_mesh(write_file("huge.obj", "v 3e38 0 0\nv 0 3e38 0\nv 0 0 3e38\nv -3e38 -3e38 -3e38\n" + tetra));
        FAIL() << "read";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("farther than EL_MAX_COORDINATE"), std::string::npos) << e.what();
    }
    EXPECT_NO_THROW(el_tools::load_mesh(write_file("far.obj", "v 1e14 0 0\nv 0 1e14 0\nv 0 0 1e14\nv 0 0 0\n" + tetra)));
}

// A PLY header's counts are checked before assimp reserves them (it took 2.4 GB and 37 s to
// refuse 200 million vertices in 213 bytes): refused in milliseconds, saying why.
void expect_refused(const std::string& path, const std::string& reason) {
    const auto start = std::chrono::steady_clock::now();
    try {
        el_tools::load_mesh(path);
        ADD_FAILURE() << path << " was read";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    }
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2)) << path;
}

const char* kPlyTriangle =
    "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

TEST(MeshIo, PlyHeaderCountsAreCheckedFirst) {
    const std::string binary_head = "ply\nformat binary_little_endian 1.0\n";
    const std::string ascii_head = "ply\nformat ascii 1.0\n";
    const std::string big =
        "element vertex 200000000\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    expect_refused(write_file("big.ply", binary_head + big + std::string(40, '\0')), "more than the limit");
    expect_refused(write_file("big_ascii.ply", ascii_head + big + "0 0 0\n"), "more than the limit");
    // Within the caps, but more than the body holds: 1000 vertices of 12 bytes in 40 bytes.
    const std::string lying =
        "element vertex 1000\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    expect_refused(write_file("lying.ply", binary_head + lying + std::string(40, '\0')), "bytes after its header");
    expect_refused(write_file("lying_ascii.ply", ascii_head + lying + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
                   "bytes after its header");
    // The same triangle, honest, is read in both encodings.
    EXPECT_NO_THROW(el_tools::load_mesh(write_file("tri_ascii.ply", ascii_head + kPlyTriangle + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")));
    std::string body(3 * 12 + 1 + 12, '\0');
    const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const int32_t idx[3] = {0, 1, 2};
    std::memcpy(body.data(), xyz, sizeof xyz);
    body[36] = 3;
    std::memcpy(body.data() + 37, idx, sizeof idx);
    const auto m = el_tools::load_mesh(write_file("tri.ply", binary_head + kPlyTriangle + body));
    EXPECT_EQ(m.triangles.size(), 3u);
}

// The library's tests read the CGAL meshes with the assimp-free OFF reader (off_mesh.cpp): it
// gives the tools' mesh, as many welded positions and the same triangles. assimp parses numbers
// with its own fast_atof, a last bit off the correctly rounded value here and there (cow: from
// the 3887th triangle on), so triangles are compared by their corners rounded to 1e-5.
TEST(MeshIo, TheOffReaderReadsWhatTheToolsRead) {
    for (const char* name : {"cube", "cow", "fandisk", "joint"}) {
        const std::string path = std::string(EDGELIGHT_TEST_MESH_DIR) + "/" + name + ".off";
        const auto a = el_tools::load_mesh(path), b = el_tools::read_off(path);
        ASSERT_EQ(a.positions.size(), b.positions.size()) << name;
        ASSERT_EQ(a.triangles.size(), b.triangles.size()) << name;
        const auto corners = [](const el_tools::LoadedMesh& m) {
            std::vector<std::array<long long, 9>> t(m.triangles.size() / 3);
            for (size_t i = 0; i < t.size(); ++i) {
                std::array<std::array<long long, 3>, 3> c;
                for (int k = 0; k < 3; ++k)
                    for (int j = 0; j < 3; ++j) c[k][j] = std::llround(1e5 * m.positions[3 * m.triangles[3 * i + k] + j]);
                std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());  // same winding, any start
                for (int k = 0; k < 3; ++k) std::copy(c[k].begin(), c[k].end(), t[i].begin() + 3 * k);
            }
            std::sort(t.begin(), t.end());
            return t;
        };
        const auto ca = corners(a), cb = corners(b);
        const auto first = std::mismatch(ca.begin(), ca.end(), cb.begin()).first - ca.begin();
        EXPECT_EQ(size_t(first), ca.size()) << name << ": triangles differ from the " << first << "th on";
    }
    EXPECT_THROW(el_tools::read_off(write_file("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n")), std::runtime_error);
}

}  // namespace
