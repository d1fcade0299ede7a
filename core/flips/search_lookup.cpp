// The last level by lookup (SearchOptions::lookupLastLevel): the other side's stored states are
// replayed and keyed once under every symmetry, so each child of the last level is looked up by its
// plain key alone.
#include "flips/search_parts.hpp"

#include <algorithm>
#include <memory>

namespace hexdual::flipsearch {
using namespace tables;

// The plain keys (identity only) of every state of `side` and of its images under the problem's
// symmetries, each mapped to its node: a state meets that side iff its plain key is here, so a
// last level needs one identity encoding per child instead of one per symmetry. States are
// replayed in node order (parents first, so consecutive nodes share their paths).
size_t imageSlots(const SearchContext& ctx, const Side& side) {
  const size_t keys = side.parent.size() * (ctx.symmetries.size() + 1);
  size_t slots = 1024;
  while (10 * (keys + 1) > 7 * slots) slots *= 2;  // FlatKeyMap's load limit: it never grows
  return slots;
}

FlatKeyMap imageKeys(const SearchContext& ctx, const Side& side, int threads) {
  const size_t n = side.parent.size();
  FlatKeyMap out(imageSlots(ctx, side));
  std::vector<std::unique_ptr<Walker>> walkers;
  std::vector<RegionEncoder> enc(static_cast<size_t>(threads));
  for (int t = 0; t < threads; ++t) walkers.push_back(std::make_unique<Walker>(side, ctx.host, ctx.opt));
  std::vector<std::vector<std::pair<Key128, int32_t>>> keys(static_cast<size_t>(threads));
  const size_t chunk = size_t(1) << 14;
  for (size_t b = 0; b < n; b += chunk) {
    const size_t e = std::min(n, b + chunk), per = (e - b + size_t(threads) - 1) / size_t(threads);
    onThreads(threads, [&](int t) {
      Walker& w = *walkers[size_t(t)];
      RegionEncoder& en = enc[size_t(t)];
      auto& list = keys[size_t(t)];
      list.clear();
      for (size_t v = std::min(e, b + per * size_t(t)), hi = std::min(e, v + per); v < hi; ++v) {
        w.goTo(int32_t(v));
        list.push_back({hashWords(en.form(w.cx, ctx.isHost)), int32_t(v)});
        for (const auto& m : ctx.symmetries) list.push_back({hashWords(en.form(w.cx, ctx.isHost, &m)), int32_t(v)});
      }
    });
    for (const auto& list : keys)
      for (const auto& [k, v] : list) out.insert(k, v);
  }
  return out;
}

}  // namespace hexdual::flipsearch
