// The catalog with support counts (AC-4) instead of bitset unions: for each active site,
// constraint edge and label c, the number of labels still possible across that edge that
// allow c. Removing a label decrements the counts it supported; a count reaching zero
// removes that label (statement 3.6 without recomputing unions). Same interface as
// BitsetCatalog. Kept for the measurement in bench/synthesis.cpp: its setup costs
// O(edges x k) per block and its memory O(sites x edges x k), and it lost to bitsets.
#pragma once

#include "runtime/synthesis/site_graph.h"
#include "runtime/synthesis/transitions.h"

#include <cstdint>
#include <vector>

namespace fgsg::rt::synthesis {

class SupportCatalog {
 public:
  SupportCatalog(const TransitionTable& t, const SiteGraph& g);

  int words() const { return words_; }
  Word* domain(int64_t site) { return &dom_[size_t(site) * size_t(words_)]; }
  const Word* domain(int64_t site) const { return &dom_[size_t(site) * size_t(words_)]; }
  void setActive(int64_t site, bool on);
  bool active(int64_t site) const { return local_[size_t(site)] >= 0; }
  void push(int64_t site) {
    if (!queued_[size_t(site)]) { queued_[size_t(site)] = 1; stack_.push_back(int32_t(site)); }
  }
  void assign(int64_t site, int label);
  int64_t propagate();
  void trackChanges(bool on) { track_ = on; }
  std::vector<int32_t>& changed() { return changed_; }
  uint64_t pops() const { return pops_; }
  size_t bytes() const {
    return dom_.size() * sizeof(Word) * 2 + local_.size() * 5 + counts_.capacity() * sizeof(uint16_t);
  }

 private:
  struct EdgeRef { int32_t other; int relation; };  // relation from this site to `other`
  void edges(int32_t s, std::vector<EdgeRef>& out) const;
  int64_t setup();
  bool remove(int32_t u, int c);
  const TransitionTable& t_;
  const SiteGraph& g_;
  int words_, k_;
  std::vector<Word> dom_, known_;       // known_: domain the counts describe
  std::vector<int32_t> local_;          // site -> index among active sites, -1 inactive
  std::vector<int32_t> activeSites_;
  std::vector<uint32_t> countStart_;    // per active site: first count (edges x k)
  std::vector<uint16_t> counts_;
  std::vector<uint16_t> columnSum_;     // [relation][c]: support of a full domain
  std::vector<uint8_t> queued_;
  std::vector<int32_t> stack_, changed_;
  std::vector<EdgeRef> scratch_;
  size_t deactivated_ = 0;
  bool dirty_ = false, track_ = false;
  uint64_t pops_ = 0;
};

}  // namespace fgsg::rt::synthesis
