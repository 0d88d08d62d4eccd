// Arrays for the per-mesh data of big meshes. A block of 2 MiB or more is mapped on its own and
// marked for transparent huge pages: fresh memory costs one page fault per 4 KiB otherwise, and
// under a hypervisor the faults of a 1M-triangle mesh took as long as building its topology.
// Freeing unmaps the block, so the host gets the memory back at once. Smaller blocks use the
// ordinary heap.
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace el {

namespace big_block {
constexpr size_t kMinBytes = size_t(2) << 20;  // one huge page
void* allocate(size_t bytes);                  // kMinBytes or more; throws std::bad_alloc
void release(void* p, size_t bytes);
}  // namespace big_block

// Zero = false leaves elements made by resize() unset (the builder writes every one it sizes).
template <class T, bool Zero = true>
struct BigAllocator {
    using value_type = T;
    template <class U> struct rebind { using other = BigAllocator<U, Zero>; };

    BigAllocator() = default;
    template <class U> BigAllocator(const BigAllocator<U, Zero>&) noexcept {}

    T* allocate(size_t n) {
        if (n > size_t(-1) / sizeof(T)) throw std::bad_alloc();
        if (n * sizeof(T) >= big_block::kMinBytes) return static_cast<T*>(big_block::allocate(n * sizeof(T)));
        return std::allocator<T>().allocate(n);
    }
    void deallocate(T* p, size_t n) noexcept {
        if (n * sizeof(T) >= big_block::kMinBytes) big_block::release(p, n * sizeof(T));
        else std::allocator<T>().deallocate(p, n);
    }
    template <class U, class... Args> void construct(U* p, Args&&... args) {
        if constexpr (!Zero && sizeof...(Args) == 0) ::new (static_cast<void*>(p)) U;
        else ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
    template <class U> bool operator==(const BigAllocator<U, Zero>&) const noexcept { return true; }
    template <class U> bool operator!=(const BigAllocator<U, Zero>&) const noexcept { return false; }
};

template <class T> using BigArray = std::vector<T, BigAllocator<T>>;
template <class T> using UnsetBigArray = std::vector<T, BigAllocator<T, false>>;

}  // namespace el
