#pragma once
// Large buffers backed by 2 MB pages. Memory returned to the kernel between refinements (a new
// process, or glibc giving back a large block) is faulted in again page by page when first
// written, and on a virtual machine each 4 KB fault costs about 15 microseconds: measured here,
// 64 MB first touched in 250 ms with 4 KB pages and in 5.5 ms with 2 MB pages, which Linux's
// transparent huge pages give a range marked MADV_HUGEPAGE (their "madvise" mode, Debian's
// default). The streaming drivers mark each large array before they first write it.

#include <cstddef>
#include <cstdint>
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
