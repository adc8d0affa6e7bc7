#include "runtime/synthesis/catalog.h"

namespace fgsg::rt::synthesis {

BitsetCatalog::BitsetCatalog(const TransitionTable& t, const SiteGraph& g)
    : t_(t), g_(g), words_(t.words()),
      dom_(size_t(g.siteCount) * size_t(t.words()), 0),
      active_(size_t(g.siteCount), 0), queued_(size_t(g.siteCount), 0),
      support_(size_t(t.words()), 0) {}

void BitsetCatalog::assign(int64_t site, int label) {
  Word* d = domain(site);
  for (int w = 0; w < words_; ++w) d[w] = 0;
  setBit(d, label);
  push(site);
}

// Narrows active site u by the support of v's domain across `relation`; true when the
// domain of u became empty.
inline bool BitsetCatalog::narrow(int64_t v, const Word* dv, int32_t u, int relation) {
  Word* du = domain(u);
  const int W = words_;
  // A single remaining label (the common case after an assignment) is one row lookup.
  int n = 0, only = -1;
  for (int w = 0; w < W && n < 2; ++w)
    if (dv[w]) { n += (dv[w] & (dv[w] - 1)) == 0 ? 1 : 2; only = w * kWordBits + std::countr_zero(dv[w]); }
  const Word* sup;
  if (n == 1) {
    sup = t_.row(relation, only);
  } else if (popcount(du, W) < popcount(dv, W)) {
    // Fewer labels at u than at v: test each label of u for a supporter in v instead of
    // building the union of v's rows (the transposed matrix, one AND per label).
    const int rev = t_.reverse(relation);
    Word* s = support_.data();
    for (int w = 0; w < W; ++w) s[w] = du[w];
    forEachBit(du, W, [&](int c) {
      const Word* r = t_.row(rev, c);
      for (int i = 0; i < W; ++i)
        if (r[i] & dv[i]) return;
      s[c >> 6] &= ~(Word(1) << (c & 63));
    });
    sup = s;
  } else {
    // Union of rows, stopping as soon as it covers du: nothing would be removed.
    Word* s = support_.data();
    for (int w = 0; w < W; ++w) s[w] = 0;
    bool covered = false;
    for (int w = 0; w < W && !covered; ++w)
      for (Word bits = dv[w]; bits && !covered; bits &= bits - 1) {
        const Word* r = t_.row(relation, w * kWordBits + std::countr_zero(bits));
        Word missing = 0;
        for (int i = 0; i < W; ++i) { s[i] |= r[i]; missing |= du[i] & ~s[i]; }
        covered = missing == 0;
      }
    if (covered) return false;
    sup = s;
  }
  Word changed = 0, any = 0;
  for (int w = 0; w < W; ++w) {
    Word nd = du[w] & sup[w];
    changed |= nd ^ du[w];
    du[w] = nd;
    any |= nd;
  }
  if (!changed) return false;
  if (track_) changed_.push_back(u);
  push(u);
  (void)v;
  return any == 0;
}

int64_t BitsetCatalog::propagate() {
  const int slots = g_.slots;
  while (!stack_.empty()) {
    const int32_t v = stack_.back();
    stack_.pop_back();
    queued_[size_t(v)] = 0;
    ++pops_;
    const Word* dv = domain(v);
    const int32_t* nb = &g_.neighbor[size_t(v) * size_t(slots)];
    int64_t failed = -1;
    for (int d = 0; d < slots; ++d) {
      const int32_t u = nb[d];
      if (u < 0 || !active_[size_t(u)]) continue;
      if (narrow(v, dv, u, d)) { failed = u; break; }
    }
    if (failed < 0 && g_.hasLinks()) {
      for (uint32_t e = g_.linkStart[size_t(v)]; e < g_.linkStart[size_t(v) + 1]; ++e) {
        const int32_t u = g_.linkSite[e];
        if (!active_[size_t(u)]) continue;
        if (narrow(v, dv, u, g_.linkRelation[e])) { failed = u; break; }
      }
    }
    if (failed >= 0) {
      for (int32_t s : stack_) queued_[size_t(s)] = 0;
      stack_.clear();
      return failed;
    }
  }
  return -1;
}

}  // namespace fgsg::rt::synthesis
