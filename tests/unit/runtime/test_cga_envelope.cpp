// CityEngine's envelope (issue #44; runtime/cga/envelope.cpp): solids over a 20 x 10 lot
// whose volumes, face areas and heights are worked out by hand in each case.
#include "runtime/cga/polygon_clip.h"
#include "runtime/cga/shape_operations.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace fgsg::rt;
using namespace fgsg::rt::cga;

namespace {

constexpr double kEnvelopeTol = 1e-9;

std::vector<Polygon3> envelopeWorldFaces(const Part& p, const GeometryArena& arena) {
  std::vector<Polygon3> out;
  for (uint32_t i = 0; i < p.geom.count; ++i) {
    const GeometryArena::Face& f = arena.face(p.geom, i);
    Polygon3 world;
    for (uint32_t k = 0; k < f.count; ++k) world.push_back(p.scope.toWorld(p.scope.S.cwiseProduct(arena.facePoints(f)[k])));
    out.push_back(world);
  }
  return out;
}

// Divergence theorem over the faces: the volume of a closed solid whose faces look out.
double envelopeVolume(const std::vector<Polygon3>& faces) {
  double v = 0.0;
  for (const Polygon3& f : faces) v += f[0].dot(0.5 * newellNormal(f)) / 3.0;
  return v;
}

double envelopeArea(const Polygon3& f) { return 0.5 * newellNormal(f).norm(); }

// Every edge of a closed solid is run once each way.
bool envelopeClosed(const std::vector<Polygon3>& faces) {
  std::vector<std::pair<Vec3, Vec3>> halfEdges;
  for (const Polygon3& f : faces)
    for (size_t i = 0; i < f.size(); ++i) halfEdges.emplace_back(f[i], f[(i + 1) % f.size()]);
  for (const auto& [a, b] : halfEdges) {
    int back = 0;
    for (const auto& [c, d] : halfEdges)
      if ((c - b).norm() < 1e-9 && (d - a).norm() < 1e-9) ++back;
    if (back != 1) return false;
  }
  return true;
}

struct EnvelopeLot {
  GeometryArena arena;
  Part lot;
  FlatPolygon polygon;
  explicit EnvelopeLot(const std::vector<Vec2>& corners) {
    std::string error;
    REQUIRE(footprint(Scope{}, corners, {}, arena, lot, error));
    REQUIRE(flatPolygon(lot.scope, lot.geom, arena, "test", polygon, error));
  }
  // Each edge's parameters chosen by the world midpoint (x, z) of the edge.
  std::vector<EnvelopeEdge> edges(const std::function<EnvelopeEdge(const Vec3&)>& byMidpoint) const {
    std::vector<EnvelopeEdge> out;
    const size_t n = polygon.ring.size();
    for (size_t i = 0; i < n; ++i) {
      const Vec2 m = 0.5 * (polygon.ring[i] + polygon.ring[(i + 1) % n]);
      out.push_back(byMidpoint(polygon.scope.P + polygon.scope.X() * m.x() + polygon.scope.Y() * m.y()));
    }
    return out;
  }
  bool run(double maxHeight, const std::vector<EnvelopeEdge>& e, Part& out, std::string& error, bool worldUp = false) {
    return envelope(lot.scope, lot.geom, polygon, worldUp, maxHeight, e, arena, out, error);
  }
};

const std::vector<Vec2> kEnvelopeRect{{0, 0}, {20, 0}, {20, 10}, {0, 10}};

}  // namespace

TEST_CASE("envelope with every edge at 45 degrees is the hipped solid, cut at maxHeight", "[envelope]") {
  EnvelopeLot lot(kEnvelopeRect);
  Part out;
  std::string error;
  const auto all45 = lot.edges([](const Vec3&) { return EnvelopeEdge{0, 45}; });
  SECTION("maxHeight above the ridge: D^2 (3W - D) / 12 = 100 * 50 / 12") {
    REQUIRE(lot.run(100, all45, out, error));
    const auto faces = envelopeWorldFaces(out, lot.arena);
    CHECK(faces.size() == 5);  // four slopes (no walls: every edge starts at 0), the bottom
    CHECK(envelopeClosed(faces));
    CHECK(envelopeVolume(faces) == Approx(5000.0 / 12).margin(kEnvelopeTol));
    CHECK(out.scope.S.y() == Approx(5).margin(kEnvelopeTol));  // the ridge at half the depth
    CHECK(out.scope.S.x() == Approx(20).margin(kEnvelopeTol));
    CHECK(out.scope.S.z() == Approx(10).margin(kEnvelopeTol));
    // The long slopes are trapezoids of 20 + 10 by 5 sqrt 2: 75 sqrt 2; the ends triangles 25 sqrt 2.
    double trapezoids = 0, triangles = 0;
    for (size_t i = 0; i + 1 < faces.size(); ++i)
      (faces[i].size() == 4 ? trapezoids : triangles) += envelopeArea(faces[i]);
    CHECK(trapezoids == Approx(150 * std::sqrt(2.0)).margin(1e-9));
    CHECK(triangles == Approx(50 * std::sqrt(2.0)).margin(1e-9));
    CHECK(envelopeArea(faces.back()) == Approx(200).margin(1e-9));
    CHECK(newellNormal(faces.back()).y() < 0);  // the bottom looks down
  }
  SECTION("maxHeight 3: the hip less the 14 x 4 hip above 3 m, 366 m3, a 56 m2 cap") {
    REQUIRE(lot.run(3, all45, out, error));
    const auto faces = envelopeWorldFaces(out, lot.arena);
    REQUIRE(faces.size() == 6);  // four slopes, the cap, the bottom
    CHECK(envelopeClosed(faces));
    CHECK(envelopeVolume(faces) == Approx(366).margin(kEnvelopeTol));
    CHECK(out.scope.S.y() == Approx(3).margin(kEnvelopeTol));
    const Polygon3& cap = faces[4];
    CHECK(envelopeArea(cap) == Approx(56).margin(1e-9));
    for (const Vec3& p : cap) CHECK(p.y() == Approx(3).margin(kEnvelopeTol));
    CHECK(newellNormal(cap).y() > 0);
  }
}

TEST_CASE("envelope with a sloped front and walls elsewhere", "[envelope]") {
  EnvelopeLot lot(kEnvelopeRect);
  Part out;
  std::string error;
  // The edge along z = 0 stands 6 m high and slopes back at 45 degrees; the others (0, 90)
  // are walls up to maxHeight 10: h = min(10, 6 + z), 20 * (24 + 8 + 60) = 1840 m3.
  const auto front = lot.edges([](const Vec3& m) { return std::abs(m.z()) < 1e-9 ? EnvelopeEdge{6, 45} : EnvelopeEdge{}; });
  REQUIRE(lot.run(10, front, out, error));
  const auto faces = envelopeWorldFaces(out, lot.arena);
  REQUIRE(faces.size() == 7);  // four walls, the slope, the cap, the bottom
  CHECK(envelopeClosed(faces));
  CHECK(envelopeVolume(faces) == Approx(1840).margin(kEnvelopeTol));
  std::vector<double> wallAreas;
  for (size_t i = 0; i < 4; ++i) {
    wallAreas.push_back(envelopeArea(faces[i]));
    CHECK(std::abs(newellNormal(faces[i]).y()) < 1e-9);  // upright
  }
  std::sort(wallAreas.begin(), wallAreas.end());
  // The sides: 4 m rising from 6 to 10 and 6 m at 10 (92 m2); the front 20 x 6; the back 20 x 10.
  CHECK(wallAreas[0] == Approx(92).margin(1e-9));
  CHECK(wallAreas[1] == Approx(92).margin(1e-9));
  CHECK(wallAreas[2] == Approx(120).margin(1e-9));
  CHECK(wallAreas[3] == Approx(200).margin(1e-9));
  CHECK(envelopeArea(faces[4]) == Approx(20 * 4 * std::sqrt(2.0)).margin(1e-9));  // the slope
  CHECK(envelopeArea(faces[5]) == Approx(120).margin(1e-9));                       // the cap, 20 x 6
  for (const Vec3& p : faces[5]) CHECK(p.y() == Approx(10).margin(kEnvelopeTol));
}

TEST_CASE("envelope: gable ends, flat planes and world.up", "[envelope]") {
  EnvelopeLot lot(kEnvelopeRect);
  Part out;
  std::string error;
  SECTION("the long edges at 45 degrees, the short ones walls: a gable solid of 20 * 10 * 5 / 2") {
    const auto gable =
        lot.edges([](const Vec3& m) { return std::abs(m.x() - 10) < 1e-9 ? EnvelopeEdge{0, 45} : EnvelopeEdge{0, 90}; });
    REQUIRE(lot.run(50, gable, out, error));
    const auto faces = envelopeWorldFaces(out, lot.arena);
    REQUIRE(faces.size() == 5);  // two gable triangles, two slopes, the bottom
    CHECK(envelopeClosed(faces));
    CHECK(envelopeVolume(faces) == Approx(500).margin(kEnvelopeTol));
    CHECK(faces[0].size() == 3);
    CHECK(envelopeArea(faces[0]) == Approx(25).margin(1e-9));
    CHECK(envelopeArea(faces[1]) == Approx(25).margin(1e-9));
  }
  SECTION("angle 0: every point at the base height, 200 * 4") {
    const auto flat = lot.edges([](const Vec3& m) { return std::abs(m.z()) < 1e-9 ? EnvelopeEdge{4, 0} : EnvelopeEdge{}; });
    REQUIRE(lot.run(10, flat, out, error));
    const auto faces = envelopeWorldFaces(out, lot.arena);
    CHECK(faces.size() == 6);  // four walls, the plane at 4 m, the bottom
    CHECK(envelopeClosed(faces));
    CHECK(envelopeVolume(faces) == Approx(800).margin(kEnvelopeTol));
    CHECK(out.scope.S.y() == Approx(4).margin(kEnvelopeTol));
  }
  SECTION("world.up on a lot is the normal's envelope") {
    const auto all45 = lot.edges([](const Vec3&) { return EnvelopeEdge{2, 30}; });
    Part up;
    REQUIRE(lot.run(8, all45, out, error));
    REQUIRE(lot.run(8, all45, up, error, true));
    const auto a = envelopeWorldFaces(out, lot.arena), b = envelopeWorldFaces(up, lot.arena);
    REQUIRE(a.size() == b.size());
    for (size_t i = 0; i < a.size(); ++i) {
      REQUIRE(a[i].size() == b[i].size());
      for (size_t k = 0; k < a[i].size(); ++k) CHECK((a[i][k] - b[i][k]).norm() < 1e-12);
    }
    // Walls of 2 m, then 30-degree planes: the ridge at 2 + 5 tan 30 < 8.
    CHECK(out.scope.S.y() == Approx(2 + 5 * std::tan(M_PI / 6)).margin(kEnvelopeTol));
  }
}

TEST_CASE("envelope by street side: front, back, side, right and left pairs", "[envelope]") {
  // Without street widths street.back / right / left are the scope's back / right / left.
  const std::vector<unsigned> classes{kEdgeFront | kEdgeStreetFront, kEdgeRight | kEdgeStreetRight,
                                      kEdgeBack | kEdgeStreetBack, kEdgeLeft | kEdgeStreetLeft, kEdgeFront};
  const double v[] = {1, 10, 2, 20, 3, 30, 4, 40};
  auto e = envelopeEdgesBySide(classes, v, 2);
  CHECK(e[0].baseHeight == 1);
  CHECK(e[0].angleDeg == 10);
  for (size_t i = 1; i < 5; ++i) CHECK((e[i].baseHeight == 0 && e[i].angleDeg == 90));
  e = envelopeEdgesBySide(classes, v, 4);
  CHECK(e[2].angleDeg == 20);
  CHECK(e[1].angleDeg == 90);
  e = envelopeEdgesBySide(classes, v, 6);  // side: right and left alike
  CHECK(e[1].angleDeg == 30);
  CHECK(e[3].angleDeg == 30);
  CHECK(e[4].angleDeg == 90);  // a front edge that is not the street's
  e = envelopeEdgesBySide(classes, v, 8);  // right, then left
  CHECK(e[1].angleDeg == 30);
  CHECK(e[3].angleDeg == 40);
  CHECK(e[3].baseHeight == 4);
}

TEST_CASE("envelope refuses what it cannot build", "[envelope]") {
  std::string error;
  Part out;
  EnvelopeLot lot(kEnvelopeRect);
  const auto ok = lot.edges([](const Vec3&) { return EnvelopeEdge{0, 45}; });
  CHECK_FALSE(lot.run(0, ok, out, error));
  CHECK(error.find("maxHeight") != std::string::npos);
  auto bad = ok;
  bad[1].baseHeight = -1;
  CHECK_FALSE(lot.run(10, bad, out, error));
  CHECK(error.find("edge 1") != std::string::npos);
  bad = ok;
  bad[2].angleDeg = 95;
  CHECK_FALSE(lot.run(10, bad, out, error));
  CHECK(error.find("between 0 and 90") != std::string::npos);
  const auto flat = lot.edges([](const Vec3&) { return EnvelopeEdge{0, 0}; });
  CHECK_FALSE(lot.run(10, flat, out, error));
  CHECK(error.find("no height") != std::string::npos);
  EnvelopeLot l({{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}});
  CHECK_FALSE(l.run(10, l.edges([](const Vec3&) { return EnvelopeEdge{0, 45}; }), out, error));
  CHECK(error.find("concave") != std::string::npos);
}
