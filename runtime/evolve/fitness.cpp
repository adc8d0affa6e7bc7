#include "runtime/evolve/fitness.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fgsg::rt::evolve {

namespace {

constexpr double kSamePointTolerance = 1e-9;

bool nearPoint(Point2 a, Point2 b) {
  return std::abs(a.x - b.x) <= kSamePointTolerance && std::abs(a.y - b.y) <= kSamePointTolerance;
}

bool sameSet(const std::array<Point2, 2>& p, const std::array<Point2, 2>& q) {
  return (nearPoint(p[0], q[0]) && nearPoint(p[1], q[1])) || (nearPoint(p[0], q[1]) && nearPoint(p[1], q[0]));
}

// Half of the 8 neighbour directions (dr, dc); the other half are their opposites.
constexpr std::array<std::array<int, 2>, 4> kForward{{{0, 1}, {1, 0}, {1, 1}, {1, -1}}};

constexpr uint8_t kNoLook = 255;

constexpr std::array<Symmetry, kSymmetryCount> kSymmetries{Symmetry::kRotate90, Symmetry::kRotate180,
                                                           Symmetry::kMirrorX,  Symmetry::kMirrorY,
                                                           Symmetry::kDiagonal, Symmetry::kAntiDiagonal};

void checkWeight(double w, const char* name) {
  if (!(w >= 0) || !std::isfinite(w))
    throw std::invalid_argument(std::string("fitness weight ") + name + " must be finite and not negative, got " +
                                std::to_string(w));
}

}  // namespace

std::array<int, 2> mapCell(Symmetry s, int n, int r, int c) {
  switch (s) {
    case Symmetry::kRotate90: return {n - 1 - c, r};
    case Symmetry::kRotate180: return {n - 1 - r, n - 1 - c};
    case Symmetry::kMirrorX: return {n - 1 - r, c};
    case Symmetry::kMirrorY: return {r, n - 1 - c};
    case Symmetry::kDiagonal: return {n - 1 - c, n - 1 - r};
    case Symmetry::kAntiDiagonal: return {c, r};
  }
  return {r, c};
}

Point2 mapPoint(Symmetry s, Point2 p) {
  switch (s) {
    case Symmetry::kRotate90: return {1 - p.y, p.x};
    case Symmetry::kRotate180: return {1 - p.x, 1 - p.y};
    case Symmetry::kMirrorX: return {p.x, 1 - p.y};
    case Symmetry::kMirrorY: return {1 - p.x, p.y};
    case Symmetry::kDiagonal: return {p.y, p.x};
    case Symmetry::kAntiDiagonal: return {1 - p.y, 1 - p.x};
  }
  return p;
}

double combineFitness(double fH, double fCon, double fCom, const FitnessWeights& w) {
  checkWeight(w.symmetry, "a (symmetry)");
  checkWeight(w.connectivity, "b (connectivity)");
  checkWeight(w.complexity, "c (complexity)");
  const double sum = w.symmetry + w.connectivity + w.complexity;
  if (sum <= 0) throw std::invalid_argument("fitness weights a, b, c are all 0");
  return (w.symmetry * fH + w.connectivity * fCon + w.complexity * fCom) / sum;
}

double combineFitness(double fH, double fCon, double fCom, double fP4, const FitnessWeights& w) {
  checkWeight(w.symmetry, "a (symmetry)");
  checkWeight(w.connectivity, "b (connectivity)");
  checkWeight(w.complexity, "c (complexity)");
  checkWeight(w.p4, "d (p4)");
  const double sum = w.symmetry + w.connectivity + w.complexity + w.p4;
  if (sum <= 0) throw std::invalid_argument("fitness weights a, b, c, d are all 0");
  return (w.symmetry * fH + w.connectivity * fCon + w.complexity * fCom + w.p4 * fP4) / sum;
}

PatternMeasure::PatternMeasure(const TileSet& tiles) : symbols_(tiles.symbolCount()) {
  validateTileSet(tiles);
  const int count = symbols_ * 4;  // <= 208: allele indices fit a byte
  std::vector<std::array<Point2, 2>> ends(static_cast<size_t>(count));
  for (int a = 0; a < count; ++a) ends[size_t(a)] = tiles.endpoints(Allele{uint8_t(a / 4), uint8_t(a % 4)});

  // Looks: the first allele of the same symbol with the same end point set names it.
  auto lookOf = [&](int symbol, const std::array<Point2, 2>& e) -> uint8_t {
    for (int t = 0; t < 4; ++t)
      if (sameSet(ends[size_t(symbol * 4 + t)], e)) return uint8_t(symbol * 4 + t);
    return kNoLook;
  };
  look_.resize(size_t(count));
  for (int a = 0; a < count; ++a) look_[size_t(a)] = lookOf(a / 4, ends[size_t(a)]);
  for (int s = 0; s < kSymmetryCount; ++s) {
    image_[size_t(s)].resize(size_t(count));
    for (int a = 0; a < count; ++a) {
      const std::array<Point2, 2> e{mapPoint(kSymmetries[size_t(s)], ends[size_t(a)][0]),
                                    mapPoint(kSymmetries[size_t(s)], ends[size_t(a)][1])};
      image_[size_t(s)][size_t(a)] = lookOf(a / 4, e);
    }
  }
  // End point p of a cell meets end point q of its neighbour at (dr, dc) when they are
  // the same point of the plane: p = q + (dc, -dr) in cell units (rows grow downwards).
  auto meets = [&](int a, int b, int dr, int dc) {
    uint8_t mask = 0;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        const Point2 q{ends[size_t(b)][size_t(j)].x + dc, ends[size_t(b)][size_t(j)].y - dr};
        if (nearPoint(ends[size_t(a)][size_t(i)], q)) mask |= uint8_t(1u << i);
      }
    return mask;
  };
  for (size_t d = 0; d < kForward.size(); ++d) {
    const int dr = kForward[d][0], dc = kForward[d][1];
    meet_[d].assign(size_t(count) * size_t(count), 0);
    for (int a = 0; a < count; ++a)
      for (int b = 0; b < count; ++b)
        meet_[d][size_t(a) * size_t(count) + size_t(b)] = uint8_t(meets(a, b, dr, dc) | meets(b, a, -dr, -dc) << 2);
  }
}

PatternMeasure::Cells PatternMeasure::prepare(const AlleleGrid& g) const {
  if (g.side < 1 || g.cells.size() != size_t(g.side) * size_t(g.side))
    throw std::invalid_argument("pattern is not a non-empty square array");
  Cells v;
  v.n = g.side;
  v.index.resize(g.cells.size());
  v.look.resize(g.cells.size());
  for (size_t i = 0; i < g.cells.size(); ++i) {
    const Allele a = g.cells[i];
    if (a.symbol >= symbols_ || a.turns > 3)
      throw std::invalid_argument("pattern holds symbol " + std::to_string(a.symbol) + " but the tile set has " +
                                  std::to_string(symbols_) + " symbols");
    v.index[i] = uint8_t(a.index());
    v.look[i] = look_[size_t(a.index())];
  }
  return v;
}

bool PatternMeasure::symmetric(const AlleleGrid& g, Symmetry s) const { return symmetricImpl(prepare(g), s); }

bool PatternMeasure::symmetricImpl(const Cells& v, Symmetry s) const {
  const uint8_t* image = image_[size_t(s)].data();
  const int n = v.n;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      const auto [tr, tc] = mapCell(s, n, r, c);
      if (image[v.index[size_t(r * n + c)]] != v.look[size_t(tr * n + tc)]) return false;
    }
  return true;
}

int PatternMeasure::symmetryCount(const AlleleGrid& g) const { return symmetryCountImpl(prepare(g)); }

int PatternMeasure::symmetryCountImpl(const Cells& v) const {
  int h = 0;
  for (Symmetry s : kSymmetries) h += symmetricImpl(v, s);
  return h;
}

double PatternMeasure::symmetry(const AlleleGrid& g) const { return symmetryCount(g) / double(kSymmetryCount); }

double PatternMeasure::complexity(const AlleleGrid& g) const { return complexityImpl(prepare(g)); }

double PatternMeasure::complexityImpl(const Cells& v) const {
  const int n = v.n;
  if (n < 2) return 0;
  long kr = 0, kc = 0;
  const uint8_t* look = v.look.data();
  for (int r = 0; r < n; ++r) {
    const uint8_t* row = look + size_t(r) * size_t(n);
    for (int c = 0; c + 1 < n; ++c) kr += row[c] != row[c + 1];
    if (r + 1 < n)
      for (int c = 0; c < n; ++c) kc += row[c] != row[c + n];
  }
  // R rows, C columns (R = C = n): R (C - 1) + C (R - 1).
  return double(kr + kc) / double(2L * n * (n - 1));
}

int PatternMeasure::connectedEndpoints(const AlleleGrid& g) const { return connectedImpl(prepare(g)); }

int PatternMeasure::connectedImpl(const Cells& v) const {
  const int n = v.n;
  const size_t count = size_t(symbols_) * 4;
  const uint8_t* const right = meet_[0].data();
  const uint8_t* const down = meet_[1].data();
  const uint8_t* const downRight = meet_[2].data();
  const uint8_t* const downLeft = meet_[3].data();
  const uint8_t* const index = v.index.data();
  // A cell's end points that meet a neighbour's, from the pair tables: bits 0-1 when the
  // cell is the first of the pair, bits 2-3 when it is the second. Reads only.
  auto endsMet = [=](int r, int c) -> int {
    const size_t here = size_t(r) * size_t(n) + size_t(c);
    const size_t a = size_t(index[here]);
    unsigned m = 0;
    if (c + 1 < n) m |= right[a * count + index[here + 1]] & 3u;
    if (c > 0) m |= right[size_t(index[here - 1]) * count + a] >> 2;
    if (r + 1 < n) {
      const size_t below = here + size_t(n);
      m |= down[a * count + index[below]] & 3u;
      if (c + 1 < n) m |= downRight[a * count + index[below + 1]] & 3u;
      if (c > 0) m |= downLeft[a * count + index[below - 1]] & 3u;
    }
    if (r > 0) {
      const size_t above = here - size_t(n);
      m |= down[size_t(index[above]) * count + a] >> 2;
      if (c > 0) m |= downRight[size_t(index[above - 1]) * count + a] >> 2;
      if (c + 1 < n) m |= downLeft[size_t(index[above + 1]) * count + a] >> 2;
    }
    return int((m & 1u) + (m >> 1));
  };
  int connected = 0;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) connected += endsMet(r, c);
  return connected;
}

double PatternMeasure::connectivity(const AlleleGrid& g) const {
  return connectedEndpoints(g) / (2.0 * double(g.cells.size()));
}

double PatternMeasure::p4(const AlleleGrid& g) const { return p4Impl(prepare(g)); }

double PatternMeasure::p4Impl(const Cells& v) const {
  const int n = v.n, m = n / 2;
  if (m == 0) return 1;
  const uint8_t* image = image_[size_t(Symmetry::kRotate90)].data();
  int match = 0;
  // The four corner sub-tiles: rows [0, m) and [n-m, n), the same for columns. A quarter
  // turn maps cell (r, c) to (n-1-c, r).
  for (int r = 0; r < n; ++r) {
    if (r == m && n % 2) continue;
    for (int c = 0; c < n; ++c) {
      if (c == m && n % 2) continue;
      match += image[v.index[size_t(r * n + c)]] == v.look[size_t((n - 1 - c) * n + r)];
    }
  }
  return match / (4.0 * m * m);
}

FitnessTerms PatternMeasure::evaluate(const AlleleGrid& g, const FitnessWeights& w, bool withP4) const {
  const Cells v = prepare(g);
  FitnessTerms t;
  t.symmetries = symmetryCountImpl(v);
  t.fH = t.symmetries / double(kSymmetryCount);
  t.fCon = connectedImpl(v) / (2.0 * double(g.cells.size()));
  t.fCom = complexityImpl(v);
  if (withP4) {
    t.fP4 = p4Impl(v);
    t.fitness = combineFitness(t.fH, t.fCon, t.fCom, t.fP4, w);
  } else {
    t.fitness = combineFitness(t.fH, t.fCon, t.fCom, w);
  }
  return t;
}

}  // namespace fgsg::rt::evolve
