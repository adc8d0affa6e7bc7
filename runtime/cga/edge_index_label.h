// CGA's index selectors of a setback's edges, `setback(2){ 0 : A | -1 : B }` (fgsg:
// `Setback(2){ 0: A | -1: B }`): the front ends label such a part "#0", "#-1", and the
// derivation gives it edge i of the polygon (the order runtime/cga/shape_operations.h's
// edgeSelectors numbers them in), an index of n edges or more, or below 0, wrapping around
// (op_setback: "modulo"). Free of the geometry headers: the front ends use it too.
#pragma once

#include <cstddef>
#include <string>

namespace fgsg::rt::cga {

inline std::string edgeIndexLabel(long long index) { return "#" + std::to_string(index); }

// Whether `label` (a merged part's trailing '=' ignored) is an index selector, and its index.
inline bool edgeIndexOfLabel(const std::string& label, long long& index) {
  std::string digits = label;
  if (!digits.empty() && digits.back() == '=') digits.pop_back();
  if (digits.size() < 2 || digits[0] != '#') return false;
  digits.erase(0, 1);
  const size_t sign = digits[0] == '-' ? 1 : 0;
  if (digits.size() == sign || digits.size() > 18 || digits.find_first_not_of("0123456789", sign) != std::string::npos)
    return false;
  index = std::stoll(digits);
  return true;
}

// Whether the index selector `index` names edge `edge` of a polygon of `edges` edges.
inline bool edgeIndexSelects(long long index, std::size_t edge, std::size_t edges) {
  const long long n = static_cast<long long>(edges);
  return n > 0 && ((index % n) + n) % n == static_cast<long long>(edge);
}

}  // namespace fgsg::rt::cga
