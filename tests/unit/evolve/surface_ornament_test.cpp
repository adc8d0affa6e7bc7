// Ornaments on a surface (runtime/evolve/surface_ornament.h): the pattern repeated on every
// face-let of the polycube, each cell's ornament carried onto the surface, rising along
// the normal by its profile times the cell's width, flattened where the offset surface
// leaves less room, facing outward.
#include "runtime/evolve/surface_ornament.h"

#include "runtime/evolve/genetic.h"
#include "runtime/surface/procedural.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Intersections_3/Triangle_3_Triangle_3.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <unordered_map>

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

// Independent of the ornament code: CGAL's exact predicates on every pair of triangles
// near each other (a uniform grid of `cell`-sized buckets), skipping pairs that share a
// corner position (neighbours in the mesh, or cells meeting on a border) and degenerate
// ones. Returns how many pairs intersect.
size_t intersectingPairs(const fgsg::rt::Mesh& m, double cell) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::map<std::array<float, 3>, uint32_t> weld;
  std::vector<std::array<uint32_t, 3>> tris;
  std::vector<K::Triangle_3> geometry;
  for (size_t t = 0; t < m.triangleCount(); ++t) {
    std::array<uint32_t, 3> ids;
    std::array<K::Point_3, 3> p;
    for (int c = 0; c < 3; ++c) {
      const uint32_t v = m.indices[3 * t + c];
      const std::array<float, 3> key{m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
      ids[c] = weld.emplace(key, uint32_t(weld.size())).first->second;
      p[c] = K::Point_3(key[0], key[1], key[2]);
    }
    const K::Triangle_3 tri(p[0], p[1], p[2]);
    if (tri.is_degenerate()) continue;
    tris.push_back(ids);
    geometry.push_back(tri);
  }
  std::unordered_map<uint64_t, std::vector<uint32_t>> buckets;
  auto key = [](int64_t x, int64_t y, int64_t z) { return uint64_t((x * 73856093) ^ (y * 19349663) ^ (z * 83492791)); };
  for (size_t t = 0; t < geometry.size(); ++t) {
    const auto box = geometry[t].bbox();
    for (int64_t x = int64_t(std::floor(box.xmin() / cell)); x <= int64_t(std::floor(box.xmax() / cell)); ++x)
      for (int64_t y = int64_t(std::floor(box.ymin() / cell)); y <= int64_t(std::floor(box.ymax() / cell)); ++y)
        for (int64_t z = int64_t(std::floor(box.zmin() / cell)); z <= int64_t(std::floor(box.zmax() / cell)); ++z)
          buckets[key(x, y, z)].push_back(uint32_t(t));
  }
  std::set<std::pair<uint32_t, uint32_t>> hits;
  for (const auto& [k, list] : buckets)
    for (size_t i = 0; i < list.size(); ++i)
      for (size_t j = i + 1; j < list.size(); ++j) {
        const uint32_t a = std::min(list[i], list[j]), b = std::max(list[i], list[j]);
        bool shared = false;
        for (uint32_t u : tris[a])
          for (uint32_t w : tris[b]) shared |= u == w;
        if (shared || hits.count({a, b}) || !CGAL::do_intersect(geometry[a], geometry[b])) continue;
        hits.insert({a, b});
      }
  return hits.size();
}

TEST_CASE("an evolved p4 ornament on a surface does not intersect itself", "[surface-ornament]") {
  Sphere s;
  const PolycubeMap map(s.mesh, PolycubeOptions{0, 2});
  EvolveOptions o;
  o.generation = 1;
  o.p4 = true;
  o.seed = 3;
  const AlleleGrid pattern = expand(evolve(s.tiles, o).best, o.generation);
  SurfaceOrnamentStats stats;
  const fgsg::rt::Mesh m = surfaceOrnament(s.tiles, pattern, map, {}, {}, &stats);
  REQUIRE(stats.droppedTriangles == 0);
  REQUIRE(m.triangleCount() > 50000);
  CHECK(intersectingPairs(m, map.cellSize() / pattern.side / 4) == 0);
  // The check finds intersections where there are some: the first cell's ornament again,
  // shifted a little along x, crosses the original.
  fgsg::rt::Mesh twice = m;
  const size_t cellTriangles = m.triangleCount() / stats.cells, vertices = m.vertexCount();
  for (size_t i = 0; i < 3 * cellTriangles; ++i) twice.indices.push_back(m.indices[i] + uint32_t(vertices));
  for (size_t v = 0; v < vertices; ++v)
    for (int k = 0; k < 3; ++k) twice.positions.push_back(m.positions[3 * v + k] + (k == 0 ? 0.003f : 0.0f));
  CHECK(intersectingPairs(twice, map.cellSize() / pattern.side / 4) > 0);
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
