#include "runtime/synthesis/continuous/arrangement.h"

#include <atomic>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fgsg::rt::synthesis::continuous {

namespace {

int64_t floorDiv(int64_t a, int64_t b) {
  int64_t q = a / b;
  if ((a % b != 0) && ((a < 0) != (b < 0))) --q;
  return q;
}
int64_t ceilDiv(int64_t a, int64_t b) { return -floorDiv(-a, b); }

struct Key {
  IVec3 n;
  int64_t d;
  bool operator==(const Key& o) const { return n[0] == o.n[0] && n[1] == o.n[1] && n[2] == o.n[2] && d == o.d; }
};

// Binary gcd of non-negative numbers (std::gcd divides: the slower in this loop).
int64_t gcd2(uint64_t a, uint64_t b) {
  if (a == 0) return int64_t(b);
  if (b == 0) return int64_t(a);
  const int shift = __builtin_ctzll(a | b);
  a >>= __builtin_ctzll(a);
  do {
    b >>= __builtin_ctzll(b);
    if (a > b) std::swap(a, b);
    b -= a;
  } while (b != 0);
  return int64_t(a << shift);
}
struct KeyHash {
  size_t operator()(const Key& k) const {
    uint64_t h = uint64_t(k.d) * 0x9e3779b97f4a7c15ULL;
    for (int64_t c : k.n) h = (h ^ uint64_t(c)) * 0xbf58476d1ce4e5b9ULL + 0x94d049bb133111ebULL;
    return size_t(h ^ (h >> 29));
  }
};

// Vertex positions to indices: open addressing over a power-of-two table (the standard
// map's nodes cost more than the arrangement's arithmetic).
class VertexIndex {
 public:
  void reserve(size_t n) {
    size_t cap = 16;
    while (cap < 2 * n) cap *= 2;
    keys_.assign(cap, Key{{0, 0, 0}, 0});
    values_.assign(cap, -1);
    mask_ = cap - 1;
  }
  void put(const Key& k, int32_t v) {
    size_t i = KeyHash{}(k) & mask_;
    while (values_[i] >= 0 && !(keys_[i] == k)) i = (i + 1) & mask_;
    keys_[i] = k;
    values_[i] = v;
  }
  int32_t find(const Key& k) const {
    for (size_t i = KeyHash{}(k) & mask_; values_[i] >= 0; i = (i + 1) & mask_)
      if (keys_[i] == k) return values_[i];
    return -1;
  }

 private:
  std::vector<Key> keys_;
  std::vector<int32_t> values_;
  size_t mask_ = 0;
};

// num/den in lowest terms, den > 0.
Key reduced(IVec3 n, int64_t d) {
  if (d < 0) {
    d = -d;
    for (auto& c : n) c = -c;
  }
  if (d == 1) return {n, d};
  // The gcd of the four, stopping as soon as it is 1 (most of the time, at once).
  int64_t g = gcd2(uint64_t(d), uint64_t(std::abs(n[0])));
  for (int c = 1; c < 3 && g > 1; ++c) g = gcd2(uint64_t(g), uint64_t(std::abs(n[size_t(c)])));
  if (g > 1) {
    for (auto& c : n) c /= g;
    d /= g;
  }
  return {n, d};
}

}  // namespace

bool buildArrangement(const std::vector<IVec3>& dirs, const std::vector<int64_t>& step,
                      std::array<int64_t, 3> box, size_t maxVertices, Arrangement& A, std::string& error,
                      const std::function<bool()>& timeUp) {
  A = Arrangement{};
  const std::string stopped = "stopped by the time limit while the planes' vertices were found";
  A.dirs = dirs;
  A.step = step;
  A.box = box;
  const size_t m = dirs.size();
  auto inBox = [&](const IVec3& n, int64_t d) {
    for (int c = 0; c < 3; ++c)
      if (n[size_t(c)] < 0 || n[size_t(c)] > box[size_t(c)] * d) return false;
    return true;
  };
  // The directions with a plane through num / den.
  auto planesAt = [&](const IVec3& n, int64_t d) {
    uint32_t P = 0;
    for (size_t e = 0; e < m; ++e)
      if (dot(dirs[e], n) % (d * step[e]) == 0) P |= 1u << e;
    return P;
  };
  // Each vertex comes from one triple only: the first independent one among its planes
  // (its two lowest directions and the next one outside their span), so none is found
  // twice and no table is needed to merge them.
  // Is (i, j, l) that triple for the point num / den (on planes of i, j and l)? No plane
  // of a lower direction through it, none between i and j, none between j and l outside
  // the span of i and j: tested in that order, most points made by a later triple are
  // turned away by the first test.
  auto through = [&](size_t e, const IVec3& n, int64_t d) { return dot(dirs[e], n) % (d * step[e]) == 0; };
  auto isFirst = [&](const IVec3& n, int64_t d, size_t i, size_t j, size_t l) {
    for (size_t e = 0; e < j; ++e)
      if (e != i && through(e, n, d)) return false;
    for (size_t e = j + 1; e < l; ++e)
      if (through(e, n, d) && dot(dirs[i], cross(dirs[j], dirs[e])) != 0) return false;
    return true;
  };
  auto addVertex = [&](const Key& k) -> bool {
    if (A.den.size() >= maxVertices) {
      error = "the output would have more than " + std::to_string(maxVertices) +
              " vertices where planes meet: use a larger spacing or a smaller size";
      return false;
    }
    A.num.push_back(k.n);
    A.den.push_back(k.d);
    return true;
  };
  // The range of plane indices k of direction i that meet the box.
  auto range = [&](size_t i, int64_t& lo, int64_t& hi) {
    int64_t mn = 0, mx = 0;
    for (int c = 0; c < 3; ++c) {
      const int64_t v = dirs[i][size_t(c)] * box[size_t(c)];
      mn += std::min<int64_t>(0, v);
      mx += std::max<int64_t>(0, v);
    }
    lo = ceilDiv(mn, step[i]);
    hi = floorDiv(mx, step[i]);
  };

  // Vertices: every triple of independent directions meets in a lattice (eq. 4.24).
  size_t rows = 0;  // the time is asked every 256 rows
  for (size_t i = 0; i < m; ++i)
    for (size_t j = i + 1; j < m; ++j)
      for (size_t l = j + 1; l < m; ++l) {
        const IVec3 c1 = cross(dirs[j], dirs[l]), c2 = cross(dirs[l], dirs[i]), c3 = cross(dirs[i], dirs[j]);
        const int64_t det = dot(dirs[i], c1);
        if (det == 0) continue;
        int64_t loI, hiI, loJ, hiJ, loL, hiL;
        range(i, loI, hiI);
        range(j, loJ, hiJ);
        range(l, loL, hiL);
        // x = (vi c1 + vj c2 + vl c3) / det with v = step k; det made positive.
        const int64_t sgn = det > 0 ? 1 : -1;
        const int64_t D = det * sgn;
        for (int64_t ki = loI; ki <= hiI; ++ki)
          for (int64_t kj = loJ; kj <= hiJ; ++kj) {
            if ((++rows & 255) == 0 && timeUp()) {
              error = stopped;
              return false;
            }
            IVec3 base{}, dir{};
            for (int c = 0; c < 3; ++c) {
              base[size_t(c)] = sgn * (step[i] * ki * c1[size_t(c)] + step[j] * kj * c2[size_t(c)]);
              dir[size_t(c)] = sgn * step[l] * c3[size_t(c)];
            }
            // kl such that 0 <= base + kl dir <= box D on every axis.
            int64_t lo = loL, hi = hiL;
            for (int c = 0; c < 3 && lo <= hi; ++c) {
              const int64_t b = base[size_t(c)], d = dir[size_t(c)], top = box[size_t(c)] * D;
              if (d == 0) {
                if (b < 0 || b > top) hi = lo - 1;
              } else if (d > 0) {
                lo = std::max(lo, ceilDiv(-b, d));
                hi = std::min(hi, floorDiv(top - b, d));
              } else {
                lo = std::max(lo, ceilDiv(top - b, d));
                hi = std::min(hi, floorDiv(-b, d));
              }
            }
            for (int64_t kl = lo; kl <= hi; ++kl) {
              const IVec3 n{base[0] + kl * dir[0], base[1] + kl * dir[1], base[2] + kl * dir[2]};
              if (!isFirst(n, D, i, j, l)) continue;
              if (!addVertex(reduced(n, D))) return false;
            }
          }
      }
  // Order vertices by position (z, y, x): the solver's scanline order, independent of
  // the hash table.
  // Doubles order them exactly: distinct coordinates num / den (den < 2^20, |num| < 2^40)
  // differ by far more than a double's rounding.
  struct Keyed {
    double z, y, x;
    int32_t index;
    bool operator<(const Keyed& o) const { return z != o.z ? z < o.z : y != o.y ? y < o.y : x < o.x; }
  };
  std::vector<Keyed> keyed(A.den.size());
  for (size_t v = 0; v < A.den.size(); ++v) {
    const double d = double(A.den[v]);
    keyed[v] = {double(A.num[v][2]) / d, double(A.num[v][1]) / d, double(A.num[v][0]) / d, int32_t(v)};
  }
  if (timeUp()) {
    error = stopped;
    return false;
  }
  tbb::parallel_sort(keyed.begin(), keyed.end());
  if (timeUp()) {
    error = stopped;
    return false;
  }
  std::vector<int32_t> order(A.den.size());
  for (size_t k = 0; k < keyed.size(); ++k) order[k] = keyed[k].index;
  VertexIndex index;
  index.reserve(order.size());
  {
    std::vector<IVec3> num(order.size());
    std::vector<int64_t> den(order.size());
    for (size_t k = 0; k < order.size(); ++k) {
      if ((k & 65535) == 0 && timeUp()) {
        error = stopped;
        return false;
      }
      num[k] = A.num[size_t(order[k])];
      den[k] = A.den[size_t(order[k])];
      index.put({num[k], den[k]}, int32_t(k));
    }
    A.num.swap(num);
    A.den.swap(den);
  }
  const size_t n = A.den.size();
  A.planes.assign(n, 0);
  A.boundary.assign(n, 0);
  for (size_t v = 0; v < n; ++v) {
    if ((v & 65535) == 0 && timeUp()) {
      error = stopped;
      return false;
    }
    A.planes[v] = planesAt(A.num[v], A.den[v]);
    for (int c = 0; c < 3; ++c)
      if (A.num[v][size_t(c)] == 0 || A.num[v][size_t(c)] == box[size_t(c)] * A.den[v]) A.boundary[v] = 1;
  }

  // Edges: from each vertex along every line through it, to the nearest vertex each way.
  // The line of two directions, once per pair (an index into A.lines).
  std::vector<int32_t> lineOfPair(m * m, -1);
  for (size_t a = 0; a < m; ++a)
    for (size_t b = a + 1; b < m; ++b) {
      const IVec3 d = canonicalDirection(cross(dirs[a], dirs[b]));
      auto it = std::find(A.lines.begin(), A.lines.end(), d);
      if (it == A.lines.end()) it = A.lines.insert(A.lines.end(), d);
      lineOfPair[a * m + b] = int32_t(it - A.lines.begin());
    }
  // Each vertex's edges along +line on their own (in parallel: the search is most of the
  // build); each edge is then also its far end's edge along -line.
  struct Forward {
    int32_t from, to, line;
  };
  constexpr size_t kChunk = 2048;  // vertices per chunk; chunks in order keep edges in vertex order
  std::vector<std::vector<Forward>> chunks((n + kChunk - 1) / kChunk);
  std::atomic<bool> late{false};
  tbb::parallel_for(size_t(0), chunks.size(), [&](size_t chunk) {
    if (late.load(std::memory_order_relaxed) || timeUp()) {
      late = true;
      return;
    }
    std::vector<int32_t> through;
    std::vector<Forward>& found = chunks[chunk];
    for (size_t v = chunk * kChunk; v < std::min(n, (chunk + 1) * kChunk); ++v) {
      through.clear();
      const uint32_t P = A.planes[v];
      for (uint32_t a = P; a; a &= a - 1)
        for (uint32_t b = a & (a - 1); b; b &= b - 1) {
          const int32_t line = lineOfPair[size_t(__builtin_ctz(a)) * m + size_t(__builtin_ctz(b))];
          if (std::find(through.begin(), through.end(), line) == through.end()) through.push_back(line);
        }
      for (const int32_t line : through) {
        const IVec3& d0 = A.lines[size_t(line)];
        {
          const IVec3& d = d0;
          // The nearest plane crossing along d: t = p / q, q > 0. Compared as doubles:
          // the quotients are exact enough to floor (a / unit is an integer or at least
          // 1 / unit away from one) and distinct crossings differ by 1 / (q q') or more.
          int64_t bestP = -1, bestQ = 1;
          double bestT = 0;
          for (size_t l = 0; l < m; ++l) {
            const int64_t c = dot(dirs[l], d);
            if (c == 0) continue;
            const int64_t a = dot(dirs[l], A.num[v]);  // the value times den
            const int64_t unit = A.den[v] * step[l];
            const double f = std::floor(double(a) / double(unit));
            const int64_t below = int64_t(f), k = c > 0 ? below + 1 : (below * unit == a ? below - 1 : below);
            int64_t p = k * unit - a, q = A.den[v] * c;
            if (q < 0) { p = -p; q = -q; }
            const double t = double(p) / double(q);
            if (bestP < 0 || t < bestT) { bestP = p; bestQ = q; bestT = t; }
          }
          if (bestP < 0) continue;
          IVec3 w{};
          for (int c = 0; c < 3; ++c) w[size_t(c)] = A.num[v][size_t(c)] * bestQ + bestP * A.den[v] * d[size_t(c)];
          const Key k = reduced(w, A.den[v] * bestQ);
          if (!inBox(k.n, k.d)) continue;
          const int32_t to = index.find(k);
          if (to < 0) continue;  // cannot happen: a crossing of two planes and a third
          found.push_back({int32_t(v), to, line + 1});
        }
      }
    }
  });
  if (late) {
    error = stopped;
    return false;
  }
  // CSR: each vertex's edges along +line (in the order found), then those arriving along
  // -line (by their start).
  std::vector<uint32_t> count(n + 1, 0);
  for (const auto& chunk : chunks)
    for (const Forward& f : chunk) ++count[size_t(f.from)], ++count[size_t(f.to)];
  A.edgeStart.assign(n + 1, 0);
  for (size_t v = 0; v < n; ++v) A.edgeStart[v + 1] = A.edgeStart[v] + count[v];
  A.edgeTo.resize(A.edgeStart[n]);
  A.edgeLine.resize(A.edgeStart[n]);
  std::vector<uint32_t> fill(A.edgeStart.begin(), A.edgeStart.end() - 1);
  for (const auto& chunk : chunks)
    for (const Forward& f : chunk) {
      const uint32_t k = fill[size_t(f.from)]++;
      A.edgeTo[k] = f.to;
      A.edgeLine[k] = f.line;
    }
  for (const auto& chunk : chunks)
    for (const Forward& f : chunk) {
      const uint32_t k = fill[size_t(f.to)]++;
      A.edgeTo[k] = f.from;
      A.edgeLine[k] = -f.line;
    }
  return true;
}

}  // namespace fgsg::rt::synthesis::continuous
