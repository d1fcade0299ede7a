// A chord label's run: its slots by place. Extraction's runs share its pool of chord slots (no
// copy); a run an edit makes (most: a hex push's three-slot chord middles) holds up to four slots
// in place, so making one allocates nothing and reading it stays on the line of its entry.
#pragma once

#include <span>

#include "complex/small_vector.hpp"
#include "dual/dual.hpp"

namespace hexdual::tracker {

class LabelRun {
 public:
  static constexpr size_t kInPlace = 4;
  LabelRun() = default;
  // Shares a pooled list's pool; copies a list that owns its slots.
  explicit LabelRun(const PooledSlots& slots) {
    if (slots.pooled()) {
      pool_ = slots.pool();
      begin_ = slots.poolBegin();
      size_ = slots.size();
    } else {
      assign(slots.begin(), slots.end());
    }
  }
  std::span<const Slot> view() const {
    return pool_ ? std::span<const Slot>(pool_->data() + begin_, size_) : std::span<const Slot>(own_);
  }
  size_t size() const { return pool_ ? size_ : own_.size(); }
  const Slot& operator[](size_t i) const { return pool_ ? (*pool_)[begin_ + i] : own_[i]; }
  size_t capacity() const { return own_.capacity(); }  // of its own slots (0 while pooled)
  void assign(const Slot* first, const Slot* last) {
    pool_.reset();
    own_.assign(first, last);
  }
  void clear() {  // keeps its own room
    pool_.reset();
    own_.clear();
  }
  void release() {  // lets its room go
    pool_.reset();
    own_ = SmallVector<Slot, kInPlace>();
  }

 private:
  PooledSlots::Pool pool_;
  size_t begin_ = 0, size_ = 0;
  SmallVector<Slot, kInPlace> own_;
};

}  // namespace hexdual::tracker
