#include "outline_lines.hpp"

#include "error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>

namespace el {

namespace {

using glm::dvec3;

// A corner's arc: only where the two lines' crossing lies farther than this many pixels outside
// the ball's circle, and then in chords that stay this close to the circle.
constexpr double kArcTolerancePx = 0.25;
constexpr int kArcMaxPieces = int(EL_OUTLINE_ARC_MAX_PIECES);
constexpr size_t kEdgeFloats = 4 * EL_OUTLINE_EDGE_TEXELS;
constexpr size_t kCornerFloats = 4 * EL_OUTLINE_CORNER_TEXELS;
constexpr double kPi = 3.14159265358979323846;

uint64_t pair_key(uint32_t a, uint32_t b) {
    if (a > b) std::swap(a, b);
    return (uint64_t(a) << 32) | b;
}

dvec3 texel(const float* record, int k) {
    return dvec3(record[4 * k], record[4 * k + 1], record[4 * k + 2]);
}

dvec3 unit(const dvec3& a) { return a / std::max(glm::length(a), 1e-30); }

// The upper-left 3x3 of a row-major 4x4 (the linear part), row-major.
struct Mat3 {
    double a[3][3];

    dvec3 operator*(const dvec3& x) const {  // A x
        return dvec3(a[0][0] * x.x + a[0][1] * x.y + a[0][2] * x.z, a[1][0] * x.x + a[1][1] * x.y + a[1][2] * x.z,
                     a[2][0] * x.x + a[2][1] * x.y + a[2][2] * x.z);
    }
    dvec3 transposed_times(const dvec3& x) const {  // A^T x
        return dvec3(a[0][0] * x.x + a[1][0] * x.y + a[2][0] * x.z, a[0][1] * x.x + a[1][1] * x.y + a[2][1] * x.z,
                     a[0][2] * x.x + a[1][2] * x.y + a[2][2] * x.z);
    }
    double det() const {
        return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
               a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    }
    Mat3 inverse() const {
        const double d = det();
        Mat3 r{};
        r.a[0][0] = (a[1][1] * a[2][2] - a[1][2] * a[2][1]) / d;
        r.a[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) / d;
        r.a[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) / d;
        r.a[1][0] = (a[1][2] * a[2][0] - a[1][0] * a[2][2]) / d;
        r.a[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) / d;
        r.a[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) / d;
        r.a[2][0] = (a[1][0] * a[2][1] - a[1][1] * a[2][0]) / d;
        r.a[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) / d;
        r.a[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) / d;
        return r;
    }
};

Mat3 linear(const Mat4& m) {
    Mat3 r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.a[i][j] = m.m[4 * i + j];
    return r;
}

dvec3 translation(const Mat4& m) { return dvec3(m.m[3], m.m[7], m.m[11]); }

Mat4 product(const Mat4& a, const Mat4& b) {
    Mat4 r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0.0;
            for (int k = 0; k < 4; ++k) s += a.m[4 * i + k] * b.m[4 * k + j];
            r.m[4 * i + j] = s;
        }
    return r;
}

// m [x, w]: (x, y, w) of clip space, of a point (w = 1) or a direction (w = 0).
dvec3 clip_xyw(const Mat4& m, const dvec3& x, double w) {
    auto row = [&](int i) { return m.m[4 * i] * x.x + m.m[4 * i + 1] * x.y + m.m[4 * i + 2] * x.z + m.m[4 * i + 3] * w; };
    return dvec3(row(0), row(1), row(3));
}

glm::dvec4 apply(const Mat4& m, const dvec3& x) {
    auto row = [&](int i) { return m.m[4 * i] * x.x + m.m[4 * i + 1] * x.y + m.m[4 * i + 2] * x.z + m.m[4 * i + 3]; };
    return glm::dvec4(row(0), row(1), row(2), row(3));
}

// The largest singular value of a 3x3: the square root of A^T A's largest eigenvalue (Jacobi).
double spectral_norm(const Mat3& a) {
    double g[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) g[i][j] = a.a[0][i] * a.a[0][j] + a.a[1][i] * a.a[1][j] + a.a[2][i] * a.a[2][j];
    for (int sweep = 0; sweep < 32; ++sweep) {
        const double off = g[0][1] * g[0][1] + g[0][2] * g[0][2] + g[1][2] * g[1][2];
        if (off <= 1e-30 * (g[0][0] * g[0][0] + g[1][1] * g[1][1] + g[2][2] * g[2][2]) + 1e-300) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (g[p][q] == 0.0) continue;
                const double theta = (g[q][q] - g[p][p]) / (2.0 * g[p][q]);
                const double t = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 3; ++k) {  // G <- J^T G J
                    const double gkp = g[k][p], gkq = g[k][q];
                    g[k][p] = c * gkp - s * gkq;
                    g[k][q] = s * gkp + c * gkq;
                }
                for (int k = 0; k < 3; ++k) {
                    const double gpk = g[p][k], gqk = g[q][k];
                    g[p][k] = c * gpk - s * gqk;
                    g[q][k] = s * gpk + c * gqk;
                }
            }
    }
    return std::sqrt(std::max({g[0][0], g[1][1], g[2][2], 0.0}));
}

// How a rounded edge's radius scales into world units under a transform (lighting.glsl's
// el_radius_scale: the mean stretch of its two faces' directions square to it).
struct RadiusScale {
    explicit RadiusScale(const Mat3& lin) : lin(lin) {
        double g[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                g[i][j] = lin.a[0][i] * lin.a[0][j] + lin.a[1][i] * lin.a[1][j] + lin.a[2][i] * lin.a[2][j];
        const double atol = 1e-12 * std::max(g[0][0], 1e-300);
        uniform = true;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                if (!(std::abs(g[i][j] - (i == j ? g[0][0] : 0.0)) <= atol)) uniform = false;
        uniform_scale = std::sqrt(g[0][0]);
        fallback = glm::length(lin * dvec3(1.0 / std::sqrt(3.0)));
    }

    double operator()(const dvec3& na, const dvec3& nb, const dvec3& e) const {
        if (uniform) return uniform_scale;  // a uniform scale s: every edge's is s
        const dvec3 u = e / std::max(glm::length(e), 1e-30);
        const dvec3 da = glm::cross(na, u), db = glm::cross(nb, u);
        const double la = glm::length(da), lb = glm::length(db);
        if (!(la > 1e-6 && lb > 1e-6)) return fallback;
        return 0.5 * (glm::length(lin * da) / la + glm::length(lin * db) / lb);
    }

    // A corner ball's (el_ball_scale): the mean of its three edges' scales.
    double ball(const dvec3& m1, const dvec3& m2, const dvec3& m3) const {
        return ((*this)(m1, m2, glm::cross(m1, m2)) + (*this)(m2, m3, glm::cross(m2, m3)) +
                (*this)(m3, m1, glm::cross(m3, m1))) /
               3.0;
    }

    Mat3 lin;
    bool uniform;
    double uniform_scale, fallback;
};

struct Vec3f {
    float v[3];
};

Vec3f get3(const std::vector<float>& a, size_t i) { return {{a[3 * i], a[3 * i + 1], a[3 * i + 2]}}; }
dvec3 as_d(const Vec3f& f) { return dvec3(f.v[0], f.v[1], f.v[2]); }
void set3f(std::vector<float>& a, size_t i, const Vec3f& x) { std::copy(x.v, x.v + 3, a.begin() + 3 * i); }

// End k of segment i (2 i + k).
Vec3f end_of(const OutlineSegments& s, size_t e) { return get3(e % 2 == 0 ? s.p0 : s.p1, e / 2); }
void set_end(OutlineSegments& s, size_t e, const Vec3f& x) { set3f(e % 2 == 0 ? s.p0 : s.p1, e / 2, x); }
Vec3f to_f(const dvec3& x) { return {{float(x.x), float(x.y), float(x.z)}}; }

// Appends a -> b seen with the faces and normals of segment `like`, the taper `taper` at both
// ends, in the chain of segment `chain_of` at arc length s at both ends (so that it sorts between
// the two it joins, and continues both).
void append(OutlineSegments& s, const Vec3f& a, const Vec3f& b, size_t like, float taper, size_t chain_of, float arc) {
    s.p0.insert(s.p0.end(), a.v, a.v + 3);
    s.p1.insert(s.p1.end(), b.v, b.v + 3);
    const Vec3f n1 = get3(s.n1, like), n2 = get3(s.n2, like);
    s.n1.insert(s.n1.end(), n1.v, n1.v + 3);
    s.n2.insert(s.n2.end(), n2.v, n2.v + 3);
    s.taper.push_back(taper);
    s.taper.push_back(taper);
    if (s.has_faces) {
        const float f0 = s.faces[2 * like], f1 = s.faces[2 * like + 1];
        s.faces.push_back(f0);
        s.faces.push_back(f1);
    }
    if (s.has_links) {
        el_chain_link l = s.links[chain_of];
        l.s0 = l.s1 = arc;
        s.links.push_back(l);
    }
}

// The segment ends (2 i + k) at the vertices where exactly two ends of the pairs meet, in pairs.
std::vector<std::array<size_t, 2>> two_ends(const std::vector<uint32_t>& verts) {
    std::vector<size_t> order(verts.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return verts[a] < verts[b]; });
    std::vector<std::array<size_t, 2>> out;
    const size_t n = order.size();
    for (size_t j = 0; j + 1 < n; ++j) {
        const uint32_t v = verts[order[j]];
        if (verts[order[j + 1]] != v) continue;
        if (j > 0 && verts[order[j - 1]] == v) continue;
        if (j + 2 < n && verts[order[j + 2]] == v) continue;
        out.push_back({order[j], order[j + 1]});
    }
    return out;
}

struct Arc {
    size_t pair;   // into the moved segments' end pairs
    dvec3 t1, t2;  // object space, the two ends on the circle
    std::array<dvec3, kArcMaxPieces + 1> points;
    int pieces;
};

}  // namespace

FilletOutline fillet_outline(const dvec3& na, const dvec3& nb, const dvec3& v) {
    const dvec3 c = (na + nb) / std::max(1.0 + glm::dot(na, nb), 1e-3);
    dvec3 p = glm::cross(glm::cross(na, nb), v);
    const double length = glm::length(p);
    const bool sil = glm::dot(na, v) * glm::dot(nb, v) < 0.0 && length > 1e-6;
    p = p / std::max(length, 1e-30);
    if (glm::dot(p, c) < 0.0) p = -p;
    return {sil ? p : dvec3(0.0), c, sil};
}

OutlineRecords make_outline_records(const el_outline_desc& d) {
    OutlineRecords r;
    r.edges.assign(d.edges, d.edges + size_t(d.edge_count) * kEdgeFloats);
    r.corners.assign(d.corners, d.corners + size_t(d.corner_count) * kCornerFloats);
    std::vector<uint32_t> order(d.edge_count);
    std::iota(order.begin(), order.end(), 0u);
    std::vector<uint64_t> keys(d.edge_count);
    for (uint32_t i = 0; i < d.edge_count; ++i) keys[i] = pair_key(d.edge_vertices[2 * size_t(i)], d.edge_vertices[2 * size_t(i) + 1]);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return keys[a] < keys[b]; });
    for (uint32_t i : order) {
        r.edge_keys.push_back(keys[i]);
        r.edge_at_key.push_back(i);
    }
    std::vector<uint32_t> corner_order(d.corner_count);
    std::iota(corner_order.begin(), corner_order.end(), 0u);
    std::stable_sort(corner_order.begin(), corner_order.end(),
                     [&](uint32_t a, uint32_t b) { return d.corner_vertices[a] < d.corner_vertices[b]; });
    for (uint32_t i : corner_order) {
        r.corner_keys.push_back(d.corner_vertices[i]);
        r.corner_at_key.push_back(i);
    }
    return r;
}

namespace {

class Outliner {
public:
    Outliner(const OutlineRecords& records, const OutlineCamera& camera)
        : rec_(records), cam_(camera), lin_(linear(camera.object_to_world)), shift_(translation(camera.object_to_world)), scale_(lin_), invertible_(std::abs(lin_.det()) > 1e-30) {
        if (invertible_) inv_ = lin_.inverse();
        world_clip_ = product(cam_.view_to_clip, cam_.world_to_view);
        clip_ = product(world_clip_, cam_.object_to_world);
        right_ = unit(dvec3(cam_.world_to_view.m[0], cam_.world_to_view.m[1], cam_.world_to_view.m[2]));
    }

    OutlineSegments run(const uint32_t* vertices, OutlineSegments seg) {
        const size_t n = seg.size();
        std::vector<size_t> hit;
        std::vector<const float*> recs;
        for (size_t i = 0; i < n; ++i) {
            const uint64_t key = pair_key(vertices[2 * i], vertices[2 * i + 1]);
            const auto it = std::lower_bound(rec_.edge_keys.begin(), rec_.edge_keys.end(), key);
            if (it == rec_.edge_keys.end() || *it != key) continue;
            hit.push_back(i);
            recs.push_back(&rec_.edges[kEdgeFloats * rec_.edge_at_key[size_t(it - rec_.edge_keys.begin())]]);
        }
        if (hit.empty()) return seg;
        const size_t h = hit.size();
        std::vector<std::array<dvec3, 2>> moves(h, {dvec3(0.0), dvec3(0.0)});
        if (invertible_)
            for (size_t j = 0; j < h; ++j) moves[j] = outline_moves(recs[j]);
        // The record runs as the segment does: both take their ends from the mesh's edge array.
        std::vector<Vec3f> d(h);
        for (size_t j = 0; j < h; ++j) {
            const size_t i = hit[j];
            for (int k = 0; k < 3; ++k) d[j].v[k] = seg.p1[3 * i + k] - seg.p0[3 * i + k];
            for (int k = 0; k < 3; ++k) {
                seg.p0[3 * i + k] += float(moves[j][0][k]);
                seg.p1[3 * i + k] += float(moves[j][1][k]);
            }
        }
        std::vector<uint32_t> hit_verts(2 * h);
        for (size_t j = 0; j < h; ++j) {
            hit_verts[2 * j] = vertices[2 * hit[j]];
            hit_verts[2 * j + 1] = vertices[2 * hit[j] + 1];
        }
        const auto pairs = two_ends(hit_verts);  // end k of moved segment j: 2 j + k
        std::vector<char> rounded(pairs.size(), 0);
        const std::vector<Arc> arcs = corner_arcs(hit_verts, pairs, recs);
        for (const Arc& a : arcs) rounded[a.pair] = 1;
        for (size_t q = 0; q < pairs.size(); ++q)
            if (!rounded[q]) join_corner(pairs[q], hit, d, seg);
        with_arcs(seg, hit, pairs, arcs);
        std::vector<char> moved(2 * n, 0);
        std::vector<double> setback(n, 0.0);
        for (size_t j = 0; j < h; ++j) {
            for (int end = 0; end < 2; ++end)
                moved[2 * hit[j] + size_t(end)] = moves[j][size_t(end)] != dvec3(0.0);
            const dvec3 na = unit(texel(recs[j], 0)), nb = unit(texel(recs[j], 1));
            const double cos_fold = std::clamp(glm::dot(na, nb), -0.999, 1.0);
            setback[hit[j]] = double(recs[j][3]) * std::sqrt((1.0 - cos_fold) / (1.0 + cos_fold));  // r tan(a / 2)
        }
        to_the_foot(seg, vertices, n, moved, setback);
        return seg;
    }

private:
    dvec3 to_eye(const dvec3& world) const { return cam_.orthographic ? -cam_.view_dir : cam_.eye - world; }

    // A side's normal at an end (half: -1/2 at p0, 1/2 at p1) in world space, by the inverse
    // transpose as el_normal_matrix does.
    dvec3 world_normal(const float* r, int normal, int turn, double half) const {
        return unit(inv_.transposed_times(texel(r, normal) + half * texel(r, turn)));
    }

    // Object-space moves of a record's two ends onto its fillet's outline; zero at an end where
    // the edge is no silhouette, and where a concave fillet meets it (the record's cut there):
    // that fillet's end fills the corner, and the outline runs out round it.
    std::array<dvec3, 2> outline_moves(const float* r) const {
        const dvec3 ma = texel(r, 0), mb = texel(r, 1), o0 = texel(r, 2), o1 = texel(r, 3);
        const double radius = double(r[3]) * scale_(ma, mb, o1 - o0);
        std::array<dvec3, 2> out{dvec3(0.0), dvec3(0.0)};
        for (int end = 0; end < 2; ++end) {
            const dvec3 w = lin_ * (end == 0 ? o0 : o1) + shift_;
            const double half = end == 0 ? -0.5 : 0.5;
            const FilletOutline f =
                fillet_outline(world_normal(r, 0, 4, half), world_normal(r, 1, 5, half), unit(to_eye(w)));
            if (f.silhouette && r[4 * (2 + end) + 3] == 0.0f) out[size_t(end)] = inv_ * (-radius * (f.c - f.p));
        }
        return out;
    }

    // Where two moved segments meet at a vertex and no ball rounds it, each was moved square to
    // its own edge and their ends overshoot each other: both end at one point where their images
    // cross, on the first one's line (so neither image tilts and the SVG's polylines still join
    // there); where the two nearly continue each other, at the mean of their two ends.
    void join_corner(const std::array<size_t, 2>& ends, const std::vector<size_t>& hit, const std::vector<Vec3f>& d,
                     OutlineSegments& seg) const {
        const size_t g1 = 2 * hit[ends[0] / 2] + ends[0] % 2, g2 = 2 * hit[ends[1] / 2] + ends[1] % 2;
        const dvec3 x1 = as_d(end_of(seg, g1)), x2 = as_d(end_of(seg, g2));
        const dvec3 d1 = as_d(d[ends[0] / 2]), d2 = as_d(d[ends[1] / 2]);
        // Each line's image as a homogeneous 2D line through its clip-space point and direction;
        // the images cross at their cross product.
        const dvec3 c1 = clip_xyw(clip_, x1, 1.0), f1 = clip_xyw(clip_, d1, 0.0);
        const dvec3 c2 = clip_xyw(clip_, x2, 1.0), f2 = clip_xyw(clip_, d2, 0.0);
        const dvec3 cross = glm::cross(glm::cross(c1, f1), glm::cross(c2, f2));
        // On line 1 at the parameter whose clip point is proportional to the crossing.
        const dvec3 a = glm::cross(c1, cross), b = glm::cross(f1, cross);
        const double lam = -glm::dot(a, b) / std::max(glm::dot(b, b), 1e-300);
        dvec3 joint = x1 + lam * d1;
        const dvec3 s = glm::cross(d1, d2);
        const double sin2 = glm::dot(s, s) / std::max(glm::dot(d1, d1) * glm::dot(d2, d2), 1e-300);
        const double gap = glm::length(x1 - x2);
        const bool near = sin2 > 0.04 && std::isfinite(lam) && glm::length(joint - x1) <= 4.0 * gap &&
                          glm::length(joint - x2) <= 4.0 * gap;
        if (!near) joint = 0.5 * (x1 + x2);
        set_end(seg, g1, to_f(joint));
        set_end(seg, g2, to_f(joint));
    }

    // The circle's image radius in pixels of a ball at `centre` (world) of radius r; 0 behind the eye.
    double radius_px(const dvec3& centre, double r) const {
        const glm::dvec4 wc = apply(world_clip_, centre), wt = apply(world_clip_, centre + r * right_);
        const double x = (wt.x / wt.w - wc.x / wc.w) * cam_.width * 0.5;
        const double y = (wt.y / wt.w - wc.y / wc.w) * cam_.height * 0.5;
        const double px = std::sqrt(x * x + y * y);
        return wc.w > 0.0 && wt.w > 0.0 && std::isfinite(px) ? px : 0.0;
    }

    // Where two moved segments meet at a vertex with a corner patch, the fillets' outline there is
    // the patch ball's circle (docs/lines.md, "Corners"): each segment ends where its fillet meets
    // the ball, at B + rb P, and an arc of the circle joins the two.
    std::vector<Arc> corner_arcs(const std::vector<uint32_t>& hit_verts, const std::vector<std::array<size_t, 2>>& pairs,
                                 const std::vector<const float*>& recs) const {
        std::vector<Arc> out;
        if (rec_.corner_keys.empty() || pairs.empty() || !invertible_) return out;
        const double stretch = spectral_norm(lin_);
        for (size_t q = 0; q < pairs.size(); ++q) {
            const uint32_t vert = hit_verts[pairs[q][0]];
            const auto it = std::lower_bound(rec_.corner_keys.begin(), rec_.corner_keys.end(), vert);
            if (it == rec_.corner_keys.end() || *it != vert) continue;
            const float* ball = &rec_.corners[kCornerFloats * rec_.corner_at_key[size_t(it - rec_.corner_keys.begin())]];
            const dvec3 centre = lin_ * texel(ball, 0) + shift_;
            // The circle's image at most: only pairs whose circle may reach a pixel go on.
            if (!(radius_px(centre, double(ball[3]) * stretch) >= kArcTolerancePx)) continue;
            const double rb = double(ball[3]) * scale_.ball(texel(ball, 2), texel(ball, 3), texel(ball, 4));
            const dvec3 v = unit(to_eye(centre));
            FilletOutline f[2];
            for (int k = 0; k < 2; ++k) {
                const size_t e = pairs[q][size_t(k)];
                const float* r = recs[e / 2];
                const double half = e % 2 == 0 ? -0.5 : 0.5;
                f[k] = fillet_outline(world_normal(r, 0, 4, half), world_normal(r, 1, 5, half), v);
            }
            // The outline turns by the arc's angle there; the lines' crossing lies
            // R (1 / cos(angle / 2) - 1) outside a circle of R pixels. An arc where that is past
            // the tolerance, in pieces whose chords stay within it of the circle.
            const double px = radius_px(centre, rb);
            const double angle = std::acos(std::clamp(glm::dot(f[0].p, f[1].p), -1.0, 1.0));
            const double step = 2.0 * std::acos(std::clamp(1.0 - kArcTolerancePx / std::max(px, 1e-9), -1.0, 1.0));
            const double overshoot = px * (1.0 / std::max(std::cos(0.5 * angle), 1e-9) - 1.0);
            if (!(f[0].silhouette && f[1].silhouette && overshoot > kArcTolerancePx && angle < 179.0 * kPi / 180.0))
                continue;
            const double want = std::ceil(angle / std::max(step, 1e-9));  // NaN only from overflowing inputs
            const int pieces = std::isfinite(want) ? int(std::clamp(want, 1.0, double(kArcMaxPieces))) : kArcMaxPieces;
            const double sin_a = std::max(std::sin(angle), 1e-9);
            auto to_object = [&](const dvec3& x) { return inv_ * (x - shift_); };
            Arc a;
            a.pair = q;
            a.pieces = pieces;
            a.t1 = to_object(centre + rb * f[0].p);
            a.t2 = to_object(centre + rb * f[1].p);
            for (int k = 0; k <= kArcMaxPieces; ++k) {
                const double t = double(k) / double(pieces);
                const double w1 = angle > 1e-6 ? std::sin((1.0 - t) * angle) / sin_a : 1.0 - t;
                const double w2 = angle > 1e-6 ? std::sin(t * angle) / sin_a : t;
                a.points[size_t(k)] = to_object(centre + rb * (w1 * f[0].p + w2 * f[1].p));
            }
            out.push_back(a);
        }
        return out;
    }

    // Each rounded corner's two ends at its ball's circle and its arc appended, chord by chord,
    // in the chain of the segment it continues (chain order is by arc length: the arc takes the
    // corner's arc length at both its ends, so it sorts between the two and continues both).
    static void with_arcs(OutlineSegments& seg, const std::vector<size_t>& hit,
                          const std::vector<std::array<size_t, 2>>& pairs, const std::vector<Arc>& arcs) {
        struct Plan {
            size_t i1, k1, i2, k2, owner, owner_k;
            bool forward;
            float s_corner;
        };
        std::vector<Plan> plans;
        for (const Arc& a : arcs) {
            const size_t e1 = pairs[a.pair][0], e2 = pairs[a.pair][1];
            Plan p{hit[e1 / 2], e1 % 2, hit[e2 / 2], e2 % 2, 0, 0, true, 0.0f};
            set_end(seg, 2 * p.i1 + p.k1, to_f(a.t1));
            set_end(seg, 2 * p.i2 + p.k2, to_f(a.t2));
            // Which way the arc runs, and in whose chain: where segment 1's chain arrives at the
            // corner, the arc follows it, from T1 to T2; else where segment 2's does, that one,
            // from T2 to T1; else (both leave it) it comes before segment 1, from T2 to T1.
            p.owner = p.i1;
            p.owner_k = p.k1;
            if (seg.has_links) {
                auto s_at = [&](size_t i, size_t k) { return k == 0 ? seg.links[i].s0 : seg.links[i].s1; };
                auto s_far = [&](size_t i, size_t k) { return k == 0 ? seg.links[i].s1 : seg.links[i].s0; };
                const bool arrives1 = s_far(p.i1, p.k1) < s_at(p.i1, p.k1);
                const bool arrives2 = s_far(p.i2, p.k2) < s_at(p.i2, p.k2);
                p.forward = arrives1;
                if (!arrives1 && arrives2) {
                    p.owner = p.i2;
                    p.owner_k = p.k2;
                }
                p.s_corner = s_at(p.owner, p.owner_k);
            }
            plans.push_back(p);
        }
        for (size_t r = 0; r < arcs.size(); ++r) {
            const Plan& p = plans[r];
            const int n = arcs[r].pieces;
            const float taper = seg.taper[2 * p.owner + p.owner_k];
            for (int q = 0; q < n; ++q) {
                const dvec3& a = arcs[r].points[size_t(p.forward ? q : n - q)];
                const dvec3& b = arcs[r].points[size_t(p.forward ? q + 1 : n - q - 1)];
                // Each chord sees with the faces of the side it is nearer.
                const size_t first = p.forward ? p.i1 : p.i2, last = p.forward ? p.i2 : p.i1;
                append(seg, to_f(a), to_f(b), q < (n + 1) / 2 ? first : last, taper, p.owner, p.s_corner);
            }
        }
    }

    // Where a silhouette moved onto its fillet's outline runs on into one that is not moved (a
    // cylinder's rounded rim into its side), the fillet's outline runs along the unmoved one's
    // line to the fillet's foot, its setback from the vertex, and from there into the moved end:
    // the unmoved segment ends at the foot, and a segment from the foot to the moved end, seen
    // with the moved one's faces, is appended in the unmoved one's chain.
    static void to_the_foot(OutlineSegments& seg, const uint32_t* vertices, size_t n, const std::vector<char>& moved,
                            const std::vector<double>& setback) {
        if (n == 0) return;
        const auto pairs = two_ends(std::vector<uint32_t>(vertices, vertices + 2 * n));
        struct Foot {
            size_t i_r, i_s, k_s;
            Vec3f foot, tip;
        };
        std::vector<Foot> feet;
        for (const auto& p : pairs) {
            if (moved[p[0]] == moved[p[1]]) continue;
            const size_t r_end = moved[p[0]] ? p[0] : p[1], s_end = moved[p[0]] ? p[1] : p[0];
            const dvec3 vert = as_d(end_of(seg, s_end)), far = as_d(end_of(seg, s_end ^ 1u));
            const double length = glm::length(far - vert);
            const dvec3 foot =
                vert + (far - vert) * (std::min(setback[r_end / 2], 0.5 * length) / std::max(length, 1e-30));
            feet.push_back({r_end / 2, s_end / 2, s_end % 2, to_f(foot), end_of(seg, r_end)});
        }
        for (const Foot& f : feet) set_end(seg, 2 * f.i_s + f.k_s, f.foot);
        for (const Foot& f : feet) {
            // Along the unmoved one's chain: after it where the chain arrives at the vertex, else before.
            bool arrives = true;
            float s_at = 0.0f;
            if (seg.has_links) {
                const el_chain_link& l = seg.links[f.i_s];
                s_at = f.k_s == 0 ? l.s0 : l.s1;
                arrives = (f.k_s == 0 ? l.s1 : l.s0) < s_at;
            }
            const float taper = seg.taper[2 * f.i_s + f.k_s];
            append(seg, arrives ? f.foot : f.tip, arrives ? f.tip : f.foot, f.i_r, taper, f.i_s, s_at);
        }
    }

    const OutlineRecords& rec_;
    const OutlineCamera& cam_;
    Mat3 lin_;
    dvec3 shift_;
    RadiusScale scale_;
    bool invertible_;
    Mat3 inv_{};
    Mat4 world_clip_{}, clip_{};
    dvec3 right_{1.0, 0.0, 0.0};
};

}  // namespace

OutlineSegments outline_lines(const OutlineRecords& records, const OutlineCamera& camera, const uint32_t* vertices,
                              OutlineSegments seg) {
    return Outliner(records, camera).run(vertices, std::move(seg));
}

}  // namespace el
