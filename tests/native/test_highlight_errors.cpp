// Every failure path of the highlight C functions: the status, and a last-error message that
// names the function and the argument.
#include <edgelight/edgelight.h>

#include <gtest/gtest.h>

#include "highlight_fixtures.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

using fixtures::set3;
using fixtures::Table;

namespace {

// Small and quick: error paths do not need the default table's accuracy.
constexpr el_table_desc kSmall{EL_TABLE_WARPED, 64, 16, 10001.0f};

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

#define EXPECT_FAILS(call, status, needle)                                                \
    do {                                                                                  \
        EXPECT_EQ((call), (status)) << #call;                                             \
        const std::string msg = el_last_error();                                          \
        EXPECT_NE(msg.find(needle), std::string::npos) << #call << ": \"" << msg << "\""; \
    } while (0)

el_highlight_input valid_input() {
    el_highlight_input in{};
    in.edge_dir[2] = 1;
    in.n1[0] = 1;
    in.n2[1] = 1;
    in.eye[0] = in.eye[1] = 3;
    in.view_dir[0] = in.view_dir[1] = -1;
    in.projection = EL_PERSPECTIVE;
    in.light[0] = in.light[1] = 1;
    in.shininess = 20;
    in.radius = 0.01f;
    in.K = 100;
    in.ortho_scale = 1;
    return in;
}

TEST(HighlightErrors, TableCreate) {
    el_highlight_table* t = reinterpret_cast<el_highlight_table*>(&t);  // must be reset to NULL
    el_table_desc ok{EL_TABLE_WARPED, 64, 16, 100.0f};
    EXPECT_FAILS(el_highlight_table_create(nullptr, &t), EL_ERR_NULL_POINTER, "desc");
    EXPECT_EQ(t, nullptr);
    EXPECT_FAILS(el_highlight_table_create(&ok, nullptr), EL_ERR_NULL_POINTER, "out");
    auto create = [&](el_table_desc d) {
        t = reinterpret_cast<el_highlight_table*>(&t);
        const el_status s = el_highlight_table_create(&d, &t);
        EXPECT_EQ(t, nullptr);
        return s;
    };
    EXPECT_FAILS(create({3, 64, 16, 100.0f}), EL_ERR_INVALID_ARGUMENT, "layout");
    EXPECT_FAILS(create({-1, 64, 16, 100.0f}), EL_ERR_INVALID_ARGUMENT, "layout");
    EXPECT_FAILS(create({EL_TABLE_WARPED, 0, 16, 100.0f}), EL_ERR_INVALID_COUNT, "phi_count");
    EXPECT_FAILS(create({EL_TABLE_WARPED, 1, 16, 100.0f}), EL_ERR_INVALID_COUNT, "phi_count");
    EXPECT_FAILS(create({EL_TABLE_PAPER, 64, 1, 0.0f}), EL_ERR_INVALID_COUNT, "m_count");
    EXPECT_FAILS(create({EL_TABLE_PAPER, 65536, 65536, 0.0f}), EL_ERR_OVERFLOW, "phi_count * desc->m_count");
    EXPECT_FAILS(create({EL_TABLE_WARPED, 0xFFFFFFFFu, 0xFFFFFFFFu, 100.0f}), EL_ERR_OVERFLOW, "overflow");
    EXPECT_FAILS(create({EL_TABLE_WARPED, 64, 16, kNaN}), EL_ERR_NON_FINITE, "m_max");
    EXPECT_FAILS(create({EL_TABLE_PAPER, 64, 16, kInf}), EL_ERR_NON_FINITE, "m_max");
    EXPECT_FAILS(create({EL_TABLE_WARPED, 64, 16, 1.0f}), EL_ERR_INVALID_ARGUMENT, "m_max = 1");
    EXPECT_FAILS(create({EL_TABLE_WARPED, 64, 16, -5.0f}), EL_ERR_INVALID_ARGUMENT, "m_max");
    EXPECT_FAILS(create({EL_TABLE_WARPED, 64, 16, 2e6f}), EL_ERR_INVALID_ARGUMENT, "m_max");
    // The smallest valid sizes work; PAPER ignores m_max.
    EXPECT_EQ(el_highlight_table_create(&ok, &t), EL_OK);
    EXPECT_STREQ(el_last_error(), "");
    el_highlight_table_destroy(t);
    el_table_desc tiny{EL_TABLE_PAPER, 2, 2, 0.0f};
    EXPECT_EQ(el_highlight_table_create(&tiny, &t), EL_OK);
    el_highlight_table_destroy(t);
    el_highlight_table_destroy(nullptr);  // accepted
}

TEST(HighlightErrors, TableAccessors) {
    Table t(kSmall);
    el_table_info info{};
    EXPECT_FAILS(el_highlight_table_get_info(nullptr, &info), EL_ERR_NULL_POINTER, "table");
    EXPECT_FAILS(el_highlight_table_get_info(t.t, nullptr), EL_ERR_NULL_POINTER, "out");
    std::vector<float> buf(64 * 16);
    EXPECT_FAILS(el_highlight_table_copy(nullptr, buf.data(), buf.size()), EL_ERR_NULL_POINTER, "table");
    EXPECT_FAILS(el_highlight_table_copy(t.t, nullptr, buf.size()), EL_ERR_NULL_POINTER, "out");
    EXPECT_FAILS(el_highlight_table_copy(t.t, buf.data(), buf.size() - 1), EL_ERR_BUFFER_TOO_SMALL, "1024");
    EXPECT_EQ(el_highlight_table_copy(t.t, buf.data(), buf.size()), EL_OK);
    float v = 0;
    EXPECT_FAILS(el_highlight_table_lookup(nullptr, 0.1f, 2, &v), EL_ERR_NULL_POINTER, "table");
    EXPECT_FAILS(el_highlight_table_lookup(t.t, 0.1f, 2, nullptr), EL_ERR_NULL_POINTER, "out");
    EXPECT_FAILS(el_highlight_table_lookup(t.t, kNaN, 2, &v), EL_ERR_NON_FINITE, "phi");
    EXPECT_FAILS(el_highlight_table_lookup(t.t, -kInf, 2, &v), EL_ERR_NON_FINITE, "phi");
    EXPECT_FAILS(el_highlight_table_lookup(t.t, 1.6f, 2, &v), EL_ERR_INVALID_ARGUMENT, "phi = 1.6");
    EXPECT_FAILS(el_highlight_table_lookup(t.t, 0.1f, kNaN, &v), EL_ERR_NON_FINITE, "m");
    EXPECT_FAILS(el_highlight_table_lookup(t.t, 0.1f, 0.5f, &v), EL_ERR_INVALID_ARGUMENT, "m = 0.5");
    EXPECT_FAILS(el_highlight_table_lookup(t.t, 0.1f, 10002, &v), EL_ERR_INVALID_ARGUMENT, "m = 10002");
    EXPECT_EQ(el_highlight_table_lookup(t.t, 1.57079637f, 10001, &v), EL_OK);  // float pi/2
    Table paper({EL_TABLE_PAPER, 64, 16, 0.0f});
    EXPECT_FAILS(el_highlight_table_lookup(paper.t, 0.1f, 16.5f, &v), EL_ERR_INVALID_ARGUMENT, "[1, 16]");
}

TEST(HighlightErrors, CosPowerFunctions) {
    double v = 0;
    const double nan = std::nan("");
    EXPECT_FAILS(el_cos_power_integral(0.1, 2, nullptr), EL_ERR_NULL_POINTER, "out");
    EXPECT_FAILS(el_cos_power_integral(nan, 2, &v), EL_ERR_NON_FINITE, "phi");
    EXPECT_FAILS(el_cos_power_integral(INFINITY, 2, &v), EL_ERR_NON_FINITE, "phi");
    EXPECT_FAILS(el_cos_power_integral(1.58, 2, &v), EL_ERR_INVALID_ARGUMENT, "phi = 1.58");
    EXPECT_FAILS(el_cos_power_integral(-2, 2, &v), EL_ERR_INVALID_ARGUMENT, "phi = -2");
    EXPECT_FAILS(el_cos_power_integral(0.1, nan, &v), EL_ERR_NON_FINITE, "m");
    EXPECT_FAILS(el_cos_power_integral(0.1, -1, &v), EL_ERR_INVALID_ARGUMENT, "m = -1");
    EXPECT_FAILS(el_cos_power_integral(0.1, 1e10, &v), EL_ERR_INVALID_ARGUMENT, "m = 1e+10");
    EXPECT_EQ(el_cos_power_integral(double(1.57079637f), 3, &v), EL_OK);  // float pi/2 accepted
    EXPECT_NEAR(v, 2.0 / 3.0, 1e-15);

    EXPECT_FAILS(el_cos_power_sin_integral(0, 1, 2, nullptr), EL_ERR_NULL_POINTER, "out");
    EXPECT_FAILS(el_cos_power_sin_integral(nan, 1, 2, &v), EL_ERR_NON_FINITE, "a");
    EXPECT_FAILS(el_cos_power_sin_integral(0, -INFINITY, 2, &v), EL_ERR_NON_FINITE, "b");
    EXPECT_FAILS(el_cos_power_sin_integral(0, 1, nan, &v), EL_ERR_NON_FINITE, "n");
    EXPECT_FAILS(el_cos_power_sin_integral(2, 1, 2, &v), EL_ERR_INVALID_ARGUMENT, "a = 2");
    EXPECT_FAILS(el_cos_power_sin_integral(0, -1.6, 2, &v), EL_ERR_INVALID_ARGUMENT, "b = -1.6");
    EXPECT_FAILS(el_cos_power_sin_integral(0, 1, -0.5, &v), EL_ERR_INVALID_ARGUMENT, "n = -0.5");
}

TEST(HighlightErrors, Weight) {
    float w = 0;
    EXPECT_FAILS(el_highlight_weight(1, 1, 1, 1, nullptr), EL_ERR_NULL_POINTER, "out_w");
    EXPECT_FAILS(el_highlight_weight(kNaN, 1, 1, 1, &w), EL_ERR_NON_FINITE, "K");
    EXPECT_FAILS(el_highlight_weight(1, kInf, 1, 1, &w), EL_ERR_NON_FINITE, "r_e");
    EXPECT_FAILS(el_highlight_weight(1, 1, kNaN, 1, &w), EL_ERR_NON_FINITE, "d");
    EXPECT_FAILS(el_highlight_weight(1, 1, 1, kNaN, &w), EL_ERR_NON_FINITE, "r_max");
    EXPECT_FAILS(el_highlight_weight(-1, 1, 1, 1, &w), EL_ERR_INVALID_ARGUMENT, "K = -1");
    EXPECT_FAILS(el_highlight_weight(1, -1, 1, 1, &w), EL_ERR_INVALID_ARGUMENT, "r_e = -1");
    EXPECT_FAILS(el_highlight_weight(1, 1, 0, 1, &w), EL_ERR_INVALID_ARGUMENT, "d = 0");
    EXPECT_FAILS(el_highlight_weight(1, 1, -2, 1, &w), EL_ERR_INVALID_ARGUMENT, "d = -2");
    EXPECT_FAILS(el_highlight_weight(1, 1, 1, -1, &w), EL_ERR_INVALID_ARGUMENT, "r_max = -1");
}

// Each bad input to eval, batch and reference; `field` must appear in the message.
struct BadInput {
    const char* field;
    el_status status;
    void (*spoil)(el_highlight_input&);
};

const BadInput kBadInputs[] = {
    {"point", EL_ERR_NON_FINITE, [](el_highlight_input& in) { in.point[1] = kNaN; }},
    {"edge_dir", EL_ERR_NON_FINITE, [](el_highlight_input& in) { in.edge_dir[0] = kInf; }},
    {"n1", EL_ERR_NON_FINITE, [](el_highlight_input& in) { in.n1[2] = kNaN; }},
    {"n2", EL_ERR_NON_FINITE, [](el_highlight_input& in) { in.n2[0] = -kInf; }},
    {"eye", EL_ERR_NON_FINITE, [](el_highlight_input& in) { in.eye[0] = kNaN; }},
    {"view_dir", EL_ERR_NON_FINITE, [](el_highlight_input& in) { in.view_dir[2] = kNaN; }},
    {"light", EL_ERR_NON_FINITE, [](el_highlight_input& in) { in.light[1] = kInf; }},
    {"shininess", EL_ERR_NON_FINITE, [](el_highlight_input& in) { in.shininess = kNaN; }},
    {"radius", EL_ERR_NON_FINITE, [](el_highlight_input& in) { in.radius = kInf; }},
    {"K", EL_ERR_NON_FINITE, [](el_highlight_input& in) { in.K = kNaN; }},
    {"ortho_scale", EL_ERR_NON_FINITE, [](el_highlight_input& in) { in.ortho_scale = kNaN; }},
    {"projection = 2", EL_ERR_INVALID_ARGUMENT, [](el_highlight_input& in) { in.projection = 2; }},
    {"light_is_point = 7", EL_ERR_INVALID_ARGUMENT, [](el_highlight_input& in) { in.light_is_point = 7; }},
    {"edge_dir is the zero", EL_ERR_INVALID_ARGUMENT, [](el_highlight_input& in) { in.edge_dir[2] = 0; }},
    {"n1 is the zero", EL_ERR_INVALID_ARGUMENT, [](el_highlight_input& in) { in.n1[0] = 0; }},
    {"n2 is the zero", EL_ERR_INVALID_ARGUMENT, [](el_highlight_input& in) { in.n2[1] = 0; }},
    {"n1 is parallel to edge_dir", EL_ERR_INVALID_ARGUMENT,
     [](el_highlight_input& in) { in.n1[0] = 1e-5f, in.n1[2] = 1; }},
    {"eye - ", EL_ERR_INVALID_ARGUMENT, [](el_highlight_input& in) { in.eye[0] = in.eye[1] = 0; }},
    {"point overflows", EL_ERR_INVALID_ARGUMENT, [](el_highlight_input& in) { in.eye[0] = 3e38f, in.point[0] = -3e38f; }},
    {"view_dir is the zero", EL_ERR_INVALID_ARGUMENT,
     [](el_highlight_input& in) { in.projection = EL_ORTHOGRAPHIC, in.view_dir[0] = in.view_dir[1] = 0; }},
    {"ortho_scale = 0", EL_ERR_INVALID_ARGUMENT,
     [](el_highlight_input& in) { in.projection = EL_ORTHOGRAPHIC, in.ortho_scale = 0; }},
    {"light is the zero", EL_ERR_INVALID_ARGUMENT, [](el_highlight_input& in) { in.light[0] = in.light[1] = 0; }},
    {"light - ", EL_ERR_INVALID_ARGUMENT,
     [](el_highlight_input& in) { in.light_is_point = 1, in.light[0] = in.light[1] = 0; }},
    {"shininess = 0.5", EL_ERR_INVALID_ARGUMENT, [](el_highlight_input& in) { in.shininess = 0.5f; }},
    {"shininess = 100000", EL_ERR_INVALID_ARGUMENT, [](el_highlight_input& in) { in.shininess = 1e5f; }},
    {"radius = -1", EL_ERR_INVALID_ARGUMENT, [](el_highlight_input& in) { in.radius = -1; }},
    {"K = -2", EL_ERR_INVALID_ARGUMENT, [](el_highlight_input& in) { in.K = -2; }},
};

TEST(HighlightErrors, Eval) {
    Table t(kSmall);
    el_highlight_input in = valid_input();
    el_highlight_result r{};
    EXPECT_FAILS(el_highlight_eval(nullptr, &in, &r), EL_ERR_NULL_POINTER, "table");
    EXPECT_FAILS(el_highlight_eval(t.t, nullptr, &r), EL_ERR_NULL_POINTER, "in");
    EXPECT_FAILS(el_highlight_eval(t.t, &in, nullptr), EL_ERR_NULL_POINTER, "out");
    ASSERT_EQ(el_highlight_eval(t.t, &in, &r), EL_OK) << el_last_error();
    EXPECT_STREQ(el_last_error(), "");
    for (const BadInput& b : kBadInputs) {
        el_highlight_input bad = valid_input();
        b.spoil(bad);
        EXPECT_FAILS(el_highlight_eval(t.t, &bad, &r), b.status, std::string("in->") + b.field);
        EXPECT_NE(std::string(el_last_error()).find("el_highlight_eval"), std::string::npos);
    }
    // Beyond the paper table's exponents.
    Table paper({EL_TABLE_PAPER, 64, 128, 0.0f});
    in.shininess = 127.5f;
    EXPECT_FAILS(el_highlight_eval(paper.t, &in, &r), EL_ERR_INVALID_ARGUMENT, "shininess = 127.5");
    in.shininess = 127;
    EXPECT_EQ(el_highlight_eval(paper.t, &in, &r), EL_OK);
}

TEST(HighlightErrors, EvalBatch) {
    Table t(kSmall);
    std::vector<el_highlight_input> in(6, valid_input());
    std::vector<el_highlight_result> out(6);
    EXPECT_FAILS(el_highlight_eval_batch(nullptr, in.data(), 6, out.data()), EL_ERR_NULL_POINTER, "table");
    EXPECT_FAILS(el_highlight_eval_batch(t.t, nullptr, 6, out.data()), EL_ERR_NULL_POINTER, "in");
    EXPECT_FAILS(el_highlight_eval_batch(t.t, in.data(), 6, nullptr), EL_ERR_NULL_POINTER, "out");
    EXPECT_FAILS(el_highlight_eval_batch(t.t, in.data(), 0, out.data()), EL_ERR_INVALID_COUNT, "count");
    for (const BadInput& b : kBadInputs) {
        std::vector<el_highlight_input> bad = in;
        b.spoil(bad[3]);
        for (auto& o : out) o.specular = -7;  // nothing is written when any input is bad
        EXPECT_FAILS(el_highlight_eval_batch(t.t, bad.data(), 6, out.data()), b.status,
                     std::string("in[3].") + b.field);
        for (const auto& o : out) EXPECT_EQ(o.specular, -7.0f);
    }
    ASSERT_EQ(el_highlight_eval_batch(t.t, in.data(), 6, out.data()), EL_OK);
    el_highlight_result one{};
    ASSERT_EQ(el_highlight_eval(t.t, &in[0], &one), EL_OK);
    EXPECT_EQ(std::memcmp(&one, &out[5], sizeof one), 0);
}

TEST(HighlightErrors, Reference) {
    el_highlight_input in = valid_input();
    el_highlight_result r{};
    EXPECT_FAILS(el_highlight_reference(nullptr, &r), EL_ERR_NULL_POINTER, "in");
    EXPECT_FAILS(el_highlight_reference(&in, nullptr), EL_ERR_NULL_POINTER, "out");
    for (const BadInput& b : kBadInputs) {
        if (std::string(b.field) == "shininess = 100000") continue;  // the reference takes it
        el_highlight_input bad = valid_input();
        b.spoil(bad);
        EXPECT_FAILS(el_highlight_reference(&bad, &r), b.status, std::string("in->") + b.field);
    }
    in.shininess = 2e6f;
    EXPECT_FAILS(el_highlight_reference(&in, &r), EL_ERR_INVALID_ARGUMENT, "shininess = 2000000");
}

}  // namespace
