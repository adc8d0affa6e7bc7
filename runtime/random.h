// Counter-based random streams. Every shape owns a key derived from the seed and its
// derivation path (parent key, position in the successor), and draws numbers by
// hashing key and a counter. So a shape's numbers do not depend on the order in which
// shapes are derived, on the engine, or on the number of threads.
#pragma once

#include <cstdint>

namespace fgsg::rt {

inline uint64_t mix64(uint64_t x) {
  // splitmix64's finaliser: a bijection with good avalanche.
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// childKey(parent, index) is keyWithSalt(parent, childSalt(index)): a rewriter that
// makes the same children again and again computes the salts once.
inline uint64_t childSalt(uint64_t index) { return mix64(index + 0x632be59bd9b4e019ull); }
inline uint64_t keyWithSalt(uint64_t parent, uint64_t salt) { return mix64(parent ^ salt); }
inline uint64_t childKey(uint64_t parent, uint64_t index) { return keyWithSalt(parent, childSalt(index)); }

inline uint64_t rootKey(uint64_t seed) { return mix64(seed ^ 0xd1b54a32d192ed03ull); }

// Uniform double in [0, 1) from a key and a counter: 53 random bits.
inline double uniform01(uint64_t key, uint64_t counter) {
  return static_cast<double>(mix64(key + mix64(counter)) >> 11) * 0x1.0p-53;
}

struct RandomStream {
  uint64_t key = 0;
  uint64_t counter = 0;
  double next() { return uniform01(key, counter++); }
};

}  // namespace fgsg::rt
