// CGA shape operations: splits, repeats, component splits, extrusion, roofs, clipping
// and triangulation, checked with exact or toleranced values.
#include "runtime/cga/cga.h"
#include "runtime/cga/geometry_queries.h"
#include "runtime/cga/polygon_clip.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fgsg::rt;
using namespace fgsg::rt::cga;

namespace {

constexpr double kTol = 1e-9;
constexpr double kPi = 3.14159265358979323846;

Scope box(double sx, double sy, double sz) {
  Scope s;
  s.S = Vec3(sx, sy, sz);
  return s;
}

SizeValue abs_(double v) { return {SizeValue::Absolute, v}; }
SizeValue rel(double v) { return {SizeValue::Relative, v}; }
SizeValue flt(double v) { return {SizeValue::Floating, v}; }

bool near(const Vec3& a, const Vec3& b, double tol = kTol) { return (a - b).norm() <= tol; }

// Area of a part's own polygon in world units.
double worldArea(const Part& p, const GeometryArena& arena) {
  if (p.empty) return 0.0;
  Polygon3 world;
  const Vec3* pts = arena.polygon(p.geom);
  for (uint32_t i = 0; i < p.geom.count; ++i)
    world.push_back(p.scope.toWorld(p.scope.S.cwiseProduct(pts[i])));
  return 0.5 * newellNormal(world).norm();
}

// Volume of a closed polyhedron part (divergence theorem over its world faces).
double worldVolume(const Part& p, const GeometryArena& arena) {
  double v = 0.0;
  for (uint32_t i = 0; i < p.geom.count; ++i) {
    const GeometryArena::Face& f = arena.face(p.geom, i);
    Polygon3 world;
    for (uint32_t k = 0; k < f.count; ++k)
      world.push_back(p.scope.toWorld(p.scope.S.cwiseProduct(arena.facePoints(f)[k])));
    v += world[0].dot(0.5 * newellNormal(world)) / 3.0;
  }
  return v;
}

double triangleArea(const std::vector<float>& pos, const std::vector<unsigned>& idx) {
  double area = 0.0;
  for (std::size_t t = 0; t < idx.size(); t += 3) {
    auto at = [&](unsigned i) { return Vec3(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]); };
    area += 0.5 * (at(idx[t + 1]) - at(idx[t])).cross(at(idx[t + 2]) - at(idx[t])).norm();
  }
  return area;
}

// An L: the 2 x 2 square without its top-right 1 x 1 quarter (area 3), on a 2 x 2 scope.
std::vector<Vec3> lShape() {
  return {{0, 0, 0}, {1, 0, 0}, {1, 0.5, 0}, {0.5, 0.5, 0}, {0.5, 1, 0}, {0, 1, 0}};
}

}  // namespace

TEST_CASE("cga: Subdiv X (1r, 2, 1r) on a width of 10", "[cga]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  const Scope s = box(10, 3, 4);
  REQUIRE(subdivide(s, GeomRef{}, 0, {rel(1), abs_(2), rel(1)}, arena, parts, err));
  REQUIRE(parts.size() == 3);
  const double x[3] = {0, 4, 6}, w[3] = {4, 2, 4};
  for (int i = 0; i < 3; ++i) {
    CHECK(parts[i].scope.P.x() == x[i]);
    CHECK(parts[i].scope.S.x() == w[i]);
    CHECK(parts[i].scope.S.y() == 3);
    CHECK(parts[i].scope.S.z() == 4);
    CHECK(parts[i].geom.kind == GeomKind::Box);
    CHECK_FALSE(parts[i].empty);
  }
}

TEST_CASE("cga: Subdiv with floating sizes", "[cga]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  SECTION("floating parts stretch when nothing is relative") {
    REQUIRE(subdivide(box(10, 1, 1), GeomRef{}, 0, {flt(2), abs_(4), flt(1)}, arena, parts, err));
    CHECK(parts[0].scope.S.x() == Approx(4));
    CHECK(parts[1].scope.S.x() == Approx(4));
    CHECK(parts[2].scope.S.x() == Approx(2));
    CHECK(parts[2].scope.P.x() == Approx(8));
  }
  SECTION("floating parts act as absolute next to relative ones") {
    REQUIRE(subdivide(box(1, 10, 1), GeomRef{}, 1, {flt(2), rel(1), abs_(3)}, arena, parts, err));
    CHECK(parts[0].scope.S.y() == 2);
    CHECK(parts[1].scope.S.y() == 5);
    CHECK(parts[2].scope.S.y() == 3);
    CHECK(parts[2].scope.P.y() == 7);
  }
  SECTION("zero-length parts are still produced") {
    REQUIRE(subdivide(box(10, 1, 1), GeomRef{}, 0, {abs_(0), rel(1), abs_(0)}, arena, parts, err));
    REQUIRE(parts.size() == 3);
    CHECK(parts[0].scope.S.x() == 0);
    CHECK(parts[1].scope.S.x() == 10);
    CHECK(parts[2].scope.P.x() == 10);
    CHECK_FALSE(parts[0].empty);
  }
  SECTION("absolute sizes that add up exactly") {
    REQUIRE(subdivide(box(10, 1, 1), GeomRef{}, 0, {abs_(2.5), abs_(7.5)}, arena, parts, err));
    CHECK(parts[1].scope.P.x() == 2.5);
  }
}

TEST_CASE("cga: Subdiv errors", "[cga]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  CHECK_FALSE(
      subdivide(box(10, 1, 1), GeomRef{}, 0, {abs_(5), rel(1), abs_(7)}, arena, parts, err));
  CHECK(err == "Subdiv along X: absolute sizes 12 exceed the scope length 10");
  CHECK(parts.empty());

  CHECK_FALSE(subdivide(box(1, 10, 1), GeomRef{}, 1, {flt(5), rel(1), abs_(7)}, arena, parts, err));
  CHECK(err == "Subdiv along Y: absolute and floating sizes 12 exceed the scope length 10");

  CHECK_FALSE(subdivide(box(1, 1, 10), GeomRef{}, 2, {abs_(11), flt(1)}, arena, parts, err));
  CHECK(err == "Subdiv along Z: absolute sizes 11 exceed the scope length 10");

  CHECK_FALSE(subdivide(box(10, 1, 1), GeomRef{}, 0, {abs_(3), abs_(4)}, arena, parts, err));
  CHECK_THAT(
      err, Catch::StartsWith("Subdiv along X: absolute sizes sum to 7 but the scope length is 10"));

  CHECK_FALSE(subdivide(box(10, 1, 1), GeomRef{}, 0, {abs_(-2), rel(1)}, arena, parts, err));
  CHECK(err == "Subdiv along X: size -2 must be a finite non-negative number");

  CHECK_FALSE(subdivide(box(10, 1, 1), GeomRef{}, 0, {}, arena, parts, err));
  CHECK(err == "Subdiv along X: no sizes given");
}

TEST_CASE("cga: Repeat tiles", "[cga]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  SECTION("Repeat X 2 on a width of 10") {
    REQUIRE(repeat(box(10, 2, 2), GeomRef{}, 1, {2}, arena, parts, err));
    REQUIRE(parts.size() == 5);
    for (int i = 0; i < 5; ++i) {
      CHECK(parts[i].scope.P.x() == 2.0 * i);
      CHECK(parts[i].scope.S.x() == 2);
      CHECK(parts[i].scope.S.y() == 2);
    }
  }
  SECTION("Repeat X 3 on a width of 10 gives 3 tiles of 10/3") {
    REQUIRE(repeat(box(10, 2, 2), GeomRef{}, 1, {3}, arena, parts, err));
    REQUIRE(parts.size() == 3);
    for (int i = 0; i < 3; ++i) {
      CHECK(parts[i].scope.S.x() == Approx(10.0 / 3));
      CHECK(parts[i].scope.P.x() == Approx(i * 10.0 / 3));
    }
  }
  SECTION("a tile longer than the scope gives one tile") {
    REQUIRE(repeat(box(10, 2, 2), GeomRef{}, 1, {30}, arena, parts, err));
    REQUIRE(parts.size() == 1);
    CHECK(parts[0].scope.S.x() == 10);
  }
  SECTION("Repeat XY orders X fastest") {
    REQUIRE(repeat(box(4, 6, 1), GeomRef{}, 3, {2, 3}, arena, parts, err));
    REQUIRE(parts.size() == 4);
    CHECK(near(parts[1].scope.P, Vec3(2, 0, 0)));
    CHECK(near(parts[2].scope.P, Vec3(0, 3, 0)));
    CHECK(near(parts[3].scope.S, Vec3(2, 3, 1)));
  }
  SECTION("errors") {
    CHECK_FALSE(repeat(box(10, 2, 2), GeomRef{}, 1, {0}, arena, parts, err));
    CHECK(err == "Repeat along X: the tile size 0 must be positive");
    CHECK_FALSE(repeat(box(10, 2, 2), GeomRef{}, 3, {1}, arena, parts, err));
    CHECK(err == "Repeat: 2 axes need 2 sizes, got 1");
    CHECK_FALSE(repeat(box(1e9, 1e9, 2), GeomRef{}, 3, {1e-3, 1e-3}, arena, parts, err));
    CHECK_THAT(err, Catch::Contains("tiles"));
  }
}

TEST_CASE("cga: rotated scopes place parts along their own axes", "[cga]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  Scope s = box(10, 3, 4);
  s.P = Vec3(5, 1, 2);
  rotateLocal(s, 1, 90);  // Ry(90): X -> -Z, Z -> +X
  REQUIRE(near(s.X(), Vec3(0, 0, -1)));

  REQUIRE(subdivide(s, GeomRef{}, 0, {rel(1), abs_(2), rel(1)}, arena, parts, err));
  CHECK(near(parts[1].scope.P, Vec3(5, 1, -2)));
  CHECK(near(parts[2].scope.P, Vec3(5, 1, -4)));
  CHECK(parts[1].scope.axes.isApprox(s.axes));

  REQUIRE(repeat(s, GeomRef{}, 1, {2}, arena, parts, err));
  CHECK(near(parts[4].scope.P, Vec3(5, 1, -6)));

  // The front face (+Z of the box) now faces world +X and starts at the box's far corner.
  REQUIRE(components(s, GeomRef{}, "front", arena, parts, err));
  REQUIRE(parts.size() == 1);
  CHECK(near(parts[0].scope.Z(), Vec3(1, 0, 0)));
  CHECK(near(parts[0].scope.Y(), Vec3(0, 1, 0)));
  CHECK(near(parts[0].scope.P, Vec3(9, 1, 2)));
  CHECK(near(parts[0].scope.S, Vec3(10, 3, 0)));
}

TEST_CASE("cga: Comp of a 20 x 10 x 12 box", "[cga]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  const Scope s = box(20, 10, 12);
  REQUIRE(components(s, GeomRef{}, "sidefaces", arena, parts, err));
  REQUIRE(parts.size() == 4);
  const Vec3 size[4] = {{20, 10, 0}, {12, 10, 0}, {20, 10, 0}, {12, 10, 0}};
  const Vec3 normal[4] = {{0, 0, 1}, {1, 0, 0}, {0, 0, -1}, {-1, 0, 0}};
  const Vec3 xAxis[4] = {{1, 0, 0}, {0, 0, -1}, {-1, 0, 0}, {0, 0, 1}};
  const Vec3 origin[4] = {{0, 0, 12}, {20, 0, 12}, {20, 0, 0}, {0, 0, 0}};
  for (int i = 0; i < 4; ++i) {
    INFO("face " << i);
    CHECK(near(parts[i].scope.S, size[i]));
    CHECK(near(parts[i].scope.Z(), normal[i]));
    CHECK(near(parts[i].scope.X(), xAxis[i]));
    CHECK(near(parts[i].scope.Y(), Vec3(0, 1, 0)));
    CHECK(near(parts[i].scope.P, origin[i]));
    REQUIRE(parts[i].geom.kind == GeomKind::Polygon);
    CHECK(isUnitSquare(arena.polygon(parts[i].geom), parts[i].geom.count));
    CHECK(worldArea(parts[i], arena) == Approx(size[i].x() * size[i].y()));
  }

  REQUIRE(components(s, GeomRef{}, "top", arena, parts, err));
  REQUIRE(parts.size() == 1);
  CHECK(near(parts[0].scope.Z(), Vec3(0, 1, 0)));
  CHECK(near(parts[0].scope.X(), Vec3(1, 0, 0)));
  CHECK(near(parts[0].scope.P, Vec3(0, 10, 12)));
  CHECK(near(parts[0].scope.S, Vec3(20, 12, 0)));

  REQUIRE(components(s, GeomRef{}, "faces", arena, parts, err));
  CHECK(parts.size() == 6);
  REQUIRE(components(s, GeomRef{}, "edges", arena, parts, err));
  CHECK(parts.size() == 12);
  REQUIRE(components(s, GeomRef{}, "sideedges", arena, parts, err));
  REQUIRE(parts.size() == 4);
  for (const Part& e : parts) {
    CHECK(e.geom.kind == GeomKind::Edge);
    CHECK(near(e.scope.S, Vec3(0, 10, 0)));
    CHECK(near(e.scope.Y(), Vec3(0, 1, 0)));
    CHECK(e.scope.P.y() == Approx(0));  // vertical edges start at their lower end
  }
  // The front-right corner edge: Z halfway between the front and right normals.
  CHECK(near(parts[0].scope.P, Vec3(20, 0, 12)));
  CHECK(near(parts[0].scope.Z(), Vec3(1, 0, 1).normalized()));
  REQUIRE(components(s, GeomRef{}, "topedges", arena, parts, err));
  CHECK(parts.size() == 4);
  for (const Part& e : parts) CHECK(e.scope.P.y() == Approx(10));

  CHECK_FALSE(components(s, GeomRef{}, "windows", arena, parts, err));
  CHECK_THAT(err, Catch::StartsWith("Comp: unknown selector \"windows\""));
}

TEST_CASE("cga: Comp of a polygon: itself and its boundary", "[cga]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  Scope s = box(6, 4, 0);
  s.P = Vec3(1, 2, 3);
  const GeomRef tri = arena.addPolygon({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}});
  REQUIRE(components(s, tri, "faces", arena, parts, err));
  REQUIRE(parts.size() == 1);
  CHECK(near(parts[0].scope.P, s.P));
  CHECK(parts[0].scope.axes.isApprox(s.axes));
  CHECK(worldArea(parts[0], arena) == Approx(12));
  REQUIRE(components(s, tri, "edges", arena, parts, err));
  CHECK(parts.size() == 3);
  REQUIRE(components(s, tri, "bottomedges", arena, parts, err));
  REQUIRE(parts.size() == 1);
  CHECK(parts[0].scope.S.y() == Approx(6));
  CHECK(near(parts[0].scope.Z(), Vec3(0, 0, 1)));
  REQUIRE(components(s, tri, "sideedges", arena, parts, err));
  CHECK(parts.size() == 2);
  CHECK_FALSE(components(s, GeomRef{GeomKind::Edge, 0, 0}, "edges", arena, parts, err));
}

TEST_CASE("cga: a shape's own surface: flat shapes one face, solids without their bottom", "[cga]") {
  GeometryArena arena;
  // Newell's normal of each polygon: its area and outward direction.
  auto normals = [](const std::vector<std::vector<Vec3>>& polys) {
    std::vector<Vec3> out;
    for (const auto& p : polys) out.push_back(0.5 * newellNormal(p));
    return out;
  };
  SECTION("a solid box: five faces, outward, no bottom") {
    Scope s = box(2, 3, 4);
    s.P = Vec3(1, 1, 1);
    const auto n = normals(surfacePolygons(s, GeomRef{}, arena));
    REQUIRE(n.size() == 5);
    Vec3 sum = Vec3::Zero();
    double area = 0;
    for (const Vec3& v : n) {
      CHECK(v.y() > -kTol);  // nothing looks down
      sum += v, area += v.norm();
    }
    CHECK(area == Approx(2 * (2 * 3 + 3 * 4) + 2 * 4));
    CHECK(near(sum, Vec3(0, 2 * 4, 0)));  // the top's area: the open bottom's, upward
  }
  SECTION("a flat box looks along the axis it has no size in") {
    const auto facade = normals(surfacePolygons(box(2, 3, 0), GeomRef{}, arena));
    REQUIRE(facade.size() == 1);
    CHECK(near(facade[0], Vec3(0, 0, 6)));
    const auto footprint = normals(surfacePolygons(box(2, 0, 3), GeomRef{}, arena));
    REQUIRE(footprint.size() == 1);
    CHECK(near(footprint[0], Vec3(0, 6, 0)));
    CHECK(surfacePolygons(box(2, 0, 0), GeomRef{}, arena).empty());
  }
  SECTION("a polygon is its face along the scope's Z, whichever way it was written") {
    const GeomRef cw = arena.addPolygon({{0, 0, 0}, {0.5, 1, 0}, {1, 0, 0}});
    const auto n = normals(surfacePolygons(box(6, 4, 0), cw, arena));
    REQUIRE(n.size() == 1);
    CHECK(near(n[0], Vec3(0, 0, 12)));
    CHECK(surfacePolygons(box(1, 1, 0), GeomRef{GeomKind::Edge, 0, 0}, arena).empty());
  }
  SECTION("a hipped roof: its four slopes") {
    Scope s = box(20, 10, 12);
    Part r;
    std::string err;
    REQUIRE(roof(s, GeomRef{}, "hipped", 30, arena, r, err));
    const auto n = normals(surfacePolygons(r.scope, r.geom, arena));
    REQUIRE(n.size() == 4);
    for (const Vec3& v : n) CHECK(v.y() > 0);
  }
}

TEST_CASE("cga: hipped roof on 20 x 12 at 30 degrees", "[cga]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  Scope s = box(20, 10, 12);
  s.P.y() = 10;  // T(0, building_height, 0)
  Part r;
  REQUIRE(roof(s, GeomRef{}, "hipped", 30, arena, r, err));
  const double h = 6 * std::tan(30 * kPi / 180);
  CHECK(r.scope.S.y() == Approx(h));
  CHECK(r.scope.S.x() == 20);
  CHECK(r.scope.S.z() == 12);
  CHECK(r.scope.P.y() == 10);
  REQUIRE(r.geom.kind == GeomKind::Polyhedron);
  CHECK(r.geom.count == 5);
  // A triangular prism 8 long plus a pyramid on a 12 x 12 base.
  CHECK(worldVolume(r, arena) == Approx(8 * 12 * h / 2 + 12 * 12 * h / 3));

  REQUIRE(components(r.scope, r.geom, "sidefaces", arena, parts, err));
  REQUIRE(parts.size() == 4);
  const double slant = std::sqrt(36 + h * h);
  CHECK(near(parts[0].scope.S, Vec3(20, slant, 0)));  // front trapezoid
  CHECK(near(parts[1].scope.S, Vec3(12, slant, 0)));  // right triangle
  CHECK(near(parts[0].scope.X(), Vec3(1, 0, 0)));
  CHECK(near(parts[0].scope.Z(), Vec3(0, std::cos(kPi / 6), std::sin(kPi / 6))));
  CHECK(worldArea(parts[0], arena) == Approx((20 + 8) / 2.0 * slant));
  CHECK(worldArea(parts[1], arena) == Approx(12 * slant / 2));

  REQUIRE(components(r.scope, r.geom, "topedges", arena, parts, err));
  REQUIRE(parts.size() == 1);
  CHECK(parts[0].scope.S.y() == Approx(8));
  CHECK(near(parts[0].scope.Y().cwiseAbs(), Vec3(1, 0, 0)));
  CHECK(parts[0].scope.P.y() == Approx(10 + h));
  CHECK(near(parts[0].scope.Z(), Vec3(0, 1, 0)));

  REQUIRE(components(r.scope, r.geom, "sideedges", arena, parts, err));
  REQUIRE(parts.size() == 4);
  for (const Part& e : parts) {
    CHECK(e.scope.S.y() == Approx(std::sqrt(36 + 36 + h * h)));
    CHECK(e.scope.P.y() == Approx(10));  // hips start at the eaves
  }
  REQUIRE(components(r.scope, r.geom, "bottomedges", arena, parts, err));
  CHECK(parts.size() == 4);
  REQUIRE(components(r.scope, r.geom, "bottom", arena, parts, err));
  CHECK(parts.size() == 1);
}

TEST_CASE("cga: gable, pyramid and deep roofs", "[cga]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  Part r;
  SECTION("a deep footprint puts the ridge along Z") {
    REQUIRE(roof(box(12, 0, 20), GeomRef{}, "hipped", 45, arena, r, err));
    CHECK(r.scope.S.y() == Approx(6));
    REQUIRE(components(r.scope, r.geom, "topedges", arena, parts, err));
    REQUIRE(parts.size() == 1);
    CHECK(near(parts[0].scope.Y().cwiseAbs(), Vec3(0, 0, 1)));
    CHECK(parts[0].scope.S.y() == Approx(8));
  }
  SECTION("gable: two slopes and two vertical gables") {
    REQUIRE(roof(box(20, 0, 12), GeomRef{}, "gable", 45, arena, r, err));
    CHECK(worldVolume(r, arena) == Approx(20 * 12 * 6 / 2.0));
    REQUIRE(components(r.scope, r.geom, "sidefaces", arena, parts, err));
    REQUIRE(parts.size() == 4);
    CHECK(near(parts[1].scope.Z(), Vec3(1, 0, 0)));  // the right gable is vertical
    CHECK(worldArea(parts[1], arena) == Approx(12 * 6 / 2.0));
    REQUIRE(components(r.scope, r.geom, "topedges", arena, parts, err));
    REQUIRE(parts.size() == 1);
    CHECK(parts[0].scope.S.y() == Approx(20));
    REQUIRE(components(r.scope, r.geom, "sideedges", arena, parts, err));
    CHECK(parts.size() == 4);
  }
  SECTION("ridge: along the scope's x on a deep footprint, overhangs and edge indices refused") {
    // 12 x 20 (x by z), 45 degrees: the ridge runs along x over z = 10, 10 m high, where a
    // gable's would run along z, 6 m high.
    REQUIRE(roof(box(12, 0, 20), GeomRef{}, "ridge", 45, arena, r, err));
    CHECK(r.scope.S.y() == Approx(10));
    CHECK(worldVolume(r, arena) == Approx(12 * 20 * 10 / 2.0));
    REQUIRE(components(r.scope, r.geom, "topedges", arena, parts, err));
    REQUIRE(parts.size() == 1);
    CHECK(near(parts[0].scope.Y().cwiseAbs(), Vec3(1, 0, 0)));
    CHECK(parts[0].scope.S.y() == Approx(12));
    CHECK_FALSE(roof(box(12, 0, 20), GeomRef{}, "ridge", 45, arena, r, err, nullptr, RoofOptions{1.0, 1.0, -1}));
    CHECK(err == "Roof: a ridge roof has no overhang (hipped and gable roofs do)");
    CHECK_FALSE(roof(box(12, 0, 20), GeomRef{}, "ridge", 45, arena, r, err, nullptr, RoofOptions{0.0, 0.0, 1}));
    CHECK(err.find("only shed and gable roofs take an edge index") != std::string::npos);
  }
  SECTION("pyramid and square hipped roofs have an apex") {
    REQUIRE(roof(box(10, 0, 10), GeomRef{}, "pyramid", 45, arena, r, err));
    CHECK(worldVolume(r, arena) == Approx(100 * 5 / 3.0));
    REQUIRE(components(r.scope, r.geom, "topedges", arena, parts, err));
    CHECK(parts.empty());
    REQUIRE(roof(box(10, 0, 10), GeomRef{}, "hipped", 45, arena, r, err));
    REQUIRE(components(r.scope, r.geom, "sideedges", arena, parts, err));
    CHECK(parts.size() == 4);
  }
  SECTION("errors") {
    CHECK_FALSE(roof(box(10, 0, 10), GeomRef{}, "hipped", 90, arena, r, err));
    CHECK(err == "Roof: the angle 90 must lie strictly between 0 and 90 degrees");
    CHECK_FALSE(roof(box(10, 0, 10), GeomRef{}, "hipped", 0, arena, r, err));
    CHECK_FALSE(roof(box(10, 0, 10), GeomRef{}, "mansard", 30, arena, r, err));
    CHECK(err == "Roof: unknown kind \"mansard\" (expected hipped, gable, pyramid, shed or ridge)");
  }
}

TEST_CASE("cga: roofs on a box have exact corners, square gables along x, no repeated hip corner", "[cga]") {
  GeometryArena arena;
  std::string err;
  Part r;
  // Every face's corners in world units, in the order the roof lists them.
  auto roofCornersInMetres = [&](const Part& p) {
    std::vector<Polygon3> faces;
    for (uint32_t i = 0; i < p.geom.count; ++i) {
      const GeometryArena::Face& f = arena.face(p.geom, i);
      Polygon3 world;
      for (uint32_t k = 0; k < f.count; ++k)
        world.push_back(p.scope.toWorld(p.scope.S.cwiseProduct(arena.facePoints(f)[k])));
      faces.push_back(world);
    }
    return faces;
  };
  auto checkFaces = [&](const std::vector<Polygon3>& got, const std::vector<Polygon3>& want) {
    REQUIRE(got.size() == want.size());
    for (size_t i = 0; i < want.size(); ++i) {
      INFO("face " << i);
      REQUIRE(got[i].size() == want[i].size());
      for (size_t k = 0; k < want[i].size(); ++k) CHECK(near(got[i][k], want[i][k], 1e-12));
    }
  };
  // Faces: front (+z), right (+x), back (-z), left (-x), bottom; each eave, then the ridge
  // ends its corners rise to, one end only where both rise to the same point.
  const Vec3 c0(0, 0, 0), c1(10, 0, 0), c2(10, 0, 10), c3(0, 0, 10);
  SECTION("a gable roof on a square: the ridge along x (the tie goes to x, as on polygons)") {
    REQUIRE(roof(box(10, 0, 10), GeomRef{}, "gable", 45, arena, r, err));
    const Vec3 west(0, 5, 5), east(10, 5, 5);
    checkFaces(roofCornersInMetres(r),
               {{c3, c2, east, west}, {c2, c1, east}, {c1, c0, west, east}, {c0, c3, west}, {c0, c1, c2, c3}});
  }
  SECTION("a hipped roof on a square is a pyramid of four triangles") {
    REQUIRE(roof(box(10, 0, 10), GeomRef{}, "hipped", 45, arena, r, err));
    const Vec3 apex(5, 5, 5);
    checkFaces(roofCornersInMetres(r),
               {{c3, c2, apex}, {c2, c1, apex}, {c1, c0, apex}, {c0, c3, apex}, {c0, c1, c2, c3}});
  }
  SECTION("a hipped roof on 20 x 12: hips end at triangles, the ridge 8 long") {
    REQUIRE(roof(box(20, 0, 12), GeomRef{}, "hipped", 45, arena, r, err));
    const Vec3 b0(0, 0, 0), b1(20, 0, 0), b2(20, 0, 12), b3(0, 0, 12), west(6, 6, 6), east(14, 6, 6);
    checkFaces(roofCornersInMetres(r),
               {{b3, b2, east, west}, {b2, b1, east}, {b1, b0, west, east}, {b0, b3, west}, {b0, b1, b2, b3}});
  }
}

TEST_CASE("cga: geometry.angle of roof faces, boxes and footprints", "[cga]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  Part r;
  // A 30 degree gable roof on a 10 x 6 footprint (x by z): the slopes tilt by 30, the gable
  // walls stand upright; the faces look south (+z, 180), east (+x, 90), north (0), west (270).
  REQUIRE(roof(box(10, 0, 6), GeomRef{}, "gable", 30, arena, r, err));
  REQUIRE(components(r.scope, r.geom, "sidefaces", arena, parts, err));
  REQUIRE(parts.size() == 4);
  const double slopes[] = {30, 90, 30, 90}, azimuths[] = {180, 90, 0, 270};
  for (size_t i = 0; i < 4; ++i) {
    INFO("face " << i);
    auto angle = [&](GeometryAngleKind kind) { return geometryAngle(parts[i].scope, parts[i].geom, arena, kind); };
    CHECK(std::abs(angle(GeometryAngleKind::MaxSlope) - slopes[i]) <= 1e-9);
    CHECK(std::abs(angle(GeometryAngleKind::Zenith) - (90 - slopes[i])) <= 1e-9);
    CHECK(std::abs(angle(GeometryAngleKind::Azimuth) - azimuths[i]) <= 1e-9);
  }
  // The whole roof: its steepest faces are the walls, the first of them (east) gives the azimuth.
  CHECK(geometryAngle(r.scope, r.geom, arena, GeometryAngleKind::MaxSlope) == Approx(90).margin(1e-9));
  CHECK(geometryAngle(r.scope, r.geom, arena, GeometryAngleKind::Azimuth) == Approx(90).margin(1e-9));
  // A box: upright, its front face (+z) first; a footprint: level, no direction.
  CHECK(geometryAngle(box(2, 3, 4), GeomRef{}, arena, GeometryAngleKind::MaxSlope) == Approx(90).margin(1e-12));
  CHECK(geometryAngle(box(2, 3, 4), GeomRef{}, arena, GeometryAngleKind::Azimuth) == Approx(180).margin(1e-12));
  CHECK(geometryAngle(box(2, 0, 4), GeomRef{}, arena, GeometryAngleKind::MaxSlope) == 0);
  CHECK(geometryAngle(box(2, 0, 4), GeomRef{}, arena, GeometryAngleKind::Azimuth) == 0);
  CHECK(geometryAngle(box(2, 0, 4), GeomRef{}, arena, GeometryAngleKind::Zenith) == Approx(90).margin(1e-12));
}

TEST_CASE("cga: geometry.du and dv spread the projection's texture coordinates", "[cga]") {
  GeometryArena arena;
  // A 10 x 4 facade (no depth) under a 2 m x 1 m projection set up in its own scope: u runs
  // 0 .. 5, v 0 .. 4; scaled by (2, 0.5) after it: 10 and 2.
  const Scope facade = box(10, 4, 0);
  UvProjection projection = projectionAt(facade, 2, 1, UvProjection::kNoImage);
  auto spread = geometryUvSpread(facade, GeomRef{}, arena, projection);
  CHECK(spread[0] == Approx(5).margin(1e-12));
  CHECK(spread[1] == Approx(4).margin(1e-12));
  projection.uvTransform = {2, 0, 0, 0, 0.5, 0};
  spread = geometryUvSpread(facade, GeomRef{}, arena, projection);
  CHECK(spread[0] == Approx(10).margin(1e-12));
  CHECK(spread[1] == Approx(2).margin(1e-12));
  // A 2.5 m piece of the facade (x 5 .. 7.5) measured in the facade's projection: 1.25 x 4.
  Scope piece = facade;
  piece.P = Vec3(5, 0, 0);
  piece.S = Vec3(2.5, 4, 0);
  spread = geometryUvSpread(piece, GeomRef{}, arena, projectionAt(facade, 2, 1, UvProjection::kNoImage));
  CHECK(spread[0] == Approx(1.25).margin(1e-12));
  CHECK(spread[1] == Approx(4).margin(1e-12));
  // An edge has no faces.
  CHECK(geometryUvSpread(facade, GeomRef{GeomKind::Edge, 0, 0}, arena, projection)[0] == 0);
}

TEST_CASE("cga: Repeat XY on a triangle marks tiles outside it empty", "[cga]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  Scope s = box(4, 4, 0);
  const GeomRef tri = arena.addPolygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  REQUIRE(repeat(s, tri, 3, {1, 1}, arena, parts, err));
  REQUIRE(parts.size() == 16);
  double area = 0.0;
  for (int iy = 0; iy < 4; ++iy)
    for (int ix = 0; ix < 4; ++ix) {
      const Part& p = parts[iy * 4 + ix];
      INFO("tile " << ix << "," << iy);
      CHECK(p.empty == (ix + iy >= 4));  // tiles touching the hypotenuse at a corner too
      CHECK(near(p.scope.P, Vec3(ix, iy, 0)));
      CHECK(near(p.scope.S, Vec3(1, 1, 0)));  // partial tiles keep the whole tile scope
      const double a = worldArea(p, arena);
      CHECK(a == Approx(ix + iy <= 2 ? 1.0 : ix + iy == 3 ? 0.5 : 0.0).margin(1e-12));
      area += a;
    }
  CHECK(area == Approx(8));
}

TEST_CASE("cga: clipping keeps area and volume", "[cga]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  SECTION("a pentagon split along X and Y") {
    const GeomRef pent =
        arena.addPolygon({{0, 0, 0}, {1, 0, 0}, {1, 0.6, 0}, {0.5, 1, 0}, {0, 0.6, 0}});
    const Scope s = box(7, 3, 0);
    Part whole{s, pent, false};
    const double total = worldArea(whole, arena);
    for (int axis = 0; axis < 2; ++axis) {
      REQUIRE(subdivide(s, pent, axis, {rel(1), abs_(1.3), rel(2), abs_(0)}, arena, parts, err));
      REQUIRE(parts.size() == 4);
      CHECK(parts[3].empty);  // a zero-width slab holds no area
      double sum = 0.0;
      for (const Part& p : parts) sum += worldArea(p, arena);
      CHECK(sum == Approx(total).epsilon(1e-12));
    }
  }
  SECTION("a concave L split through its notch") {
    const GeomRef l = arena.addPolygon(lShape());
    const Scope s = box(2, 2, 0);
    REQUIRE(repeat(s, l, 3, {0.3, 0.7}, arena, parts, err));
    double sum = 0.0;
    for (const Part& p : parts) sum += worldArea(p, arena);
    CHECK(sum == Approx(3).epsilon(1e-12));
  }
  SECTION("a convex roof gets caps where it is cut") {
    Part r;
    REQUIRE(roof(box(20, 0, 12), GeomRef{}, "hipped", 30, arena, r, err));
    const double total = worldVolume(r, arena);
    REQUIRE(subdivide(r.scope, r.geom, 0, {abs_(3), rel(1), abs_(9)}, arena, parts, err));
    double sum = 0.0;
    for (const Part& p : parts) {
      REQUIRE(p.geom.kind == GeomKind::Polyhedron);
      sum += worldVolume(p, arena);  // closed solids only: caps present
    }
    CHECK(sum == Approx(total).epsilon(1e-12));
    CHECK(parts[0].geom.count == 5);  // the left hip's tip: 3 slopes, bottom and cap
  }
  SECTION("polygon slabs: LocalGeometry round trip") {
    LocalGeometry g;
    g.faces = {lShape()};
    REQUIRE(clipToSlab(g, 1, 0.5, 1.0));
    renormalise(g, 1, 0.5, 1.0);
    CHECK(0.5 * newellNormal(g.faces[0]).norm() == Approx(0.5));
    LocalGeometry outside;
    outside.faces = {lShape()};
    CHECK_FALSE(clipToSlab(outside, 0, 1.0, 1.0));
  }
}

TEST_CASE("cga: box faces share geometry through splits", "[cga]") {
  GeometryArena arena;
  std::vector<Part> faces, tiles, cells;
  std::string err;
  REQUIRE(components(box(20, 10, 12), GeomRef{}, "sidefaces", arena, faces, err));
  CHECK(faces[0].geom.first == faces[1].geom.first);  // one unit square for all faces
  REQUIRE(repeat(faces[0].scope, faces[0].geom, 1, {3}, arena, tiles, err));
  REQUIRE(tiles.size() == 6);
  REQUIRE(
      subdivide(tiles[2].scope, tiles[2].geom, 1, {rel(2), abs_(1.5), rel(1)}, arena, cells, err));
  CHECK(cells[1].geom.first == faces[0].geom.first);
  CHECK(cells[1].geom.kind == GeomKind::Polygon);
  CHECK(near(cells[1].scope.P, Vec3(20.0 / 6 * 2, 17.0 / 3, 12)));
}

TEST_CASE("cga: Extrude", "[cga]") {
  GeometryArena arena;
  std::vector<Part> parts;
  std::string err;
  Part solid;
  SECTION("a flat box grows along Y") {
    REQUIRE(extrude(box(20, 0, 12), GeomRef{}, 10, arena, solid, err));
    CHECK(solid.geom.kind == GeomKind::Box);
    CHECK(near(solid.scope.S, Vec3(20, 10, 12)));
  }
  SECTION("an L-shaped polygon becomes a Y-up prism") {
    Scope s = box(2, 2, 0);
    s.axes.col(1) = Vec3(0, 0, -1);  // a footprint lying on the ground: its normal Z is up
    s.axes.col(2) = Vec3(0, 1, 0);
    const GeomRef l = arena.addPolygon(lShape());
    REQUIRE(extrude(s, l, 5, arena, solid, err));
    REQUIRE(solid.geom.kind == GeomKind::Polyhedron);
    CHECK(solid.geom.count == 8);
    CHECK(near(solid.scope.Y(), Vec3(0, 1, 0)));
    CHECK(near(solid.scope.S, Vec3(2, 5, 2)));
    CHECK(worldVolume(solid, arena) == Approx(15));
    REQUIRE(components(solid.scope, solid.geom, "sidefaces", arena, parts, err));
    CHECK(parts.size() == 6);
    for (const Part& f : parts) CHECK(near(f.scope.Y(), Vec3(0, 1, 0)));
    REQUIRE(components(solid.scope, solid.geom, "top", arena, parts, err));
    REQUIRE(parts.size() == 1);
    CHECK(worldArea(parts[0], arena) == Approx(3));
    // Concave: cut without caps, but the side walls keep their area.
    REQUIRE(subdivide(solid.scope, solid.geom, 1, {rel(1), rel(1)}, arena, parts, err));
    CHECK(parts[0].geom.count == 7);  // six walls and the bottom
  }
  SECTION("a unit-square polygon becomes a box") {
    Scope s = box(4, 3, 0);
    const GeomRef sq = arena.addPolygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    REQUIRE(extrude(s, sq, 2, arena, solid, err));
    CHECK(solid.geom.kind == GeomKind::Box);
    CHECK(near(solid.scope.S, Vec3(4, 2, 3)));
    CHECK(near(solid.scope.P, Vec3(0, 3, 0)));
    CHECK(near(solid.scope.Z(), Vec3(0, -1, 0)));
  }
  SECTION("errors") {
    CHECK_FALSE(extrude(box(2, 0, 2), GeomRef{}, -1, arena, solid, err));
    CHECK(err == "Extrude: the height -1 must be positive");
    // Zero is no solid either (a mutation run found nothing asking, #51).
    CHECK_FALSE(extrude(box(2, 0, 2), GeomRef{}, 0, arena, solid, err));
    CHECK(err == "Extrude: the height 0 must be positive");
  }
}

TEST_CASE("cga: offset distances that are not positive are errors", "[cga]") {
  // CGA's inward offset(-d) arrives here as d > 0; zero would give a band of no width
  // (a mutation run found nothing asking, #51).
  GeometryArena arena;
  std::vector<Part> inside, border;
  std::string err;
  for (double d : {0.0, -1.0}) {
    CHECK_FALSE(offset(box(4, 0, 3), GeomRef{}, d, true, arena, inside, border, err, nullptr));
    CHECK(err == "Offset: the distance " + std::string(d == 0 ? "0" : "-1") + " must be positive");
    CHECK(inside.empty());
    CHECK(border.empty());
  }
}

TEST_CASE("cga: triangulate", "[cga]") {
  GeometryArena arena;
  std::vector<float> pos;
  std::vector<unsigned> idx;
  SECTION("a box gives 12 triangles covering its surface") {
    triangulate(box(2, 3, 4), GeomRef{}, arena, pos, idx);
    CHECK(idx.size() == 36);
    CHECK(triangleArea(pos, idx) == Approx(2 * (6 + 8 + 12)));
  }
  SECTION("a box with a zero size gives its two non-degenerate faces") {
    triangulate(box(2, 3, 0), GeomRef{}, arena, pos, idx);
    CHECK(idx.size() == 12);
    CHECK(triangleArea(pos, idx) == Approx(12));
  }
  SECTION("an L-shaped polygon is ear-clipped") {
    Scope s = box(2, 2, 0);
    s.P = Vec3(1, 2, 3);
    rotateLocal(s, 0, 30);
    const GeomRef l = arena.addPolygon(lShape());
    triangulate(s, l, arena, pos, idx);
    CHECK(idx.size() == 12);
    CHECK(triangleArea(pos, idx) == Approx(3));
    // Every triangle faces along the scope's Z, like the polygon.
    for (std::size_t t = 0; t < idx.size(); t += 3) {
      auto at = [&](unsigned i) { return Vec3(pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]); };
      const Vec3 n = (at(idx[t + 1]) - at(idx[t])).cross(at(idx[t + 2]) - at(idx[t]));
      CHECK(n.dot(s.Z()) > 0);
    }
  }
  SECTION("a hipped roof: each face, appended after what is there") {
    pos.assign(6, 0.f);
    Part r;
    std::string err;
    REQUIRE(roof(box(20, 0, 12), GeomRef{}, "hipped", 30, arena, r, err));
    triangulate(r.scope, r.geom, arena, pos, idx);
    CHECK(idx.size() == 3 * (2 + 1 + 2 + 1 + 2));
    for (unsigned i : idx) CHECK(i >= 2);
  }
}

TEST_CASE("cga: Mueller's building grammar on a rectangular footprint", "[cga]") {
  GeometryArena arena;
  std::string err;
  const double buildingHeight = 12, roofAngle = 30, windowSpacing = 3, windowWidth = 1.2,
               windowHeight = 1.5, flatbrickWidth = 0.3, brickLength = 0.4, overlap = 0.05;
  // footprint ~> S(1r, building_height, 1r) facades T(0, building_height, 0) Roof(...)
  Scope mass = box(20, 0, 12);
  mass.S.y() = buildingHeight;
  std::vector<Part> facades, tiles, cols, rows, roofFaces, covering, edges, segments;
  REQUIRE(components(mass, GeomRef{}, "sidefaces", arena, facades, err));
  std::size_t windows = 0;
  for (const Part& f : facades) {
    REQUIRE(repeat(f.scope, f.geom, 1, {windowSpacing}, arena, tiles, err));
    for (const Part& t : tiles) {
      REQUIRE(subdivide(t.scope, t.geom, 0, {rel(1), abs_(windowWidth), rel(1)}, arena, cols, err));
      REQUIRE(subdivide(cols[1].scope, cols[1].geom, 1, {rel(2), abs_(windowHeight), rel(1)}, arena,
                        rows, err));
      windows += 1;
    }
  }
  CHECK(windows == 2 * (6 + 4));
  Scope top = mass;
  top.P.y() += buildingHeight;
  Part r;
  REQUIRE(roof(top, GeomRef{}, "hipped", roofAngle, arena, r, err));
  // roof ~> Comp("sidefaces"){ covering } Comp("sideedges"){ roofedge } ...
  REQUIRE(components(r.scope, r.geom, "sidefaces", arena, roofFaces, err));
  double tiled = 0.0, faceArea = 0.0;
  for (const Part& f : roofFaces) {
    faceArea += worldArea(f, arena);
    REQUIRE(repeat(f.scope, f.geom, 3, {flatbrickWidth, brickLength}, arena, covering, err));
    for (const Part& b : covering) tiled += worldArea(b, arena);
    REQUIRE(subdivide(f.scope, f.geom, 0, {abs_(flatbrickWidth), rel(1)}, arena, cols, err));
    REQUIRE(repeat(cols[1].scope, cols[1].geom, 1, {flatbrickWidth}, arena, tiles, err));
  }
  CHECK(tiled == Approx(faceArea).epsilon(1e-9));
  REQUIRE(components(r.scope, r.geom, "sideedges", arena, edges, err));
  for (const Part& e : edges) {
    // roofedge ~> Subdiv("Y", a, b, 1r){ ε | roundbrick | Repeat("Y", ...){ roundbrick } }
    REQUIRE(subdivide(e.scope, e.geom, 1, {abs_(0.3), abs_(brickLength), rel(1)}, arena, segments,
                      err));
    CHECK(segments[2].geom.kind == GeomKind::Edge);
    REQUIRE(
        repeat(segments[2].scope, segments[2].geom, 2, {brickLength - overlap}, arena, tiles, err));
    CHECK(tiles.size() > 10);
  }
}

// Which triangles a quad or a triangle gives, index for index (the .glb's bytes follow
// them): a convex quad clips its first corner; a quad whose first corner is reflex, or
// whose first ear holds the opposite vertex, is cut along the other diagonal.
TEST_CASE("cga: ear clipping quads and triangles gives the exact triangles", "[cga]") {
  std::vector<uint32_t> tris;
  const auto clip = [&](const Polygon3& p) {
    tris.clear();
    earClip(p, tris);
    return tris;
  };
  using Tris = std::vector<uint32_t>;
  CHECK(clip({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)}) == Tris{3, 0, 1, 1, 2, 3});
  // A dart whose reflex corner (0.5, 1) is its last vertex, then the same dart with it first.
  CHECK(clip({Vec3(0, 0, 0), Vec3(2, 1, 0), Vec3(0, 2, 0), Vec3(0.5, 1, 0)}) == Tris{3, 0, 1, 1, 2, 3});
  CHECK(clip({Vec3(0.5, 1, 0), Vec3(0, 0, 0), Vec3(2, 1, 0), Vec3(0, 2, 0)}) == Tris{0, 1, 2, 0, 2, 3});
  // Vertex 2 lies inside the ear at vertex 0 (the triangle 3 0 1).
  CHECK(clip({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0.5, 0), Vec3(1, 2, 0)}) == Tris{0, 1, 2, 0, 2, 3});
  // Upright (in the YZ plane) and clockwise seen from +Z: each clipped about its own normal.
  CHECK(clip({Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 1), Vec3(0, 1, 0)}) == Tris{3, 0, 1, 1, 2, 3});
  CHECK(clip({Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(1, 0, 0)}) == Tris{3, 0, 1, 1, 2, 3});
  // A quad with a collinear corner first: that corner goes, one triangle stays.
  CHECK(clip({Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(1, 1, 0), Vec3(0, 0, 0)}) == Tris{1, 2, 3});
  CHECK(clip({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}) == Tris{0, 1, 2});
  CHECK(clip({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)}).empty());  // no area
}

TEST_CASE("cga: ear clipping a 2 000-corner comb covers it exactly", "[cga]") {
  // Issue 42: a comb-shaped lot's flat roof (500 teeth) took most of a minute to clip;
  // its speed is `bench_cga --earclip`'s (a timed check here failed under the sanitizers).
  Polygon3 comb = {Vec3(0, 0, 0), Vec3(1000, 0, 0)};
  const int h = 1000;
  for (int y = 1; y < h; ++y) {
    if (y % 2) comb.insert(comb.end(), {Vec3(1000, y, 0), Vec3(1, y, 0)});
    else comb.insert(comb.end(), {Vec3(1, y, 0), Vec3(1000, y, 0)});
  }
  comb.insert(comb.end(), {Vec3(1, h, 0), Vec3(0, h, 0)});
  std::vector<uint32_t> tris;
  earClip(comb, tris);
  REQUIRE(tris.size() == 3 * (comb.size() - 2));
  double area = 0;  // the comb: 1 x 1000 spine and 500 teeth of 999 x 1
  for (size_t t = 0; t < tris.size(); t += 3) {
    const Vec3 a = comb[tris[t]], b = comb[tris[t + 1]], c = comb[tris[t + 2]];
    const double doubled = (b - a).cross(c - a).z();
    CHECK(doubled > 0);
    area += doubled / 2;
  }
  CHECK(area == Approx(1000.0 + 500 * 999.0));
}
