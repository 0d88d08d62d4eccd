// Frames of the add-on's passes, drawn by edgelight-render's renderer (OSMesa, llvmpipe: the
// rasteriser Blender uses here): surface only against surface + edge highlights, on the viewport
// benchmark's dense scenes at its 3D view size, without Blender's own redraw cost and its noise.
// Geometry is uploaded once, as the add-on caches its batches; each frame is one sample, waited
// for (glFinish). Real time, and the CPU time of all threads (llvmpipe rasterises on its own):
// the steadier of the two on a shared machine.
//
//   build/native/bench/edgelight_pass_bench --benchmark_repetitions=5 \
//       --benchmark_enable_random_interleaving=true
#include "mesh_batches.hpp"
#include "mesh_io.hpp"
#include "osmesa_context.hpp"
#include "render_passes.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

namespace {

using glm::dvec3;

constexpr int kWidth = 1156, kHeight = 852;  // bench/viewport_bench.py's 3D view

struct BenchScene {
    // surface only; + highlights as the add-on draws them; without the edge pass's early depth
    // test; with quads symmetric about the edge line instead of fitted to the band; with a
    // fragment shader that does next to nothing (the pass's cost before any shading).
    el_tools::Scene surface_only, with_edges, no_depth_test, symmetric_quads, floor;
    el_tools::Camera camera;
};

// `count` unit cubes on a grid with spacing 2 (bench/viewport_bench.py's cube_grid).
el_tools::LoadedMesh cube_grid(int count) {
    const int side = int(std::ceil(std::cbrt(double(count)) - 1e-9));
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    el_tools::LoadedMesh m;
    for (int i = 0; i < count; ++i) {
        const dvec3 c(2.0 * (i % side), 2.0 * ((i / side) % side), 2.0 * (i / (side * side)));
        const uint32_t base = uint32_t(m.positions.size() / 3);
        for (int k = 0; k < 8; ++k) {
            m.positions.push_back(float(c.x + ((k & 1) ? 0.5 : -0.5)));
            m.positions.push_back(float(c.y + ((k & 2) ? 0.5 : -0.5)));
            m.positions.push_back(float(c.z + ((k & 4) ? 0.5 : -0.5)));
        }
        for (const auto& q : quads) {
            for (int t : {0, 1, 2, 0, 2, 3}) m.triangles.push_back(base + uint32_t(q[t]));
        }
    }
    return m;
}

// The mesh repeated on a side^3 grid with spacing step (the viewport benchmark's fandisk array).
el_tools::LoadedMesh repeated(const el_tools::LoadedMesh& one, int side, double step) {
    el_tools::LoadedMesh m;
    const uint32_t n = uint32_t(one.positions.size() / 3);
    for (int k = 0; k < side * side * side; ++k) {
        const dvec3 off = step * (dvec3(k % side, (k / side) % side, k / (side * side)) - 0.5 * (side - 1));
        for (size_t i = 0; i < one.positions.size(); ++i) m.positions.push_back(float(one.positions[i] + off[int(i % 3)]));
        for (uint32_t t : one.triangles) m.triangles.push_back(t + uint32_t(k) * n);
    }
    return m;
}

// Blender's roughness -> Blinn exponent (addon/extract/materials.py).
float shininess(double roughness) { return float(2.0 / std::pow(roughness, 4.0) - 2.0); }

// distance: of the grid's size, along the benchmark's view direction.
BenchScene make(const el_tools::LoadedMesh& mesh, float radius, double roughness, double size, double distance) {
    BenchScene s;
    s.with_edges.surface = el_tools::surface_corners(mesh, 30.0f);
    s.with_edges.edges = el_tools::choose_edges(mesh, 30.0f);
    s.with_edges.material.radius = radius;
    s.with_edges.material.shininess = shininess(roughness);
    s.with_edges.suns.push_back({glm::normalize(dvec3(-0.4, -0.7, 0.6)), dvec3(3.0)});
    s.surface_only = s.no_depth_test = s.symmetric_quads = s.floor = s.with_edges;
    s.floor.edge_floor = true;
    s.surface_only.edges = {};
    s.no_depth_test.edge_depth_test = false;
    s.symmetric_quads.tight_edge_quads = false;
    const el_tools::Box box = el_tools::bounding_box(mesh.positions);
    s.camera.target = box.centre();
    s.camera.eye = s.camera.target + distance * size * glm::normalize(dvec3(1.0, -0.85, 0.7));
    s.camera.width = kWidth;
    s.camera.height = kHeight;
    const double dist = glm::length(s.camera.eye - s.camera.target), diag = box.diagonal();
    s.camera.clip_end = dist + diag;
    s.camera.clip_start = std::max(0.01, dist - diag);
    return s;
}

el_tools::OsmesaContext& context() {
    static el_tools::OsmesaContext ctx;
    return ctx;
}

el_tools::Renderer& renderer() {
    context();
    static el_tools::Renderer r(EDGELIGHT_SHADER_DIR);
    return r;
}

void frames(benchmark::State& state, const el_tools::Scene* scene, const el_tools::Camera* camera) {
    auto up = renderer().upload(*scene);
    renderer().draw(*up, *camera, 1);  // warm up: shader variants, targets
    for (auto _ : state) renderer().draw(*up, *camera, 1);
    state.counters["edges"] = double(scene->edges.size());
    state.counters["triangles"] = double(scene->surface.pos.size() / 9);
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    static std::vector<std::pair<std::string, BenchScene>> scenes;
    const int cubes = 100000 / 12;
    const double grid_size = 2.0 * std::ceil(std::cbrt(double(cubes)) - 1e-9);  // as cube_grid lays them out
    scenes.emplace_back("cube_grid_100k", make(cube_grid(cubes), 0.02f, 0.3, grid_size, 2.2));
    const std::string dir = EDGELIGHT_DEFAULT_MESH_DIR;
    const el_tools::LoadedMesh fandisk = el_tools::load_mesh(dir + "/fandisk.off");
    const el_tools::Box box = el_tools::bounding_box(fandisk.positions);
    const dvec3 extent = box.hi - box.lo;
    const double step = 1.3 * std::max({extent.x, extent.y, extent.z});
    scenes.emplace_back("fandisk_array_100k", make(repeated(fandisk, 2, step), 0.004f, 0.25, 2.0 * step, 1.6));
    scenes.emplace_back("fandisk_array_830k", make(repeated(fandisk, 4, step), 0.004f, 0.25, 4.0 * step, 1.6));
    scenes.emplace_back("fandisk", make(fandisk, 0.004f, 0.25, step / 1.3, 2.5));
    for (const auto& [name, s] : scenes) {
        for (const auto& [variant, scene] : {std::pair{"surface", &s.surface_only},
                                             {"surface+highlights", &s.with_edges},
                                             {"no_early_depth_test", &s.no_depth_test},
                                             {"symmetric_quads", &s.symmetric_quads},
                                             {"floor", &s.floor}}) {
            benchmark::RegisterBenchmark((name + "/" + variant).c_str(), frames, scene, &s.camera)
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime()
                ->MeasureProcessCPUTime();
        }
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
