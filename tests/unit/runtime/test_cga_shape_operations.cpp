// CityEngine's scope operations and footprint shaping (issue #44; runtime/cga/
// shape_operations.h), checked against areas, sizes and positions computed by hand.
#include "runtime/cga/geometry_queries.h"
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/shape_operations.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fgsg::rt;
using namespace fgsg::rt::cga;

namespace {

constexpr double kTol = 1e-9;

bool near(const Vec3& a, const Vec3& b, double tol = kTol) { return (a - b).norm() <= tol; }

Polygon3 worldPolygon(const Part& p, const GeometryArena& arena) {
  Polygon3 world;
  const Vec3* pts = arena.polygon(p.geom);
  for (uint32_t i = 0; i < p.geom.count; ++i) world.push_back(p.scope.toWorld(p.scope.S.cwiseProduct(pts[i])));
  return world;
}

// A polygon part's area in square metres (holes joined by bridges count off).
double area(const Part& p, const GeometryArena& arena) { return 0.5 * newellNormal(worldPolygon(p, arena)).norm(); }

double volume(const Part& p, const GeometryArena& arena) {
  if (p.geom.kind == GeomKind::Box) return p.scope.S.prod();
  double v = 0.0;
  for (uint32_t i = 0; i < p.geom.count; ++i) {
    const GeometryArena::Face& f = arena.face(p.geom, i);
    Polygon3 world;
    for (uint32_t k = 0; k < f.count; ++k) world.push_back(p.scope.toWorld(p.scope.S.cwiseProduct(arena.facePoints(f)[k])));
    v += world[0].dot(0.5 * newellNormal(world)) / 3.0;
  }
  return v;
}

// A lot as Footprint makes it from (x, z) corners.
Part lot(GeometryArena& arena, const std::vector<Vec2>& corners, const std::vector<std::vector<Vec2>>& holes = {}) {
  Part part;
  std::string error;
  const bool ok = footprint(Scope{}, corners, holes, arena, part, error);
  INFO(error);
  REQUIRE(ok);
  return part;
}

FlatPolygon flat(const Part& p, GeometryArena& arena) {
  FlatPolygon f;
  std::string error;
  REQUIRE(flatPolygon(p.scope, p.geom, arena, "test", f, error));
  return f;
}

const std::vector<Vec2> kRect20x10{{0, 0}, {20, 0}, {20, 10}, {0, 10}};

// Runs setback with one distance per edge and every set-back edge in group 0.
void setbackAll(const FlatPolygon& f, const std::vector<double>& d, bool merged, GeometryArena& arena,
                std::vector<Part>& pieces, std::vector<Part>& rest) {
  std::vector<int> group(d.size());
  for (size_t i = 0; i < d.size(); ++i) group[i] = d[i] != 0 ? 0 : -1;
  std::vector<int> pieceGroup;
  std::string error;
  REQUIRE(setback(f, d, group, {merged}, arena, pieces, pieceGroup, rest, error));
}

}  // namespace

TEST_CASE("setback(3) on every edge of a 20 x 10 lot: trapezoid bands and a 14 x 4 remainder") {
  GeometryArena arena;
  const FlatPolygon f = flat(lot(arena, kRect20x10), arena);
  REQUIRE(f.ring.size() == 4);
  std::vector<Part> pieces, rest;
  setbackAll(f, {3, 3, 3, 3}, false, arena, pieces, rest);
  REQUIRE(pieces.size() == 4);
  double sum = 0;
  std::vector<double> areas;
  for (const Part& p : pieces) {
    CHECK(p.geom.count == 4);
    areas.push_back(area(p, arena));
    sum += areas.back();
  }
  std::sort(areas.begin(), areas.end());
  // Long sides (20 + 14) / 2 * 3 = 51, short sides (10 + 4) / 2 * 3 = 21.
  CHECK(areas[0] == Approx(21).margin(kTol));
  CHECK(areas[1] == Approx(21).margin(kTol));
  CHECK(areas[2] == Approx(51).margin(kTol));
  CHECK(areas[3] == Approx(51).margin(kTol));
  CHECK(sum == Approx(144).margin(kTol));
  REQUIRE(rest.size() == 1);
  CHECK(area(rest[0], arena) == Approx(56).margin(kTol));
  // The remainder's scope is fitted to it: 14 x 4, 3 m in from the lot's corner (x 3..17, z -7..-3).
  CHECK(near(rest[0].scope.S, Vec3(14, 4, 0)));
  Vec3 lo = Vec3::Constant(1e9), hi = -lo;
  for (const Vec3& p : worldPolygon(rest[0], arena)) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  CHECK(near(lo, Vec3(3, 0, 3)));
  CHECK(near(hi, Vec3(17, 0, 7)));

  // Merged (`all = A`): one ring around the remainder.
  setbackAll(f, {3, 3, 3, 3}, true, arena, pieces, rest);
  REQUIRE(pieces.size() == 1);
  CHECK(area(pieces[0], arena) == Approx(144).margin(kTol));
  CHECK(ringsOf(Polygon3(arena.polygon(pieces[0].geom), arena.polygon(pieces[0].geom) + pieces[0].geom.count)).size() ==
        2);
}

TEST_CASE("setback selectors classify edges by the scope's quadrants, street.front the front edge") {
  GeometryArena arena;
  const FlatPolygon f = flat(lot(arena, kRect20x10), arena);
  const std::vector<unsigned> c = edgeSelectors(f);
  REQUIRE(c.size() == 4);
  int front = -1, back = -1, left = -1, right = -1;
  for (int i = 0; i < 4; ++i) {
    if (c[i] & kEdgeFront) front = i;
    if (c[i] & kEdgeBack) back = i;
    if (c[i] & kEdgeLeft) left = i;
    if (c[i] & kEdgeRight) right = i;
  }
  // Footprint's scope has y running north (-z): the front edge is the south one (z = 10).
  CHECK(front >= 0);
  CHECK((c[front] & kEdgeStreetFront) != 0);
  CHECK((c[front] & kEdgeSouth) != 0);
  CHECK((c[back] & kEdgeNorth) != 0);
  CHECK((c[left] & kEdgeWest) != 0);
  CHECK((c[right] & kEdgeEast) != 0);
  CHECK(edgeSelectorMask("side") == (kEdgeLeft | kEdgeRight));
  CHECK(edgeSelectorMask("all=") == ~0u);

  // setback(2) on the front edge alone: a 20 x 2 band and a 20 x 8 remainder.
  std::vector<double> d(4, 0.0);
  d[front] = 2;
  std::vector<Part> pieces, rest;
  setbackAll(f, d, false, arena, pieces, rest);
  REQUIRE(pieces.size() == 1);
  CHECK(area(pieces[0], arena) == Approx(40).margin(kTol));
  CHECK(near(pieces[0].scope.S, Vec3(20, 2, 0)));
  REQUIRE(rest.size() == 1);
  CHECK(area(rest[0], arena) == Approx(160).margin(kTol));
}

TEST_CASE("shapeL, shapeU and shapeO are setbacks of the front, side and back wings, merged") {
  GeometryArena arena;
  const FlatPolygon f = flat(lot(arena, kRect20x10), arena);
  const std::vector<unsigned> c = edgeSelectors(f);
  auto wings = [&](double front, double right, double back, double left) {
    std::vector<double> d;
    for (unsigned k : c)
      d.push_back(k & kEdgeFront ? front : k & kEdgeRight ? right : k & kEdgeBack ? back : left);
    return d;
  };
  std::vector<Part> pieces, rest;
  // shapeL(4, 5): 20 x 4 along the front, 5 x 6 along the left: 110 m2 in one L of 6 corners.
  setbackAll(f, wings(4, 0, 0, 5), true, arena, pieces, rest);
  REQUIRE(pieces.size() == 1);
  CHECK(pieces[0].geom.count == 6);
  CHECK(area(pieces[0], arena) == Approx(110).margin(kTol));
  CHECK(area(rest[0], arena) == Approx(90).margin(kTol));  // 15 x 6
  // shapeU(2, 3, 4): 200 - 13 x 8 = 96 in 8 corners.
  setbackAll(f, wings(2, 3, 0, 4), true, arena, pieces, rest);
  REQUIRE(pieces.size() == 1);
  CHECK(pieces[0].geom.count == 8);
  CHECK(area(pieces[0], arena) == Approx(96).margin(kTol));
  CHECK(area(rest[0], arena) == Approx(104).margin(kTol));
  // shapeO(1, 2, 3, 4): a ring around 14 x 6.
  setbackAll(f, wings(1, 2, 3, 4), true, arena, pieces, rest);
  REQUIRE(pieces.size() == 1);
  CHECK(area(pieces[0], arena) == Approx(116).margin(kTol));
  CHECK(near(rest[0].scope.S, Vec3(14, 6, 0)));
}

TEST_CASE("setback refuses distances that make an edge vanish") {
  GeometryArena arena;
  const FlatPolygon f = flat(lot(arena, kRect20x10), arena);
  std::vector<Part> pieces, rest;
  std::vector<int> pieceGroup;
  std::string error;
  CHECK_FALSE(setback(f, {6, 6, 6, 6}, {0, 0, 0, 0}, {false}, arena, pieces, pieceGroup, rest, error));
  CHECK(error.find("vanish") != std::string::npos);
  CHECK_FALSE(setback(f, {-1, 1, 0, 0}, {0, 0, 0, 0}, {false}, arena, pieces, pieceGroup, rest, error));
  CHECK(error.find("both signs") != std::string::npos);
}

TEST_CASE("negative setback distances grow the polygon outward (CGA's offset(+d))") {
  GeometryArena arena;
  const FlatPolygon f = flat(lot(arena, kRect20x10), arena);
  std::vector<Part> pieces, rest;
  // 2 m all round: a 24 x 14 polygon (336 m2), the band around the lot 336 - 200 = 136 m2.
  setbackAll(f, {-2, -2, -2, -2}, true, arena, pieces, rest);
  REQUIRE(rest.size() == 1);
  CHECK(area(rest[0], arena) == Approx(336).margin(kTol));
  CHECK(near(rest[0].scope.S, Vec3(24, 14, 0)));
  REQUIRE(pieces.size() == 1);
  CHECK(area(pieces[0], arena) == Approx(136).margin(kTol));
  // Per edge: trapezoids (20 + 24) / 2 * 2 = 44 and (10 + 14) / 2 * 2 = 24.
  setbackAll(f, {-2, -2, -2, -2}, false, arena, pieces, rest);
  REQUIRE(pieces.size() == 4);
  double sum = 0;
  for (const Part& p : pieces) sum += area(p, arena);
  CHECK(sum == Approx(136).margin(kTol));
}

TEST_CASE("innerRectangle: the largest rectangle along the scope or along an edge") {
  GeometryArena arena;
  Part out;
  std::string error;
  // An L of 20 x 9 and 9 x 18: the 20 x 9 wing is the larger (180 > 162).
  REQUIRE(innerRectangle(flat(lot(arena, {{0, 0}, {20, 0}, {20, 9}, {9, 9}, {9, 18}, {0, 18}}), arena), false, arena,
                         out, error));
  CHECK(area(out, arena) == Approx(180).margin(kTol));
  CHECK(out.geom.count == 4);
  // A right triangle with legs of 10: a 5 x 5 square in its right angle.
  REQUIRE(innerRectangle(flat(lot(arena, {{0, 0}, {10, 0}, {0, 10}}), arena), false, arena, out, error));
  CHECK(area(out, arena) == Approx(25).margin(1e-6));
  // A square turned by 45 degrees (side sqrt(50)): 25 along the scope, all of it (50) along an edge.
  const FlatPolygon diamond = flat(lot(arena, {{5, 0}, {10, 5}, {5, 10}, {0, 5}}), arena);
  REQUIRE(innerRectangle(diamond, false, arena, out, error));
  CHECK(area(out, arena) == Approx(25).margin(1e-6));
  REQUIRE(innerRectangle(diamond, true, arena, out, error));
  CHECK(area(out, arena) == Approx(50).margin(1e-6));
  CHECK(out.scope.S.x() == Approx(std::sqrt(50.0)).margin(1e-6));
}

TEST_CASE("rotateScope keeps the geometry and fits the scope around it") {
  GeometryArena arena;
  Scope s;
  s.S = Vec3(4, 2, 1);
  Part out;
  std::string error;
  // A quarter turn about y: still the box, now 1 x 2 x 4 with its origin at world (0, 0, 1).
  REQUIRE(rotateScope(s, GeomRef{}, arena, Vec3(0, 90, 0), out, error));
  CHECK(out.geom.kind == GeomKind::Box);
  CHECK(near(out.scope.S, Vec3(1, 2, 4)));
  CHECK(near(out.scope.P, Vec3(0, 0, 1)));
  // 45 degrees: a 2 x 1 x 2 box spans 2 sqrt(2) across both turned axes; its volume stays 4.
  s.S = Vec3(2, 1, 2);
  REQUIRE(rotateScope(s, GeomRef{}, arena, Vec3(0, 45, 0), out, error));
  CHECK(out.geom.kind == GeomKind::Polyhedron);
  CHECK(near(out.scope.S, Vec3(2 * std::sqrt(2.0), 1, 2 * std::sqrt(2.0))));
  CHECK(volume(out, arena) == Approx(4).margin(kTol));
  // alignScopeToAxes() turns it back: the world's axes, 2 x 1 x 2 at the origin.
  Part back;
  REQUIRE(alignScopeToAxes(out.scope, out.geom, arena, 7, back, error));
  CHECK(near(back.scope.axes.col(0), Vec3(1, 0, 0)));
  CHECK(near(back.scope.S, Vec3(2, 1, 2)));
  CHECK(near(back.scope.P, Vec3(0, 0, 0)));
  CHECK(volume(back, arena) == Approx(4).margin(kTol));
}

TEST_CASE("alignScopeToGeometry lays x along the chosen edge, a polygon keeps z as its normal") {
  GeometryArena arena;
  // A 10 x 5 rectangle turned by 30 degrees, its long edge first.
  const double c = std::cos(3.14159265358979323846 / 6), s = std::sin(3.14159265358979323846 / 6);
  const Part rect = lot(arena, {{0, 0}, {10 * c, 10 * s}, {10 * c - 5 * s, 10 * s + 5 * c}, {-5 * s, 5 * c}});
  Part out;
  std::string error;
  for (int up : {1, 2}) {
    REQUIRE(alignScopeToGeometry(rect.scope, rect.geom, arena, up, -1, -1, out, error));
    INFO("S " << out.scope.S.transpose() << " X " << out.scope.X().transpose() << " Z " << out.scope.Z().transpose());
    CHECK(near(out.scope.S, Vec3(10, 5, 0), 1e-9));
    // Along the long edge, in whichever direction the stored ring runs it.
    CHECK(std::abs(out.scope.X().dot(Vec3(c, 0, s))) == Approx(1).margin(kTol));
    CHECK(near(out.scope.Z(), Vec3(0, 1, 0)));
    CHECK(area(out, arena) == Approx(50).margin(kTol));
  }
  // Its second edge (5 m): x along it, the scope 5 x 10.
  REQUIRE(alignScopeToGeometry(rect.scope, rect.geom, arena, 2, 0, 1, out, error));
  CHECK(near(out.scope.S, Vec3(5, 10, 0), 1e-9));
  CHECK_FALSE(alignScopeToGeometry(rect.scope, rect.geom, arena, 2, 3, 0, out, error));  // one face only
}

TEST_CASE("mirrorScope flips axes around the geometry, mirror flips the geometry in its scope") {
  GeometryArena arena;
  Scope s;
  s.S = Vec3(4, 2, 1);
  Part out;
  std::string error;
  const bool flipX[3] = {true, false, false};
  REQUIRE(mirrorScope(s, GeomRef{}, arena, flipX, out, error));
  CHECK(out.geom.kind == GeomKind::Box);
  CHECK(near(out.scope.P, Vec3(4, 0, 0)));
  CHECK(near(out.scope.X(), Vec3(-1, 0, 0)));
  CHECK(near(out.scope.S, Vec3(4, 2, 1)));
  // A right triangle (0,0) (4,0) (0,3) mirrored across its scope's x: the right angle moves to x = 4.
  const Part tri = lot(arena, {{0, 0}, {4, 0}, {0, 3}});
  REQUIRE(mirrorGeometry(tri.scope, tri.geom, arena, flipX, out, error));
  CHECK(area(out, arena) == Approx(6).margin(kTol));
  CHECK(newellNormal(Polygon3(arena.polygon(out.geom), arena.polygon(out.geom) + 3)).z() > 0);
  bool rightAngleAt4 = false;
  for (const Vec3& p : worldPolygon(out, arena)) rightAngleAt4 |= near(p, Vec3(4, 0, 0)) || near(p, Vec3(4, 0, 3));
  CHECK(rightAngleAt4);
}

TEST_CASE("primitives fill the scope or stand centred on it with the given sizes") {
  GeometryArena arena;
  Scope s;
  s.S = Vec3(4, 3, 4);
  Part out;
  std::string error;
  // An octagon of radius 1, 2 high: 8 sides, top and bottom; volume 2 * 2 sqrt(2).
  REQUIRE(primitive(s, "PrimitiveCylinder", {8, 1, 2}, arena, out, error));
  CHECK(out.geom.count == 10);
  CHECK(near(out.scope.S, Vec3(2, 2, 2)));
  CHECK(near(out.scope.P, Vec3(1, 0, 1)));
  CHECK(volume(out, arena) == Approx(4 * std::sqrt(2.0)).margin(1e-9));
  REQUIRE(primitive(s, "PrimitiveSphere", {8, 16, 1}, arena, out, error));
  CHECK(out.geom.count == 128);
  CHECK(volume(out, arena) > 0);
  REQUIRE(primitive(s, "PrimitiveQuad", {2, 3}, arena, out, error));
  CHECK(area(out, arena) == Approx(6).margin(kTol));
  CHECK(out.geom.count == 4);
  REQUIRE(primitive(s, "PrimitiveDisk", {4, 1}, arena, out, error));
  CHECK(area(out, arena) == Approx(2).margin(kTol));
  Scope flatScope;
  flatScope.S = Vec3(4, 0, 2);
  REQUIRE(primitive(flatScope, "PrimitiveCube", {}, arena, out, error));
  CHECK(near(out.scope.S, Vec3(4, 3, 2)));  // the zero size: the mean of 4 and 2
  CHECK_FALSE(primitive(s, "PrimitiveCylinder", {2}, arena, out, error));
  CHECK_FALSE(primitive(s, "PrimitiveCylinder", {8, 1}, arena, out, error));  // no (sides, radius) form
  CHECK_FALSE(primitive(s, "PrimitiveSphere", {8}, arena, out, error));
}

TEST_CASE("primitives take CityEngine's defaults, sphere parameters and planes") {
  GeometryArena arena;
  Part out;
  std::string error;
  Scope s;
  s.S = Vec3(4, 3, 4);
  // primitiveSphere(): 16 sides around, 16 divisions pole to pole: 16 * 16 faces,
  // 15 latitude rings of 16 corners and the two poles.
  REQUIRE(primitive(s, "PrimitiveSphere", {}, arena, out, error));
  GeometryFacts facts = geometryFacts(out.scope, out.geom, arena);
  CHECK(facts.faces == 256);
  CHECK(facts.vertices == 15 * 16 + 2);
  // (8 sides, 4 divisions): 32 faces, 3 rings of 8 and the poles (read the other way round: 30).
  REQUIRE(primitive(s, "PrimitiveSphere", {8, 4}, arena, out, error));
  facts = geometryFacts(out.scope, out.geom, arena);
  CHECK(facts.faces == 32);
  CHECK(facts.vertices == 26);
  // A scope with no x size (a lot turned by rotateScope(0, 0, 90)): the quad lies in its yz
  // plane, facing +x; 2 along y and 3 along z, centred in the 4 x 6: y 1..3, z 1.5..4.5.
  Scope upright;
  upright.S = Vec3(0, 4, 6);
  REQUIRE(primitive(upright, "PrimitiveQuad", {2, 3}, arena, out, error));
  const Polygon3 quad = worldPolygon(out, arena);
  CHECK(0.5 * newellNormal(quad).norm() == Approx(6).margin(kTol));
  CHECK(newellNormal(quad).normalized().x() == Approx(1).margin(kTol));
  for (const Vec3& p : quad) {
    CHECK(p.x() == Approx(0).margin(kTol));
    CHECK((p.y() > 1 - kTol && p.y() < 3 + kTol && p.z() > 1.5 - kTol && p.z() < 4.5 + kTol));
  }
  // No z size: the disk fills the xy plane, facing +z: a square of 4 corners inscribed in
  // the 4 x 4 has half its area, 8.
  Scope wall;
  wall.S = Vec3(4, 4, 0);
  REQUIRE(primitive(wall, "PrimitiveDisk", {4}, arena, out, error));
  const Polygon3 disk = worldPolygon(out, arena);
  CHECK(0.5 * newellNormal(disk).norm() == Approx(8).margin(kTol));
  CHECK(newellNormal(disk).normalized().z() == Approx(1).margin(kTol));
}

TEST_CASE("reverseNormals, deleteHoles and cleanupGeometry") {
  GeometryArena arena;
  Part out;
  std::string error;
  const Part tri = lot(arena, {{0, 0}, {4, 0}, {0, 3}});
  REQUIRE(reverseNormals(tri.scope, tri.geom, arena, out, error));
  CHECK(area(out, arena) == Approx(6).margin(kTol));
  CHECK(near(out.scope.Z(), Vec3(0, -1, 0)));
  const Part court = lot(arena, {{0, 0}, {30, 0}, {30, 20}, {0, 20}}, {{{10, 5}, {10, 15}, {20, 15}, {20, 5}}});
  CHECK(area(court, arena) == Approx(500).margin(kTol));
  REQUIRE(deleteHoles(court.scope, court.geom, arena, out, error));
  CHECK(area(out, arena) == Approx(600).margin(kTol));
  CHECK(out.geom.count == 4);
  // A corner on a straight edge and one 1 mm from its neighbour: both go at a 1 cm tolerance.
  const Part messy = lot(arena, {{0, 0}, {5, 0}, {10, 0}, {10, 10}, {9.999, 10}, {0, 10}});
  REQUIRE(cleanupGeometry(messy.scope, messy.geom, arena, 7, 0.01, out, error));
  CHECK(out.geom.count == 4);
  CHECK(area(out, arena) == Approx(100).margin(1e-2));
}

TEST_CASE("deleteHoles on a ground face keeps its outline") {
  // The `.cga` dialect's lots are one-face solids lying on the ground (asGroundFace).
  GeometryArena arena;
  Part court = lot(arena, {{0, 0}, {30, 0}, {30, 20}, {0, 20}}, {{{10, 5}, {10, 15}, {20, 15}, {20, 5}}});
  asGroundFace(court, court.scope.X(), arena);
  REQUIRE(court.geom.kind == GeomKind::Polyhedron);
  CHECK(geometryFacts(court.scope, court.geom, arena).area == Approx(500).margin(kTol));
  Part out;
  std::string error;
  REQUIRE(deleteHoles(court.scope, court.geom, arena, out, error));
  REQUIRE(out.geom.kind == GeomKind::Polyhedron);
  REQUIRE(out.geom.count == 1);
  CHECK(arena.face(out.geom, 0).count == 4);
  CHECK(geometryFacts(out.scope, out.geom, arena).area == Approx(600).margin(kTol));
}

TEST_CASE("cleanupGeometry's components and tolerance scale") {
  GeometryArena arena;
  Part out;
  std::string error;
  // A corner where the outline turns by 5 degrees: straight at tolerance 0.6 (6 degrees),
  // not at 0.4 (4 degrees). The step 3 (vertices) merges corners and drops straight ones.
  const double t = 5 * M_PI / 180;
  const Vec2 c(5 + 5 * std::cos(t), 5 * std::sin(t));
  const Part bent = lot(arena, {{0, 0}, {5, 0}, c, {c.x(), 10}, {0, 10}});
  REQUIRE(cleanupGeometry(bent.scope, bent.geom, arena, 3, 0.4, out, error));
  CHECK(out.geom.count == 5);
  REQUIRE(cleanupGeometry(bent.scope, bent.geom, arena, 3, 0.6, out, error));
  CHECK(out.geom.count == 4);
  CHECK_FALSE(cleanupGeometry(bent.scope, bent.geom, arena, 3, 1.5, out, error));  // the range is 0 to 1
  // A 20 x 10 lot with a fifth corner in its first edge, extruded 3: the wall along that
  // edge is two coplanar faces (7 faces). edges (9) joins them (6 faces, the wall 6 corners,
  // the middle ones still there); all (15) also drops the straight corners: a box's 6
  // faces of 4 corners, 8 corners in all. The surface stays 2 (200 + 60 + 30) = 580 m2.
  const Part notched = lot(arena, {{0, 0}, {10, 0}, {20, 0}, {20, 10}, {0, 10}});
  Part mass;
  REQUIRE(extrude(notched.scope, notched.geom, 3, arena, mass, error));
  REQUIRE(geometryFacts(mass.scope, mass.geom, arena).faces == 7);
  REQUIRE(cleanupGeometry(mass.scope, mass.geom, arena, 9, 0, out, error));
  GeometryFacts facts = geometryFacts(out.scope, out.geom, arena);
  CHECK(facts.faces == 6);
  CHECK(facts.vertices == 10);
  CHECK(facts.area == Approx(580).margin(1e-9));
  CHECK(volume(out, arena) == Approx(600).margin(1e-9));
  REQUIRE(cleanupGeometry(mass.scope, mass.geom, arena, 15, 0, out, error));
  facts = geometryFacts(out.scope, out.geom, arena);
  CHECK(facts.faces == 6);
  CHECK(facts.vertices == 8);
  CHECK(facts.area == Approx(580).margin(1e-9));
  for (uint32_t i = 0; i < out.geom.count; ++i) CHECK(arena.face(out.geom, i).count == 4);
  // faces (5): a second copy of a face and a sliver of 0.05 m2 go at tolerance 0.1 (0.1 m2).
  const Polygon3 square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const Polygon3 sliver{{0, 0, 0}, {1, 0, 0}, {0.5, 0.1, 0}};
  Scope unit;
  const GeomRef soup = arena.addPolyhedron({square, square, sliver});
  REQUIRE(cleanupGeometry(unit, soup, arena, 5, 0.1, out, error));
  CHECK(geometryFacts(out.scope, out.geom, arena).faces == 1);
}

TEST_CASE("setbackToArea finds the distance that leaves the area asked for") {
  GeometryArena arena;
  const FlatPolygon f = flat(lot(arena, kRect20x10), arena);
  double d = 0;
  std::string error;
  // Every edge: (20 - 2d)(10 - 2d) = 56 at d = 3.
  REQUIRE(setbackDistanceForArea(f, {true, true, true, true}, 56, d, error));
  CHECK(d == Approx(3).margin(1e-6));
  // One long edge: 20 (10 - d) = 160 at d = 2.
  REQUIRE(setbackDistanceForArea(f, {true, false, false, false}, 160, d, error));
  CHECK(d == Approx(2).margin(1e-6));
  CHECK_FALSE(setbackDistanceForArea(f, {true, true, true, true}, 250, d, error));  // more than the lot
  CHECK_FALSE(setbackDistanceForArea(f, {true, false, false, false}, 0, d, error));
}

TEST_CASE("splitAreaSizes cuts where the part before the cut has the area asked for") {
  GeometryArena arena;
  // The right triangle (0,0) (20,0) (0,10): 100 m2, the area left of x = t is 10 t - t^2 / 4,
  // so 50 m2 end at t = 20 - sqrt(200); the floating part takes the rest of the 20 m.
  const Part tri = lot(arena, {{0, 0}, {20, 0}, {0, 10}});
  std::vector<SizeValue> lengths;
  std::vector<bool> derived;
  std::string error;
  REQUIRE(splitAreaSizes(tri.scope, tri.geom, arena, 0, false, {{SizeValue::Absolute, 50}, {SizeValue::Floating, 1}},
                         lengths, derived, error));
  REQUIRE(lengths.size() == 2);
  CHECK(lengths[0].value == Approx(20 - std::sqrt(200.0)).margin(1e-9));
  CHECK(lengths[1].value == Approx(std::sqrt(200.0)).margin(1e-9));
  CHECK((derived[0] && derived[1]));
  // A relative area is that share of the whole: 0.25 of the 20 x 10 lot along x is 5 m.
  const Part rect = lot(arena, kRect20x10);
  REQUIRE(splitAreaSizes(rect.scope, rect.geom, arena, 0, false, {{SizeValue::Relative, 0.25}}, lengths, derived,
                         error));
  REQUIRE(lengths.size() == 2);  // the part asked for, then the rest (not derived)
  CHECK(lengths[0].value == Approx(5).margin(1e-9));
  CHECK((derived[0] && !derived[1]));
  // A solid is refused.
  Part box;
  REQUIRE(extrude(rect.scope, rect.geom, 3, arena, box, error));
  CHECK_FALSE(splitAreaSizes(box.scope, box.geom, arena, 0, false, {{SizeValue::Absolute, 10}}, lengths, derived,
                             error));
}

TEST_CASE("convexify cuts a ring around a courtyard into four trapezoids") {
  // A 10 x 10 square around a 4 x 4 courtyard (3..7): at least four convex pieces; the cuts
  // from the courtyard's corners to the outline's give four trapezoids of (10 + 4) / 2 * 3 = 21.
  GeometryArena arena;
  const Part court = lot(arena, {{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{{3, 3}, {3, 7}, {7, 7}, {7, 3}}});
  Part out;
  std::string error;
  REQUIRE(convexify(court.scope, court.geom, arena, INFINITY, out, error));
  REQUIRE(out.geom.kind == GeomKind::Polyhedron);
  REQUIRE(out.geom.count == 4);
  for (uint32_t i = 0; i < 4; ++i) {
    const GeometryArena::Face& f = arena.face(out.geom, i);
    Polygon3 world;
    for (uint32_t k = 0; k < f.count; ++k) world.push_back(out.scope.toWorld(out.scope.S.cwiseProduct(arena.facePoints(f)[k])));
    CHECK(world.size() == 4);
    CHECK(0.5 * newellNormal(world).norm() == Approx(21).margin(1e-9));
  }
}

TEST_CASE("convexify cuts an L from its reflex corner, and not where maxLength forbids") {
  GeometryArena arena;
  const Part l = lot(arena, {{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 20}, {0, 20}});
  Part out;
  std::string error;
  REQUIRE(convexify(l.scope, l.geom, arena, INFINITY, out, error));
  REQUIRE(out.geom.kind == GeomKind::Polyhedron);
  REQUIRE(out.geom.count == 2);
  for (uint32_t i = 0; i < 2; ++i) {  // the cut (0,0)-(10,10) leaves two 150 m2 quadrilaterals
    const GeometryArena::Face& f = arena.face(out.geom, i);
    Polygon3 world;
    for (uint32_t k = 0; k < f.count; ++k) world.push_back(out.scope.toWorld(out.scope.S.cwiseProduct(arena.facePoints(f)[k])));
    CHECK(world.size() == 4);
    CHECK(0.5 * newellNormal(world).norm() == Approx(150).margin(1e-9));
  }
  // The only cut is 14.14 m long: maxLength 10 leaves the L as it was.
  REQUIRE(convexify(l.scope, l.geom, arena, 10, out, error));
  CHECK(out.geom.kind == l.geom.kind);
  CHECK(out.geom.first == l.geom.first);
}

TEST_CASE("taper raises a pyramid over the polygon's centre of gravity") {
  GeometryArena arena;
  // The 20 x 10 lot tapered by 6: apex (10, 6, 5), volume 200 * 6 / 3 = 400.
  const Part rect = lot(arena, kRect20x10);
  Part out;
  std::string error;
  REQUIRE(taper(rect.scope, rect.geom, 6, arena, out, error));
  REQUIRE(out.geom.kind == GeomKind::Polyhedron);
  CHECK(out.geom.count == 5);
  CHECK(out.scope.S.y() == Approx(6));
  CHECK(volume(out, arena) == Approx(400).margin(1e-9));
  const GeometryArena::Face& side = arena.face(out.geom, 0);
  const Vec3 apex = out.scope.toWorld(out.scope.S.cwiseProduct(arena.facePoints(side)[2]));
  CHECK(near(apex, Vec3(10, 6, 5), 1e-9));
  CHECK_FALSE(taper(rect.scope, rect.geom, -1, arena, out, error));
}
