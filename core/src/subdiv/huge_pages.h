#pragma once
// Large buffers backed by 2 MB pages. Memory returned to the kernel between refinements (a new
// process, or glibc giving back a large block) is faulted in again page by page when first
// written, and on a virtual machine each 4 KB fault costs about 15 microseconds: measured here,
// 64 MB first touched in 250 ms with 4 KB pages and in 5.5 ms with 2 MB pages, which Linux's
// transparent huge pages give a range marked MADV_HUGEPAGE (their "madvise" mode, Debian's
// default). The streaming drivers mark each large array before they first write it.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace crossdiv::detail {

/// Marks the whole 2 MB pages inside [p, p + bytes) for huge pages. Call it before the memory
/// is first written; nothing below 2 MB or off Linux. A hint: where the kernel has no huge page
/// to give, the range is backed as before.
inline void prefer_huge_pages(const void* p, size_t bytes) {
#ifdef __linux__
    constexpr std::uintptr_t kHuge = std::uintptr_t{1} << 21;
    if (bytes < kHuge) return;
    const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
    const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kHuge - 1);
    if (end > begin) (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
    (void)p;
    (void)bytes;
#endif
}

/// An allocation for `bytes` of uninitialized memory, released with release_huge_pages. From
/// 2 MB on, the array lies in whole 2 MB pages marked for huge pages: a block from malloc starts
/// anywhere, and its parts before its first 2 MB boundary and after its last are faulted in by
/// 4 KB pages, up to 4 MB of them per array. The block is a plain malloc of 4 MB more than the
/// array, never written outside the pages the array uses: the margin costs address space only,
/// and malloc reuses the block whole when memory is kept between refinements (an aligned_alloc
/// leaves pieces that it does not reuse: measured 2,000 new faults a warm run, 1.4x its time).
/// The array starts a few cache lines past the boundary, a different number for each array:
/// arrays that all start at the same offset within a page are read at the same index by one
/// loop and contend for the same cache sets.
inline void* allocate_on_huge_pages(size_t bytes) {
    constexpr size_t kHuge = size_t{1} << 21;
    if (bytes < kHuge) {
        void* p = std::malloc(bytes == 0 ? 1 : bytes);
        if (!p) throw std::bad_alloc();
        return p;
    }
    static std::atomic<unsigned> arrays{0};
    const size_t offset = size_t{arrays.fetch_add(1, std::memory_order_relaxed) % 16} * 256 + 64;
    const size_t pages = (bytes + offset + kHuge - 1) & ~(kHuge - 1);
    char* block = static_cast<char*>(std::malloc(pages + 2 * kHuge));
    if (!block) throw std::bad_alloc();
    char* first = reinterpret_cast<char*>((reinterpret_cast<std::uintptr_t>(block) + kHuge - 1) & ~(kHuge - 1));
    prefer_huge_pages(first, pages);
    char* array = first + offset;
    std::memcpy(array - sizeof block, &block, sizeof block);  // for release_huge_pages
    return array;
}

/// Releases what allocate_on_huge_pages gave for `bytes`.
inline void release_huge_pages(void* p, size_t bytes) {
    constexpr size_t kHuge = size_t{1} << 21;
    if (p && bytes >= kHuge) std::memcpy(&p, static_cast<char*>(p) - sizeof p, sizeof p);
    std::free(p);
}

/// The deleter of an array from allocate_on_huge_pages: it knows the array's size in bytes.
struct HugePagesDeleter {
    size_t bytes = 0;
    void operator()(void* p) const { release_huge_pages(p, bytes); }
};

/// `v` sized for `n` elements that the caller writes next (any it held are dropped when it has
/// to grow), its new storage marked for huge pages before the resize makes the elements
/// (zeros for ints, nothing for Eigen's vectors).
template <class T, class A>
void resize_on_huge_pages(std::vector<T, A>& v, size_t n) {
    if (n > v.capacity()) {
        v.clear();
        v.reserve(n);
        prefer_huge_pages(v.data(), n * sizeof(T));
    }
    v.resize(n);
}

}  // namespace crossdiv::detail
