// Shared by the highlight tests: a table owned for the test's duration, and small setters.
#pragma once

#include <edgelight/edgelight.h>

#include <gtest/gtest.h>

namespace fixtures {

inline constexpr float kInvSqrt2 = 0.70710678f;

// The recommended table unless the test asks for another.
struct Table {
    el_highlight_table* t = nullptr;
    explicit Table(el_table_desc desc = EL_TABLE_DEFAULT_DESC) {
        EXPECT_EQ(el_highlight_table_create(&desc, &t), EL_OK) << el_last_error();
    }
    ~Table() { el_highlight_table_destroy(t); }
    Table(const Table&) = delete;
    Table& operator=(const Table&) = delete;
};

inline void set3(float* d, float x, float y, float z) {
    d[0] = x;
    d[1] = y;
    d[2] = z;
}

}  // namespace fixtures
