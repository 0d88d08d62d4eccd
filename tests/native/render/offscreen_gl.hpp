// The one OSMesa context of the render test binary, and a fixture that fails (never skips) on a
// machine without it.
#pragma once

#include "osmesa_context.hpp"

#include <gtest/gtest.h>

#include <exception>
#include <memory>

// Created on first use and current on this thread from then on; throws saying what is missing.
inline el_tools::OsmesaContext& offscreen_context() {
    static std::unique_ptr<el_tools::OsmesaContext> ctx;
    if (!ctx) ctx = std::make_unique<el_tools::OsmesaContext>();
    return *ctx;
}

class OffscreenGlTest : public ::testing::Test {
protected:
    void SetUp() override {
        try {
            offscreen_context();
        } catch (const std::exception& e) {
            FAIL() << "no offscreen GL: " << e.what();  // a failure, never a silent skip
        }
    }
};
