// The allocator behind big per-mesh arrays: blocks of 2 MiB or more are their own huge-page
// aligned mappings, smaller ones come from the heap; contents survive growth either way.
#include "big_array.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

TEST(BigArray, BigBlocksStartOnAHugePageBoundaryAndKeepTheirContents) {
    el::UnsetBigArray<uint32_t> a(1000);  // heap
    std::iota(a.begin(), a.end(), 0u);
    a.resize(3u << 20);  // 12 MiB: its own mapping
#if defined(__linux__)
    EXPECT_EQ(reinterpret_cast<uintptr_t>(a.data()) % el::big_block::kMinBytes, 0u);
#else
    // Only Linux's path maps big blocks on a 2 MiB boundary (transparent huge pages); elsewhere
    // they come page-aligned from operator new (big_array.cpp), checked here instead.
    EXPECT_EQ(reinterpret_cast<uintptr_t>(a.data()) % 4096u, 0u);
#endif
    for (uint32_t i = 0; i < 1000; ++i) ASSERT_EQ(a[i], i) << "copied on growth";
    a.back() = 7u;  // the last element is mapped and writable
    EXPECT_EQ(a.back(), 7u);
    a.resize(500);
    a.shrink_to_fit();  // back to the heap
    EXPECT_EQ(a[499], 499u);
}

TEST(BigArray, ZeroingArraysZeroWhatResizeAdds) {
    el::BigArray<uint64_t> z(10, 5u);
    z.resize(1u << 20);  // 8 MiB
    EXPECT_EQ(z[9], 5u);
    EXPECT_EQ(z[10], 0u);
    EXPECT_EQ(z.back(), 0u);
    EXPECT_EQ(std::accumulate(z.begin(), z.end(), uint64_t(0)), 50u);
}
