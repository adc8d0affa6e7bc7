// street.front / back / left / right from a lot's street widths (runtime/cga/street_edges.h)
// in comp(e), comp(v), comp(f) and setback, by hand. The lots lie on the ground as --lots
// puts them (x east, north at -z), counter-clockwise seen from above.
#include "runtime/cga/street_edges.h"

#include "runtime/cga/cga.h"
#include "runtime/cga/shape_operations.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <string>
#include <vector>

using namespace fgsg::rt;
using namespace fgsg::rt::cga;

namespace {

// The 4 x 2 lot (0,0,0) (4,0,0) (4,0,-2) (0,0,-2): edge 0 south (+z), 1 east, 2 north, 3 west.
const std::vector<Vec3> kStreetLot{{0, 0, 0}, {4, 0, 0}, {4, 0, -2}, {0, 0, -2}};

// Which street.* labels take each comp(e) edge of `lot`, by the edge's midpoint (x, z).
std::map<std::pair<double, double>, std::string> streetEdgeLabels(const Part& lot, GeometryArena& arena,
                                                                  const StreetEdges& streets) {
  std::vector<Part> parts;
  std::string err;
  REQUIRE(components(lot.scope, lot.geom, "e", arena, parts, err, Mat3::Identity(), ~uint64_t{0}, &streets));
  std::map<std::pair<double, double>, std::string> out;
  for (const Part& p : parts) {
    const Vec3 mid = p.scope.P + 0.5 * p.scope.S.x() * p.scope.X();
    std::string labels;
    for (const char* name : {"streetFront", "streetBack", "streetLeft", "streetRight"})
      if (componentSelectorMask("e", name) & p.faceClass) labels += std::string(labels.empty() ? "" : " ") + name;
    out[{std::round(mid.x() * 1e6) / 1e6, std::round(mid.z() * 1e6) / 1e6}] = labels;
  }
  return out;
}

// Which setback labels take each edge of `lot`, by the edge's midpoint (x, z).
std::map<std::pair<double, double>, std::string> streetSetbackLabels(const Part& lot, GeometryArena& arena,
                                                                     const StreetEdges& streets) {
  FlatPolygon polygon;
  std::string err;
  REQUIRE(flatPolygon(lot.scope, lot.geom, arena, "Setback", polygon, err));
  const std::vector<unsigned> classes = edgeSelectors(polygon, &streets);
  std::map<std::pair<double, double>, std::string> out;
  const size_t n = polygon.ring.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec2 m = 0.5 * (polygon.ring[i] + polygon.ring[(i + 1) % n]);
    const Vec3 mid = polygon.scope.P + polygon.scope.X() * m.x() + polygon.scope.Y() * m.y();
    std::string labels;
    for (const char* name : {"streetFront", "streetBack", "streetLeft", "streetRight"})
      if (edgeSelectorMask(name) & classes[i]) labels += std::string(labels.empty() ? "" : " ") + name;
    out[{std::round(mid.x() * 1e6) / 1e6, std::round(mid.z() * 1e6) / 1e6}] = labels;
  }
  return out;
}

Part streetLotPart(GeometryArena& arena, const std::vector<Vec3>& ring) {
  std::vector<Vec2> xz;
  for (const Vec3& p : ring) xz.emplace_back(p.x(), p.z());
  Part lot;
  std::string err;
  REQUIRE(footprint(Scope{}, xz, {}, arena, lot, err));
  return lot;
}

}  // namespace

// A corner lot: streets along the south edge (5 m, the widest: front +z, right +x) and the
// east edge (3 m). Both are street.front; north faces away from the main street (back);
// west faces its left.
TEST_CASE("street widths: a corner lot's two street edges are both street.front", "[cga][street]") {
  GeometryArena arena;
  const Part lot = streetLotPart(arena, kStreetLot);
  const StreetEdges streets = streetEdgesOfLot(kStreetLot, {5, 3, 0, 0}, Vec3::UnitZ());
  const std::map<std::pair<double, double>, std::string> want{
      {{2, 0}, "streetFront"}, {{4, -1}, "streetFront"}, {{2, -2}, "streetBack"}, {{0, -1}, "streetLeft"}};
  CHECK(streetEdgeLabels(lot, arena, streets) == want);
  CHECK(streetSetbackLabels(lot, arena, streets) == want);
  // The mass's walls (extrude 3) by their normals: south and east face a street.
  Scope mass;
  mass.P = Vec3(0, 0, -2);
  mass.S = Vec3(4, 3, 2);
  std::vector<Part> walls;
  std::string err;
  REQUIRE(components(mass, GeomRef{}, "f", arena, walls, err, Mat3::Identity(), ~uint64_t{0}, &streets));
  int front = 0, back = 0, left = 0, right = 0;
  for (const Part& w : walls) {
    front += (componentSelectorMask("f", "streetFront") & w.faceClass) != 0;
    back += (componentSelectorMask("f", "streetBack") & w.faceClass) != 0;
    left += (componentSelectorMask("f", "streetLeft") & w.faceClass) != 0;
    right += (componentSelectorMask("f", "streetRight") & w.faceClass) != 0;
  }
  CHECK(front == 2);
  CHECK(back == 1);
  CHECK(left == 1);
  CHECK(right == 0);
  // Corners lean out along both edges: SW and SE at 45 degrees to the south street, NE to
  // the east one (the diagonal counts); NW faces away from the main street.
  REQUIRE(components(lot.scope, lot.geom, "v", arena, walls, err, Mat3::Identity(), ~uint64_t{0}, &streets));
  int frontCorners = 0, backCorners = 0;
  for (const Part& v : walls) {
    frontCorners += (componentSelectorMask("v", "streetFront") & v.faceClass) != 0;
    backCorners += (componentSelectorMask("v", "streetBack") & v.faceClass) != 0;
  }
  CHECK(frontCorners == 3);
  CHECK(backCorners == 1);
}

// The widest street edge sets the frame: the east edge (5 m) is the main street, front +x,
// right (seen from it) -z, north. South is on a street too; north faces right, west back.
TEST_CASE("street widths: the widest street sets back, left and right", "[cga][street]") {
  GeometryArena arena;
  const Part lot = streetLotPart(arena, kStreetLot);
  const StreetEdges streets = streetEdgesOfLot(kStreetLot, {2, 5, 0, 0}, Vec3::UnitZ());
  CHECK((streets.front - Vec3(1, 0, 0)).norm() < 1e-12);
  CHECK((streets.right - Vec3(0, 0, -1)).norm() < 1e-12);
  const std::map<std::pair<double, double>, std::string> want{
      {{2, 0}, "streetFront"}, {{4, -1}, "streetFront"}, {{2, -2}, "streetRight"}, {{0, -1}, "streetBack"}};
  CHECK(streetEdgeLabels(lot, arena, streets) == want);
  CHECK(streetSetbackLabels(lot, arena, streets) == want);
}

// An inner lot (all widths 0): no street.front; back, left and right in the object system
// (front +z: the first edge's side). The south edge faces that front squarely: none.
TEST_CASE("street widths: an inner lot has no street.front", "[cga][street]") {
  GeometryArena arena;
  const Part lot = streetLotPart(arena, kStreetLot);
  const StreetEdges streets = streetEdgesOfLot(kStreetLot, {0, 0, 0, 0}, Vec3::UnitZ());
  const std::map<std::pair<double, double>, std::string> want{
      {{2, 0}, ""}, {{4, -1}, "streetRight"}, {{2, -2}, "streetBack"}, {{0, -1}, "streetLeft"}};
  CHECK(streetEdgeLabels(lot, arena, streets) == want);
  CHECK(streetSetbackLabels(lot, arena, streets) == want);
}

// A lot edge takes its own width; a component on no lot edge goes by its direction. The
// south side is two edges, only the western one on the street: the eastern one faces the
// same way but is no street edge, while a direction +z off the lot (a setback remainder's
// edge, a wall) faces the street.
TEST_CASE("street widths: a lot edge goes by its width, other components by direction", "[cga][street]") {
  GeometryArena arena;
  const std::vector<Vec3> ring{{0, 0, 0}, {2, 0, 0}, {4, 0, 0}, {4, 0, -2}, {0, 0, -2}};
  const Part lot = streetLotPart(arena, ring);
  const StreetEdges streets = streetEdgesOfLot(ring, {5, 0, 0, 0, 0}, Vec3::UnitZ());
  const std::map<std::pair<double, double>, std::string> want{{{1, 0}, "streetFront"},
                                                              {{3, 0}, ""},
                                                              {{4, -1}, "streetRight"},
                                                              {{2, -2}, "streetBack"},
                                                              {{0, -1}, "streetLeft"}};
  CHECK(streetSetbackLabels(lot, arena, streets) == want);
  CHECK(streetSide(streets, Vec3(0, 0, 1)) == kStreetFront);
  CHECK(streetSide(streets, Vec3(1, 0, 1)) == kStreetFront);   // 45 degrees: the diagonal counts
  CHECK(streetSide(streets, Vec3(1, 0, -1)) == kStreetBack);   // facing away, the diagonal counts
  CHECK(streetSide(streets, Vec3(1, 0.5, 0)) == kStreetRight);  // its level part
  CHECK(streetSide(streets, Vec3(0, 1, 0)) == 0u);              // no level part
  const Vec3 a(3, 0, -1), b(3, 0, -2);                          // an edge inside the lot, facing east
  CHECK(streetSide(streets, Vec3(1, 0, 0), &a, &b) == kStreetRight);
}

// A courtyard's edges are on no street: the 20 x 20 lot with its street on the south edge
// and a 4 x 4 hole (x 8..12, z -8..-12). The hole's north edge faces south (+z, into the
// hole) like the street but is no street edge: facing the main street squarely, none; its
// west edge faces east (right), its south edge north (back), its east edge west (left).
// The same segment without the hole given is a component off the lot's edges: front.
TEST_CASE("street widths: a hole's edges are never street.front", "[cga][street]") {
  const std::vector<Vec3> ring{{0, 0, 0}, {20, 0, 0}, {20, 0, -20}, {0, 0, -20}};
  const std::vector<std::vector<Vec3>> holes{{{8, 0, -8}, {8, 0, -12}, {12, 0, -12}, {12, 0, -8}}};
  const StreetEdges streets = streetEdgesOfLot(ring, {5, 0, 0, 0}, Vec3::UnitZ(), holes);
  const Vec3 nw(8, 0, -12), ne(12, 0, -12), sw(8, 0, -8), se(12, 0, -8);
  CHECK(streetSide(streets, Vec3(0, 0, 1), &ne, &nw) == 0u);
  CHECK(streetSide(streets, Vec3(1, 0, 0), &nw, &sw) == kStreetRight);
  CHECK(streetSide(streets, Vec3(0, 0, -1), &sw, &se) == kStreetBack);
  CHECK(streetSide(streets, Vec3(-1, 0, 0), &se, &ne) == kStreetLeft);
  const Vec3 half(10, 0, -12);  // part of the hole's edge (a split of it) is on the hole too
  CHECK(streetSide(streets, Vec3(0, 0, 1), &half, &nw) == 0u);
  CHECK(streetSide(streets, Vec3(0, 0, 1)) == kStreetFront);  // no ends: by direction
  const StreetEdges noHoles = streetEdgesOfLot(ring, {5, 0, 0, 0}, Vec3::UnitZ());
  CHECK(streetSide(noHoles, Vec3(0, 0, 1), &ne, &nw) == kStreetFront);
}
