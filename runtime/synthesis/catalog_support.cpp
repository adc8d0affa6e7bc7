#include "runtime/synthesis/catalog_support.h"

#include <algorithm>

namespace fgsg::rt::synthesis {

SupportCatalog::SupportCatalog(const TransitionTable& t, const SiteGraph& g)
    : t_(t), g_(g), words_(t.words()), k_(t.labelCount()),
      dom_(size_t(g.siteCount) * size_t(t.words()), 0), known_(dom_.size(), 0),
      local_(size_t(g.siteCount), -1), queued_(size_t(g.siteCount), 0) {
  columnSum_.assign(size_t(t.relationCount()) * size_t(k_), 0);
  for (int r = 0; r < t.relationCount(); ++r)
    for (int b = 0; b < k_; ++b)
      forEachBit(t.row(r, b), words_, [&](int c) { ++columnSum_[size_t(r) * size_t(k_) + size_t(c)]; });
}

void SupportCatalog::setActive(int64_t site, bool on) {
  if (on && local_[size_t(site)] < 0) {
    local_[size_t(site)] = int32_t(activeSites_.size());
    activeSites_.push_back(int32_t(site));
    dirty_ = true;
  } else if (!on && local_[size_t(site)] >= 0) {
    // The solver deactivates a whole block at once; forget it when the last one goes.
    local_[size_t(site)] = -1;
    if (++deactivated_ == activeSites_.size()) { activeSites_.clear(); deactivated_ = 0; }
  }
}

void SupportCatalog::edges(int32_t s, std::vector<EdgeRef>& out) const {
  // Slot d is always edge d (other = -1 without a neighbour), so the edge back from a
  // grid neighbour is slot d^1; links follow.
  out.clear();
  for (int d = 0; d < g_.slots; ++d) out.push_back({g_.at(s, d), d});
  if (g_.hasLinks())
    for (uint32_t e = g_.linkStart[size_t(s)]; e < g_.linkStart[size_t(s) + 1]; ++e)
      out.push_back({g_.linkSite[e], g_.linkRelation[e]});
}

void SupportCatalog::assign(int64_t site, int label) {
  Word* d = domain(site);
  for (int w = 0; w < words_; ++w) d[w] = 0;
  setBit(d, label);
  push(site);
}

bool SupportCatalog::remove(int32_t u, int c) {
  Word* d = domain(u);
  if (!testBit(d, c)) return false;
  d[c >> 6] &= ~(Word(1) << (c & 63));
  if (track_) changed_.push_back(u);
  push(u);
  return firstBit(d, words_) < 0;
}

// Counts for every active site from the current domains; then drops unsupported labels.
int64_t SupportCatalog::setup() {
  dirty_ = false;
  countStart_.assign(activeSites_.size() + 1, 0);
  for (size_t i = 0; i < activeSites_.size(); ++i) {
    edges(activeSites_[i], scratch_);
    countStart_[i + 1] = countStart_[i] + uint32_t(scratch_.size()) * uint32_t(k_);
  }
  counts_.assign(countStart_.back(), 0);
  for (size_t i = 0; i < activeSites_.size(); ++i) {
    const int32_t u = activeSites_[i];
    edges(u, scratch_);
    uint16_t* cnt = &counts_[countStart_[i]];
    for (size_t j = 0; j < scratch_.size(); ++j, cnt += k_) {
      // Labels of v allow c at u through the reverse of u's relation to v.
      const int32_t v = scratch_[j].other;
      const int rv = t_.reverse(scratch_[j].relation);
      if (v < 0 || local_[size_t(v)] < 0) {
        // No neighbour, or a fixed one the solver already applied: never decremented.
        std::fill(cnt, cnt + k_, 1);
        continue;
      }
      const Word* dv = domain(v);
      if (popcount(dv, words_) == k_) {
        std::copy_n(&columnSum_[size_t(rv) * size_t(k_)], k_, cnt);
        continue;
      }
      std::fill(cnt, cnt + k_, 0);
      forEachBit(dv, words_, [&](int b) { forEachBit(t_.row(rv, b), words_, [&](int c) { ++cnt[c]; }); });
    }
  }
  for (int32_t s : activeSites_) std::copy_n(domain(s), words_, &known_[size_t(s) * size_t(words_)]);
  return -1;
}

int64_t SupportCatalog::propagate() {
  if (dirty_) {
    const int64_t bad = setup();
    if (bad >= 0) return bad;
    // Initial pass: drop labels whose support is zero along some edge.
    for (size_t i = 0; i < activeSites_.size(); ++i) {
      const int32_t u = activeSites_[i];
      edges(u, scratch_);
      for (size_t j = 0; j < scratch_.size(); ++j) {
        if (scratch_[j].other < 0 || local_[size_t(scratch_[j].other)] < 0) continue;
        const uint16_t* cnt = &counts_[countStart_[i] + uint32_t(j) * uint32_t(k_)];
        bool empty = false;
        forEachBit(domain(u), words_, [&](int c) {
          if (cnt[c] == 0 && !empty) empty = remove(u, c);
        });
        if (empty) {
          for (int32_t s : stack_) queued_[size_t(s)] = 0;
          stack_.clear();
          return u;
        }
      }
    }
  }
  std::vector<EdgeRef> back;
  while (!stack_.empty()) {
    const int32_t v = stack_.back();
    stack_.pop_back();
    queued_[size_t(v)] = 0;
    ++pops_;
    Word* known = &known_[size_t(v) * size_t(words_)];
    const Word* dv = domain(v);
    edges(v, scratch_);
    int64_t failed = -1;
    for (int w = 0; w < words_ && failed < 0; ++w) {
      for (Word gone = known[w] & ~dv[w]; gone && failed < 0; gone &= gone - 1) {
        const int b = w * kWordBits + std::countr_zero(gone);
        for (size_t ei = 0; ei < scratch_.size(); ++ei) {
          const EdgeRef& e = scratch_[ei];
          const int32_t u = e.other;
          if (u < 0) continue;
          const int32_t lu = local_[size_t(u)];
          if (lu < 0) continue;
          size_t j = ei ^ 1;  // the grid edge back from u
          if (ei >= size_t(g_.slots)) {  // a link: find u's link back to v
            edges(u, back);
            j = size_t(g_.slots);
            while (j < back.size() && !(back[j].other == v && back[j].relation == t_.reverse(e.relation))) ++j;
          }
          uint16_t* cnt = &counts_[countStart_[size_t(lu)] + uint32_t(j) * uint32_t(k_)];
          forEachBit(t_.row(e.relation, b), words_, [&](int c) {
            if (--cnt[c] == 0 && failed < 0 && remove(u, c)) failed = u;
          });
          if (failed >= 0) break;
        }
      }
    }
    std::copy_n(dv, words_, known);
    if (failed >= 0) {
      for (int32_t s : stack_) queued_[size_t(s)] = 0;
      stack_.clear();
      return failed;
    }
  }
  return -1;
}

}  // namespace fgsg::rt::synthesis
