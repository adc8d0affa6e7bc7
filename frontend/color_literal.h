// Colour literals as grammars write them: Color("#8c3b2e"). The same reading for the
// checker (E042 for anything else) and the lowering (three numbers 0..1).
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <vector>

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

// "#rrggbb #rrggbb ..." (separated by spaces) -> the colours; false when it holds none or
// anything else.
inline bool parseHexColors(const std::string& text, std::vector<std::array<float, 3>>& out) {
  out.clear();
  size_t at = 0;
  while ((at = text.find_first_not_of(' ', at)) != std::string::npos) {
    const size_t end = std::min(text.find(' ', at), text.size());
    std::array<double, 3> rgb;
    if (!parseHexColor(text.substr(at, end - at), rgb)) return false;
    out.push_back({float(rgb[0]), float(rgb[1]), float(rgb[2])});
    at = end;
  }
  return !out.empty();
}

}  // namespace fgsg::frontend
