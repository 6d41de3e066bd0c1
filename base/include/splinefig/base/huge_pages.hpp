#pragma once
// Large buffers (the canvas, a million-point outline, an image handed over from Python) are touched page by page when first
// written; with 4 KiB pages that costs one page fault per 4 KiB, which dominated rendering a
// 1M-point path. Asking for transparent huge pages on such a buffer *before* writing it cuts
// the faults 512-fold. Advice only: without THP support nothing changes.
#include <cstddef>
#include <cstdint>
#include <sys/mman.h>
#include <vector>

namespace splinefig {

inline void advise_huge_pages(const void* data, std::size_t bytes) {
#ifdef MADV_HUGEPAGE
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  if (bytes < 2 * kHuge) return;
  std::uintptr_t b = (reinterpret_cast<std::uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
  std::uintptr_t e = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHuge - 1);
  if (e > b) ::madvise(reinterpret_cast<void*>(b), e - b, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

// Gives back to the system the memory of [data, data + bytes) that will not be read again, in
// whole aligned blocks of 2 MiB inside the range (the size of a huge page, so that no huge page is
// split and kept whole until the kernel reclaims it); the rest of the range stays. A block given
// back reads as zeros if touched again. A buffer read once from end to end (a long outline
// consumed band by band) so holds only what is still ahead.
inline void release_pages(const void* data, std::size_t bytes) {
#ifdef MADV_DONTNEED
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  const std::uintptr_t b = (reinterpret_cast<std::uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t e = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHuge - 1);
  if (e > b) ::madvise(reinterpret_cast<void*>(b), e - b, MADV_DONTNEED);
#else
  (void)data;
  (void)bytes;
#endif
}

// reserve() that advises huge pages for the new, untouched storage.
template <class T, class A>
void reserve_huge(std::vector<T, A>& v, std::size_t n) {
  if (v.capacity() >= n) return;
  v.reserve(n);
  advise_huge_pages(v.data() + v.size(), (v.capacity() - v.size()) * sizeof(T));
}

}  // namespace splinefig
