// SlotList: a sheet's sorted slot list with edits that wait for the next read (runs handed over by
// a merge, a few additions, removals), merged in one linear pass when read (dual/dual.hpp).
#include <algorithm>

#include "dual/dual.hpp"

namespace hexdual {

PooledSlots::PooledSlots(std::vector<Slot> own) : own_(std::move(own)) {}
// Slot is an aggregate with a trivial destructor: storage from the allocator holds its objects
// once written (no constructor has to run first), and needs no destructor calls.
SlotPool::SlotPool(size_t n) : data_(HugePageAllocator<Slot>().allocate(n)), size_(n) {}
SlotPool::~SlotPool() { HugePageAllocator<Slot>().deallocate(data_, size_); }

PooledSlots::PooledSlots(Pool pool, size_t begin, size_t size) : pool_(std::move(pool)), begin_(begin), size_(size) {}
PooledSlots::PooledSlots(const PooledSlots&) = default;
PooledSlots::PooledSlots(PooledSlots&&) noexcept = default;
PooledSlots& PooledSlots::operator=(const PooledSlots&) = default;
PooledSlots& PooledSlots::operator=(PooledSlots&&) noexcept = default;
PooledSlots::~PooledSlots() = default;

PooledSlots& PooledSlots::operator=(std::vector<Slot> own) {
  pool_.reset();
  own_ = std::move(own);
  return *this;
}

void PooledSlots::clear() {
  pool_.reset();
  own_.clear();
}

void PooledSlots::copyOut() {
  own_.assign(pool_->begin() + std::ptrdiff_t(begin_), pool_->begin() + std::ptrdiff_t(begin_ + size_));
  pool_.reset();
}

bool PooledSlots::equal(std::span<const Slot> a, std::span<const Slot> b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end());
}

SlotList& SlotList::operator=(std::vector<Slot> sorted) {
  ++version_;
  list_ = std::move(sorted);
  runs_.clear();
  adds_.clear();
  gone_.clear();
  size_ = list_.size();
  return *this;
}

void SlotList::clear() {
  ++version_;
  list_.clear();
  runs_.clear();
  adds_.clear();
  gone_.clear();
  size_ = 0;
}

namespace {
// Pending runs, additions and removals kept before a list is merged without being read: few runs,
// and additions or removals up to 256 and half the list, so that merging them stays linear in it
// (with fewer merges of a small sheet's list than at an eighth: bench/README, 2026-12-06).
constexpr size_t kMaxRuns = 16;
bool tooMany(size_t pending, size_t size) { return pending > 256 + size / 2; }

// Merges sorted `run` into sorted `base` in place, from the back (no second buffer).
void mergeInto(std::vector<Slot>& base, const std::vector<Slot>& run) {
  size_t i = base.size(), j = run.size(), k = i + j;
  base.resize(k);
  while (j > 0) base[--k] = i > 0 && run[j - 1] < base[i - 1] ? base[--i] : run[--j];
}
}  // namespace

void SlotList::add(std::span<const Slot> slots) {
  if (slots.empty()) return;
  size_ += slots.size();
  adds_.insert(adds_.end(), slots.begin(), slots.end());  // sorted once, when merged
  if (tooMany(adds_.size(), size_)) settle();
}

void SlotList::absorb(SlotList&& other) {
  if (other.size_ == 0 && other.gone_.empty()) return;
  if (size_ == 0 && runs_.empty() && adds_.empty() && gone_.empty()) {
    const uint64_t v = version_;
    *this = std::move(other);
    version_ = v + 1;
    other.clear();
    return;
  }
  size_ += other.size_;
  if (!other.list_.empty()) runs_.push_back(std::move(other.list_.own()));
  for (auto& r : other.runs_) runs_.push_back(std::move(r));
  if (!other.adds_.empty()) {  // a run is sorted; additions wait in no order
    std::sort(other.adds_.begin(), other.adds_.end());
    runs_.push_back(std::move(other.adds_));
  }
  gone_.insert(gone_.end(), other.gone_.begin(), other.gone_.end());
  other.clear();
  if (runs_.size() > kMaxRuns || tooMany(gone_.size(), size_)) settle();
}

void SlotList::remove(std::span<const Slot> listed) {
  if (listed.empty()) return;
  size_ -= listed.size();
  gone_.insert(gone_.end(), listed.begin(), listed.end());
  if (tooMany(gone_.size(), size_)) settle();
}

std::vector<std::vector<Slot>> SlotList::rollBack(const Mark& m) {
  std::vector<std::vector<Slot>> since(std::make_move_iterator(runs_.begin() + std::ptrdiff_t(m.runs)),
                                       std::make_move_iterator(runs_.end()));
  runs_.resize(m.runs);
  adds_.resize(m.adds);
  gone_.resize(m.gone);
  size_ = m.size;
  return since;
}

void SlotList::reset(std::vector<Slot> listed, std::vector<std::vector<Slot>> runs, std::vector<Slot> adds,
                     std::vector<Slot> gone, const Mark& m) {
  list_ = std::move(listed);
  runs_ = std::move(runs);
  adds_ = std::move(adds);
  gone_ = std::move(gone);
  size_ = m.size;
  version_ = m.version;
}

// Merges the pending runs into the longest list (the smaller ones first, then once into it from
// the back, in place), then the pending additions (sorted first), and drops the pending removals in one pass
// (one listed copy per removal). The pending buffers keep their capacity.
void SlotList::settle() const {
  ++version_;
  if (!runs_.empty()) {
    runs_.push_back(std::move(list_.own()));
    std::sort(runs_.begin(), runs_.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
    std::vector<Slot> base = std::move(runs_[0]), rest;
    for (size_t r = runs_.size(); r-- > 1;) {
      if (rest.empty()) {
        rest = std::move(runs_[r]);
        continue;
      }
      std::vector<Slot> both(rest.size() + runs_[r].size());
      std::merge(rest.begin(), rest.end(), runs_[r].begin(), runs_[r].end(), both.begin());
      rest = std::move(both);
    }
    mergeInto(base, rest);
    list_ = std::move(base);
    runs_.clear();
  }
  if (!adds_.empty()) {
    if (!std::is_sorted(adds_.begin(), adds_.end())) std::sort(adds_.begin(), adds_.end());
    mergeInto(list_.own(), adds_);
    adds_.clear();
  }
  if (!gone_.empty()) {
    std::sort(gone_.begin(), gone_.end());
    std::vector<Slot>& list = list_.own();
    size_t w = 0, g = 0;
    for (size_t r = 0; r < list.size(); ++r) {
      while (g < gone_.size() && gone_[g] < list[r]) ++g;
      if (g < gone_.size() && gone_[g] == list[r]) {
        ++g;
        continue;
      }
      list[w++] = list[r];
    }
    list.resize(w);
    gone_.clear();
  }
}

}  // namespace hexdual
