#include "runtime/synthesis/transitions.h"

#include <algorithm>

namespace fgsg::rt::synthesis {

int TransitionTable::addRelationPair(const std::vector<std::pair<int32_t, int32_t>>& pairs) {
  const int r = relationCount();
  const size_t W = size_t(words_), before = size_t(r), after = before + 2;
  // Relations are added while the problem is compiled: re-lay the rows with two more.
  std::vector<Word> rows(size_t(k_) * after * W, 0);
  for (size_t b = 0; b < size_t(k_) && before > 0; ++b)
    std::copy_n(&rows_[b * before * W], before * W, &rows[b * after * W]);
  rows_ = std::move(rows);
  reverse_.push_back(r + 1);
  reverse_.push_back(r);
  for (auto [b, c] : pairs) {
    if (b < 0 || c < 0 || b >= k_ || c >= k_) continue;
    setBit(&rows_[(size_t(b) * after + size_t(r)) * W], c);
    setBit(&rows_[(size_t(c) * after + size_t(r) + 1) * W], b);
  }
  return r;
}

TransitionTable buildTransitions(const Example& ex, int words) {
  TransitionTable t(ex.labelCount(), words);
  for (int a = 0; a < 3; ++a) t.addRelationPair(ex.allowed[size_t(a)]);
  return t;
}

std::vector<std::pair<int32_t, int32_t>> mapPairs(const std::vector<int32_t>& f, int k) {
  std::vector<std::pair<int32_t, int32_t>> p;
  for (int32_t b = 0; b < k; ++b) p.push_back({b, f.empty() ? b : f[size_t(b)]});
  return p;
}

}  // namespace fgsg::rt::synthesis
