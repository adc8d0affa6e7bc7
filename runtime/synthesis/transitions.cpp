#include "runtime/synthesis/transitions.h"

namespace fgsg::rt::synthesis {

int TransitionTable::addRelationPair(const std::vector<std::pair<int32_t, int32_t>>& pairs) {
  const int r = relationCount();
  const size_t rowBlock = size_t(k_) * size_t(words_);
  rows_.resize(rows_.size() + 2 * rowBlock, 0);
  any_.resize(any_.size() + 2 * size_t(words_), 0);
  reverse_.push_back(r + 1);
  reverse_.push_back(r);
  Word* fwd = &rows_[size_t(r) * rowBlock];
  Word* bwd = &rows_[size_t(r + 1) * rowBlock];
  for (auto [b, c] : pairs) {
    if (b < 0 || c < 0 || b >= k_ || c >= k_) continue;
    setBit(fwd + size_t(b) * size_t(words_), c);
    setBit(bwd + size_t(c) * size_t(words_), b);
  }
  for (int rr = r; rr < r + 2; ++rr) {
    Word* any = &any_[size_t(rr) * size_t(words_)];
    for (int b = 0; b < k_; ++b)
      for (int w = 0; w < words_; ++w) any[w] |= row(rr, b)[w];
  }
  return r;
}

TransitionTable buildTransitions(const Example& ex) {
  TransitionTable t(ex.labelCount());
  for (int a = 0; a < 3; ++a) t.addRelationPair(ex.allowed[size_t(a)]);
  return t;
}

std::vector<std::pair<int32_t, int32_t>> mapPairs(const std::vector<int32_t>& f, int k) {
  std::vector<std::pair<int32_t, int32_t>> p;
  for (int32_t b = 0; b < k; ++b) p.push_back({b, f.empty() ? b : f[size_t(b)]});
  return p;
}

}  // namespace fgsg::rt::synthesis
