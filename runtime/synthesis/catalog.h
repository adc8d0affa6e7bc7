// The catalog C (§3.3.2): the labels still possible at each site, one bitset per site,
// and Algorithm 3.2/3.3 propagation. Only "active" sites (the block being modified) may
// change; every other site is fixed and has already been applied to its active
// neighbours' domains by the caller. Propagation pops a site and narrows each active
// neighbour to the union of the rows of the site's remaining labels (statement 3.6),
// stopping that union early once it already covers the neighbour's domain.
//
// Measured against support counts (AC-4, catalog_support.h) in bench/synthesis.cpp:
// bitsets won at every size tried (see docs/synthesis.md), so this is the default.
#pragma once

#include "runtime/synthesis/site_graph.h"
#include "runtime/synthesis/transitions.h"

#include <cstdint>
#include <vector>

namespace fgsg::rt::synthesis {

class BitsetCatalog {
 public:
  BitsetCatalog(const TransitionTable& t, const SiteGraph& g);

  int words() const { return words_; }
  Word* domain(int64_t site) { return &dom_[size_t(site) * size_t(words_)]; }
  const Word* domain(int64_t site) const { return &dom_[size_t(site) * size_t(words_)]; }
  void setActive(int64_t site, bool on) { active_[size_t(site)] = on; }
  bool active(int64_t site) const { return active_[size_t(site)]; }

  // Queues a site whose domain the caller changed.
  void push(int64_t site) {
    if (!queued_[size_t(site)]) { queued_[size_t(site)] = 1; stack_.push_back(int32_t(site)); }
  }
  // Narrows the domain of an active site to `label` (statement 3.7) and queues it.
  void assign(int64_t site, int label);
  // Runs propagation until the queue is empty. Returns -1, or the site whose domain
  // became empty (the queue is then cleared).
  int64_t propagate();

  // Sites whose domain shrank since the last call (for minimum-entropy order).
  void trackChanges(bool on) { track_ = on; }
  std::vector<int32_t>& changed() { return changed_; }

  uint64_t pops() const { return pops_; }
  size_t bytes() const { return dom_.size() * sizeof(Word) + active_.size() * 2 + stack_.capacity() * 4; }

 private:
  bool narrow(int64_t v, const Word* dv, int32_t u, int relation);
  const TransitionTable& t_;
  const SiteGraph& g_;
  int words_;
  std::vector<Word> dom_;
  std::vector<uint8_t> active_, queued_;
  std::vector<int32_t> stack_, changed_;
  std::vector<Word> support_;
  bool track_ = false;
  uint64_t pops_ = 0;
};

}  // namespace fgsg::rt::synthesis
