// C entry points of the highlight math: argument validation, then one call into the core.
// Every check names the argument and its value; nothing below the checks can fail on valid input.
#include "capi_common.hpp"
#include "cos_power_integral.hpp"
#include "highlight_arc.hpp"
#include "highlight_reference.hpp"
#include "highlight_table.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

struct el_highlight_table {
    el::HighlightTable table;
};

namespace {

constexpr double kHalfPi = 0.5 * std::numbers::pi;
// float32's pi/2 rounds up (1.5707963705); callers passing it mean pi/2.
constexpr double kHalfPiFloat = double(float(kHalfPi));
// The reference accepts the same exponents a table can cover.
constexpr double kMaxShininess = double(el::kMaxTableExponent) - 1.0;

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

[[noreturn]] void bad(const std::string& what) { el::fail(EL_ERR_INVALID_ARGUMENT, what); }

void check_angle(double v, const char* name) {
    el::require_finite(v, name);
    if (std::fabs(v) > kHalfPiFloat) bad(std::string(name) + " = " + num(v) + " is outside [-pi/2, pi/2]");
}

double clamp_angle(double v) { return std::fmax(-kHalfPi, std::fmin(kHalfPi, v)); }

struct V3 {
    double x, y, z;
    double norm() const { return std::sqrt(x * x + y * y + z * z); }
};
V3 v3(const float* v) { return {v[0], v[1], v[2]}; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// Names an input field in messages: "in->radius" or "in[17].radius". Strings are only built
// on failure, so validating a large batch allocates nothing.
struct Field {
    int64_t index;  // -1: a single input
    std::string operator()(const char* name) const {
        return index < 0 ? std::string("in->") + name : "in[" + std::to_string(index) + "]." + name;
    }
};

void check_finite3(const float* v, const Field& f, const char* name) {
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(v[i]))
            el::fail(EL_ERR_NON_FINITE, f(name) + "[" + std::to_string(i) + "] = " + num(v[i]) + " is not finite");
}

void check_finite(float v, const Field& f, const char* name) {
    if (!std::isfinite(v)) el::fail(EL_ERR_NON_FINITE, f(name) + " = " + num(v) + " is not finite");
}

bool is_zero3(const float* v) { return v[0] == 0.0f && v[1] == 0.0f && v[2] == 0.0f; }

// a - b as the float path computes it: must stay finite and nonzero.
void check_difference(const float* a, const float* b, const Field& f, const char* an, const char* bn) {
    float d[3];
    for (int i = 0; i < 3; ++i) d[i] = a[i] - b[i];
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(d[i])) bad(f(an) + " - " + f(bn) + " overflows float32");
    if (is_zero3(d)) bad(f(an) + " - " + f(bn) + " is the zero vector (the points coincide)");
}

// max_m: the largest exponent m = shininess + 1 allowed (the table's, or the reference's).
void validate_input(const el_highlight_input& in, double max_m, const Field& f) {
    check_finite3(in.point, f, "point");
    check_finite3(in.edge_dir, f, "edge_dir");
    check_finite3(in.n1, f, "n1");
    check_finite3(in.n2, f, "n2");
    check_finite3(in.eye, f, "eye");
    check_finite3(in.view_dir, f, "view_dir");
    check_finite3(in.light, f, "light");
    check_finite(in.shininess, f, "shininess");
    check_finite(in.radius, f, "radius");
    check_finite(in.K, f, "K");
    check_finite(in.ortho_scale, f, "ortho_scale");

    if (in.projection != EL_PERSPECTIVE && in.projection != EL_ORTHOGRAPHIC)
        bad(f("projection") + " = " + std::to_string(in.projection) +
            " is neither EL_PERSPECTIVE (0) nor EL_ORTHOGRAPHIC (1)");
    if (in.light_is_point != 0 && in.light_is_point != 1)
        bad(f("light_is_point") + " = " + std::to_string(in.light_is_point) + " is neither 0 nor 1");

    if (is_zero3(in.edge_dir)) bad(f("edge_dir") + " is the zero vector");
    const V3 e = v3(in.edge_dir);
    const double elen = e.norm();
    const V3 eu{e.x / elen, e.y / elen, e.z / elen};
    for (auto [v, name] : {std::pair{in.n1, "n1"}, std::pair{in.n2, "n2"}}) {
        if (is_zero3(v)) bad(f(name) + " is the zero vector");
        const V3 n = v3(v);
        const double sine = cross(n, eu).norm() / n.norm();
        if (!(sine >= el::kMinNormalSine))
            bad(f(name) + " is parallel to edge_dir (sine of the angle " + num(sine) + " < " +
                num(el::kMinNormalSine) + ")");
    }

    if (in.projection == EL_PERSPECTIVE) {
        check_difference(in.eye, in.point, f, "eye", "point");
    } else {
        if (is_zero3(in.view_dir)) bad(f("view_dir") + " is the zero vector");
        if (!(in.ortho_scale > 0.0f))
            bad(f("ortho_scale") + " = " + num(in.ortho_scale) + " must be > 0 for EL_ORTHOGRAPHIC");
    }
    if (in.light_is_point)
        check_difference(in.light, in.point, f, "light", "point");
    else if (is_zero3(in.light))
        bad(f("light") + " is the zero vector");

    if (!(in.shininess >= 1.0f)) bad(f("shininess") + " = " + num(in.shininess) + " is below 1");
    if (!(double(in.shininess) + 1.0 <= max_m))
        bad(f("shininess") + " = " + num(in.shininess) + " needs the exponent m = shininess + 1 = " +
            num(double(in.shininess) + 1.0) + ", beyond the largest covered, " + num(max_m));
    if (!(in.radius >= 0.0f)) bad(f("radius") + " = " + num(in.radius) + " is negative");
    if (!(in.K >= 0.0f)) bad(f("K") + " = " + num(in.K) + " is negative");
}

const el::HighlightTable& table_of(const el_highlight_table* t) {
    el::require(t, "table");
    return t->table;
}

}  // namespace

extern "C" {

EL_API el_status el_highlight_table_create(const el_table_desc* desc, el_highlight_table** out) {
    return el::guarded("el_highlight_table_create", [&] {
        el::require(out, "out");
        *out = nullptr;
        el::require(desc, "desc");
        if (desc->layout != EL_TABLE_PAPER && desc->layout != EL_TABLE_WARPED &&
            desc->layout != EL_TABLE_BICUBIC)
            bad("desc->layout = " + std::to_string(desc->layout) +
                " is none of EL_TABLE_PAPER (0), EL_TABLE_WARPED (1), EL_TABLE_BICUBIC (2)");
        if (desc->phi_count < 2)
            el::fail(EL_ERR_INVALID_COUNT, "desc->phi_count = " + std::to_string(desc->phi_count) + " is below 2");
        if (desc->m_count < 2)
            el::fail(EL_ERR_INVALID_COUNT, "desc->m_count = " + std::to_string(desc->m_count) + " is below 2");
        if (desc->layout == EL_TABLE_BICUBIC &&
            (desc->phi_count < el::kBicubicMinCount || desc->m_count < el::kBicubicMinCount))
            el::fail(EL_ERR_INVALID_COUNT, "desc->phi_count = " + std::to_string(desc->phi_count) +
                                               ", desc->m_count = " + std::to_string(desc->m_count) +
                                               ": EL_TABLE_BICUBIC needs both >= 4 (its 4-point stencil)");
        const uint64_t floats = uint64_t(desc->phi_count) * desc->m_count;
        if (floats > el::kMaxTableFloats)
            el::fail(EL_ERR_OVERFLOW, "desc->phi_count * desc->m_count = " + std::to_string(floats) +
                                          " floats: the byte size would overflow int32 (limit " +
                                          std::to_string(el::kMaxTableFloats) + " floats)");
        el::require_finite(desc->m_max, "desc->m_max");
        if (desc->layout != EL_TABLE_PAPER &&
            !(desc->m_max > 1.0f && desc->m_max <= el::kMaxTableExponent))
            bad("desc->m_max = " + num(desc->m_max) + " is outside (1, " + num(el::kMaxTableExponent) + "]");
        auto* t = new el_highlight_table{
            el::build_highlight_table(desc->layout, desc->phi_count, desc->m_count, desc->m_max)};
        *out = t;
    });
}

EL_API void el_highlight_table_destroy(el_highlight_table* table) { delete table; }

EL_API el_status el_highlight_table_get_info(const el_highlight_table* table, el_table_info* out) {
    return el::guarded("el_highlight_table_get_info", [&] {
        const el::HighlightTable& t = table_of(table);
        el::require(out, "out");
        *out = el_table_info{t.layout, t.phi_count, t.m_count, t.m_max, t.warp_c};
    });
}

EL_API el_status el_highlight_table_copy(const el_highlight_table* table, float* out,
                                         uint64_t capacity_floats) {
    return el::guarded("el_highlight_table_copy", [&] {
        const el::HighlightTable& t = table_of(table);
        el::require(out, "out");
        el::require_capacity(capacity_floats, t.data.size(), "capacity_floats");
        std::copy(t.data.begin(), t.data.end(), out);
    });
}

EL_API el_status el_highlight_table_lookup(const el_highlight_table* table, float phi, float m,
                                           float* out) {
    return el::guarded("el_highlight_table_lookup", [&] {
        const el::HighlightTable& t = table_of(table);
        el::require(out, "out");
        check_angle(phi, "phi");
        el::require_finite(m, "m");
        if (!(m >= 1.0f && m <= t.m_max))
            bad("m = " + num(m) + " is outside the table's range [1, " + num(t.m_max) + "]");
        *out = el::table_lookup(t, el::table_row(t, m), phi);
    });
}

EL_API el_status el_cos_power_integral(double phi, double m, double* out) {
    return el::guarded("el_cos_power_integral", [&] {
        el::require(out, "out");
        check_angle(phi, "phi");
        el::require_finite(m, "m");
        if (!(m >= 0.0 && m <= el::kCosPowerMaxExponent))
            bad("m = " + num(m) + " is outside [0, " + num(el::kCosPowerMaxExponent) + "]");
        *out = el::cos_power_integral(clamp_angle(phi), m);
    });
}

EL_API el_status el_cos_power_sin_integral(double a, double b, double n, double* out) {
    return el::guarded("el_cos_power_sin_integral", [&] {
        el::require(out, "out");
        check_angle(a, "a");
        check_angle(b, "b");
        el::require_finite(n, "n");
        if (!(n >= 0.0)) bad("n = " + num(n) + " is negative");
        *out = el::cos_power_sin_integral(clamp_angle(a), clamp_angle(b), n);
    });
}

EL_API el_status el_highlight_weight(float K, float r_e, float d, float r_max, float* out_w) {
    return el::guarded("el_highlight_weight", [&] {
        el::require(out_w, "out_w");
        el::require_finite(K, "K");
        el::require_finite(r_e, "r_e");
        el::require_finite(d, "d");
        el::require_finite(r_max, "r_max");
        if (!(K >= 0.0f)) bad("K = " + num(K) + " is negative");
        if (!(r_e >= 0.0f)) bad("r_e = " + num(r_e) + " is negative");
        if (!(d > 0.0f)) bad("d = " + num(d) + " must be > 0");
        if (!(r_max >= 0.0f)) bad("r_max = " + num(r_max) + " is negative");
        *out_w = el::highlight_weight(K, r_e, d, r_max);
    });
}

EL_API el_status el_highlight_eval(const el_highlight_table* table, const el_highlight_input* in,
                                   el_highlight_result* out) {
    return el::guarded("el_highlight_eval", [&] {
        const el::HighlightTable& t = table_of(table);
        el::require(in, "in");
        el::require(out, "out");
        validate_input(*in, t.m_max, Field{-1});
        *out = el::highlight_eval(t, *in);
    });
}

EL_API el_status el_highlight_eval_batch(const el_highlight_table* table,
                                         const el_highlight_input* in, uint32_t count,
                                         el_highlight_result* out) {
    return el::guarded("el_highlight_eval_batch", [&] {
        const el::HighlightTable& t = table_of(table);
        el::require(in, "in");
        el::require(out, "out");
        if (count == 0) el::fail(EL_ERR_INVALID_COUNT, "count is 0");
        // All inputs are checked before any output is written.
        for (uint32_t i = 0; i < count; ++i)
            validate_input(in[i], t.m_max, Field{int64_t(i)});
        for (uint32_t i = 0; i < count; ++i) out[i] = el::highlight_eval(t, in[i]);
    });
}

EL_API el_status el_highlight_reference(const el_highlight_input* in, el_highlight_result* out) {
    return el::guarded("el_highlight_reference", [&] {
        el::require(in, "in");
        el::require(out, "out");
        validate_input(*in, kMaxShininess + 1.0, Field{-1});
        *out = el::highlight_reference(*in);
    });
}

}  // extern "C"
