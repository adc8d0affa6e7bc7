// Different L-systems on selected face-lets (Chan & Hui 2013 §6.4, surface_ornament.h's
// shownFacelets and faceletsFacing) and the ornament parted by colour class
// (partOrnament), on a cube that is its own polycube: 8 x 8 x 8 at resolution 8, 64
// face-lets a side, every face-let point on the surface.
#include "../box_surface.h"
#include "runtime/evolve/surface_ornament.h"

#include "runtime/evolve/colour_symmetry.h"

#include <catch2/catch.hpp>

#include <map>

using namespace fgsg::rt::evolve;
using fgsg::rt::Vec3;
using fgsg::rt::surface::SurfaceMesh;

namespace {

// The box from the origin to hi (box_surface.h).
SurfaceMesh variationBox(const Vec3& hi) { return fgsg::test::boxSurface(Vec3::Zero(), hi); }

// The triangles of one cell's ornament for `allele` (ornament.h's grid, two per quad).
size_t cellTriangles(const TileSet& tiles, Allele allele) {
  const OrnamentGrid g = ornamentGrid(tiles, allele);
  return 2 * (g.t.size() - 1) * (g.r.size() - 1);
}

Vec3 centroid(const fgsg::rt::Mesh& m, size_t t) {
  Vec3 c = Vec3::Zero();
  for (size_t k = 0; k < 3; ++k)
    for (int d = 0; d < 3; ++d) c[d] += m.positions[3 * size_t(m.indices[3 * t + k]) + size_t(d)] / 3.0;
  return c;
}

}  // namespace

TEST_CASE("face-lets facing +z take one pattern, the others another", "[surface-ornament][variation]") {
  const PolycubeMap map(variationBox(Vec3(8, 8, 8)), PolycubeOptions{0, 8});
  REQUIRE(map.facelets().size() == 6 * 64);
  const TileSet tiles = exampleTileSet();
  AlleleGrid a(2, Allele{0, 0});  // arcs, turned by cell
  a.at(0, 1) = Allele{0, 1}, a.at(1, 0) = Allele{0, 3}, a.at(1, 1) = Allele{0, 2};
  const AlleleGrid b(2, Allele{1, 1});  // vertical lines
  const std::vector<char> top = faceletsFacing(map, {4});
  const std::vector<char> rest = faceletsFacing(map, {0, 1, 2, 3, 5});
  size_t tops = 0;
  for (size_t f = 0; f < top.size(); ++f) {
    const Facelet& fl = map.facelets()[f];
    CHECK(bool(top[f]) == (fl.axis == 2 && fl.sign > 0));
    CHECK(bool(rest[f]) != bool(top[f]));
    tops += top[f] ? 1 : 0;
  }
  CHECK(tops == 64);

  std::vector<uint32_t> cellsA, cellsB;
  SurfaceOrnamentStats statsA;
  const fgsg::rt::Mesh onTop = surfaceOrnament(tiles, a, map, {}, {}, &statsA, 0, &top, &cellsA);
  const fgsg::rt::Mesh onSides = surfaceOrnament(tiles, b, map, {}, {}, nullptr, 0, &rest, &cellsB);
  // Every cell of A's pattern on each of the 64 top face-lets, with its own allele's
  // triangles; B's on the 320 others.
  size_t perA = 0;
  for (const Allele x : a.cells) perA += cellTriangles(tiles, x);
  CHECK(onTop.triangleCount() == 64 * perA);
  CHECK(statsA.triangles == onTop.triangleCount());
  CHECK(statsA.droppedTriangles == 0);
  CHECK(onSides.triangleCount() == 320 * 4 * cellTriangles(tiles, Allele{1, 1}));
  REQUIRE(cellsA.size() == onTop.triangleCount());
  std::map<uint32_t, size_t> perCell;
  for (const uint32_t c : cellsA) ++perCell[c];
  for (uint32_t c = 0; c < 4; ++c) CHECK(perCell[c] == 64 * cellTriangles(tiles, a.cells[c]));
  // A lies on the top (z = 8, rising), B off it.
  size_t above = 0, below = 0;
  for (size_t t = 0; t < onTop.triangleCount(); ++t) above += centroid(onTop, t).z() >= 8 - 1e-9 ? 1 : 0;
  CHECK(above == onTop.triangleCount());
  // (At the top's rim a side's ornament rises along the smooth normal, which leans up
  // there: above z = 8 only within a hair of the rim.)
  for (size_t t = 0; t < onSides.triangleCount(); ++t) {
    const Vec3 c = centroid(onSides, t);
    const bool onTopInside = c.z() >= 8 && c.x() > 0.1 && c.x() < 7.9 && c.y() > 0.1 && c.y() < 7.9;
    below += onTopInside ? 0 : 1;
  }
  CHECK(below == onSides.triangleCount());
  // Showing some face-lets changes no vertex: the same pattern shown everywhere has the
  // same positions, and the two halves' triangles add up to it.
  const fgsg::rt::Mesh all = surfaceOrnament(tiles, a, map, {}, {});
  const fgsg::rt::Mesh aOnSides = surfaceOrnament(tiles, a, map, {}, {}, nullptr, 0, &rest);
  CHECK(all.positions == onTop.positions);
  CHECK(onTop.triangleCount() + aOnSides.triangleCount() == all.triangleCount());
  const std::vector<char> three(3, 1);  // a flag per face-let is needed
  CHECK_THROWS_AS(surfaceOrnament(tiles, a, map, {}, {}, nullptr, 0, &three), std::invalid_argument);
}

TEST_CASE("the ornament parted by colour class keeps every triangle once", "[surface-ornament][variation]") {
  const PolycubeMap map(variationBox(Vec3(8, 8, 8)), PolycubeOptions{0, 8});
  const TileSet tiles = exampleTileSet();
  const AlleleGrid lines(4, Allele{1, 0});
  const ColourClasses k = colourClasses(PatternMeasure(tiles), lines, 1);
  REQUIRE(k.classCount == 4);  // colour_symmetry_test: the orbits of the half turn and mirrors
  std::vector<uint32_t> cells;
  const fgsg::rt::Mesh m = surfaceOrnament(tiles, lines, map, {}, {}, nullptr, 0, nullptr, &cells);
  const std::vector<fgsg::rt::Mesh> parts = partOrnament(m, cells, k.ofCell, k.classCount);
  REQUIRE(parts.size() == 4);
  const size_t perCell = cellTriangles(tiles, Allele{1, 0});
  for (int c = 0; c < 4; ++c) {
    // Four cells of each class per face-let, 384 face-lets.
    CHECK(parts[size_t(c)].triangleCount() == 384 * 4 * perCell);
    CHECK(parts[size_t(c)].normals.size() == parts[size_t(c)].positions.size());
    size_t outside = 0;
    for (const uint32_t v : parts[size_t(c)].indices) outside += v < parts[size_t(c)].vertexCount() ? 0 : 1;
    CHECK(outside == 0);
  }
  CHECK_THROWS_AS(partOrnament(m, std::vector<uint32_t>(3), k.ofCell, 4), std::invalid_argument);
}
