// Transition matrices (eq. 3.2) compiled to bit rows: row(r, b) is the set of labels that
// may sit across relation r from a cell labelled b. Relations 0..5 are the grid directions
// +x -x +y -y +z -z (T_x, T_x^T, T_y, ...); further relations are added for symmetry
// links (§3.5.2: a transition matrix between distant cells). Every relation has a reverse
// (the transposed matrix), so any constraint edge can be read from both ends.
#pragma once

#include "runtime/synthesis/example.h"

#include <bit>
#include <cstdint>
#include <utility>
#include <vector>

namespace fgsg::rt::synthesis {

using Word = uint64_t;
constexpr int kWordBits = 64;

inline int wordsFor(int k) { return (k + kWordBits - 1) / kWordBits; }
inline bool testBit(const Word* s, int b) { return (s[b >> 6] >> (b & 63)) & 1; }
inline void setBit(Word* s, int b) { s[b >> 6] |= Word(1) << (b & 63); }
inline int popcount(const Word* s, int words) {
  int n = 0;
  for (int i = 0; i < words; ++i) n += std::popcount(s[i]);
  return n;
}
inline int firstBit(const Word* s, int words) {
  for (int i = 0; i < words; ++i)
    if (s[i]) return i * kWordBits + std::countr_zero(s[i]);
  return -1;
}
// Calls f(label) for each set bit.
template <class F>
inline void forEachBit(const Word* s, int words, F&& f) {
  for (int i = 0; i < words; ++i)
    for (Word w = s[i]; w; w &= w - 1) f(i * kWordBits + std::countr_zero(w));
}

enum Relation : int { kPosX = 0, kNegX, kPosY, kNegY, kPosZ, kNegZ, kGridRelations };

class TransitionTable {
 public:
  TransitionTable() = default;
  explicit TransitionTable(int k) : k_(k), words_(wordsFor(k)) {}

  int labelCount() const { return k_; }
  int words() const { return words_; }
  int relationCount() const { return int(reverse_.size()); }
  int reverse(int r) const { return reverse_[size_t(r)]; }
  const Word* row(int r, int b) const { return &rows_[(size_t(r) * size_t(k_) + size_t(b)) * size_t(words_)]; }
  // Union of all rows of r (the support of a cell that still allows every label).
  const Word* anySupport(int r) const { return &any_[size_t(r) * size_t(words_)]; }

  // Adds the relation "c may sit across it from b" for each (b, c) and its reverse;
  // returns the id of the forward relation (the reverse is id + 1).
  int addRelationPair(const std::vector<std::pair<int32_t, int32_t>>& pairs);

 private:
  int k_ = 0, words_ = 0;
  std::vector<Word> rows_;  // [relation][b][words]
  std::vector<Word> any_;   // [relation][words]
  std::vector<int> reverse_;
};

// T_x, T_y, T_z of the example as relations 0..5.
TransitionTable buildTransitions(const Example& ex);

// A label map f as a relation: T_f[b, c] = 1 <=> c = f(b) (the symmetry matrix T_s).
std::vector<std::pair<int32_t, int32_t>> mapPairs(const std::vector<int32_t>& f, int k);

}  // namespace fgsg::rt::synthesis
