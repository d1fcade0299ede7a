// SmallVector<T, N>: a vector of trivially copyable T that holds its first N entries in place and
// moves to the heap only beyond them. For the tracker's per-chord and per-label lists (a chord's
// pieces, a label's cuts), which have one or two entries almost always: with std::vector every
// chord cut or made allocated, and every read of the list was a second cache line away.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <span>
#include <type_traits>

namespace hexdual {

template <class T, uint32_t N>
class SmallVector {
  static_assert(std::is_trivially_copyable_v<T> && N > 0);

 public:
  SmallVector() = default;
  SmallVector(const SmallVector& o) {
    if (o.onHeap()) {
      append(o.begin(), o.end());
    } else {  // the whole in-place room: a fixed-size copy
      std::memcpy(local_, o.local_, sizeof(local_));
      size_ = o.size_;
    }
  }
  SmallVector(SmallVector&& o) noexcept { take(o); }
  SmallVector& operator=(const SmallVector& o) {
    if (this != &o) assign(o.begin(), o.end());
    return *this;
  }
  SmallVector& operator=(SmallVector&& o) noexcept {
    if (this != &o) {
      freeHeap();
      take(o);
    }
    return *this;
  }
  ~SmallVector() { freeHeap(); }

  T* data() { return data_; }
  const T* data() const { return data_; }
  size_t size() const { return size_; }
  size_t capacity() const { return cap_; }
  bool empty() const { return size_ == 0; }
  T* begin() { return data(); }
  T* end() { return data() + size_; }
  const T* begin() const { return data(); }
  const T* end() const { return data() + size_; }
  T& operator[](size_t i) { return data()[i]; }
  const T& operator[](size_t i) const { return data()[i]; }
  T& back() { return data()[size_ - 1]; }
  const T& back() const { return data()[size_ - 1]; }
  operator std::span<const T>() const { return {data(), size_}; }

  void clear() { size_ = 0; }  // keeps its room
  void push_back(const T& x) {
    const T copy = x;  // x may be an entry of this list, which growing moves
    if (size_ == cap_) grow(2 * size_t(cap_));
    data()[size_++] = copy;
  }
  void assign(size_t n, const T& x) {
    clear();
    if (n > cap_) grow(n);
    std::fill_n(data(), n, x);
    size_ = uint32_t(n);
  }
  void assign(const T* first, const T* last) {
    clear();
    append(first, last);
  }
  T* erase(T* at) {
    std::memmove(at, at + 1, size_t(end() - at - 1) * sizeof(T));
    --size_;
    return at;
  }

 private:
  bool onHeap() const { return cap_ > N; }
  void append(const T* first, const T* last) {
    const size_t n = size_t(last - first);
    if (size_ + n > cap_) grow(std::max(size_ + n, 2 * size_t(cap_)));
    if (n) std::memmove(data() + size_, first, n * sizeof(T));  // assign's range may lie in this list (it never grows then)
    size_ += uint32_t(n);
  }
  [[gnu::noinline]] void grow(size_t room) {  // the rare path, kept out of the callers
    T* heap = static_cast<T*>(std::malloc(room * sizeof(T)));
    if (!heap) throw std::bad_alloc();
    if (size_) std::memcpy(heap, data(), size_ * sizeof(T));
    freeHeap();
    data_ = heap;
    cap_ = uint32_t(room);
  }
  void freeHeap() {
    if (onHeap()) std::free(data_);
    data_ = local_;
    cap_ = N;
  }
  void take(SmallVector& o) {  // this holds no heap storage
    size_ = o.size_;
    cap_ = o.cap_;
    if (o.onHeap()) data_ = o.data_;
    else std::memcpy(local_, o.local_, sizeof(local_));
    o.data_ = o.local_;
    o.size_ = 0;
    o.cap_ = N;
  }

  T* data_ = local_;  // local_ or the heap: no branch on reading
  uint32_t size_ = 0, cap_ = N;
  T local_[N];
};

}  // namespace hexdual
