// Large per-hex and per-slot arrays ask the kernel for transparent huge pages before they are
// first written: on Linux a fresh 4 KiB page costs a fault each (about 13 µs on a VM), so a
// 1M-hex mesh's first build paid 3x its warm time in page faults; a 2 MiB page is one fault.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>
#if __has_include(<sys/mman.h>)
#include <sys/mman.h>
#endif

namespace hexdual {

// Advises huge pages for the 2 MiB-aligned part of [p, p + bytes); a no-op where unsupported
// or below 4 MiB (the advice is a hint: memory and results are the same either way).
inline void adviseHugePages(const void* p, size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr uintptr_t kHuge = uintptr_t(2) << 20;
  if (bytes < 2 * kHuge) return;
  const uintptr_t begin = (reinterpret_cast<uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
  const uintptr_t end = (reinterpret_cast<uintptr_t>(p) + bytes) & ~(kHuge - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

// v.reserve(n), with huge pages advised for the new storage before anything writes it.
template <class T>
void reserveHuge(std::vector<T>& v, size_t n) {
  if (v.capacity() >= n) return;
  v.reserve(n);
  adviseHugePages(v.data() + v.size(), (n - v.size()) * sizeof(T));
}

// v.assign(n, x) into storage reserved by reserveHuge.
template <class T>
void assignHuge(std::vector<T>& v, size_t n, const T& x) {
  if (v.capacity() < n) {
    std::vector<T>().swap(v);
    reserveHuge(v, n);
  }
  v.assign(n, x);
}

}  // namespace hexdual
