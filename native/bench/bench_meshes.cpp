#include "bench_meshes.hpp"

#include "mesh_io.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>

namespace el_bench {

namespace {

// Closed torus, 1000 x 500 quads = 1,000,000 triangles, vertices in grid order like most files.
BenchMesh torus() {
    BenchMesh m;
    m.name = "torus_1M";
    const int nu = 1000, nv = 500;
    const float pi = 3.14159265358979f;
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            const float u = 2 * pi * float(i) / float(nu), v = 2 * pi * float(j) / float(nv);
            m.positions.insert(m.positions.end(), {(2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v)});
        }
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            const uint32_t a = uint32_t(j * nu + i), b = uint32_t(j * nu + (i + 1) % nu);
            const uint32_t c = uint32_t(((j + 1) % nv) * nu + (i + 1) % nu), d = uint32_t(((j + 1) % nv) * nu + i);
            m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
        }
    return m;
}

}  // namespace

const std::vector<std::string>& bench_mesh_names() {
    static const std::vector<std::string> names = {"cow", "fandisk", "bunny00", "armadillo", "torus_1M"};
    return names;
}

const BenchMesh& bench_mesh(int index) {
    static std::map<int, std::unique_ptr<BenchMesh>> cache;
    auto& slot = cache[index];
    if (slot) return *slot;
    const std::string& name = bench_mesh_names().at(size_t(index));
    if (name == "torus_1M") {
        slot = std::make_unique<BenchMesh>(torus());
        return *slot;
    }
    const char* dir = std::getenv("EDGELIGHT_MESH_DIR");
    const std::string path = std::string(dir ? dir : EDGELIGHT_DEFAULT_MESH_DIR) + "/" + name + ".off";
    try {
        el_tools::LoadedMesh l = el_tools::load_mesh(path);
        slot = std::make_unique<BenchMesh>(BenchMesh{name, std::move(l.positions), std::move(l.triangles)});
    } catch (const std::exception& e) {
        std::fprintf(stderr, "edgelight_bench: %s (set EDGELIGHT_MESH_DIR)\n", e.what());
        std::exit(2);
    }
    return *slot;
}

}  // namespace el_bench
