// Large arrays written whole right after allocation (a complex's per-hex arrays, the dual's per-slot
// labels): reserved with a request for transparent huge pages, so that fresh memory faults in once
// per 2 MiB instead of once per 4 KiB page (about 13 us a fault on a VM, most of a cold build).
#pragma once
#include <cstdint>
#include <vector>
#if defined(__linux__) && !defined(__EMSCRIPTEN__)
#include <sys/mman.h>
#endif

namespace hexdual {

// v.reserve(n), then madvise(MADV_HUGEPAGE) on the whole 2 MiB pages of the reservation. Only
// advice: where it is not honoured (other systems, THP off, wasm) nothing changes.
template <class T>
void reserveLarge(std::vector<T>& v, size_t n) {
  v.reserve(n);
#if defined(__linux__) && !defined(__EMSCRIPTEN__) && defined(MADV_HUGEPAGE)
  constexpr uintptr_t kHuge = uintptr_t(2) << 20;
  const uintptr_t from = (uintptr_t(v.data()) + kHuge - 1) & ~(kHuge - 1);
  const uintptr_t to = uintptr_t(v.data() + v.capacity()) & ~(kHuge - 1);
  if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_HUGEPAGE);
#endif
}

}  // namespace hexdual
