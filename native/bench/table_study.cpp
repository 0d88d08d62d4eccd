// Table study (docs/highlight_math.md, "Table study"): for each candidate F(phi, m) table
// (layout x size), its byte size, its maximum absolute and relative error against the exact F in
// double over a dense (phi, m) grid, and its lookup cost (Google Benchmark, in the same run, as a
// ratio to the paper's 1024 x 128). Prints Markdown.
//
//   build/native/bench/edgelight_table_study [--benchmark_repetitions=5 ...]
//
// Grid: m at 1200 log-spaced values in [1, 10001] (offset so that they fall between rows) plus
// the integers 1..128; per m, phi at 4096 points on [0, phi_cut], phi_cut = min(pi/2, 8/sqrt(m))
// (at least 4 per texel of every candidate), and 256 more on [phi_cut, pi/2]. phi and m are
// rounded to float32 as a shader would see them; the exact F is taken at the rounded values.
#include "cos_power_integral.hpp"
#include "highlight_table.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

constexpr double kHalfPi = 0.5 * std::numbers::pi;
constexpr double kMMax = 10001.0;

struct Candidate {
    std::string name;
    int32_t layout;
    uint32_t phi_count, m_count;
    double c = 0.0;  // BICUBIC's c (0: the library's)
};

struct Sample {
    float phi, m;
    double exact;
    double full;  // F(pi/2, m): the scale for the relative error
    bool integer_m;
};

std::vector<Sample> make_grid() {
    std::vector<double> ms;
    for (int k = 0; k < 1200; ++k) ms.push_back(std::exp(std::log(kMMax) * (k + 0.37) / 1200.0));
    ms.push_back(kMMax);
    for (int m = 1; m <= 128; ++m) ms.push_back(m);
    std::vector<std::vector<Sample>> parts(ms.size());
    auto work = [&](size_t first, size_t step) {
        for (size_t j = first; j < ms.size(); j += step) {
            const float mf = float(ms[j]);
            const double m = mf;
            const double full = el::cos_power_integral(kHalfPi, m);
            const double cut = std::min(kHalfPi, 8.0 / std::sqrt(m));
            const bool integer_m = m == std::floor(m) && m <= 128.0;
            for (int i = 0; i < 4096 + 256; ++i) {
                const double phi = i < 4096 ? cut * (i + 0.5) / 4096.0
                                            : cut + (kHalfPi - cut) * (i - 4096 + 1) / 256.0;
                const float pf = float(phi);
                const double p = std::min(double(pf), kHalfPi);
                parts[j].push_back({pf, mf, el::cos_power_integral(p, m), full, integer_m});
            }
        }
    };
    std::thread helper(work, 1, 2);
    work(0, 2);
    helper.join();
    std::vector<Sample> grid;
    for (auto& p : parts) grid.insert(grid.end(), p.begin(), p.end());
    return grid;
}

struct Errors {
    double abs = 0, rel = 0, abs_m = 0, abs_phi = 0;
    double abs_n1 = 0, rel_n1 = 0;  // m >= 2 only: shininess n = m - 1 >= 1
    void add(const Sample& s, double err) {
        if (err > abs) abs = err, abs_m = s.m, abs_phi = s.phi;
        rel = std::max(rel, err / s.full);
        if (s.m >= 2.0f) abs_n1 = std::max(abs_n1, err), rel_n1 = std::max(rel_n1, err / s.full);
    }
};

struct Result {
    Errors all, integers;  // integers: integer m only (the paper's design domain)
    double ns = 0;
};

el::HighlightTable build(const Candidate& c) {
    return el::build_highlight_table(c.layout, c.phi_count, c.m_count, float(kMMax), c.c);
}

Result measure(const Candidate& c, const std::vector<Sample>& grid) {
    const el::HighlightTable t = build(c);
    Result r;
    for (const Sample& s : grid) {
        if (s.m > t.m_max) continue;
        const float got = el::table_lookup(t, el::table_row(t, s.m), s.phi);
        const double err = std::fabs(double(got) - s.exact);
        r.all.add(s, err);
        if (s.integer_m) r.integers.add(s, err);
    }
    return r;
}

// One lookup as the C API and the arc do it: the row for m, then F at phi.
void lookup_benchmark(benchmark::State& state, Candidate c) {
    const el::HighlightTable t = build(c);
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> phi(-1.5f, 1.5f), logm(0.0f, std::log(t.m_max));
    std::vector<std::pair<float, float>> q(1024);
    for (auto& x : q) x = {phi(rng), std::exp(logm(rng))};
    size_t i = 0;
    for (auto _ : state) {
        const auto& [p, m] = q[i++ & 1023];
        float v = el::table_lookup(t, el::table_row(t, m), p);
        benchmark::DoNotOptimize(v);
    }
}

// Keeps the median (or the single run) of each benchmark's real time.
class Collector : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> ns;
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& run : runs)
            if (run.aggregate_name.empty() || run.aggregate_name == "median")
                ns[run.run_name.function_name] = run.GetAdjustedCPUTime();  // shared machine: CPU time
        ConsoleReporter::ReportRuns(runs);
    }
};

std::string sci(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2e", v);
    return buf;
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<Candidate> candidates = {
        {"paper", EL_TABLE_PAPER, 1024, 128},
        {"warped (linear)", EL_TABLE_WARPED, 256, 256},
        {"warped (linear)", EL_TABLE_WARPED, 512, 512},
        {"warped (linear)", EL_TABLE_WARPED, 1024, 1024},
        {"bicubic", EL_TABLE_BICUBIC, 32, 128},
        {"bicubic", EL_TABLE_BICUBIC, 48, 128},
        {"bicubic", EL_TABLE_BICUBIC, 64, 128},
        {"bicubic", EL_TABLE_BICUBIC, 80, 128},
        {"bicubic", EL_TABLE_BICUBIC, 96, 64},
        {"bicubic", EL_TABLE_BICUBIC, 96, 128},
        {"bicubic", EL_TABLE_BICUBIC, 96, 256},
        {"bicubic", EL_TABLE_BICUBIC, 128, 256},
        {"bicubic, c = 6.0", EL_TABLE_BICUBIC, 96, 128, 6.0},
        {"bicubic, c = 7.0", EL_TABLE_BICUBIC, 96, 128, 7.0},
    };
    std::fprintf(stderr, "table_study: exact F on the grid ...\n");
    const std::vector<Sample> grid = make_grid();
    std::vector<Result> results;
    for (const Candidate& c : candidates) {
        std::fprintf(stderr, "table_study: errors of %s %u x %u\n", c.name.c_str(), c.phi_count, c.m_count);
        results.push_back(measure(c, grid));
    }

    std::vector<std::string> ids;
    for (const Candidate& c : candidates) {
        const std::string id = "Lookup/" + std::to_string(c.layout) + "/" + std::to_string(c.phi_count) +
                               "x" + std::to_string(c.m_count) + (c.c > 0 ? "/c" + std::to_string(c.c) : "");
        ids.push_back(id);
        benchmark::RegisterBenchmark(id.c_str(), lookup_benchmark, c);
    }
    benchmark::Initialize(&argc, argv);
    Collector collector;
    benchmark::RunSpecifiedBenchmarks(&collector);
    for (size_t k = 0; k < candidates.size(); ++k) results[k].ns = collector.ns[ids[k]];
    const double paper_ns = results[0].ns;

    std::printf(
        "\nm range: paper [1, 128] (integer m by design; its row 'real m' interpolates between "
        "integers), the others [1, %g]. rel = error / F(pi/2, m). n >= 1: m >= 2.\n\n",
        kMMax);
    std::printf(
        "| layout | size (phi x m) | bytes | max abs err | at (m, phi) | max rel err | max abs, n >= 1 "
        "| max rel, n >= 1 | ns/lookup | ratio to paper |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    for (size_t k = 0; k < candidates.size(); ++k) {
        const Candidate& c = candidates[k];
        const Result& r = results[k];
        const double bytes = 4.0 * c.phi_count * c.m_count;
        auto row = [&](const std::string& name, const Errors& e) {
            char at[64];
            std::snprintf(at, sizeof at, "(%.4g, %.4g)", e.abs_m, e.abs_phi);
            std::printf("| %s | %u x %u | %.0f KiB | %s | %s | %s | %s | %s | %.1f | %.2f |\n", name.c_str(),
                        c.phi_count, c.m_count, bytes / 1024.0, sci(e.abs).c_str(), at, sci(e.rel).c_str(),
                        sci(e.abs_n1).c_str(), sci(e.rel_n1).c_str(), r.ns, r.ns / paper_ns);
        };
        if (c.layout == EL_TABLE_PAPER) {
            row(c.name + ", integer m", r.integers);
            row(c.name + ", real m", r.all);
        } else {
            row(c.name, r.all);
        }
    }
    return 0;
}
