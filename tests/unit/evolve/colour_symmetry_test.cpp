// Colour symmetry (runtime/evolve/colour_symmetry.h, Chan & Hui 2013 §6.4): blocks of the
// pattern share a colour when a symmetry of the pattern carries one onto the other. The
// expected classes are worked out by hand from the orbits of the cells.
#include "runtime/evolve/colour_symmetry.h"

#include "runtime/evolve/genetic.h"

#include <catch2/catch.hpp>

#include <stdexcept>

using namespace fgsg::rt::evolve;

namespace {

// A 4 x 4 p4 pattern: the top-left quadrant's cells chosen freely, every other cell the
// quarter turn of one of them (cell (r, c) to (n-1-c, r), the allele gaining a turn), so
// the whole pattern is its own quarter turn.
AlleleGrid p4Pattern() {
  AlleleGrid g(4);
  const Allele quadrant[2][2] = {{{0, 0}, {1, 0}}, {{0, 3}, {0, 1}}};
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) {
      int tr = r, tc = c;
      Allele a = quadrant[r][c];
      for (int t = 0; t < 4; ++t) {
        g.at(tr, tc) = a;
        const int nr = 3 - tc, nc = tr;
        tr = nr, tc = nc;
        a.turns = uint8_t((a.turns + 1) & 3);
      }
    }
  return g;
}

std::vector<int> flat(std::initializer_list<std::initializer_list<int>> rows) {
  std::vector<int> out;
  for (const auto& row : rows) out.insert(out.end(), row.begin(), row.end());
  return out;
}

}  // namespace

TEST_CASE("a p4 pattern's colour classes are the orbits of its quarter turn", "[colour-symmetry]") {
  const TileSet tiles = exampleTileSet();
  const PatternMeasure measure(tiles);
  const AlleleGrid g = p4Pattern();
  REQUIRE(turnGrid(g, 1) == g);
  REQUIRE(measure.p4(g) == 1.0);
  for (const Symmetry s : {Symmetry::kMirrorX, Symmetry::kMirrorY, Symmetry::kDiagonal, Symmetry::kAntiDiagonal})
    REQUIRE_FALSE(measure.symmetric(g, s));
  const ColourClasses k = colourClasses(measure, g, 1);
  // Orbits of (r, c) -> (3 - c, r), numbered by their first cell in row order:
  // {(0,0),(3,0),(3,3),(0,3)} 0, {(0,1),(2,0),(3,2),(1,3)} 1, {(0,2),(1,0),(3,1),(2,3)} 2,
  // {(1,1),(2,1),(2,2),(1,2)} 3.
  CHECK(k.classCount == 4);
  CHECK(k.ofCell == flat({{0, 1, 2, 0}, {2, 3, 3, 1}, {1, 3, 3, 2}, {0, 2, 1, 0}}));
  // The colouring is its own quarter turn: the colour picture turned equals itself.
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) CHECK(k.ofCell[size_t(r * 4 + c)] == k.ofCell[size_t((3 - c) * 4 + r)]);
  // Blocks of 2 x 2: each corner block turns onto the next, one class.
  const ColourClasses blocks = colourClasses(measure, g, 2);
  CHECK(blocks.classCount == 1);
  CHECK_THROWS_AS(colourClasses(measure, g, 3), std::invalid_argument);
}

TEST_CASE("colours follow the symmetries the pattern has, and no others", "[colour-symmetry]") {
  const TileSet tiles = exampleTileSet();
  const PatternMeasure measure(tiles);
  // Straight horizontal lines everywhere (B0): the half turn and both midline mirrors hold,
  // the quarter turn and the diagonals do not.
  const AlleleGrid lines(4, Allele{1, 0});
  const ColourClasses k = colourClasses(measure, lines, 1);
  // Orbits of {identity, half turn, x mirror, y mirror}.
  CHECK(k.classCount == 4);
  CHECK(k.ofCell == flat({{0, 1, 1, 0}, {2, 3, 3, 2}, {2, 3, 3, 2}, {0, 1, 1, 0}}));
  // Not turned: cell (0, 1) and its quarter turn (2, 0) differ in colour.
  CHECK(k.ofCell[1] != k.ofCell[8]);
  // One arc (A0) in the corner breaks the mirrors; the half turn still joins, cell by cell,
  // the 7 pairs that do not hold the arc or its image: 16 - 7 classes.
  AlleleGrid broken = lines;
  broken.at(0, 0) = Allele{0, 0};
  const ColourClasses some = colourClasses(measure, broken, 1);
  CHECK(some.classCount == 9);
  CHECK(some.ofCell[0] != some.ofCell[15]);
  CHECK(some.ofCell[1] == some.ofCell[14]);
}

TEST_CASE("an evolved p4 pattern's colours are invariant under its quarter turn", "[colour-symmetry]") {
  const TileSet tiles = exampleTileSet();
  const PatternMeasure measure(tiles);
  EvolveOptions o;
  o.ruleSide = 2;  // an even side: the corner sub-tiles cover the whole pattern
  o.generation = 3;
  o.p4 = true;
  o.seed = 7;
  const AlleleGrid g = expand(evolve(tiles, o).best, o.generation);
  REQUIRE(g.side == 8);
  REQUIRE(measure.p4(g) == 1.0);
  for (const int block : {1, 2, 4}) {
    const ColourClasses k = colourClasses(measure, g, block);
    for (int r = 0; r < 8; ++r)
      for (int c = 0; c < 8; ++c) CHECK(k.ofCell[size_t(r * 8 + c)] == k.ofCell[size_t((7 - c) * 8 + r)]);
    // Every orbit of the quarter turn has four blocks (an even side has no centre block).
    const int blocks = (8 / block) * (8 / block);
    CHECK(k.classCount <= blocks / 4);
  }
  CHECK(classColour(0) != classColour(1));
  CHECK(classColour(8) == classColour(0));
}
