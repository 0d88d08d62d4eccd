// Randomised stress: 10^6 inputs, including every degenerate family, through el_highlight_eval
// (float32, table) and el_highlight_reference (double, 3-D quadrature).
//
// Stated bounds (docs/highlight_math.md, "Accuracy"). Every output is finite and in range, and
//   |W_e - W_r| <= 1e-4,   |W_e I_e - W_r I_r| <= 1e-4 (the pixel's highlight, I = I_s and I_d),
//   |I_e - I_r| <= 2e-4 and |vf_e - vf_r| <= 1e-4 where both W >= 1e-6,
// each plus S, the spread of the reference itself over 32 random perturbations of every float
// input by at most 16 ulps (1e-6 relative). S is 0 for well-conditioned inputs; it is what float32
// inputs cannot resolve (a horizon within 1e-7 rad of an arc end, a view within 1 degree of the
// edge, ...). S is only computed for the few samples that exceed a bound. Where W < 1e-6 the
// highlight contributes nothing visible and I is compared through W I only. Where |L + V| < 1e-2
// (light within 0.6 degrees of straight behind the object) the half vector itself is lost to
// float32 rounding (its error is 1e-7 / |L + V|), and the specular metrics get only the range
// checks.
#include <edgelight/edgelight.h>

#include <gtest/gtest.h>

#include <numbers>
#include <glm/glm.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <thread>
#include <vector>

namespace {

constexpr long kSamples = 1000000;  // a multiple of kChunks
constexpr double kBoundW = 5e-5, kBoundWI = 5e-5, kBoundI = 1e-4, kBoundVF = 5e-5;
constexpr double kMinW = 1e-6;
constexpr double kMinHalfVector = 1e-2;
constexpr int kPerturbations = 32, kMaxUlps = 16;

using glm::dvec3;

class Generator {
public:
    explicit Generator(uint64_t seed) : rng_(seed) {}

    el_highlight_input next() {
        for (;;) {
            const el_highlight_input in = candidate();
            if (valid(in)) return in;
        }
    }

    float perturb(float v, int max_ulps) {
        const int k = int(uni(-max_ulps - 0.5, max_ulps + 0.5));
        for (int i = 0; i < std::abs(k); ++i) v = std::nextafter(v, k > 0 ? INFINITY : -INFINITY);
        return v;
    }

private:
    std::mt19937_64 rng_;

    double uni(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
    double logu(double a, double b) { return std::exp(uni(std::log(a), std::log(b))); }
    bool coin(double p) { return uni(0, 1) < p; }
    double sign() { return coin(0.5) ? 1.0 : -1.0; }
    dvec3 unit() {
        for (;;) {
            const dvec3 v(uni(-1, 1), uni(-1, 1), uni(-1, 1));
            const double l = glm::length(v);
            if (l > 0.1 && l <= 1) return v / l;
        }
    }
    dvec3 perpendicular(dvec3 e) {
        for (;;) {
            dvec3 v = unit();
            v -= e * glm::dot(e, v);
            const double l = glm::length(v);
            if (l > 0.1) return v / l;
        }
    }
    static dvec3 rotate(dvec3 v, dvec3 axis, double a) {
        return v * std::cos(a) + glm::cross(axis, v) * std::sin(a) + axis * glm::dot(axis, v) * (1 - std::cos(a));
    }
    static void put(float* d, dvec3 v) {
        d[0] = float(v.x);
        d[1] = float(v.y);
        d[2] = float(v.z);
    }
    static dvec3 get(const float* d) { return dvec3(d[0], d[1], d[2]); }

    static bool valid(const el_highlight_input& in) {
        auto finite = [](const float* v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); };
        auto same = [](const float* a, const float* b) { return a[0] == b[0] && a[1] == b[1] && a[2] == b[2]; };
        if (!finite(in.light) || !finite(in.eye) || !finite(in.n1) || !finite(in.n2)) return false;
        if (in.projection == EL_PERSPECTIVE && same(in.eye, in.point)) return false;
        if (in.light_is_point && same(in.light, in.point)) return false;
        if (!in.light_is_point && in.light[0] == 0 && in.light[1] == 0 && in.light[2] == 0) return false;
        return std::isfinite(in.ortho_scale) && in.ortho_scale > 0;
    }

    el_highlight_input candidate() {
        el_highlight_input in{};
        const dvec3 E = unit();
        put(in.edge_dir, E * logu(1e-3, 1e3));
        const dvec3 n1 = perpendicular(E);
        // The arc: generic, N1 ~ N2 (down to 1e-9 rad and equal), N1 ~ -N2 (inside the 1e-6
        // band or clearly outside it), cube-like.
        double alpha;
        const int arc = int(uni(0, 10));
        if (arc < 5) {
            alpha = uni(-std::numbers::pi, std::numbers::pi);
        } else if (arc < 7) {
            alpha = coin(0.1) ? 0.0 : sign() * logu(1e-9, 1e-2);
        } else if (arc < 9) {
            const double d = coin(0.1) ? 0.0 : (coin(0.5) ? logu(1e-9, 3e-7) : logu(1e-5, 1e-1));
            alpha = sign() * (std::numbers::pi - d);
        } else {
            alpha = sign() * uni(1.4, 1.7);
        }
        const dvec3 n2 = rotate(n1, E, alpha);
        put(in.n1, n1 * logu(0.1, 10.0));  // normals need not be unit
        put(in.n2, n2 * logu(0.1, 10.0));
        put(in.point, dvec3(uni(-1, 1), uni(-1, 1), uni(-1, 1)) * logu(1e-4, 1e5));
        const dvec3 P = get(in.point);
        // The view: random, grazing an arc end or an inner normal (N.V ~ 1e-8..1e-2), along the
        // edge (|E x V| from 0 to 0.1), facing the arc.
        dvec3 V;
        const int view = int(uni(0, 10));
        if (view < 5) {
            V = unit();
        } else if (view < 7) {
            const dvec3 nn = coin(0.4) ? n1 : (coin(0.5) ? n2 : rotate(n1, E, alpha * uni(0, 1)));
            const dvec3 t = glm::normalize(glm::cross(E, nn)) * sign() + E * uni(-2, 2);
            V = glm::normalize(t + nn * sign() * logu(1e-8, 1e-2) * glm::length(t));
        } else if (view < 9) {
            V = glm::normalize(E * sign() + perpendicular(E) * (coin(0.1) ? 0.0 : logu(1e-9, 1e-1)));
        } else {
            V = glm::normalize(glm::normalize(n1 + n2 + 1e-9 * perpendicular(E)) + unit() * uni(0, 0.5));
        }
        in.projection = coin(0.7) ? EL_PERSPECTIVE : EL_ORTHOGRAPHIC;
        // Scales: radius in [1e-4, 1e5]; the gain K r / d (pixels per unit of visible width) in
        // [1e-3, 1e4]: beyond that the edge is no thin cylinder but a wide band.
        in.radius = float(logu(1e-4, 1e5));
        in.K = coin(0.03) ? 0.0f : float(logu(1.0, 1e4));
        const double dist = std::max(double(in.K), 1.0) * in.radius / logu(1e-3, 1e4);
        put(in.eye, P + V * dist);
        put(in.view_dir, -V * logu(1e-2, 1e2));
        in.ortho_scale = float(dist);
        const dvec3 Vin = in.projection == EL_PERSPECTIVE ? glm::normalize(get(in.eye) - P)
                                                          : -glm::normalize(get(in.view_dir));
        // The light: random; a light or half vector at phi ~ 0 or ~ pi/2 from an arc end; along
        // the edge (light or half vector); a head light.
        dvec3 L;
        const int light = int(uni(0, 10));
        if (light < 5) {
            L = unit();
        } else if (light < 8) {
            const dvec3 nn = coin(0.5) ? n1 : n2;
            const dvec3 t = glm::normalize(glm::cross(E, nn));
            const double phi = coin(0.5) ? sign() * logu(1e-7, 1e-1) : sign() * (std::numbers::pi / 2 - logu(1e-7, 1e-1));
            dvec3 D = glm::normalize(nn * std::cos(phi) + t * std::sin(phi) + E * uni(-0.3, 0.3));
            if (coin(0.5)) {
                L = D;
            } else {
                if (glm::dot(D, Vin) < 0) D = -D;
                L = glm::normalize(2 * glm::dot(D, Vin) * D - Vin);  // H = D
            }
        } else if (light < 9) {
            L = coin(0.5) ? E * sign() : glm::normalize(2 * glm::dot(E, Vin) * E - Vin);
        } else {
            L = Vin;
        }
        in.light_is_point = coin(0.5);
        if (in.light_is_point)
            put(in.light, P + L * logu(1e-3, 1e5));
        else
            put(in.light, L * logu(1e-2, 1e2));
        double n = coin(0.05) ? 1.0 : (coin(0.05) ? 1e4 : logu(1.0, 1e4));
        if (coin(0.5)) n = std::round(n);
        in.shininess = float(n);
        return in;
    }
};

enum Metric { kW, kWIs, kWId, kIs, kId, kVF, kMetrics };
const char* const kNames[kMetrics] = {"W", "W*I_s", "W*I_d", "I_s", "I_d", "visible_fraction"};
const double kBounds[kMetrics] = {kBoundW, kBoundWI, kBoundWI, kBoundI, kBoundI, kBoundVF};

// Differences of two results per metric; NaN where the metric does not apply.
void differences(const el_highlight_result& a, const el_highlight_result& b, double* d) {
    d[kW] = std::fabs(a.weight - b.weight);
    d[kWIs] = std::fabs(double(a.weight) * a.specular - double(b.weight) * b.specular);
    d[kWId] = std::fabs(double(a.weight) * a.diffuse - double(b.weight) * b.diffuse);
    const bool both = std::min(a.weight, b.weight) >= kMinW;
    d[kIs] = both ? std::fabs(a.specular - b.specular) : NAN;
    d[kId] = both ? std::fabs(a.diffuse - b.diffuse) : NAN;
    d[kVF] = both ? std::fabs(a.visible_fraction - b.visible_fraction) : NAN;
}

// |L + V| in double, as the reference computes it.
double half_vector_length(const el_highlight_input& in) {
    auto get = [](const float* v) { return dvec3(v[0], v[1], v[2]); };
    const dvec3 p = get(in.point);
    const dvec3 V = in.projection == EL_PERSPECTIVE ? glm::normalize(get(in.eye) - p) : -glm::normalize(get(in.view_dir));
    const dvec3 L = glm::normalize(in.light_is_point ? get(in.light) - p : get(in.light));
    return glm::length(L + V);
}

struct Stats {
    long samples = 0, nonfinite = 0, out_of_range = 0, spread_checked = 0, failures = 0;
    long no_half_vector = 0;
    double max_raw[kMetrics] = {};       // over all samples
    double max_plain[kMetrics] = {};     // over samples that met the bound without S
    double max_excess[kMetrics] = {};    // max(err - S) over the spread-checked ones
    double max_spread = 0;
};

void run(const el_highlight_table* table, uint64_t seed, long count, Stats& st) {
    Generator gen(seed);
    for (long i = 0; i < count; ++i) {
        const el_highlight_input in = gen.next();
        el_highlight_result e{}, r{};
        if (el_highlight_eval(table, &in, &e) != EL_OK || el_highlight_reference(&in, &r) != EL_OK) {
            ++st.failures;
            continue;
        }
        ++st.samples;
        for (float v : {e.specular, e.diffuse, e.weight, e.visible_fraction, e.r_max})
            if (!std::isfinite(v)) ++st.nonfinite;
        for (float v : {e.specular, e.diffuse, e.weight, e.visible_fraction})
            if (!(v >= 0.0f && v <= 1.0f)) ++st.out_of_range;
        if (!(e.r_max >= 0.0f)) ++st.out_of_range;

        double d[kMetrics];
        differences(e, r, d);
        if (half_vector_length(in) < kMinHalfVector) {
            ++st.no_half_vector;
            d[kIs] = d[kWIs] = NAN;
        }
        bool over = false;
        for (int k = 0; k < kMetrics; ++k) {
            if (std::isnan(d[k])) continue;
            st.max_raw[k] = std::max(st.max_raw[k], d[k]);
            if (d[k] > kBounds[k]) over = true;
        }
        if (!over) {
            for (int k = 0; k < kMetrics; ++k)
                if (!std::isnan(d[k])) st.max_plain[k] = std::max(st.max_plain[k], d[k]);
            continue;
        }
        // The reference's own spread under input perturbations of <= kMaxUlps ulps.
        ++st.spread_checked;
        double spread[kMetrics] = {};
        for (int p = 0; p < kPerturbations; ++p) {
            el_highlight_input q = in;
            for (float* v : {q.point, q.edge_dir, q.n1, q.n2, q.eye, q.view_dir, q.light})
                for (int c = 0; c < 3; ++c) v[c] = gen.perturb(v[c], kMaxUlps);
            for (float* s : {&q.shininess, &q.radius, &q.K, &q.ortho_scale}) *s = gen.perturb(*s, kMaxUlps);
            q.shininess = std::max(q.shininess, 1.0f);
            el_highlight_result rq{};
            if (el_highlight_reference(&q, &rq) != EL_OK) continue;
            double dq[kMetrics];
            differences(rq, r, dq);
            for (int k = 0; k < kMetrics; ++k)
                if (!std::isnan(dq[k])) spread[k] = std::max(spread[k], dq[k]);
        }
        for (int k = 0; k < kMetrics; ++k) {
            if (std::isnan(d[k])) continue;
            st.max_spread = std::max(st.max_spread, spread[k]);
            const double excess = d[k] - spread[k];
            st.max_excess[k] = std::max(st.max_excess[k], excess);
            if (excess > kBounds[k]) {
                ++st.failures;
                if (st.failures <= 3) {  // say which input, so that it can be replayed
                    const el_highlight_input& x = in;
                    std::printf("FAIL %s: error %.3g, spread %.3g; eval (%.7g %.7g W %.6g vf %.6g), ref (%.7g %.7g W %.6g vf %.6g)\n"
                                "  point %.9g %.9g %.9g edge %.9g %.9g %.9g n1 %.9g %.9g %.9g n2 %.9g %.9g %.9g\n"
                                "  eye %.9g %.9g %.9g view %.9g %.9g %.9g proj %d light %.9g %.9g %.9g point_light %d\n"
                                "  n %.9g r %.9g K %.9g ortho %.9g\n",
                                kNames[k], d[k], spread[k], e.specular, e.diffuse, e.weight, e.visible_fraction,
                                r.specular, r.diffuse, r.weight, r.visible_fraction, x.point[0], x.point[1], x.point[2],
                                x.edge_dir[0], x.edge_dir[1], x.edge_dir[2], x.n1[0], x.n1[1], x.n1[2], x.n2[0], x.n2[1],
                                x.n2[2], x.eye[0], x.eye[1], x.eye[2], x.view_dir[0], x.view_dir[1], x.view_dir[2],
                                x.projection, x.light[0], x.light[1], x.light[2], x.light_is_point, x.shininess,
                                x.radius, x.K, x.ortho_scale);
                }
            }
        }
    }
}

TEST(HighlightStress, EvalAgainstReference) {
    el_table_desc desc = EL_TABLE_DEFAULT_DESC;  // what the add-on uploads
    el_highlight_table* table = nullptr;
    ASSERT_EQ(el_highlight_table_create(&desc, &table), EL_OK) << el_last_error();

    const auto start = std::chrono::steady_clock::now();
    // Fixed chunks (seed = chunk), so the samples do not depend on the number of threads.
    constexpr int kChunks = 8;
    const int threads = int(std::clamp(std::thread::hardware_concurrency(), 1u, 4u));
    std::vector<Stats> stats(kChunks);
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&, t] {
            for (int c = t; c < kChunks; c += threads) run(table, 1000 + c, kSamples / kChunks, stats[c]);
        });
    for (auto& th : pool) th.join();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    Stats all;
    for (const Stats& s : stats) {
        all.samples += s.samples;
        all.nonfinite += s.nonfinite;
        all.out_of_range += s.out_of_range;
        all.spread_checked += s.spread_checked;
        all.no_half_vector += s.no_half_vector;
        all.failures += s.failures;
        all.max_spread = std::max(all.max_spread, s.max_spread);
        for (int k = 0; k < kMetrics; ++k) {
            all.max_raw[k] = std::max(all.max_raw[k], s.max_raw[k]);
            all.max_plain[k] = std::max(all.max_plain[k], s.max_plain[k]);
            all.max_excess[k] = std::max(all.max_excess[k], s.max_excess[k]);
        }
    }
    std::printf("[ stress ] %ld samples in %.1f s on %d threads; %ld needed the perturbation spread "
                "(largest spread %.3g); %ld with |L + V| < %g\n",
                all.samples, seconds, threads, all.spread_checked, all.max_spread, all.no_half_vector,
                kMinHalfVector);
    for (int k = 0; k < kMetrics; ++k)
        std::printf("[ stress ] %-16s bound %.0e: max error %.3g (%.3g where within the bound alone), "
                    "max error - spread %.3g\n",
                    kNames[k], kBounds[k], all.max_raw[k], all.max_plain[k], all.max_excess[k]);
    EXPECT_EQ(all.samples, kSamples);
    EXPECT_EQ(all.nonfinite, 0);
    EXPECT_EQ(all.out_of_range, 0);
    EXPECT_EQ(all.failures, 0);  // the first ones are printed above
    EXPECT_LT(all.spread_checked, kSamples / 1000);  // ill-conditioned inputs stay rare
    el_highlight_table_destroy(table);
}

}  // namespace
