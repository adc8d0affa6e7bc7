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
// Words per domain as the solver stores them: a power of two (1, 2, 4, ... 64), so the
// solver can be compiled for a fixed width (k <= 64, <= 128, <= 256, ...).
inline int paddedWordsFor(int k) {
  int w = 1;
  while (w < wordsFor(k)) w *= 2;
  return w;
}
inline bool testBit(const Word* s, int b) { return (s[b >> 6] >> (b & 63)) & 1; }
inline void setBit(Word* s, int b) { s[b >> 6] |= Word(1) << (b & 63); }
// Without -mpopcnt (the build has no -march) both std::popcount and __builtin_popcountll
// compile to a call to libgcc's __popcountdi2; this is the same bit trick, inlined.
inline int popcount64(Word x) {
  x = x - ((x >> 1) & 0x5555555555555555ULL);
  x = (x & 0x3333333333333333ULL) + ((x >> 2) & 0x3333333333333333ULL);
  x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0fULL;
  return int((x * 0x0101010101010101ULL) >> 56);
}
inline int popcount(const Word* s, int words) {
  int n = 0;
  for (int i = 0; i < words; ++i) n += popcount64(s[i]);
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
  // `words` per row (at least wordsFor(k); the solver pads to paddedWordsFor(k)).
  TransitionTable(int k, int words) : k_(k), words_(words) {}

  int labelCount() const { return k_; }
  int words() const { return words_; }
  int relationCount() const { return int(reverse_.size()); }
  int reverse(int r) const { return reverse_[size_t(r)]; }
  // Rows are stored label-major ([b][relation][words]): the rows of one label for all
  // directions are adjacent, and row(r, b) = row(0, b) + r * words().
  const Word* row(int r, int b) const {
    return &rows_[(size_t(b) * reverse_.size() + size_t(r)) * size_t(words_)];
  }

  // Adds the relation "c may sit across it from b" for each (b, c) and its reverse;
  // returns the id of the forward relation (the reverse is id + 1).
  int addRelationPair(const std::vector<std::pair<int32_t, int32_t>>& pairs);

 private:
  int k_ = 0, words_ = 0;
  std::vector<Word> rows_;  // [b][relation][words]
  std::vector<int> reverse_;
};

// T_x, T_y, T_z of the example as relations 0..5, rows of `words` words.
TransitionTable buildTransitions(const Example& ex, int words);

// A label map f as a relation: T_f[b, c] = 1 <=> c = f(b) (the symmetry matrix T_s).
std::vector<std::pair<int32_t, int32_t>> mapPairs(const std::vector<int32_t>& f, int k);

}  // namespace fgsg::rt::synthesis
