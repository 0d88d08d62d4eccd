// Meshes the benchmarks run on: libcgal-demo's classics and a generated 1M-triangle torus.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace el_bench {

struct BenchMesh {
    std::string name;
    std::vector<float> positions;
    std::vector<uint32_t> triangles;
    uint32_t triangle_count() const { return uint32_t(triangles.size() / 3); }
};

// Index i of bench_mesh_names(); loaded once and cached. Aborts the benchmark run with a message
// if a file is missing (set EDGELIGHT_MESH_DIR).
const BenchMesh& bench_mesh(int index);
const std::vector<std::string>& bench_mesh_names();

}  // namespace el_bench
