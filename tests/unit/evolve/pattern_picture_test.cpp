// The pattern picture (fgsg evolve --preview): each cell's locus drawn where its allele,
// orientation applied, puts it, in its symbol's colour, on a grid; row 0 at the top.
#include "runtime/evolve/pattern_picture.h"

#include <catch2/catch.hpp>

#include <array>
#include <stdexcept>

using namespace fgsg::rt::evolve;

namespace {

std::array<int, 3> pixel(const PatternPicture& p, int x, int y) {
  const uint8_t* c = &p.rgb[(size_t(y) * size_t(p.width) + size_t(x)) * 3];
  return {c[0], c[1], c[2]};
}

constexpr std::array<int, 3> kBackground{250, 250, 250}, kGrid{215, 215, 215};
constexpr std::array<int, 3> kA{31, 78, 160}, kB{200, 70, 40};

}  // namespace

TEST_CASE("a pattern picture draws each cell's turned locus in its symbol's colour", "[picture]") {
  const TileSet tiles = exampleTileSet();  // B: the line from the left edge's middle to the right's
  AlleleGrid g(2);
  g.at(0, 0) = {1, 0};  // B: horizontal, top left
  g.at(0, 1) = {1, 1};  // B90: vertical, top right
  g.at(1, 0) = {0, 0};  // A: the arc from the bottom edge's middle to the right edge's
  g.at(1, 1) = {1, 0};
  const PatternPicture p = drawPattern(tiles, g, 32);
  REQUIRE(p.width == 64);
  REQUIRE(p.height == 64);
  REQUIRE(p.rgb.size() == 64u * 64u * 3u);
  CHECK(pixel(p, 16, 16) == kB);          // on the horizontal line
  CHECK(pixel(p, 16, 4) == kBackground);  // above it
  CHECK(pixel(p, 48, 4) == kB);           // on the vertical line of B90
  CHECK(pixel(p, 40, 16) == kBackground);
  CHECK(pixel(p, 0, 8) == kGrid);         // the cells' border
  CHECK(pixel(p, 20, 32) == kGrid);
  CHECK(pixel(p, 16, 63) == kA);          // A starts at the bottom edge's middle ...
  CHECK(pixel(p, 31, 48) == kA);          // ... and ends at the right edge's middle
  CHECK(pixel(p, 4, 40) == kBackground);
}

TEST_CASE("a pattern picture stays within its size limit and refuses bad patterns", "[picture]") {
  const TileSet tiles = exampleTileSet();
  const PatternPicture big = drawPattern(tiles, AlleleGrid(300), 32);
  CHECK(big.width == 300 * (kMaxPatternPicturePixels / 300));
  CHECK(big.width <= kMaxPatternPicturePixels);
  CHECK_THROWS_AS(drawPattern(tiles, AlleleGrid(), 32), std::invalid_argument);
  CHECK_THROWS_WITH(drawPattern(tiles, AlleleGrid(1025), 32),
                    "a pattern of 1025 cells a side is too large to draw (at most 1024, 4 pixels a cell)");
  AlleleGrid unknown(1);
  unknown.at(0, 0) = {7, 0};
  CHECK_THROWS_WITH(drawPattern(tiles, unknown, 32), "drawPattern: the pattern has symbol 7, the tile set 2");
}
