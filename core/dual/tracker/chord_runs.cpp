// Chords as pieces of labelled runs (Dual::chordLabel, chordPlace, labelChord, labelCuts): a chord
// label is written once on a run of slots with their places, and a chord lists pieces [lo, hi) of
// label runs, forward or reversed, so cutting or joining chords writes only the touched slots.
// Owns: runs_, pieces_, freeChordLabels_, dropped_, chordSelf_, and the chord lists readers have
// not settled yet (unsettled_, unsettledMark_).
// Keeps: every piece of a live chord has a matching cut in its label's labelCuts, and every cut a
// piece; labelChord is a label's one chord, or -1 when its cuts lie in several or none; every
// place a cut lists holds a slot carrying that label at that place (chordPlace), whose chordAt is
// the cut's chord; a chord has at most 16 pieces; a free label has no cuts; a chord whose slot
// list is not settled is listed in unsettled_ once.
#include <algorithm>

#include "complex/huge_pages.hpp"
#include "complex/sorted_ids.hpp"
#include "dual/dual_tracker.hpp"
#include "dual/tracker/slots.hpp"

namespace hexdual {
using namespace tracker;

int32_t DualTracker::chordLength(int32_t id) const {
  int32_t n = 0;
  for (const Piece& p : pieces_[size_t(id)]) n += p.hi - p.lo;
  return n;
}

// The piece of chord id listing slot s, s's offset k in it and its place q in the chord; null
// when s is not listed in the chord.
const DualTracker::Piece* DualTracker::pieceOf(int32_t id, Slot s, int32_t* k, int32_t* q) const {
  const int32_t l = dual_.chordLabel[size_t(s.hex)][size_t(s.axis)];
  if (l < 0) return nullptr;
  const int32_t i = dual_.chordPlace[slotIndex(s)];
  int32_t before = 0;
  for (const Piece& p : pieces_[size_t(id)]) {
    if (p.label == l && i >= p.lo && i < p.hi) {
      *k = p.reversed ? p.hi - 1 - i : i - p.lo;
      *q = before + *k;
      return &p;
    }
    before += p.hi - p.lo;
  }
  return nullptr;
}

int32_t DualTracker::placeInChord(int32_t id, Slot s) const {
  int32_t k = 0, q = -1;
  return pieceOf(id, s, &k, &q) ? q : -1;
}

// Read within s's piece where they lie in it; only at a piece's end does it read the chord's
// length and closedness and walk the pieces again (chordSlotAt).
int32_t DualTracker::chordNeighbours(int32_t id, Slot s, Slot* prev, bool* hasPrev, Slot* next, bool* hasNext) const {
  int32_t k = 0, q = -1;
  const Piece* p = pieceOf(id, s, &k, &q);
  if (!p) return -1;
  // s's neighbours inside the piece: its run's places beside s's, in the piece's direction.
  const int32_t i = dual_.chordPlace[slotIndex(s)], step = p->reversed ? -1 : 1;
  const std::span<const Slot> run = runs_[size_t(p->label)].view();
  int32_t len = -1;
  bool closed = false;
  auto ends = [&] {  // the chord's length and closedness, read once and only at a piece's end
    if (len < 0) len = chordLength(id), closed = dual_.chords[size_t(id)].closed;
  };
  if (k > 0) {
    *prev = run[size_t(i - step)];
    *hasPrev = true;
  } else {
    ends();
    *hasPrev = q > 0 || closed;
    if (*hasPrev) *prev = chordSlotAt(id, q > 0 ? q - 1 : len - 1);
  }
  if (k + 1 < p->hi - p->lo) {
    *next = run[size_t(i + step)];
    *hasNext = true;
  } else {
    ends();
    *hasNext = q + 1 < len || closed;
    if (*hasNext) *next = chordSlotAt(id, q + 1 < len ? q + 1 : 0);
  }
  return q;
}

// The chords lose their pieces (their labels' places are cut from them).
void DualTracker::dropPieces(const std::vector<int32_t>& ids) {
  for (int32_t id : ids) {
    for (const Piece& p : pieces_[size_t(id)]) cutLabel(p.label, p.lo, p.hi, id, false);
    pieces_[size_t(id)].clear();
  }
}

// The slots of pieces, in order.
void DualTracker::appendSlots(std::span<const Piece> pieces, std::vector<Slot>& out) const {
  for (const Piece& p : pieces)
    for (int32_t k = 0; k < p.hi - p.lo; ++k)
      out.push_back(runs_[size_t(p.label)][size_t(p.reversed ? p.hi - 1 - k : p.lo + k)]);
}

Slot DualTracker::chordSlotAt(int32_t id, int32_t q) const {
  for (const Piece& p : pieces_[size_t(id)]) {
    const int32_t n = p.hi - p.lo;
    if (q < n) return runs_[size_t(p.label)][size_t(p.reversed ? p.hi - 1 - q : p.lo + q)];
    q -= n;
  }
  return {};
}

void DualTracker::sliceChord(int32_t id, int32_t a, int32_t b, std::vector<Piece>& out) const {
  int32_t before = 0;
  for (const Piece& p : pieces_[size_t(id)]) {
    const int32_t n = p.hi - p.lo, from = std::max(a, before), to = std::min(b + 1, before + n);
    if (from < to) {
      const int32_t x = from - before, y = to - before;  // listed offsets [x, y) in the piece
      out.push_back(p.reversed ? Piece{p.label, p.hi - y, p.hi - x, true} : Piece{p.label, p.lo + x, p.lo + y, false});
    }
    before += n;
  }
}

// A label for a run of slots, written on them with their places (its run is copied into the
// room a released label left, when there is one: see releaseLabels).
int32_t DualTracker::newChordLabel(std::span<const Slot> run) {
  int32_t l;
  if (!freeChordLabels_.empty()) {
    l = freeChordLabels_.back();
    freeChordLabels_.pop_back();
  } else {
    l = int32_t(runs_.size());
    growHuge(runs_, size_t(l) + 1);  // with room to spare, advised huge pages (huge_pages.hpp)
    growHuge(dual_.labelCuts, size_t(l) + 1);
    growHuge(dual_.labelChord, size_t(l) + 1, -1);
  }
  for (size_t i = 0; i < run.size(); ++i) {
    dual_.chordLabel[size_t(run[i].hex)][size_t(run[i].axis)] = l;
    dual_.chordPlace[slotIndex(run[i])] = int32_t(i);
  }
  runs_[size_t(l)].assign(run.data(), run.data() + run.size());
  dual_.labelCuts[size_t(l)].clear();
  dual_.labelChord[size_t(l)] = -1;
  return l;
}

// Adds or removes a range of a label's places listed in a chord; the label's chord (or -1 when its
// places lie in several) follows. Labels left with no range are released by releaseLabels().
void DualTracker::cutLabel(int32_t label, int32_t lo, int32_t hi, int32_t chord, bool add) {
  auto& cuts = dual_.labelCuts[size_t(label)];
  if (add) {
    cuts.push_back({lo, hi, chord});
  } else {
    for (size_t i = 0; i < cuts.size(); ++i)
      if (cuts[i].lo == lo && cuts[i].hi == hi && cuts[i].chord == chord) {
        cuts.erase(cuts.begin() + std::ptrdiff_t(i));
        break;
      }
    dropped_.push_back(label);
  }
  int32_t c = cuts.empty() ? -1 : cuts[0].chord;
  for (const Dual::ChordCut& k : cuts) c = k.chord == c ? c : -1;
  dual_.labelChord[size_t(label)] = c;
}

// Labels that lost places in this update and lie in no chord any more: no slot carries them.
void DualTracker::releaseLabels() {
  sortUniqueIds(dropped_);  // (a sheet extraction drops thousands: by bitmap)
  for (int32_t l : dropped_)
    if (dual_.labelCuts[size_t(l)].empty()) {
      // A short run keeps its room for the label's next use (no allocation per cut); a long one is freed.
      constexpr size_t kKeptRoom = 64;
      if (runs_[size_t(l)].capacity() > kKeptRoom)
        runs_[size_t(l)].release();
      else
        runs_[size_t(l)].clear();
      dual_.labelChord[size_t(l)] = -1;
      freeChordLabels_.push_back(l);
    }
  dropped_.clear();
}

// Lists chord id as these pieces (joined where they continue one another). A chord cut and joined
// so often that it has many pieces is given one run again (its slots re-labelled: a rare, whole pass).
void DualTracker::setChordPieces(int32_t id, const std::vector<Piece>& pieces) {
  auto& joined = pieces_[size_t(id)];  // emptied by dropPieces (its room is reused)
  joined.clear();
  for (const Piece& p : pieces) {
    if (!joined.empty()) {
      Piece& q = joined.back();
      if (q.label == p.label && q.reversed == p.reversed && (p.reversed ? p.hi == q.lo : q.hi == p.lo)) {
        q.lo = std::min(q.lo, p.lo);
        q.hi = std::max(q.hi, p.hi);
        continue;
      }
    }
    joined.push_back(p);
  }
  constexpr size_t kMaxPieces = 16;
  if (joined.size() > kMaxPieces) {
    std::vector<Slot> run;
    appendSlots(joined, run);
    for (const Piece& p : joined) dropped_.push_back(p.label);  // they lose these places
    slotsTouched_ += run.size();
    const int32_t n = int32_t(run.size());
    joined.assign(1, Piece{newChordLabel(run), 0, n, false});
  }
  for (const Piece& p : joined) cutLabel(p.label, p.lo, p.hi, id, true);
  if (!unsettledMark_[size_t(id)]) {
    unsettledMark_[size_t(id)] = 1;
    unsettled_.push_back(id);
  }
}

void DualTracker::growChordIds(size_t n) {
  growHuge(dual_.chords, n);  // each with room to spare (huge_pages.hpp)
  growHuge(pieces_, n);
  growHuge(chordSelf_, n, uint8_t(0));
  growHuge(unsettledMark_, n, uint8_t(0));
}

bool DualTracker::chordSelfIntersects(int32_t id) const {
  for (const Piece& p : pieces_[size_t(id)])
    for (int32_t i = p.lo; i < p.hi; ++i) {
      const Slot t = runs_[size_t(p.label)][size_t(i)];
      if (dual_.chordAt(t.hex, (t.axis + 1) % 3) == id || dual_.chordAt(t.hex, (t.axis + 2) % 3) == id) return true;
    }
  return false;
}

// Chord lists (and self-intersection where the update left it open) from their pieces, for readers.
void DualTracker::settleChords() const {
  for (int32_t id : unsettled_) {
    unsettledMark_[size_t(id)] = 0;
    Chord& ch = dual_.chords[size_t(id)];
    ch.slots.clear();
    if (!ch.alive) continue;
    ch.slots.reserve(size_t(chordLength(id)));
    appendSlots(pieces_[size_t(id)], ch.slots.own());
    if (chordSelf_[size_t(id)] == 2) chordSelf_[size_t(id)] = chordSelfIntersects(id);
    ch.selfIntersecting = chordSelf_[size_t(id)] != 0;
  }
  unsettled_.clear();
}

// ---- invariants ----

// Pieces and label cuts agree both ways; every place a piece lists holds a live slot carrying the
// label at that place, whose chordAt is the chord; together the chords list every live slot once.
void DualTracker::checkChordRuns(const Complex& cx) const {
  const Dual& d = dual_;
  const size_t chords = d.chords.size(), labels = runs_.size();
  if (pieces_.size() != chords || chordSelf_.size() != chords || unsettledMark_.size() != chords ||
      d.labelCuts.size() != labels || d.labelChord.size() != labels)
    invariantBroken("the per-chord or per-label arrays disagree in size with " + std::to_string(chords) +
                    " chords and " + std::to_string(labels) + " labels");
  int64_t listed = 0;
  for (int32_t id = 0; id < int32_t(chords); ++id) {
    const std::string name = "chord " + std::to_string(id);
    if (!d.chords[size_t(id)].alive) {
      if (!pieces_[size_t(id)].empty()) invariantBroken("retired " + name + " keeps pieces");
      continue;
    }
    if (pieces_[size_t(id)].empty() || pieces_[size_t(id)].size() > 16 || chordSelf_[size_t(id)] > 2)
      invariantBroken(name + " has " + std::to_string(pieces_[size_t(id)].size()) + " pieces (1 to 16 allowed)");
    for (const Piece& p : pieces_[size_t(id)]) {
      const auto& cuts = d.labelCuts[size_t(p.label)];
      if (p.lo < 0 || p.lo >= p.hi || size_t(p.hi) > runs_[size_t(p.label)].size() ||
          std::none_of(cuts.begin(), cuts.end(),
                       [&](const Dual::ChordCut& k) { return k.lo == p.lo && k.hi == p.hi && k.chord == id; }))
        invariantBroken(name + " has a piece [" + std::to_string(p.lo) + ", " + std::to_string(p.hi) + ") of label " +
                        std::to_string(p.label) + " that its label's cuts do not list");
      for (int32_t i = p.lo; i < p.hi; ++i) {
        const Slot s = runs_[size_t(p.label)][size_t(i)];
        if (!cx.isHex(s.hex) || d.chordLabel[size_t(s.hex)][size_t(s.axis)] != p.label ||
            d.chordPlace[slotIndex(s)] != i || d.chordAt(s.hex, s.axis) != id)
          invariantBroken(name + " lists slot " + slotName(s) + " at place " + std::to_string(i) + " of label " +
                          std::to_string(p.label) + ", which the slot does not carry");
      }
      listed += p.hi - p.lo;
    }
    if (!unsettledMark_[size_t(id)]) {
      std::vector<Slot> slots;
      appendSlots(pieces_[size_t(id)], slots);
      if (slots != d.chords[size_t(id)].slots) invariantBroken(name + "'s settled slot list is not its pieces'");
    }
  }
  if (listed != 3 * cx.numHexes())
    invariantBroken("the chords list " + std::to_string(listed) + " slots, the complex has " +
                    std::to_string(3 * cx.numHexes()));
  checkLabelCuts();
}

// Every cut has its piece; labelChord names a label's one chord; free labels have no cuts; each
// unsettled chord is listed once.
void DualTracker::checkLabelCuts() const {
  const Dual& d = dual_;
  for (size_t l = 0; l < runs_.size(); ++l) {
    int32_t one = d.labelCuts[l].empty() ? -1 : d.labelCuts[l][0].chord;
    for (const Dual::ChordCut& k : d.labelCuts[l]) {
      const auto& ps = pieces_[size_t(k.chord)];
      if (std::none_of(ps.begin(), ps.end(),
                       [&](const Piece& p) { return int32_t(l) == p.label && p.lo == k.lo && p.hi == k.hi; }))
        invariantBroken("label " + std::to_string(l) + " has a cut in chord " + std::to_string(k.chord) +
                        " that the chord's pieces do not list");
      one = k.chord == one ? one : -1;
    }
    if (d.labelChord[l] != one)
      invariantBroken("label " + std::to_string(l) + "'s chord is " + std::to_string(d.labelChord[l]) +
                      ", its cuts give " + std::to_string(one));
  }
  for (int32_t l : freeChordLabels_)
    if (!d.labelCuts[size_t(l)].empty()) invariantBroken("free chord label " + std::to_string(l) + " has cuts");
  std::vector<uint8_t> listed(unsettledMark_.size(), 0);
  for (int32_t id : unsettled_)
    if (listed[size_t(id)]++ || !unsettledMark_[size_t(id)])
      invariantBroken("chord " + std::to_string(id) + " is listed as unsettled twice or unmarked");
  for (size_t id = 0; id < listed.size(); ++id)
    if (unsettledMark_[id] && !listed[id])
      invariantBroken("chord " + std::to_string(id) + " is marked unsettled but not listed");
}

}  // namespace hexdual
