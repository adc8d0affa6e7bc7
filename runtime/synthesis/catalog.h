// The catalog C (§3.3.2): the labels still possible at each site, one fixed-width bitset
// of NW words per site, and Algorithm 3.2/3.3 propagation (AC-3 over a queue of changed
// sites). Only "active" sites (the block being modified) may change; every other site is
// fixed and has already been applied to its active neighbours' domains by the caller.
//
// Popping site v narrows each active neighbour u across slot d to
//   dom(u) & support(d, dom(v)),   support(d, D) = OR of row(d, b) over the labels b in D
// (statement 3.6). When dom(v) is one label that is one row; otherwise SupportMemo gives
// it: the same domains recur all over a model (a wall cell whose neighbours are decided,
// ...), so the supports of a domain for all six slots are computed once and then cost a
// hash probe (on the 109-label benchmark about 1 pop in 11 misses).
//
// The queue is first in, first out: a stack popped 2.4x as often, because a site narrowed
// twice in one wave is then popped once. Settled neighbours (one label, and popped since
// they got it) are skipped: that pop narrowed v to labels compatible with theirs
// (relations are symmetric) unless v was settled then, in which case v's own pop came
// after and checked them. A neighbour with one label that is still queued must be
// checked: two cells narrowed to incompatible single labels in one wave would otherwise
// skip each other.
// Links (symmetry) are rare and build their union directly.
//
// Measured in bench/synthesis.cpp (docs/synthesis.md). Tried and dropped: re-checking only
// the labels that lost support since the site's last pop (bounds the union work by k per
// site, but with a FIFO queue and the memo it was 0-20% slower and took 16 more bytes per
// site), and the support-count (AC-4) catalog that used to sit beside this one (slower on
// every case, O(sites x edges x k) counters).
#pragma once

#include "runtime/synthesis/site_array.h"
#include "runtime/synthesis/site_graph.h"
#include "runtime/synthesis/transitions.h"

#include <bit>
#include <cstdint>
#include <vector>

namespace fgsg::rt::synthesis {

constexpr int kMaxSlots = 6;  // buildTransitions always makes relations 0..5

// The label of a singleton set, else -1 (empty or two labels or more).
template <int NW>
inline int singleLabel(const Word* d) {
  int label = -1;
  for (int i = 0; i < NW; ++i) {
    if (!d[i]) continue;
    if (label >= 0 || (d[i] & (d[i] - 1))) return -1;
    label = i * kWordBits + std::countr_zero(d[i]);
  }
  return label;
}

// support(d, D) for the grid slots d = 0..5, memoised by D in a direct-mapped table.
template <int NW>
class SupportMemo {
 public:
  explicit SupportMemo(const TransitionTable& t) : t_(t) {
    // ~1 MiB, at least 64 entries, a power of two for the hash. On the 109-label
    // benchmark 1 MiB beat 256 and 512 KiB (fewer misses) and 4 MiB (cache misses).
    size_t n = 64;
    while (n * 2 * sizeof(Entry) <= (size_t(1) << 20)) n *= 2;
    table_.assign(n, Entry{});
    shift_ = 64 - std::countr_zero(n);
  }

  // The supports of `d` for slots 0..5, slot s at offset s * NW. `d` must not be empty
  // (the all-zero key marks an unused entry).
  const Word* get(const Word* d) {
    uint64_t h = 0;
    for (int i = 0; i < NW; ++i) h = (h ^ d[i]) * 0x9e3779b97f4a7c15ULL;
    Entry& e = table_[size_t(h >> shift_)];
    Word diff = 0;
    for (int i = 0; i < NW; ++i) diff |= e.key[i] ^ d[i];
    if (diff == 0) return e.sup;
    ++misses_;
    for (int i = 0; i < NW; ++i) e.key[i] = d[i];
    Word sup[kMaxSlots * NW] = {};  // local, so it stays in registers (rows may alias e.sup)
    for (int i = 0; i < NW; ++i)
      for (Word bits = d[i]; bits; bits &= bits - 1) {
        const Word* r = t_.row(0, i * kWordBits + std::countr_zero(bits));
        for (int j = 0; j < kMaxSlots * NW; ++j) sup[j] |= r[j];
      }
    for (int j = 0; j < kMaxSlots * NW; ++j) e.sup[j] = sup[j];
    return e.sup;
  }

  uint64_t misses() const { return misses_; }
  size_t bytes() const { return table_.size() * sizeof(Entry); }

 private:
  struct Entry {
    Word key[NW] = {};
    Word sup[kMaxSlots * NW] = {};
  };
  const TransitionTable& t_;
  std::vector<Entry> table_;
  int shift_ = 58;
  uint64_t misses_ = 0;
};

// support(r, D) for links (symmetry, the edges of continuous synthesis's arrangement),
// memoised by (relation, D) in a direct-mapped table: an arrangement vertex pops with a
// dozen links, and unioning the rows of its labels for each was most of the time.
template <int NW>
class LinkSupportMemo {
 public:
  explicit LinkSupportMemo(const TransitionTable& t) : t_(t) {}

  const Word* get(int relation, const Word* d) {
    if (table_.empty()) {
      table_.assign(size_t(1) << kBits, Entry{});
    }
    uint64_t h = uint64_t(relation + 1) * 0xff51afd7ed558ccdULL;
    for (int i = 0; i < NW; ++i) h = (h ^ d[i]) * 0x9e3779b97f4a7c15ULL;
    Entry& e = table_[size_t(h >> (64 - kBits))];
    Word diff = Word(e.relation ^ uint32_t(relation + 1));
    for (int i = 0; i < NW; ++i) diff |= e.key[i] ^ d[i];
    if (diff == 0) return e.sup;
    e.relation = uint32_t(relation + 1);
    for (int i = 0; i < NW; ++i) e.key[i] = d[i], e.sup[i] = 0;
    forEachBit(d, NW, [&](int b) {
      const Word* r = t_.row(relation, b);
      for (int i = 0; i < NW; ++i) e.sup[i] |= r[i];
    });
    return e.sup;
  }

 private:
  static constexpr int kBits = 14;  // 16 K entries
  struct Entry {
    uint32_t relation = 0;  // + 1; 0 = unused
    Word key[NW] = {};
    Word sup[NW] = {};
  };
  const TransitionTable& t_;
  std::vector<Entry> table_;  // allocated at the first link
};

template <int NW>
class BitsetCatalog {
 public:
  BitsetCatalog(const TransitionTable& t, const SiteGraph& g)
      : t_(t), g_(g), memo_(t), linkMemo_(t), dom_(size_t(g.siteCount) * NW), flags_(size_t(g.siteCount)),
        queue_(std::bit_ceil(size_t(g.siteCount))), queueMask_(queue_.size() - 1) {
    flags_.fill(0);  // domains are written when a site is activated, before any read
  }

  Word* domain(int64_t site) { return &dom_[size_t(site) * NW]; }
  const Word* domain(int64_t site) const { return &dom_[size_t(site) * NW]; }
  // Makes `site` modifiable with the domain `base` (the caller queues it).
  void activate(int64_t site, const Word* base) {
    flags_[size_t(site)] = uint8_t((flags_[size_t(site)] & kQueued) | kActive |
                                   (singleLabel<NW>(base) >= 0 ? kDecided : 0));
    for (int i = 0; i < NW; ++i) domain(site)[i] = base[i];
  }
  void deactivate(int64_t site) { flags_[size_t(site)] &= uint8_t(~kActive); }
  bool active(int64_t site) const { return flags_[size_t(site)] & kActive; }

  // Queues a site whose domain the caller changed. A site is queued at most once, so the
  // ring (one slot per site) never overflows.
  void push(int64_t site) {
    if (!(flags_[size_t(site)] & kQueued)) {
      flags_[size_t(site)] |= kQueued;
      queue_[tail_++ & queueMask_] = int32_t(site);
    }
  }
  // Narrows the domain of an active site to `label` (statement 3.7) and queues it.
  void assign(int64_t site, int label) {
    if (recording_) save(int32_t(site));
    Word* d = domain(site);
    for (int i = 0; i < NW; ++i) d[i] = 0;
    setBit(d, label);
    flags_[size_t(site)] |= kDecided;
    push(site);
  }
  // Runs propagation until the queue is empty. Returns -1, or the site whose domain
  // became empty (the queue is then cleared).
  int64_t propagate();
  // Drops queued sites without propagating (a block given up before propagation).
  void clearQueue() {
    for (; head_ != tail_; ++head_) flags_[size_t(queue_[head_ & queueMask_])] &= uint8_t(~kQueued);
  }

  // Sites whose domain shrank since the last call (for minimum-entropy order).
  void trackChanges(bool on) { track_ = on; }
  std::vector<int32_t>& changed() { return changed_; }

  // Removes `label` from an active site's domain and queues it; false when none is left.
  bool exclude(int64_t site, int label) {
    Word keep[NW];
    for (int i = 0; i < NW; ++i) keep[i] = ~Word(0);
    keep[label / kWordBits] &= ~(Word(1) << (label % kWordBits));
    return narrow(int32_t(site), keep);
  }

  // Backtracking (minimum-entropy order): while recording, each domain change keeps the
  // domain it replaced, and undo(mark) restores every change since trailMark() returned
  // `mark`, most recent first, calling restored(site) for each. Undo only with an empty
  // queue (propagate() leaves it empty).
  void recordTrail(bool on, size_t expected = 0) {
    recording_ = on;
    trail_.clear();
    if (on) trail_.reserve(expected);
  }
  size_t trailMark() const { return trail_.size(); }
  template <class Restored>
  void undo(size_t mark, Restored restored) {
    while (trail_.size() > mark) {
      const TrailEntry& e = trail_.back();
      for (int i = 0; i < NW; ++i) domain(e.site)[i] = e.domain[i];
      uint8_t& f = flags_[size_t(e.site)];
      f = uint8_t((f & ~kDecided) | (e.flags & kDecided));  // queued-ness stays (nothing is)
      restored(e.site);
      trail_.pop_back();
    }
  }

  uint64_t pops() const { return pops_; }
  uint64_t memoMisses() const { return memo_.misses(); }
  size_t bytes() const {
    return dom_.size() * sizeof(Word) + flags_.size() + queue_.size() * 4 + memo_.bytes();
  }

 private:
  // kDecided: the domain is one label (set where the catalog narrows it to one; a domain
  // the caller narrows to one label directly is just not known to be decided). Decided
  // and not queued = settled.
  enum : uint8_t { kActive = 1, kQueued = 2, kDecided = 4 };

  struct TrailEntry {
    int32_t site;
    uint8_t flags;
    Word domain[NW];
  };
  void save(int32_t site) {
    TrailEntry e{site, flags_[size_t(site)], {}};
    for (int i = 0; i < NW; ++i) e.domain[i] = domain(site)[i];
    trail_.push_back(e);
  }

  // dom(u) &= keep; false when it became empty.
  bool narrow(int32_t u, const Word* keep) {
    Word* du = domain(u);
    Word nd[NW];
    Word changed = 0, any = 0;
    for (int i = 0; i < NW; ++i) {
      nd[i] = du[i] & keep[i];
      changed |= nd[i] ^ du[i];
      any |= nd[i];
    }
    if (!changed) return true;
    if (recording_) save(u);
    for (int i = 0; i < NW; ++i) du[i] = nd[i];
    if (track_) changed_.push_back(u);
    if (singleLabel<NW>(du) >= 0) flags_[size_t(u)] |= kDecided;
    push(u);
    return any != 0;
  }

  const TransitionTable& t_;
  const SiteGraph& g_;
  SupportMemo<NW> memo_;
  LinkSupportMemo<NW> linkMemo_;
  SiteArray<Word> dom_;
  SiteArray<uint8_t> flags_;
  // Sites to pop, first in first out: a ring buffer over [head_, tail_).
  SiteArray<int32_t> queue_;
  size_t queueMask_, head_ = 0, tail_ = 0;
  std::vector<int32_t> changed_;
  bool track_ = false;
  std::vector<TrailEntry> trail_;
  bool recording_ = false;
  uint64_t pops_ = 0;
};

template <int NW>
int64_t BitsetCatalog<NW>::propagate() {
  const uint8_t* face = g_.face.data();
  int64_t failed = -1;
  while (head_ != tail_ && failed < 0) {
    const int32_t v = queue_[head_++ & queueMask_];
    flags_[size_t(v)] &= uint8_t(~kQueued);
    ++pops_;
    // Active neighbours, except settled ones (see the top of this file).
    int32_t nu[kMaxSlots];
    int nd[kMaxSlots], n = 0;
    const uint8_t fv = face[size_t(v)];
    for (int d = 0; d < kMaxSlots; ++d) {  // slots past g_.slots have no neighbour
      const int32_t u = g_.neighbor(v, fv, d);
      if (u < 0) continue;
      const uint8_t f = flags_[size_t(u)];
      if ((f & kActive) && (f & (kDecided | kQueued)) != kDecided) {
        nu[n] = u;
        nd[n++] = d;
      }
    }
    const Word* dv = domain(v);
    if (n > 0) {
      const int only = singleLabel<NW>(dv);
      const Word* sup = only >= 0 ? t_.row(0, only) : memo_.get(dv);
      for (int j = 0; j < n && failed < 0; ++j)
        if (!narrow(nu[j], sup + nd[j] * NW)) failed = nu[j];
    }

    if (failed < 0 && g_.hasLinks()) {
      const int only = singleLabel<NW>(dv);
      for (uint32_t e = g_.linkStart[size_t(v)]; e < g_.linkStart[size_t(v) + 1] && failed < 0; ++e) {
        const int32_t u = g_.linkSite[e];
        const uint8_t f = flags_[size_t(u)];
        if (!(f & kActive) || (f & (kDecided | kQueued)) == kDecided) continue;  // settled: see the top
        const int rel = g_.linkRelation[e];
        const Word* s = only >= 0 ? t_.row(rel, only) : linkMemo_.get(rel, dv);
        if (!narrow(u, s)) failed = u;
      }
    }
  }
  clearQueue();
  return failed;
}

}  // namespace fgsg::rt::synthesis
