// A 128-bit content hash for the disk caches (prepared marching surfaces, compiled
// grammars): keys and checksums, not a defence against forgery.
#pragma once

#include "runtime/random.h"

#include <cstdint>
#include <cstring>
#include <string>

namespace fgsg::rt::io {

// 128 bits from two independent 64-bit chains over 8-byte words (splitmix64's finaliser
// as the mixing step): a content key and a checksum, not a defence against forgery.
class ContentHash {
 public:
  void bytes(const void* data, size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    word(n);
    for (; n >= 8; n -= 8, p += 8) {
      uint64_t w;
      std::memcpy(&w, p, 8);
      word(w);
    }
    if (n > 0) {
      uint64_t w = 0;
      std::memcpy(&w, p, n);
      word(w);
    }
  }
  void word(uint64_t w) {
    a_ = mix64(a_ ^ w);
    b_ = mix64(b_ + w + 0x632be59bd9b4e019ull);
  }
  std::string hex() const {
    static const char* digits = "0123456789abcdef";
    std::string out;
    for (uint64_t v : {a_, b_})
      for (int shift = 60; shift >= 0; shift -= 4) out += digits[(v >> shift) & 15];
    return out;
  }
  uint64_t first() const { return a_; }
  uint64_t second() const { return b_; }

 private:
  uint64_t a_ = 0x243f6a8885a308d3ull, b_ = 0x13198a2e03707344ull;
};

}  // namespace fgsg::rt::io
