#include "runtime/evolve/pattern_picture.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fgsg::rt::evolve {
namespace {

// Distinct, print-friendly colours for the first symbols; later ones repeat.
constexpr std::array<std::array<uint8_t, 3>, 8> kSymbolColours{{{31, 78, 160},
                                                                {200, 70, 40},
                                                                {40, 140, 70},
                                                                {150, 60, 150},
                                                                {200, 150, 20},
                                                                {20, 140, 150},
                                                                {120, 90, 50},
                                                                {90, 90, 90}}};
constexpr uint8_t kBackground = 250, kGrid = 215;
constexpr int kLocusSamples = 48;

double segmentDistance(Point2 p, Point2 a, Point2 b) {
  const double ex = b.x - a.x, ey = b.y - a.y, len2 = ex * ex + ey * ey;
  double t = len2 > 0 ? ((p.x - a.x) * ex + (p.y - a.y) * ey) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - a.x - t * ex, p.y - a.y - t * ey);
}

}  // namespace

PatternPicture drawPattern(const TileSet& tiles, const AlleleGrid& pattern, int cellPixels, double strokeWidth) {
  if (pattern.side <= 0 || pattern.cells.size() != size_t(pattern.side) * size_t(pattern.side))
    throw std::invalid_argument("drawPattern: an empty pattern");
  for (const Allele& a : pattern.cells)
    if (a.symbol >= tiles.symbolCount() || a.turns > 3)
      throw std::invalid_argument("drawPattern: the pattern has symbol " + std::to_string(a.symbol) +
                                  ", the tile set " + std::to_string(tiles.symbolCount()));
  if (pattern.side * 4 > kMaxPatternPicturePixels)
    throw std::invalid_argument("a pattern of " + std::to_string(pattern.side) + " cells a side is too large to draw (at most " +
                                std::to_string(kMaxPatternPicturePixels / 4) + ", 4 pixels a cell)");
  const int cell = std::max(4, std::min(cellPixels, kMaxPatternPicturePixels / pattern.side));
  PatternPicture pic;
  pic.width = pic.height = cell * pattern.side;
  pic.rgb.assign(size_t(pic.width) * size_t(pic.height) * 3, kBackground);

  // Each allele's locus once, in its tile's unit square.
  std::vector<std::vector<Point2>> loci(size_t(tiles.symbolCount()) * 4);
  for (const Allele& a : tiles.alleles()) loci[size_t(a.index())] = tiles.locusPoints(a, kLocusSamples);
  for (const Allele& a : pattern.cells)
    if (loci[size_t(a.index())].empty()) loci[size_t(a.index())] = tiles.locusPoints(a, kLocusSamples);

  // Each cell's stroke, segment by segment over the pixels near it (not every pixel
  // against every segment): the coverage is the largest any segment gives.
  const double halfStroke = std::max(0.5, strokeWidth * cell / 2);  // pixels
  tbb::parallel_for(0, pattern.side, [&](int row) {
    std::vector<float> coverage(size_t(cell) * size_t(cell));
    for (int col = 0; col < pattern.side; ++col) {
      std::fill(coverage.begin(), coverage.end(), 0.0f);
      const Allele a = pattern.at(row, col);
      const auto& pts = loci[size_t(a.index())];
      for (size_t i = 0; i + 1 < pts.size(); ++i) {
        // The segment in pixels of this cell, y down.
        const Point2 p0{pts[i].x * cell, (1 - pts[i].y) * cell}, p1{pts[i + 1].x * cell, (1 - pts[i + 1].y) * cell};
        const double reach = halfStroke + 1;
        const int x0 = std::max(0, int(std::floor(std::min(p0.x, p1.x) - reach)));
        const int x1 = std::min(cell - 1, int(std::ceil(std::max(p0.x, p1.x) + reach)));
        const int y0 = std::max(0, int(std::floor(std::min(p0.y, p1.y) - reach)));
        const int y1 = std::min(cell - 1, int(std::ceil(std::max(p0.y, p1.y) + reach)));
        for (int y = y0; y <= y1; ++y)
          for (int x = x0; x <= x1; ++x) {
            const double d = segmentDistance({x + 0.5, y + 0.5}, p0, p1);
            float& c = coverage[size_t(y) * size_t(cell) + size_t(x)];
            c = std::max(c, float(std::clamp(halfStroke + 0.5 - d, 0.0, 1.0)));
          }
      }
      const auto& colour = kSymbolColours[a.symbol % kSymbolColours.size()];
      for (int y = 0; y < cell; ++y)
        for (int x = 0; x < cell; ++x) {
          uint8_t* out = &pic.rgb[(size_t(row * cell + y) * size_t(pic.width) + size_t(col * cell + x)) * 3];
          if (x == 0 || y == 0) std::fill(out, out + 3, kGrid);
          const float c = coverage[size_t(y) * size_t(cell) + size_t(x)];
          if (c > 0)
            for (int k = 0; k < 3; ++k) out[k] = uint8_t(std::lround(out[k] + c * (colour[size_t(k)] - out[k])));
        }
    }
  });
  return pic;
}

}  // namespace fgsg::rt::evolve
