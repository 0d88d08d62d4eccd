// Topology, static classification, silhouettes (cold and cached) and contours per mesh.
// Counters: ns per triangle or per edge (the "per_*" rates are inverted to time per item).
#include "bench_meshes.hpp"

#include "chains.hpp"
#include "classify.hpp"
#include "contour.hpp"
#include "mesh_build.hpp"
#include "orient.hpp"
#include "silhouette.hpp"
#include "topology.hpp"
#include "view_cache.hpp"

#include <edgelight/edgelight.h>

#include <benchmark/benchmark.h>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>

namespace {

using el_bench::bench_mesh;

el_mesh_desc desc_of(const el_bench::BenchMesh& m) {
    el_mesh_desc d{};
    d.positions = m.positions.data();
    d.vertex_count = uint32_t(m.positions.size() / 3);
    d.triangles = m.triangles.data();
    d.triangle_count = m.triangle_count();
    return d;
}

void per_item(benchmark::State& state, const char* name, double items) {
    state.counters[name] = benchmark::Counter(items, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    state.SetLabel(bench_mesh(int(state.range(0))).name);
}

// Views orbiting the mesh's bounding box in 1-degree steps, made before timing.
std::vector<el::ViewPoint> orbit(const el::MeshData& m) {
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : m.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::vec3 c = 0.5f * (lo + hi);
    const float r = 2.5f * glm::length(hi - lo);
    std::vector<el::ViewPoint> views(360);
    for (int k = 0; k < 360; ++k) {
        const float a = 2.0f * 3.14159265f * float(k) / 360.0f;
        views[k].eye = c + glm::vec3(r * std::cos(a), r * std::sin(a), 0.4f * r);
    }
    return views;
}

void BM_Topology(benchmark::State& state) {
    const auto& m = bench_mesh(int(state.range(0)));
    const uint32_t vn = uint32_t(m.positions.size() / 3);
    for (auto _ : state) {
        el::Topology t = el::build_topology(m.triangles.data(), m.triangle_count(), vn);
        benchmark::DoNotOptimize(t.edge_faces.data());
    }
    per_item(state, "ns_per_triangle", m.triangle_count());
}

void BM_MeshCreate(benchmark::State& state) {  // whole el_mesh_create: validate, topology, normals, classify
    const auto& m = bench_mesh(int(state.range(0)));
    const el_mesh_desc d = desc_of(m);
    for (auto _ : state) {
        el_mesh* mesh = nullptr;
        if (el_mesh_create(&d, &mesh) != EL_OK) state.SkipWithError(el_last_error());
        el_mesh_destroy(mesh);
    }
    per_item(state, "ns_per_triangle", m.triangle_count());
}

void BM_Classify(benchmark::State& state) {
    const auto& m = bench_mesh(int(state.range(0)));
    auto data = el::build_mesh(desc_of(m));
    el::Classification cls;
    for (auto _ : state) {
        el::analyze_edges(*data, cls);
        el::apply_crease_threshold(cls, 30.0f);
        benchmark::DoNotOptimize(cls.edge_flags.data());
    }
    per_item(state, "ns_per_edge", data->edge_count());
}

void BM_Orient(benchmark::State& state) {  // the component walk of el_mesh_create
    const auto& m = bench_mesh(int(state.range(0)));
    auto data = el::build_mesh(desc_of(m));
    for (auto _ : state) {
        el::Orientation o = el::find_orientation(*data);
        benchmark::DoNotOptimize(o.flips.data());
    }
    per_item(state, "ns_per_triangle", data->triangle_count());
}

void BM_CreaseThreshold(benchmark::State& state) {  // el_mesh_classify: a new threshold only
    const auto& m = bench_mesh(int(state.range(0)));
    auto data = el::build_mesh(desc_of(m));
    float deg = 30.0f;
    for (auto _ : state) {
        el::apply_crease_threshold(data->cls, deg);
        deg = deg == 30.0f ? 31.0f : 30.0f;
        benchmark::DoNotOptimize(data->cls.edge_flags.data());
    }
    per_item(state, "ns_per_edge", data->edge_count());
}

void BM_SilhouetteCold(benchmark::State& state) {  // every frame a new view: facing + edge pass
    const auto& m = bench_mesh(int(state.range(0)));
    auto data = el::build_mesh(desc_of(m));
    std::vector<uint8_t> bits;
    std::vector<uint32_t> out;
    const auto views = orbit(*data);
    size_t k = 0;
    for (auto _ : state) {
        el::compute_facing(*data, views[k++ % views.size()], bits);
        el::collect_silhouettes(*data, bits, out);
        benchmark::DoNotOptimize(out.data());
    }
    per_item(state, "ns_per_edge", data->edge_count());
}

void BM_SilhouetteOrbit(benchmark::State& state) {  // el_view_update with a 1-degree orbit step
    const auto& m = bench_mesh(int(state.range(0)));
    auto data = el::build_mesh(desc_of(m));
    el::ViewCache cache;
    cache.mesh = data;
    const auto views = orbit(*data);
    size_t k = 0;
    for (auto _ : state) benchmark::DoNotOptimize(cache.update(views[k++ % views.size()], EL_VIEW_SILHOUETTES));
    per_item(state, "ns_per_edge", data->edge_count());
}

void BM_SilhouetteCached(benchmark::State& state) {  // the same view again: a comparison
    const auto& m = bench_mesh(int(state.range(0)));
    auto data = el::build_mesh(desc_of(m));
    el::ViewCache cache;
    cache.mesh = data;
    const el::ViewPoint v = orbit(*data)[0];
    cache.update(v, EL_VIEW_SILHOUETTES);
    for (auto _ : state) benchmark::DoNotOptimize(cache.update(v, EL_VIEW_SILHOUETTES));
    per_item(state, "ns_per_edge", data->edge_count());
}

void BM_Contours(benchmark::State& state) {
    const auto& m = bench_mesh(int(state.range(0)));
    auto data = el::build_mesh(desc_of(m));
    std::vector<float> pts;
    std::vector<uint32_t> tris;
    std::vector<uint64_t> keys;
    const auto views = orbit(*data);
    size_t k = 0;
    for (auto _ : state) {
        el::compute_contours(*data, views[k++ % views.size()], pts, tris, keys);
        benchmark::DoNotOptimize(pts.data());
    }
    per_item(state, "ns_per_triangle", m.triangle_count());
}

void meshes(benchmark::internal::Benchmark* b) {
    for (size_t i = 0; i < el_bench::bench_mesh_names().size(); ++i) b->Arg(int64_t(i));
    b->Unit(benchmark::kMicrosecond);
}

}  // namespace

BENCHMARK(BM_Topology)->Apply(meshes);
BENCHMARK(BM_MeshCreate)->Apply(meshes);
BENCHMARK(BM_Classify)->Apply(meshes);
BENCHMARK(BM_Orient)->Apply(meshes);
BENCHMARK(BM_CreaseThreshold)->Apply(meshes);
BENCHMARK(BM_SilhouetteCold)->Apply(meshes);
BENCHMARK(BM_SilhouetteOrbit)->Apply(meshes);
BENCHMARK(BM_SilhouetteCached)->Apply(meshes);
BENCHMARK(BM_Contours)->Apply(meshes);

namespace {

void BM_FacingOnly(benchmark::State& state) {
    const auto& m = bench_mesh(int(state.range(0)));
    auto data = el::build_mesh(desc_of(m));
    std::vector<uint8_t> bits;
    const auto views = orbit(*data);
    size_t k = 0;
    for (auto _ : state) {
        el::compute_facing(*data, views[k++ % views.size()], bits);
        benchmark::DoNotOptimize(bits.data());
    }
    per_item(state, "ns_per_triangle", m.triangle_count());
}

void BM_SilhouetteEdgePass(benchmark::State& state) {
    const auto& m = bench_mesh(int(state.range(0)));
    auto data = el::build_mesh(desc_of(m));
    std::vector<uint8_t> bits;
    std::vector<uint32_t> out;
    el::compute_facing(*data, orbit(*data)[0], bits);
    for (auto _ : state) {
        el::collect_silhouettes(*data, bits, out);
        benchmark::DoNotOptimize(out.data());
    }
    per_item(state, "ns_per_edge", data->edge_count());
}

}  // namespace

BENCHMARK(BM_FacingOnly)->Apply(meshes);
BENCHMARK(BM_SilhouetteEdgePass)->Apply(meshes);

namespace {

// Chaining the silhouette edges of one view (what a tapered silhouette line costs per view on
// top of the silhouette pass), per silhouette edge.
void BM_ChainSilhouettes(benchmark::State& state) {
    const auto& m = bench_mesh(int(state.range(0)));
    auto data = el::build_mesh(desc_of(m));
    std::vector<uint8_t> bits;
    std::vector<uint32_t> sil;
    el::compute_facing(*data, orbit(*data)[0], bits);
    el::collect_silhouettes(*data, bits, sil);
    std::vector<el::ChainItem> items(sil.size());
    for (auto _ : state) {
        for (size_t i = 0; i < sil.size(); ++i) {
            const uint32_t a = data->topo.edge_vertices[2 * size_t(sil[i])], b = data->topo.edge_vertices[2 * size_t(sil[i]) + 1];
            items[i] = el::ChainItem{{a, b}, {data->positions[a], data->positions[b]}};
        }
        el::Chains c = el::build_chains(items);
        benchmark::DoNotOptimize(c.chains.data());
    }
    per_item(state, "ns_per_silhouette_edge", double(std::max<size_t>(sil.size(), 1)));
    state.counters["silhouette_edges"] = double(sil.size());
}

}  // namespace

BENCHMARK(BM_ChainSilhouettes)->Apply(meshes);
