// A picture of a 2D L-system pattern the way the paper draws its figures (Chan & Hui 2013,
// Figs. 2-3 and 6): each cell's locus, orientation applied, as a stroke in its symbol's
// colour, on a light grid of cells. Row 0 of the pattern is the picture's top row.
#pragma once

#include "runtime/evolve/lsystem2d.h"
#include "runtime/evolve/tiles.h"

#include <cstdint>
#include <vector>

namespace fgsg::rt::evolve {

struct PatternPicture {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;  // rows top to bottom, 3 bytes per pixel
};

// The largest picture drawPattern makes, in pixels a side: cells shrink to fit.
constexpr int kMaxPatternPicturePixels = 4096;

// `cellPixels` a side per cell (at least 4), reduced so that the picture stays within
// kMaxPatternPicturePixels; the stroke is `strokeWidth` of a cell wide (anti-aliased).
// Throws std::invalid_argument for an empty pattern, one whose symbols the tile set lacks,
// or one of more than kMaxPatternPicturePixels / 4 cells a side.
PatternPicture drawPattern(const TileSet& tiles, const AlleleGrid& pattern, int cellPixels = 32,
                           double strokeWidth = 0.12);

}  // namespace fgsg::rt::evolve
