#include "runtime/evolve/colour_symmetry.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace fgsg::rt::evolve {
namespace {

// Union-find over the blocks, the smaller root kept so that class numbering is stable.
struct ColourBlockSets {
  std::vector<int> parent;
  explicit ColourBlockSets(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int root(int b) {
    while (parent[size_t(b)] != b) b = parent[size_t(b)] = parent[size_t(parent[size_t(b)])];
    return b;
  }
  void join(int a, int b) {
    a = root(a), b = root(b);
    if (a != b) parent[size_t(std::max(a, b))] = std::min(a, b);
  }
};

// Whether every cell of block (R, C), turned `turns` quarter turns about the pattern's
// centre, looks like the cell it lands on.
bool colourBlockTurnsAlike(const PatternMeasure& measure, const AlleleGrid& g, int side, int R, int C, int turns) {
  const int n = g.side;
  for (int r = R * side; r < (R + 1) * side; ++r)
    for (int c = C * side; c < (C + 1) * side; ++c) {
      int tr = r, tc = c;
      for (int t = 0; t < turns; ++t) {
        const int nr = n - 1 - tc, nc = tr;
        tr = nr, tc = nc;
      }
      const Allele a = g.at(r, c);
      if (!measure.lookAlike(Allele{a.symbol, uint8_t((a.turns + turns) & 3)}, g.at(tr, tc))) return false;
    }
  return true;
}

}  // namespace

ColourClasses colourClasses(const PatternMeasure& measure, const AlleleGrid& pattern, int blockSide) {
  const int n = pattern.side;
  if (n <= 0 || blockSide <= 0 || n % blockSide != 0)
    throw std::invalid_argument("colourClasses: a block of " + std::to_string(blockSide) +
                                " cells does not divide the pattern's " + std::to_string(n));
  const int m = n / blockSide;
  ColourBlockSets sets(size_t(m) * size_t(m));
  for (int R = 0; R < m; ++R)
    for (int C = 0; C < m; ++C) {
      if (colourBlockTurnsAlike(measure, pattern, blockSide, R, C, 1)) sets.join(R * m + C, (m - 1 - C) * m + R);
      if (colourBlockTurnsAlike(measure, pattern, blockSide, R, C, 2))
        sets.join(R * m + C, (m - 1 - R) * m + (m - 1 - C));
    }
  for (const Symmetry s : {Symmetry::kMirrorX, Symmetry::kMirrorY, Symmetry::kDiagonal, Symmetry::kAntiDiagonal}) {
    if (!measure.symmetric(pattern, s)) continue;
    for (int R = 0; R < m; ++R)
      for (int C = 0; C < m; ++C) {
        const std::array<int, 2> to = mapCell(s, m, R, C);
        sets.join(R * m + C, to[0] * m + to[1]);
      }
  }
  ColourClasses out;
  out.blockSide = blockSide;
  std::vector<int> classOfRoot(size_t(m) * size_t(m), -1);
  std::vector<int> blockClass(size_t(m) * size_t(m));
  for (int b = 0; b < m * m; ++b) {
    int& c = classOfRoot[size_t(sets.root(b))];
    if (c < 0) c = out.classCount++;
    blockClass[size_t(b)] = c;
  }
  out.ofCell.resize(size_t(n) * size_t(n));
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c)
      out.ofCell[size_t(r) * size_t(n) + size_t(c)] = blockClass[size_t(r / blockSide) * size_t(m) + size_t(c / blockSide)];
  return out;
}

std::array<float, 3> classColour(int c) {
  // Distinct at a glance, none near the surface's grey.
  static constexpr std::array<std::array<float, 3>, 8> kPalette{{{0.80f, 0.25f, 0.20f},
                                                                  {0.20f, 0.45f, 0.80f},
                                                                  {0.95f, 0.75f, 0.15f},
                                                                  {0.25f, 0.65f, 0.30f},
                                                                  {0.60f, 0.30f, 0.70f},
                                                                  {0.95f, 0.50f, 0.10f},
                                                                  {0.15f, 0.70f, 0.70f},
                                                                  {0.55f, 0.35f, 0.20f}}};
  return kPalette[size_t(c < 0 ? 0 : c) % kPalette.size()];
}

}  // namespace fgsg::rt::evolve
