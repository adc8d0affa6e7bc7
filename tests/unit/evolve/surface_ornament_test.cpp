// Ornaments on a surface (runtime/evolve/surface_ornament.h): the pattern repeated on every
// face-let of the polycube, each cell's ornament carried onto the surface, rising along
// the normal by its profile times the cell's width, flattened where the offset surface
// leaves less room, facing outward.
#include "runtime/evolve/surface_ornament.h"

#include "runtime/surface/procedural.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

using namespace fgsg::rt::evolve;
using fgsg::rt::Vec3;

namespace {

Vec3 vertex(const fgsg::rt::Mesh& m, size_t v) {
  return {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
}

double largestRadius(const fgsg::rt::Mesh& m) {
  double r = 0;
  for (size_t v = 0; v < m.vertexCount(); ++v) r = std::max(r, vertex(m, v).norm());
  return r;
}

struct Sphere {
  fgsg::rt::surface::SurfaceMesh mesh = fgsg::rt::surface::sphere(1.0, 3);
  PolycubeMap map{mesh, PolycubeOptions{0, 4}};
  TileSet tiles = exampleTileSet();
  AlleleGrid pattern{2, Allele{1, 0}};  // four straight B cells per face-let
  double cellWidth() const { return map.cellSize() / pattern.side; }
};

}  // namespace

TEST_CASE("a pattern covers every face-let of the polycube, one ornament per cell", "[surface-ornament]") {
  Sphere s;
  SurfaceOrnamentStats stats;
  const fgsg::rt::Mesh m = surfaceOrnament(s.tiles, s.pattern, s.map, {}, {}, &stats);
  const OrnamentGrid g = ornamentGrid(s.tiles, Allele{1, 0});
  const size_t perCell = 2 * (g.t.size() - 1) * (g.r.size() - 1);
  CHECK(stats.facelets == s.map.facelets().size());
  CHECK(stats.cells == 4 * stats.facelets);
  CHECK(stats.triangles == stats.cells * perCell);
  CHECK(m.triangleCount() == stats.triangles);
  CHECK(m.hasTexcoords());
  CHECK(stats.lowestScale == 1.0);
  CHECK(stats.droppedTriangles == 0);
  // Rising along the normal by the section's height (0.1 of a cell) at most, and clearly.
  const OrnamentOptions o;
  const double top = 1 + o.height * s.cellWidth();
  CHECK(largestRadius(m) <= top + 1e-6);
  CHECK(largestRadius(m) >= 1 + 0.9 * o.height * s.cellWidth());
  // Outward: the triangles enclose a positive signed volume about the centre.
  double volume = 0;
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    const Vec3 a = vertex(m, m.indices[3 * t]), b = vertex(m, m.indices[3 * t + 1]), c = vertex(m, m.indices[3 * t + 2]);
    volume += a.dot(b.cross(c)) / 6;
  }
  CHECK(volume > 0);
}

TEST_CASE("the offset surface's room limits the ornament's height", "[surface-ornament]") {
  Sphere s;
  const OrnamentOptions o;
  const double full = o.height * s.cellWidth();
  SurfaceOrnamentStats half, none;
  const fgsg::rt::Mesh m = surfaceOrnament(
      s.tiles, s.pattern, s.map, [&](const MappedPoint&) { return full / 2; }, o, &half);
  CHECK(half.lowestScale == Approx(0.5).epsilon(1e-12));
  CHECK(largestRadius(m) <= 1 + full / 2 + 1e-6);
  CHECK(largestRadius(m) >= 1 + 0.45 * full);
  // No room: every vertex on the (polygonal) sphere itself.
  const fgsg::rt::Mesh flat = surfaceOrnament(s.tiles, s.pattern, s.map, [](const MappedPoint&) { return 0.0; }, o, &none);
  CHECK(none.lowestScale == 0.0);
  CHECK(largestRadius(flat) <= 1 + 1e-6);
  // The polygonal sphere's faces lie between their planes' distance and 1 from the centre.
  double closest = 1;
  for (const auto& f : s.mesh.faces) {
    const Vec3 &a = s.mesh.vertices[f[0]], &b = s.mesh.vertices[f[1]], &c = s.mesh.vertices[f[2]];
    closest = std::min(closest, std::abs(a.dot((b - a).cross(c - a).normalized())));
  }
  for (size_t v = 0; v < flat.vertexCount(); ++v) CHECK(vertex(flat, v).norm() >= closest - 1e-6);
}

TEST_CASE("triangles spanning a jump of the map are dropped, not stretched", "[surface-ornament]") {
  // The genus-2 surface's bars are thinner than a resolution-6 polycube cell: neighbouring
  // face-let points may land on opposite sides of a bar.
  const auto mesh = fgsg::rt::surface::genus2();
  const PolycubeMap map(mesh, PolycubeOptions{0, 6});
  const AlleleGrid pattern(3, Allele{0, 1});
  SurfaceOrnamentStats stats;
  const fgsg::rt::Mesh m = surfaceOrnament(exampleTileSet(), pattern, map, {}, {}, &stats);
  CHECK(stats.droppedTriangles > 0);
  const OrnamentGrid g = ornamentGrid(exampleTileSet(), Allele{0, 1});
  CHECK(m.triangleCount() + stats.droppedTriangles == stats.cells * 2 * (g.t.size() - 1) * (g.r.size() - 1));
  CHECK(stats.droppedTriangles < m.triangleCount() / 100);  // a few cells, not the ornament
  const double longest = 2.0 * map.cellSize() / pattern.side;
  double worst = 0;
  for (size_t t = 0; t < m.triangleCount(); ++t)
    for (int e = 0; e < 3; ++e)
      worst = std::max(worst, (vertex(m, m.indices[3 * t + e]) - vertex(m, m.indices[3 * t + (e + 1) % 3])).norm());
  CHECK(worst <= longest * (1 + 1e-6));
}

TEST_CASE("a surface ornament refuses patterns it cannot draw", "[surface-ornament]") {
  Sphere s;
  CHECK_THROWS_AS(surfaceOrnament(s.tiles, AlleleGrid(), s.map, {}), std::invalid_argument);
  CHECK_THROWS_WITH(surfaceOrnament(s.tiles, AlleleGrid(1, Allele{9, 0}), s.map, {}),
                    "surfaceOrnament: the pattern has symbol 9, the tile set 2");
  OrnamentOptions bad;
  bad.halfWidth = -1;
  CHECK_THROWS_AS(surfaceOrnament(s.tiles, s.pattern, s.map, {}, bad), std::invalid_argument);
}
