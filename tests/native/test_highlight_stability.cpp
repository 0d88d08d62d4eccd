// Numerical stability sweeps, deterministic, one family of hard configurations per test:
// N1 ~ N2 down to 1e-7 rad, N1 ~ -N2, the view along the edge, grazing views, shininess 1..1e4,
// scene scales 1e-4..1e5. The float32 path (el_highlight_eval, default table: what the shader
// computes) against the double reference (el_highlight_reference) from the same float inputs.
//
// Every output must be finite and in [0, 1]. The error metric is relative with a floor:
//   rel(e, r) = |e - r| / max(|r|, 1e-2)
// (relative where the value is visible, absolute / 1e-2 below), over W, W I_s, W I_d and, where
// both W >= 1e-6, I_s and I_d. Stated bounds below; measured maxima are printed and recorded in
// docs/highlight_math.md ("Stability sweeps").
#include <edgelight/edgelight.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace {

constexpr double kFloor = 1e-2;
constexpr float kShininess[] = {1.0f, 3.0f, 10.0f, 100.0f, 1000.0f, 10000.0f};

struct Max {
    double rel = 0;
    long samples = 0, nonfinite = 0, out_of_range = 0;
    std::string worst;
};

double rel(double e, double r) { return std::fabs(e - r) / std::max(std::fabs(r), kFloor); }

bool finite_in_range(const el_highlight_result& x) {
    for (float v : {x.specular, x.diffuse, x.weight, x.visible_fraction})
        if (!(v >= 0.0f && v <= 1.0f)) return false;
    return std::isfinite(x.r_max) && x.r_max >= 0.0f;
}

class Sweep {
public:
    Sweep() {
        const el_table_desc d = EL_TABLE_DEFAULT_DESC;
        EXPECT_EQ(el_highlight_table_create(&d, &table_), EL_OK) << el_last_error();
    }
    ~Sweep() { el_highlight_table_destroy(table_); }

    // Evaluates `in` at every shininess, in perspective and orthographic projection.
    void run(el_highlight_input in, const char* what) {
        for (int proj : {EL_PERSPECTIVE, EL_ORTHOGRAPHIC}) {
            in.projection = proj;
            if (proj == EL_ORTHOGRAPHIC) {
                for (int i = 0; i < 3; ++i) in.view_dir[i] = in.point[i] - in.eye[i];
                float len = 0;
                for (int i = 0; i < 3; ++i) len = std::max(len, std::fabs(in.view_dir[i]));
                in.ortho_scale = len;
            }
            for (float n : kShininess) {
                in.shininess = n;
                el_highlight_result e{}, r{};
                if (el_highlight_eval(table_, &in, &e) != EL_OK || el_highlight_reference(&in, &r) != EL_OK) {
                    ADD_FAILURE() << what << ": " << el_last_error();
                    continue;
                }
                ++m.samples;
                if (!finite_in_range(e) || !finite_in_range(r)) {
                    ++(std::isfinite(e.specular + e.diffuse + e.weight + e.visible_fraction + e.r_max) ? m.out_of_range
                                                                                                       : m.nonfinite);
                    continue;
                }
                double d = std::max({rel(e.weight, r.weight), rel(double(e.weight) * e.specular, double(r.weight) * r.specular),
                                     rel(double(e.weight) * e.diffuse, double(r.weight) * r.diffuse)});
                if (e.weight >= 1e-6f && r.weight >= 1e-6f)
                    d = std::max({d, rel(e.specular, r.specular), rel(e.diffuse, r.diffuse)});
                if (d > m.rel) {
                    m.rel = d;
                    char buf[200];
                    std::snprintf(buf, sizeof buf, "%s, n = %g, %s: eval (%.6g %.6g W %.6g) ref (%.6g %.6g W %.6g)", what,
                                  n, proj ? "ortho" : "persp", e.specular, e.diffuse, e.weight, r.specular, r.diffuse,
                                  r.weight);
                    m.worst = buf;
                }
            }
        }
    }

    void report(const char* family, double bound) {
        std::printf("[ stability ] %-22s %5ld samples: max rel error %.3g (bound %.0e); worst: %s\n", family,
                    m.samples, m.rel, bound, m.worst.c_str());
        EXPECT_GT(m.samples, 0);
        EXPECT_EQ(m.nonfinite, 0);
        EXPECT_EQ(m.out_of_range, 0);
        EXPECT_LE(m.rel, bound) << m.worst;
    }

    Max m;

private:
    el_highlight_table* table_ = nullptr;
};

void set3(float* v, double x, double y, double z) { v[0] = float(x), v[1] = float(y), v[2] = float(z); }

// A cube-like edge along z through the origin, normals in the xy plane; eye and light around it.
el_highlight_input base() {
    el_highlight_input in{};
    set3(in.edge_dir, 0, 0, 1);
    set3(in.n1, 1, 0, 0);
    set3(in.n2, 0, 1, 0);
    set3(in.eye, 3, 2, 1);
    set3(in.light, 1, 0.8, 0.3);
    in.radius = 0.01f;
    in.K = 1000.0f;
    return in;
}

// Views from several sides of the arc (and along its bisector), lights likewise.
void views_and_lights(Sweep& s, el_highlight_input in, const char* what) {
    const double views[][3] = {{3, 2, 1}, {1, 3, 0.5}, {3, 3, -2}, {-1, 3, 0.2}, {2, -0.5, 1}};
    const double lights[][3] = {{1, 0.8, 0.3}, {0.7, 0.7, 0}, {0, 1, 1}, {1, 0, 0}};
    for (const auto& v : views)
        for (const auto& l : lights) {
            set3(in.eye, in.point[0] + v[0], in.point[1] + v[1], in.point[2] + v[2]);
            set3(in.light, l[0], l[1], l[2]);
            s.run(in, what);
        }
}

TEST(HighlightStability, NearlyEqualNormals) {
    Sweep s;
    for (int k = 0; k <= 8; ++k) {  // arcs of 1e-1 .. 1e-7 rad, and 0
        const double a = k == 8 ? 0.0 : std::pow(10.0, -1 - k * 6.0 / 7.0);
        for (double start : {0.0, 0.7, 2.0}) {
            el_highlight_input in = base();
            set3(in.n1, std::cos(start), std::sin(start), 0);
            set3(in.n2, std::cos(start + a), std::sin(start + a), 0);
            views_and_lights(s, in, ("arc " + std::to_string(a)).c_str());
        }
    }
    s.report("N1 ~ N2 (1e-7 rad)", 2e-5);
}

TEST(HighlightStability, NearlyOppositeNormals) {
    Sweep s;
    for (double off : {0.0, 1e-7, -1e-7, 1e-6, -1e-6, 1e-5, -1e-5, 1e-3, -1e-3, 1e-1}) {
        el_highlight_input in = base();
        set3(in.n1, 1, 0, 0);
        set3(in.n2, -std::cos(off), -std::sin(off), 0);
        views_and_lights(s, in, ("antiparallel " + std::to_string(off)).c_str());
    }
    s.report("N1 ~ -N2", 2e-5);
}

TEST(HighlightStability, ViewAlongTheEdge) {
    Sweep s;
    for (double eps : {0.0, 1e-7, 1e-5, 1e-3, 5e-3, 1e-2, 1.5e-2, 2e-2, 5e-2, 0.2}) {
        for (double psi : {0.3, 1.2, 3.0, 4.5}) {
            el_highlight_input in = base();
            const double d = 4.0;
            set3(in.eye, d * std::sin(eps) * std::cos(psi), d * std::sin(eps) * std::sin(psi), d * std::cos(eps));
            for (const auto& l : {std::array<double, 3>{1, 0.8, 0.3}, std::array<double, 3>{0, 0, 1}}) {
                set3(in.light, l[0], l[1], l[2]);
                s.run(in, ("axial " + std::to_string(eps)).c_str());
            }
        }
    }
    s.report("view along the edge", 2e-5);
}

TEST(HighlightStability, GrazingViews) {
    Sweep s;
    // The eye in the plane perpendicular to the edge, N1.V = +-1e-k: a horizon next to an arc end.
    for (int k = 1; k <= 7; ++k)
        for (double sign : {1.0, -1.0})
            for (double start : {0.0, 1.0}) {
                el_highlight_input in = base();
                set3(in.n1, std::cos(start), std::sin(start), 0);
                set3(in.n2, std::cos(start + 1.2), std::sin(start + 1.2), 0);
                // V at angle pi/2 - g from N1, turning away from the arc: N1.V = sin g.
                const double g = sign * std::pow(10.0, -k);
                const double ang = start - (0.5 * 3.141592653589793 - g);
                set3(in.eye, 5 * std::cos(ang), 5 * std::sin(ang), 0.5);
                for (const auto& l : {std::array<double, 3>{1, 0.8, 0.3}, std::array<double, 3>{0.2, 1, 0}})
                    set3(in.light, l[0], l[1], l[2]), s.run(in, ("grazing " + std::to_string(g)).c_str());
            }
    s.report("grazing views", 2e-5);
}

TEST(HighlightStability, SceneScales) {
    Sweep s;
    for (double scale : {1e-4, 1e-3, 1e-2, 1.0, 1e2, 1e3, 1e5}) {
        el_highlight_input in = base();
        set3(in.point, 0.3 * scale, -0.2 * scale, 0.7 * scale);
        in.radius = float(1e-3 * scale);  // the gain K r / d stays 1000 * 1e-3 / |eye - point|
        const double views[][3] = {{3, 2, 1}, {1, 3, 0.5}, {-1, 3, 0.2}};
        for (const auto& v : views) {
            set3(in.eye, in.point[0] + scale * v[0], in.point[1] + scale * v[1], in.point[2] + scale * v[2]);
            for (int point_light : {0, 1}) {
                in.light_is_point = point_light;
                if (point_light)
                    set3(in.light, in.point[0] + scale * 2, in.point[1] + scale * 1.5, in.point[2] + scale);
                else
                    set3(in.light, 1, 0.8, 0.3);
                s.run(in, ("scale " + std::to_string(scale)).c_str());
            }
        }
    }
    s.report("scales 1e-4 .. 1e5", 2e-5);
}

}  // namespace
