// Colour literals as grammars write them: Color("#8c3b2e"). The same reading for the
// checker (E042 for anything else) and the lowering (three numbers 0..1).
#pragma once

#include <array>
#include <string>

namespace fgsg::frontend {

// "#rrggbb" (hex digits, either case) -> r, g, b in [0, 1]; false for anything else.
inline bool parseHexColor(const std::string& text, std::array<double, 3>& rgb) {
  if (text.size() != 7 || text[0] != '#') return false;
  auto digit = [](char c) {
    return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
  };
  for (int k = 0; k < 3; ++k) {
    const int hi = digit(text[size_t(1 + 2 * k)]), lo = digit(text[size_t(2 + 2 * k)]);
    if (hi < 0 || lo < 0) return false;
    rgb[size_t(k)] = (16 * hi + lo) / 255.0;
  }
  return true;
}

}  // namespace fgsg::frontend
