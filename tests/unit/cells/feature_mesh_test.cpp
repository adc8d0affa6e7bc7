// The two-level base mesh of Legakis et al. 2001 §3 (feature_mesh.h) and its edge and
// face parameterisations (feature_param.h), on boxes, a stepped block, the procedural
// cylinder, sphere and plane, with counts computed by hand.
#include "runtime/cells/feature_mesh.h"
#include "runtime/cells/feature_param.h"
#include "runtime/surface/procedural.h"
#include "tests/unit/cells/rectilinear_mesh.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <algorithm>
#include <numbers>
#include <set>

using namespace fgsg::rt;
using namespace fgsg::rt::cells;
using surface::SurfaceMesh;

namespace {

constexpr double kPi = std::numbers::pi;

// The boundary of a union of unit cubes (cell (x, y, z) spans [x, x+1] x ...), each unit
// square split into n x n squares of two triangles, counter-clockwise from outside:
// rectilinearMesh over the grid of 1/n steps, every cube made of its n^3 small ones.
SurfaceMesh polycube(const std::set<std::array<int, 3>>& cells, int n) {
  int hi = 0;
  for (const auto& c : cells) hi = std::max({hi, c[0], c[1], c[2]});
  std::vector<double> steps;
  for (int i = 0; i <= (hi + 1) * n; ++i) steps.push_back(double(i) / n);
  std::set<std::array<int, 3>> small;
  for (const auto& c : cells)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k) small.insert({c[0] * n + i, c[1] * n + j, c[2] * n + k});
  return fgsg::test::rectilinearMesh({steps, steps, steps}, small, false);
}

int count(const FeatureMesh& fm, EdgeDirection d) {
  int k = 0;
  for (const auto& e : fm.edges) k += e.direction == d;
  return k;
}

}  // namespace

TEST_CASE("unit cube: 6 planar faces, 12 straight convex edges, 8 convex corners", "[cells]") {
  for (int n : {1, 3}) {  // 12 triangles, and subdivided: chains through flat vertices
    const SurfaceMesh m = polycube({{0, 0, 0}}, n);
    CHECK(m.faceCount() == size_t(12 * n * n));
    const FeatureMesh fm = buildFeatureMesh(m);
    REQUIRE(fm.faces.size() == 6);
    REQUIRE(fm.edges.size() == 12);
    REQUIRE(fm.corners.size() == 8);
    for (const auto& c : fm.corners) {
      CHECK(c.valence == 3);
      CHECK(c.kind == CornerKind::Convex);
      CHECK(c.faces.size() == 3);
    }
    CHECK(count(fm, EdgeDirection::Vertical) == 4);
    CHECK(count(fm, EdgeDirection::Horizontal) == 8);
    for (const auto& e : fm.edges) {
      CHECK(e.shape == EdgeShape::Line);
      CHECK(e.fold == EdgeFold::Convex);
      CHECK(e.length == Approx(1).epsilon(1e-12));
      CHECK(e.dihedralDegrees == Approx(90));
      CHECK(int(e.vertices.size()) == n + 1);
      CHECK(e.leftFace >= 0);
      CHECK(e.rightFace >= 0);
      CHECK(e.leftFace != e.rightFace);
      CHECK(e.startCorner >= 0);
      CHECK(e.endCorner >= 0);
    }
    std::set<std::array<int, 3>> normals;
    for (const auto& f : fm.faces) {
      CHECK(f.planar());
      CHECK(f.edges.size() == 4);
      CHECK(f.loops == 1);
      CHECK(f.area == Approx(1));
      CHECK(int(f.triangles.size()) == 2 * n * n);
      // Every triangle of the face has the face's normal, an axis direction.
      for (int t : f.triangles) CHECK((m.faceNormals[t] - f.normal).norm() < 1e-12);
      normals.insert({int(std::lround(f.normal.x())), int(std::lround(f.normal.y())), int(std::lround(f.normal.z()))});
    }
    CHECK(normals.size() == 6);
    // Deterministic order: faces by smallest triangle, corners by vertex.
    for (size_t i = 1; i < fm.faces.size(); ++i) CHECK(fm.faces[i - 1].triangles[0] < fm.faces[i].triangles[0]);
    for (size_t i = 1; i < fm.corners.size(); ++i) CHECK(fm.corners[i - 1].vertex < fm.corners[i].vertex);
    for (size_t i = 0; i < fm.corners.size(); ++i) CHECK(fm.cornerOfVertex[fm.corners[i].vertex] == int(i));
    for (size_t t = 0; t < m.faceCount(); ++t) CHECK(fm.faces[fm.faceOfTriangle[t]].normal.dot(m.faceNormals[t]) > 0.999);
  }
}

TEST_CASE("edge orientation: the left face is on the left seen from outside", "[cells]") {
  const SurfaceMesh m = polycube({{0, 0, 0}}, 2);
  const FeatureMesh fm = buildFeatureMesh(m);
  for (const auto& e : fm.edges) {
    const Vec3 t = (e.points.back() - e.points.front()).normalized();
    const Vec3 nl = fm.faces[e.leftFace].normal, nr = fm.faces[e.rightFace].normal;
    // Walking along t with the left face's normal up, that face is to the left: n x t
    // points into it, away from the right face (the edge is convex).
    CHECK(nl.cross(t).dot(nr) < -0.999);
  }
}

TEST_CASE("stepped block: 8 faces, 18 edges, 12 corners, one concave edge", "[cells]") {
  // Two cubes side by side, one on top of the left one: an L in the XZ plane, extruded
  // along Y. Each L side has 6 corners and 6 edges; 6 edges run along Y. The only
  // re-entrant edge is the one along Y at x = 1, z = 1.
  const SurfaceMesh m = polycube({{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, 2);
  const FeatureMesh fm = buildFeatureMesh(m);
  REQUIRE(fm.faces.size() == 8);
  REQUIRE(fm.edges.size() == 18);
  REQUIRE(fm.corners.size() == 12);
  int concave = 0;
  for (const auto& e : fm.edges) {
    CHECK(e.shape == EdgeShape::Line);
    if (e.fold != EdgeFold::Concave) continue;
    ++concave;
    CHECK(e.direction == EdgeDirection::Horizontal);
    CHECK(e.length == Approx(1));
    CHECK(e.dihedralDegrees == Approx(90));
    for (const Vec3& p : e.points) {
      CHECK(p.x() == Approx(1));
      CHECK(p.z() == Approx(1));
    }
  }
  CHECK(concave == 1);
  int mixed = 0;
  for (const auto& c : fm.corners) {
    CHECK(c.valence == 3);
    const Vec3 p = m.vertices[c.vertex];
    const bool reentrant = std::abs(p.x() - 1) < 1e-9 && std::abs(p.z() - 1) < 1e-9;
    CHECK(c.kind == (reentrant ? CornerKind::Mixed : CornerKind::Convex));
    mixed += c.kind == CornerKind::Mixed;
  }
  CHECK(mixed == 2);
  // The L-shaped sides are single concave faces of area 3 bounded by 6 edges.
  int lFaces = 0;
  for (const auto& f : fm.faces)
    if (std::abs(std::abs(f.normal.y()) - 1) < 1e-12) {
      ++lFaces;
      CHECK(f.planar());
      CHECK(f.area == Approx(3));
      CHECK(f.edges.size() == 6);
    }
  CHECK(lFaces == 2);
  // Vertical edges: 3 heights on each L side (x = 0: 2 tall, x = 1: 1, x = 2: 1).
  CHECK(count(fm, EdgeDirection::Vertical) == 6);
  CHECK(count(fm, EdgeDirection::Horizontal) == 12);
}

TEST_CASE("open cylinder: one cylindrical face, two boundary circles", "[cells]") {
  const double r = 1.5, h = 2;
  const SurfaceMesh m = surface::cylinder(r, h, 48);
  const FeatureMesh fm = buildFeatureMesh(m);
  REQUIRE(fm.faces.size() == 1);
  CHECK(fm.corners.empty());
  const FeatureFace& f = fm.faces[0];
  REQUIRE(f.kind == FaceKind::Cylindrical);
  CHECK(f.radius == Approx(r).epsilon(1e-9));
  CHECK(f.outward);
  CHECK((f.axis - Vec3::UnitZ()).norm() < 1e-9);
  CHECK(f.centre.z() == Approx(-h / 2));
  CHECK(f.loops == 2);
  REQUIRE(fm.edges.size() == 2);
  for (const auto& e : fm.edges) {
    CHECK(e.closed);
    CHECK(e.fold == EdgeFold::Boundary);
    CHECK(e.rightFace == -1);
    CHECK(e.leftFace == 0);
    REQUIRE(e.shape == EdgeShape::Arc);
    CHECK(e.direction == EdgeDirection::Curved);
    CHECK(std::abs(e.radius - r) < 1e-3 * r);
    CHECK(e.length == Approx(2 * kPi * r).epsilon(1e-9));
    CHECK(std::abs(std::abs(e.axis.z()) - 1) < 1e-9);
    for (double s : {0.0, 0.7, 3.1, 9.0}) {
      const EdgeFrame fr = edgeAt(e, s);
      CHECK(std::hypot(fr.point.x(), fr.point.y()) == Approx(r).epsilon(1e-9));
      CHECK(std::abs(fr.point.z()) == Approx(h / 2));
      CHECK(std::abs(fr.tangent.dot(fr.point - Vec3(0, 0, fr.point.z()))) < 1e-9);
      CHECK(std::abs(fr.tangent.norm() - 1) < 1e-12);
      // On a closed edge, s and s + length are the same point.
      const double d = std::abs(projectOnEdge(e, fr.point) - std::fmod(s, e.length));
      CHECK(std::min(d, e.length - d) < 1e-9);
    }
  }
  // (radius * angle, height) round trip and frame.
  const Vec2 q(0.4, 0.7);
  const FaceFrame fr = faceAt(f, q);
  CHECK(std::hypot(fr.point.x(), fr.point.y()) == Approx(r).epsilon(1e-12));
  CHECK(fr.point.z() == Approx(-h / 2 + 0.7));
  CHECK((projectOnFace(f, fr.point) - q).norm() < 1e-12);
  CHECK((fr.v - Vec3::UnitZ()).norm() < 1e-9);
  CHECK(fr.u.cross(fr.v).dot(fr.normal) == Approx(1));
  // A world point a quarter turn on: u grows by r * pi / 2.
  const Vec3 turned = Vec3(-fr.point.y(), fr.point.x(), fr.point.z());
  CHECK(projectOnFace(f, turned).x() == Approx(0.4 + r * kPi / 2));
}

TEST_CASE("a wall with a window: faces with holes, concave reveals", "[cells]") {
  // A 3 x 1 x 3 slab of cubes without the middle one: a square hole through it. Faces:
  // front and back (each with 2 loops), 4 outer sides, 4 reveals of the hole. Edges: 12
  // of the outer box, 4 round the hole on each side, 4 along the hole (concave).
  std::set<std::array<int, 3>> cells;
  for (int x = 0; x < 3; ++x)
    for (int z = 0; z < 3; ++z)
      if (x != 1 || z != 1) cells.insert({x, 0, z});
  const SurfaceMesh m = polycube(cells, 2);
  const FeatureMesh fm = buildFeatureMesh(m);
  REQUIRE(fm.faces.size() == 10);
  REQUIRE(fm.edges.size() == 24);
  REQUIRE(fm.corners.size() == 16);
  int holed = 0;
  for (const auto& f : fm.faces) {
    CHECK(f.planar());
    if (f.loops == 2) {
      ++holed;
      CHECK(std::abs(f.normal.y()) == Approx(1));
      CHECK(f.area == Approx(8));
      CHECK(f.edges.size() == 8);
    } else {
      CHECK(f.loops == 1);
    }
  }
  CHECK(holed == 2);
  int concave = 0, mixed = 0;
  for (const auto& e : fm.edges)
    if (e.fold == EdgeFold::Concave) {
      ++concave;
      CHECK(e.direction == EdgeDirection::Horizontal);  // along Y, through the wall
    }
  for (const auto& c : fm.corners) mixed += c.kind == CornerKind::Mixed;
  CHECK(concave == 4);
  CHECK(mixed == 8);
}

TEST_CASE("capped cylinder: convex circular rims between a cylinder and two discs", "[cells]") {
  const int segments = 32;
  SurfaceMesh m = surface::cylinder(1, 2, segments);
  const int rows = int(m.vertexCount()) / segments - 1;
  const int bottom = int(m.vertexCount()), top = bottom + 1;
  m.vertices.emplace_back(0, 0, -1);
  m.vertices.emplace_back(0, 0, 1);
  for (int i = 0; i < segments; ++i) {
    const int j = (i + 1) % segments;
    m.faces.push_back({bottom, j, i});  // seen from below: counter-clockwise
    m.faces.push_back({top, rows * segments + i, rows * segments + j});
  }
  m.buildTopology();
  const FeatureMesh fm = buildFeatureMesh(m);
  REQUIRE(fm.faces.size() == 3);
  REQUIRE(fm.edges.size() == 2);
  CHECK(fm.corners.empty());
  int caps = 0;
  for (const auto& f : fm.faces) {
    CHECK(f.loops == 1 + (f.kind == FaceKind::Cylindrical));
    if (f.planar()) {
      ++caps;
      CHECK(std::abs(f.normal.z()) == Approx(1));
      CHECK(f.area == Approx(segments * std::sin(2 * kPi / segments) / 2));
    } else {
      CHECK(f.kind == FaceKind::Cylindrical);
    }
  }
  CHECK(caps == 2);
  for (const auto& e : fm.edges) {
    CHECK(e.fold == EdgeFold::Convex);
    CHECK(e.shape == EdgeShape::Arc);
    CHECK(e.radius == Approx(1).epsilon(1e-9));
    CHECK(e.dihedralDegrees == Approx(90));
    CHECK(e.rightFace >= 0);
    // The outward normal at the rim bisects the cap and the side.
    const EdgeFrame fr = edgeAt(e, 1.0);
    const Vec3 radial = Vec3(fr.point.x(), fr.point.y(), 0).normalized();
    const Vec3 expect = (radial + Vec3(0, 0, fr.point.z() > 0 ? 1 : -1)).normalized();
    CHECK((fr.normal - expect).norm() < 0.1);  // the side's facets are 1/32 turn wide
  }
}

TEST_CASE("the inside of a cylinder is a cylindrical face facing its axis", "[cells]") {
  SurfaceMesh m = surface::cylinder(2, 1, 40);
  for (auto& t : m.faces) std::swap(t[1], t[2]);
  m.buildTopology();
  const FeatureMesh fm = buildFeatureMesh(m);
  REQUIRE(fm.faces.size() == 1);
  const FeatureFace& f = fm.faces[0];
  REQUIRE(f.kind == FaceKind::Cylindrical);
  CHECK_FALSE(f.outward);
  CHECK(f.radius == Approx(2).epsilon(1e-9));
  const FaceFrame fr = faceAt(f, Vec2(1, 0.5));
  CHECK(fr.normal.dot(Vec3(fr.point.x(), fr.point.y(), 0)) == Approx(-2));
  CHECK((projectOnFace(f, fr.point) - Vec2(1, 0.5)).norm() < 1e-12);
}

TEST_CASE("sphere: one freeform face, no edges, no corners", "[cells]") {
  const SurfaceMesh m = surface::sphere(1, 3);
  const FeatureMesh fm = buildFeatureMesh(m);
  REQUIRE(fm.faces.size() == 1);
  CHECK(fm.edges.empty());
  CHECK(fm.corners.empty());
  CHECK(fm.faces[0].kind == FaceKind::Freeform);
  CHECK(fm.faces[0].loops == 0);
  CHECK(fm.faces[0].triangles.size() == m.faceCount());
  CHECK_THROWS_AS(faceAt(fm.faces[0], Vec2(0, 0)), std::invalid_argument);
  CHECK_THROWS_AS(projectOnFace(fm.faces[0], Vec3(1, 0, 0)), std::invalid_argument);
}

TEST_CASE("plane: one horizontal face framed by X and Y, four boundary edges", "[cells]") {
  const SurfaceMesh m = surface::plane(2, 1, 8);
  const FeatureMesh fm = buildFeatureMesh(m);
  REQUIRE(fm.faces.size() == 1);
  REQUIRE(fm.edges.size() == 4);
  REQUIRE(fm.corners.size() == 4);
  for (const auto& c : fm.corners) {
    CHECK(c.kind == CornerKind::Boundary);
    CHECK(c.valence == 2);
  }
  double total = 0;
  for (const auto& e : fm.edges) {
    CHECK(e.fold == EdgeFold::Boundary);
    CHECK(e.direction == EdgeDirection::Horizontal);
    total += e.length;
  }
  CHECK(total == Approx(6));
  const FeatureFace& f = fm.faces[0];
  CHECK(f.planar());
  CHECK((f.uAxis - Vec3::UnitX()).norm() < 1e-12);
  CHECK((f.vAxis - Vec3::UnitY()).norm() < 1e-12);
  CHECK((f.origin - Vec3(-1, -0.5, 0)).norm() < 1e-12);
}

TEST_CASE("planar face parameterisation: walls have horizontal u and vertical v", "[cells]") {
  const SurfaceMesh m = polycube({{0, 0, 0}, {1, 0, 0}, {0, 0, 1}}, 1);
  const FeatureMesh fm = buildFeatureMesh(m);
  int walls = 0;
  for (const auto& f : fm.faces) {
    REQUIRE(f.planar());
    const bool wall = std::abs(f.normal.z()) < 1e-12;
    if (wall) {
      ++walls;
      CHECK(std::abs(f.uAxis.z()) < 1e-12);           // courses run horizontally
      CHECK((f.vAxis - Vec3::UnitZ()).norm() < 1e-12);  // v is world up
    }
    CHECK(f.uAxis.cross(f.vAxis).dot(f.normal) == Approx(1));
    // Round trips: param -> world -> param, and a world point on the face.
    for (const Vec2& q : {Vec2(0.3, 0.6), Vec2(1.7, 0.25), Vec2(-2, 5)}) {
      const FaceFrame fr = faceAt(f, q);
      CHECK((projectOnFace(f, fr.point) - q).norm() < 1e-12);
      CHECK(std::abs((fr.point - f.origin).dot(f.normal)) < 1e-12);
    }
    double umin = INFINITY, vmin = INFINITY;
    for (int t : f.triangles)
      for (int v : m.faces[t]) {
        const Vec3& p = m.vertices[v];
        const Vec2 q = projectOnFace(f, p);
        CHECK((faceAt(f, q).point - p).norm() < 1e-12);
        umin = std::min(umin, q.x());
        vmin = std::min(vmin, q.y());
      }
    CHECK(umin == Approx(0).margin(1e-12));
    CHECK(vmin == Approx(0).margin(1e-12));
  }
  CHECK(walls == 5);  // the two L sides, x = 0, x = 2 and the riser at x = 1
}

TEST_CASE("straight edge parameterisation: midpoint, projection, normal", "[cells]") {
  const SurfaceMesh m = polycube({{0, 0, 0}}, 4);
  const FeatureMesh fm = buildFeatureMesh(m);
  for (const auto& e : fm.edges) {
    const Vec3 a = e.points.front(), b = e.points.back();
    const EdgeFrame mid = edgeAt(e, e.length / 2);
    CHECK((mid.point - (a + b) / 2).norm() < 1e-12);
    CHECK((mid.tangent - (b - a).normalized()).norm() < 1e-12);
    // The outward normal bisects the two faces' normals.
    const Vec3 bis = (fm.faces[e.leftFace].normal + fm.faces[e.rightFace].normal).normalized();
    CHECK((mid.normal - bis).norm() < 1e-12);
    // A point off the edge projects to its foot; beyond the ends it clamps.
    const Vec3 off = a + 0.3 * (b - a) + 0.5 * mid.normal;
    CHECK(projectOnEdge(e, off) == Approx(0.3));
    CHECK(projectOnEdge(e, a - (b - a)) == 0);
    CHECK(projectOnEdge(e, b + (b - a)) == Approx(1));
    CHECK((edgeAt(e, 5).point - b).norm() < 1e-12);
  }
}

TEST_CASE("an arch: an open chain on a half circle is fitted as an arc", "[cells]") {
  // A semicircular arch of radius 2 in the XZ plane over (1, 0, 0), 12 segments.
  FeatureEdge e;
  const int n = 12;
  for (int i = 0; i <= n; ++i) {
    const double a = kPi * i / n;
    e.points.emplace_back(1 + 2 * std::cos(a), 0, 2 * std::sin(a));
  }
  e.segmentNormals.assign(n, Vec3(0, -1, 0));
  FeatureOptions o;
  fitEdge(e, o);
  REQUIRE(e.shape == EdgeShape::Arc);
  CHECK(e.direction == EdgeDirection::Curved);
  CHECK(e.radius == Approx(2).epsilon(1e-12));
  CHECK((e.centre - Vec3(1, 0, 0)).norm() < 1e-12);
  CHECK(e.length == Approx(2 * kPi));
  for (double s : {0.0, 1.0, kPi, 5.5, 2 * kPi}) {
    const EdgeFrame fr = edgeAt(e, s);
    CHECK((fr.point - Vec3(1, 0, 0)).norm() == Approx(2));
    CHECK(std::abs(fr.point.y()) < 1e-12);
    CHECK(projectOnEdge(e, fr.point) == Approx(s).margin(1e-12));
  }
  CHECK((edgeAt(e, kPi).point - Vec3(1, 0, 2)).norm() < 1e-12);  // the keystone
  CHECK((edgeAt(e, 0).tangent - Vec3(0, 0, 1)).norm() < 1e-12);
  // Below the springing line, the nearer end.
  CHECK(projectOnEdge(e, Vec3(3.5, 0, -1)) == 0);
  CHECK(projectOnEdge(e, Vec3(-1.5, 0, -1)) == Approx(2 * kPi));

  // A chain that wanders off the circle stays a polyline, parameterised by arc length.
  e.points[5].y() += 0.1;
  fitEdge(e, o);
  CHECK(e.shape == EdgeShape::Polyline);
  CHECK((edgeAt(e, 0).point - e.points[0]).norm() < 1e-12);
  CHECK(projectOnEdge(e, e.points[3]) == Approx((e.points[1] - e.points[0]).norm() * 3));
}

TEST_CASE("buildFeatureMesh rejects bad input", "[cells]") {
  SurfaceMesh empty;
  CHECK_THROWS_AS(buildFeatureMesh(empty), std::invalid_argument);
  SurfaceMesh raw;
  raw.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  raw.faces = {{0, 1, 2}};
  CHECK_THROWS_WITH(buildFeatureMesh(raw), Catch::Contains("buildTopology"));
  raw.buildTopology();
  CHECK_NOTHROW(buildFeatureMesh(raw));
  FeatureOptions o;
  o.creaseDegrees = 0;
  CHECK_THROWS_AS(buildFeatureMesh(raw, o), std::invalid_argument);
  o = {};
  o.creaseDegrees = NAN;
  CHECK_THROWS_AS(buildFeatureMesh(raw, o), std::invalid_argument);
  o = {};
  o.planarDegrees = 45;
  CHECK_THROWS_WITH(buildFeatureMesh(raw, o), Catch::Contains("planarDegrees"));
  o = {};
  o.up = Vec3::Zero();
  CHECK_THROWS_WITH(buildFeatureMesh(raw, o), Catch::Contains("up"));
  o = {};
  o.fitTolerance = 0;
  CHECK_THROWS_AS(buildFeatureMesh(raw, o), std::invalid_argument);
  o = {};
  o.directionDegrees = 50;
  CHECK_THROWS_AS(buildFeatureMesh(raw, o), std::invalid_argument);
  raw.faces[0][2] = 7;
  CHECK_THROWS_WITH(buildFeatureMesh(raw), Catch::Contains("vertex 7"));
}
