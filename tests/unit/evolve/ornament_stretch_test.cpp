// The stretch of the pattern's cells as the inverse poly-cube map carries them onto the
// surface (runtime/evolve/ornament_stretch.h, Chan & Hui 2013 §6.4), against values
// worked out by hand on boxes, and the stretch bound of surfaceOrnament: with it no
// emitted cell is stretched beyond it, without it a thin box's cells are.
#include "../box_surface.h"
#include "runtime/evolve/ornament_stretch.h"

#include "runtime/evolve/surface_ornament.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

using namespace fgsg::rt::evolve;
using fgsg::rt::Vec3;
using fgsg::rt::surface::SurfaceMesh;

namespace {

// The box from the origin to hi (box_surface.h).
SurfaceMesh box(const Vec3& hi) { return fgsg::test::boxSurface(Vec3::Zero(), hi); }

size_t countAbove(const std::vector<double>& r, double limit) {
  return size_t(std::count_if(r.begin(), r.end(), [&](double x) { return x > limit; }));
}

}  // namespace

TEST_CASE("a cell's stretch is its longest mapped side over its shortest", "[ornament-stretch]") {
  const Vec3 square[2][2] = {{Vec3(0, 0, 0), Vec3(1, 0, 0)}, {Vec3(0, 1, 0), Vec3(1, 1, 0)}};
  CHECK(cellStretch(square) == 1.0);
  const Vec3 rect[2][2] = {{Vec3(0, 0, 0), Vec3(3, 0, 0)}, {Vec3(0, 0.5, 0), Vec3(3, 0.5, 0)}};
  CHECK(cellStretch(rect) == Approx(6.0).epsilon(1e-12));
  // A trapezoid: sides 2, sqrt(1 + 1), 1, 1 -> 2 / 1.
  const Vec3 trap[2][2] = {{Vec3(0, 0, 0), Vec3(2, 0, 0)}, {Vec3(0, 1, 0), Vec3(1, 1, 0)}};
  CHECK(cellStretch(trap) == Approx(2.0).epsilon(1e-12));
  const Vec3 collapsedSide[2][2] = {{Vec3(0, 0, 0), Vec3(1, 0, 0)}, {Vec3(0, 0, 0), Vec3(1, 0, 0)}};
  CHECK(cellStretch(collapsedSide) == std::numeric_limits<double>::infinity());
}

TEST_CASE("nearest-rank median and 95th percentile of the stretch", "[ornament-stretch]") {
  std::vector<double> r;
  for (int i = 20; i >= 1; --i) r.push_back(i);  // 1..20, shuffled order does not matter
  const StretchSummary s = summarizeStretch(r);
  CHECK(s.cells == 20);
  CHECK(s.median == 10);  // ceil(0.5 * 20) = 10th smallest
  CHECK(s.p95 == 19);     // ceil(0.95 * 20) = 19th smallest
  CHECK(s.max == 20);
  const StretchSummary none = summarizeStretch({});
  CHECK(none.cells == 0);
  CHECK(none.max == 1);
}

TEST_CASE("a cube on the lattice maps its cells without stretch", "[ornament-stretch]") {
  // Cell size 1, the polycube is the cube itself: every face-let point lies on the surface.
  const PolycubeMap map(box(Vec3(8, 8, 8)), PolycubeOptions{0, 8});
  REQUIRE(map.facelets().size() == 6 * 64);
  const std::vector<double> r = patternStretch(map, 3);
  REQUIRE(r.size() == 6 * 64 * 9);
  for (const double x : r) CHECK(x == Approx(1.0).margin(1e-9));
}

// Box 8 x 8 x 2.4 at resolution 8 (cell 1): the polycube is 8 x 8 x 2 (cells with centres
// at z 2.5 are outside). Side and bottom face-lets lie on the surface and map to
// themselves. A top face-let point projects along the blend of its corners' directions:
// inside the top (0,0,-1) up to z 2.4, on the rim (8, y, 2) the direction (-1,0,-1) from
// a point already on the side. Across a rim face-let, a in [0,1] from the inner corner,
// D = (-a, 0, -1), and the line meets the top at (7 + 1.4 a, 2.4) while 1.4 a <= 1, then
// the side at (8, 2 + (1 - a) / a).
TEST_CASE("the stretch of a flat box's rim, worked out by hand", "[ornament-stretch]") {
  const PolycubeMap map(box(Vec3(8, 8, 2.4)), PolycubeOptions{0, 8});
  REQUIRE(map.cellSize() == Approx(1.0));
  REQUIRE(map.facelets().size() == 64 + 64 + 4 * 8 * 2);
  SECTION("one cell per face-let") {
    // A rim face-let's corners: (7, 2.4) and (8, 2) across the rim, sqrt(1 + 0.4^2) apart,
    // 1 apart along it; the 24 rim and 4 corner face-lets of the top (the corner one has
    // two such sides and two of length 1), the other 164 unstretched.
    const std::vector<double> r = patternStretch(map, 1);
    const double rim = std::sqrt(1.16);
    CHECK(countAbove(r, 1 + 1e-9) == 28);
    for (const double x : r)
      if (x > 1 + 1e-9) CHECK(x == Approx(rim).epsilon(1e-9));
    const StretchSummary s = summarizeStretch(r);
    CHECK(s.median == Approx(1.0).epsilon(1e-9));
    CHECK(s.p95 == Approx(rim).epsilon(1e-9));  // the 183rd of 192: past the 164 ones
    CHECK(s.max == Approx(rim).epsilon(1e-9));
  }
  SECTION("two cells a side") {
    // The rim face-let's inner cell (a in [0, 0.5]) spans the top from x 7 to 7.7, 0.7
    // long, 0.5 wide: stretch 1.4; its outer cell runs from (7.7, 2.4) to (8, 2), 0.5 long.
    const StretchSummary s = summarizeStretch(patternStretch(map, 2));
    CHECK(s.max == Approx(1.4).epsilon(1e-9));
  }
}

TEST_CASE("surfaceOrnament leaves out cells stretched beyond the bound", "[ornament-stretch]") {
  // A long thin box: its cross-section (1.3 x 1.4) is under two cells, so its polycube is
  // one cell thick and the rims' face-lets are carried across the wider surface.
  const PolycubeMap map(box(Vec3(8, 1.3, 1.4)), PolycubeOptions{0, 8});
  const TileSet tiles = exampleTileSet();
  const AlleleGrid pattern(4, Allele{1, 0});
  const std::vector<double> independent = patternStretch(map, 4);
  SurfaceOrnamentStats free;
  const fgsg::rt::Mesh all = surfaceOrnament(tiles, pattern, map, {}, {}, &free);
  const double bound = 1.5;
  REQUIRE(free.stretch.max > bound);  // without the bound some cells are stretched past it
  CHECK(free.stretchedCells == 0);
  CHECK(free.emittedStretch.max == free.stretch.max);
  CHECK(free.stretch.max == *std::max_element(independent.begin(), independent.end()));

  SurfaceOrnamentStats bounded;
  const fgsg::rt::Mesh kept = surfaceOrnament(tiles, pattern, map, {}, {}, &bounded, bound);
  CHECK(bounded.emittedStretch.max <= bound);
  CHECK(bounded.stretchedCells == countAbove(independent, bound));
  CHECK(bounded.stretchedCells > 0);
  CHECK(bounded.stretchedCells < bounded.cells);
  CHECK(bounded.emittedStretch.cells == bounded.cells - bounded.stretchedCells);
  const OrnamentGrid g = ornamentGrid(tiles, Allele{1, 0});
  const size_t perCell = 2 * (g.t.size() - 1) * (g.r.size() - 1);
  CHECK(kept.triangleCount() + bounded.droppedTriangles == (bounded.cells - bounded.stretchedCells) * perCell);
  CHECK(all.triangleCount() + free.droppedTriangles == free.cells * perCell);
}

TEST_CASE("bad stretch bounds and pattern sizes are refused", "[ornament-stretch]") {
  const PolycubeMap map(box(Vec3(2, 2, 2)), PolycubeOptions{0, 2});
  CHECK_THROWS_AS(patternStretch(map, 0), std::invalid_argument);
  const AlleleGrid pattern(1, Allele{1, 0});
  for (const double bad : {0.5, -1.0, std::numeric_limits<double>::infinity(), std::nan("")})
    CHECK_THROWS_WITH(surfaceOrnament(exampleTileSet(), pattern, map, {}, {}, nullptr, bad),
                      Catch::Contains("the stretch limit must be 0 (none) or a ratio of at least 1"));
}
