// Highlight math: table creation, table lookup, the float path per pixel (batch) and the double
// reference per sample. Run: edgelight_bench --benchmark_filter=Highlight
#include <edgelight/edgelight.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

el_highlight_table* make_table(el_table_desc desc) {
    el_highlight_table* t = nullptr;
    if (el_highlight_table_create(&desc, &t) != EL_OK) return nullptr;
    return t;
}

void BM_HighlightTableCreate(benchmark::State& state) {
    const el_table_desc desc{int32_t(state.range(0)), uint32_t(state.range(1)), uint32_t(state.range(2)), 10001.0f};
    for (auto _ : state) {
        el_highlight_table* t = make_table(desc);
        benchmark::DoNotOptimize(t);
        el_highlight_table_destroy(t);
    }
    state.SetLabel(desc.layout == EL_TABLE_PAPER ? "paper" : desc.layout == EL_TABLE_WARPED ? "warped" : "bicubic (default)");
}
BENCHMARK(BM_HighlightTableCreate)
    ->Args({EL_TABLE_BICUBIC, 96, 128})
    ->Args({EL_TABLE_WARPED, 256, 256})
    ->Args({EL_TABLE_PAPER, 1024, 128})
    ->Unit(benchmark::kMillisecond);

void BM_HighlightTableLookup(benchmark::State& state) {
    el_highlight_table* t = make_table(EL_TABLE_DEFAULT_DESC);
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> phi(-1.5f, 1.5f), logm(0.0f, 9.2f);
    std::vector<std::pair<float, float>> q(1024);
    for (auto& x : q) x = {phi(rng), std::exp(logm(rng))};
    size_t i = 0;
    float v = 0;
    for (auto _ : state) {
        const auto& [p, m] = q[i++ & 1023];
        el_highlight_table_lookup(t, p, m, &v);
        benchmark::DoNotOptimize(v);
    }
    el_highlight_table_destroy(t);
}
BENCHMARK(BM_HighlightTableLookup);

// Random pixels: any arc, view, light, shininess log-uniform in [1, 1e4].
std::vector<el_highlight_input> random_inputs(size_t count) {
    std::mt19937 rng(2);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f), logn(0.0f, 9.21f), angle(-3.1f, 3.1f);
    std::vector<el_highlight_input> in(count);
    for (auto& x : in) {
        x = el_highlight_input{};
        x.edge_dir[2] = 1;
        const float a = angle(rng), b = angle(rng);
        x.n1[0] = std::cos(a), x.n1[1] = std::sin(a);
        x.n2[0] = std::cos(b), x.n2[1] = std::sin(b);
        for (int k = 0; k < 3; ++k) {
            x.point[k] = u(rng);
            x.eye[k] = 10 * u(rng);
            x.light[k] = u(rng);
        }
        x.eye[0] += 20;
        x.light[0] += 2;
        x.projection = EL_PERSPECTIVE;
        x.shininess = std::exp(logn(rng));
        x.radius = 0.01f;
        x.K = 1000;
    }
    return in;
}

void BM_HighlightEvalBatch(benchmark::State& state) {
    el_highlight_table* t = make_table(EL_TABLE_DEFAULT_DESC);
    const std::vector<el_highlight_input> in = random_inputs(4096);
    std::vector<el_highlight_result> out(in.size());
    for (auto _ : state) {
        el_highlight_eval_batch(t, in.data(), uint32_t(in.size()), out.data());
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(in.size()));
    state.counters["ns_per_eval"] = benchmark::Counter(double(in.size()),
        benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    el_highlight_table_destroy(t);
}
BENCHMARK(BM_HighlightEvalBatch)->Unit(benchmark::kMicrosecond);

void BM_HighlightReference(benchmark::State& state) {
    const std::vector<el_highlight_input> in = random_inputs(256);
    size_t i = 0;
    el_highlight_result r{};
    for (auto _ : state) {
        el_highlight_reference(&in[i++ & 255], &r);
        benchmark::DoNotOptimize(r);
    }
    state.SetItemsProcessed(int64_t(state.iterations()));
}
BENCHMARK(BM_HighlightReference)->Unit(benchmark::kMicrosecond);

}  // namespace
