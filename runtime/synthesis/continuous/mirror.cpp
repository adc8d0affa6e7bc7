#include "runtime/synthesis/continuous/mirror.h"

#include <algorithm>
#include <numeric>

namespace fgsg::rt::synthesis::continuous {

bool mirrorLabels(const std::vector<IVec3>& dirs, const std::vector<Label>& labels, int axis, std::vector<int32_t>& out,
                  std::string& error) {
  // Direction e mirrors onto ±dirs[image[e]]; flip: onto the minus sign.
  std::vector<int> image(dirs.size());
  std::vector<bool> flip(dirs.size());
  for (size_t e = 0; e < dirs.size(); ++e) {
    IVec3 m = dirs[e];
    m[size_t(axis)] = -m[size_t(axis)];
    const IVec3 c = canonicalDirection(m);
    const auto it = std::find(dirs.begin(), dirs.end(), c);
    if (it == dirs.end()) {
      error = "the example is not symmetric enough for this mirror: its face direction (" + std::to_string(dirs[e][0]) +
              ", " + std::to_string(dirs[e][1]) + ", " + std::to_string(dirs[e][2]) + ") has no mirror image among them";
      return false;
    }
    image[e] = int(it - dirs.begin());
    flip[e] = c != m;
  }
  out.assign(labels.size(), -1);
  for (size_t b = 0; b < labels.size(); ++b) {
    Label m;
    for (uint32_t d = labels[b].dirs; d; d &= d - 1) m.dirs |= 1u << image[size_t(__builtin_ctz(d))];
    for (uint32_t s : labels[b].in) {
      // The mirrored direction r' has a_image(e) · r' = ±(a_e · r): the sign, flipped or not.
      uint32_t t = 0;
      for (uint32_t d = labels[b].dirs; d; d &= d - 1) {
        const int e = __builtin_ctz(d);
        if (bool((s >> e) & 1) != flip[size_t(e)]) t |= 1u << image[size_t(e)];
      }
      m.in.push_back(t);
    }
    std::sort(m.in.begin(), m.in.end());
    const auto it = std::find(labels.begin(), labels.end(), m);
    if (it != labels.end()) out[b] = int32_t(it - labels.begin());
  }
  return true;
}

bool mirrorVertices(const Arrangement& A, int axis, std::vector<int32_t>& out, std::string& error) {
  const size_t n = A.vertexCount();
  // The mirror image of num / den: box - x on the axis.
  auto mirrored = [&](size_t v) {
    IVec3 p = A.num[v];
    p[size_t(axis)] = A.box[size_t(axis)] * A.den[v] - p[size_t(axis)];
    return p;
  };
  // Rank vertices by position and by mirrored position alike: the k-th of one is the
  // mirror of the k-th of the other.
  auto rank = [&](bool mirror) {
    std::vector<int32_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int32_t a, int32_t b) {
      const IVec3 pa = mirror ? mirrored(size_t(a)) : A.num[size_t(a)], pb = mirror ? mirrored(size_t(b)) : A.num[size_t(b)];
      for (int c = 0; c < 3; ++c) {
        const __int128 x = __int128(pa[size_t(c)]) * A.den[size_t(b)], y = __int128(pb[size_t(c)]) * A.den[size_t(a)];
        if (x != y) return x < y;
      }
      return false;
    });
    return order;
  };
  const std::vector<int32_t> plain = rank(false), image = rank(true);
  out.assign(n, -1);
  for (size_t k = 0; k < n; ++k) {
    const size_t v = size_t(image[k]), w = size_t(plain[k]);
    const IVec3 p = mirrored(v);
    if (A.den[v] != A.den[w] || p != A.num[w]) {
      error = "the planes are not symmetric across the middle of the box (a fixed width that does not fit the box)";
      return false;
    }
    out[v] = int32_t(w);
  }
  return true;
}

}  // namespace fgsg::rt::synthesis::continuous
