#include "big_array.hpp"

#include <cstdint>
#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace el::big_block {

namespace {
constexpr size_t kSmallPage = 4096;
size_t mapped_length(size_t bytes) { return (bytes + kSmallPage - 1) & ~(kSmallPage - 1); }
}  // namespace

#if defined(__linux__)

void* allocate(size_t bytes) {
    // Map one huge page more than needed and trim both ends, so the block starts on a 2 MiB
    // boundary and the kernel can back it with huge pages from the first touch.
    const size_t length = mapped_length(bytes);
    if (length > SIZE_MAX - kMinBytes) throw std::bad_alloc();
    void* raw = mmap(nullptr, length + kMinBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED) throw std::bad_alloc();
    const uintptr_t base = reinterpret_cast<uintptr_t>(raw);
    const uintptr_t start = (base + kMinBytes - 1) & ~uintptr_t(kMinBytes - 1);
    if (start > base) munmap(raw, start - base);
    const uintptr_t tail = start + length, end = base + length + kMinBytes;
    if (end > tail) munmap(reinterpret_cast<void*>(tail), end - tail);
    madvise(reinterpret_cast<void*>(start), length, MADV_HUGEPAGE);  // advice: ignored where THP is off
    return reinterpret_cast<void*>(start);
}

void release(void* p, size_t bytes) { munmap(p, mapped_length(bytes)); }

#else

void* allocate(size_t bytes) { return ::operator new(bytes, std::align_val_t(kSmallPage)); }
void release(void* p, size_t) { ::operator delete(p, std::align_val_t(kSmallPage)); }

#endif

}  // namespace el::big_block
