// Large per-hex and per-slot arrays ask the kernel for transparent huge pages before they are
// first written: on Linux a fresh 4 KiB page costs a fault each (about 13 µs on a VM), so a
// 1M-hex mesh's first build paid 3x its warm time in page faults; a 2 MiB page is one fault.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <cstdint>
#include <iterator>
#include <type_traits>
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

template <class T>
struct HugePageAllocator;

// v.reserve(n), with huge pages advised for the new storage before anything writes it (a
// HugePageAllocator has advised all of it already).
template <class T, class A>
void reserveHuge(std::vector<T, A>& v, size_t n) {
  if (v.capacity() >= n) return;
  v.reserve(n);
  if constexpr (!std::is_same_v<A, HugePageAllocator<T>>) adviseHugePages(v.data() + v.size(), (n - v.size()) * sizeof(T));
}

// Room for n entries and an eighth more (as Complex::reserve leaves for new hexes), so that arrays
// kept per hex grow once every n/8 new hexes, not on the first step after a build.
inline size_t withHeadroom(size_t n) { return n + n / 8 + 64; }

// v.assign(n, x) for a per-hex or per-slot array: new storage (with headroom) is reserved by
// reserveHuge before anything writes it.
template <class T, class A>
void assignHuge(std::vector<T, A>& v, size_t n, const T& x) {
  if (v.capacity() < n) {
    std::vector<T, A>().swap(v);
    reserveHuge(v, withHeadroom(n));
  }
  v.assign(n, x);
}

// The room an array that grows with the complex takes when it holds `had` entries and needs n:
// twice `had` while it is under 2^20 entries, so that a mesh grown step by step from a few
// thousand hexes copies (and page-faults) each array a few times, not once every eighth more;
// an eighth more above that, so that a 1M-hex mesh reserves 12.5% more, not 100%.
inline size_t grownCapacity(size_t n, size_t had) {
  constexpr size_t kDoubleBelow = size_t(1) << 20;
  return std::max(withHeadroom(n), had < kDoubleBelow ? 2 * had : 0);
}

// v.resize(n, x) for a per-hex or per-slot array that grows with the complex: new storage gets
// headroom (grownCapacity) and huge-page advice before anything is moved into it.
template <class T, class A>
void growHuge(std::vector<T, A>& v, size_t n, const T& x = T()) {
  if (v.size() >= n) return;
  if (v.capacity() < n) {
    std::vector<T, A> w;
    reserveHuge(w, grownCapacity(n, v.capacity()));
    w.assign(std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
    v.swap(w);
  }
  v.resize(n, x);
}

// Room for as many new entries as an array has, reserved before it is filled: for the arrays kept
// per chord and per chord label, which an edited mesh grows (a pillow adds two closed chords, a hex
// push one, a cut chord a label). Reserved address space is not memory until written, so the room
// costs nothing until used; without it a 1M-hex mesh's first few thousand steps re-copied (and
// page-faulted, about 10 µs a page on a VM) a few MB of per-chord arrays.
template <class T, class A>
void reserveRoom(std::vector<T, A>& v, size_t n) {
  reserveHuge(v, 2 * n + 64);
}

// The allocator of HugeVector (below): from 1 MiB up, storage is whole 2 MiB pages, aligned and
// advised, so its first writes take one fault per 2 MiB. reserveHuge's advice on a plain vector
// covers only the 2 MiB-aligned middle: the unaligned first and last MiB or so of every array stayed
// in 4 KiB pages, a fault each (a cold 1M-hex build still took 11,000 faults; with this, 2,300).
// Below 1 MiB, and where there are no huge pages, it is operator new.
template <class T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) {}
  static constexpr size_t kHuge = size_t(2) << 20;
  static bool huge(size_t n) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    return n * sizeof(T) >= kHuge / 2;
#else
    (void)n;
    return false;
#endif
  }
  // The storage starts at the first 2 MiB boundary inside a plain allocation 2 MiB larger, which
  // is remembered just before it. (aligned_alloc asks glibc for the size plus the alignment on
  // every call, so the previous build's freed arrays never fitted and each repetition grew the heap.)
  // It fits: malloc aligns to max_align_t, so the boundary after raw + 8 is at most raw + 2 MiB.
  static_assert(alignof(std::max_align_t) >= sizeof(void*));
  T* allocate(size_t n) {
    if (!huge(n)) return static_cast<T*>(::operator new(n * sizeof(T)));
    const size_t bytes = (n * sizeof(T) + kHuge - 1) & ~(kHuge - 1);
    char* raw = static_cast<char*>(std::malloc(bytes + kHuge));
    if (!raw) throw std::bad_alloc();
    char* p = reinterpret_cast<char*>((reinterpret_cast<uintptr_t>(raw) + sizeof(void*) + kHuge - 1) & ~(kHuge - 1));
    reinterpret_cast<char**>(p)[-1] = raw;
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    madvise(p, bytes, MADV_HUGEPAGE);
#endif
    return reinterpret_cast<T*>(p);
  }
  void deallocate(T* p, size_t n) {
    if (huge(n))
      std::free(reinterpret_cast<char**>(p)[-1]);
    else
      ::operator delete(p);
  }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const {
    return true;
  }
};

// The per-hex and per-slot arrays of a complex and its dual: a std::vector whose storage, from 1 MiB
// up, is whole advised 2 MiB pages (a 1M-hex mesh's arrays are 3-24 MB each; in plain vectors the
// unaligned first and last MiB or so of each stayed in 4 KiB pages, a fault each).
// Where there are no huge pages to advise (WebAssembly) it is std::vector itself: the same code,
// not a second instantiation of every vector operation in the module.
#if defined(__linux__) && defined(MADV_HUGEPAGE)
template <class T>
using HugeVector = std::vector<T, HugePageAllocator<T>>;
#else
template <class T>
using HugeVector = std::vector<T>;
#endif

}  // namespace hexdual
