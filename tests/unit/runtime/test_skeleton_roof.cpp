// Roofs on footprint polygons from the straight skeleton: volumes against closed formulas,
// slopes, watertightness and the errors.
#include "runtime/cga/skeleton_roof.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <utility>

using namespace fgsg::rt;
using namespace fgsg::rt::cga;

namespace {

constexpr double kTol = 1e-9;
constexpr double kPi = 3.14159265358979323846;

double slopeOf(double angleDeg) { return std::tan(angleDeg * kPi / 180.0); }

// Counter-clockwise seen from above (+Y): (0,0) (0,d) (w,d) (w,0) as (x, z).
std::vector<Vec2> rectangle(double w, double d) { return {{0, 0}, {0, d}, {w, d}, {w, 0}}; }

std::vector<Vec2> reversed(std::vector<Vec2> ring) { return {ring.rbegin(), ring.rend()}; }

// Legs 4 wide, 10 long; clockwise seen from above (the function reverses it).
const std::vector<Vec2> kLShape = {{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}};

struct Roof {
  std::vector<Polygon3> faces;
  std::vector<int> faceEdges;
  double height = 0.0;
};

Roof build(const std::vector<Vec2>& outer, const std::vector<std::vector<Vec2>>& holes,
           SkeletonRoofKind kind, double angleDeg) {
  Roof r;
  std::string error;
  const bool ok = skeletonRoof(outer, holes, kind, angleDeg, r.faces, r.height, error, &r.faceEdges);
  INFO(error);
  REQUIRE(ok);
  REQUIRE(r.faces.size() == r.faceEdges.size());
  return r;
}

std::string failure(const std::vector<Vec2>& outer, const std::vector<std::vector<Vec2>>& holes,
                    SkeletonRoofKind kind, double angleDeg) {
  std::vector<Polygon3> faces;
  double height = -1.0;
  std::string error;
  CHECK_FALSE(skeletonRoof(outer, holes, kind, angleDeg, faces, height, error));
  CHECK(error.rfind("Roof: ", 0) == 0);
  return error;
}

// Divergence theorem over the faces.
double volume(const std::vector<Polygon3>& faces) {
  double v = 0.0;
  for (const Polygon3& f : faces) v += f[0].dot(newellNormal(f)) / 6.0;
  return v;
}

Vec3 unitNormal(const Polygon3& f) { return newellNormal(f).normalized(); }

bool isPlanar(const Polygon3& f) {
  const Vec3 n = unitNormal(f);
  for (const Vec3& p : f)
    if (std::abs(n.dot(p - f[0])) > kTol) return false;
  return true;
}

// Welds points within kTol and requires every directed edge exactly once with its reverse
// exactly once: a closed, consistently oriented surface. A zero-width bridge of a face with
// holes is such a pair inside one face.
bool isClosedManifold(const std::vector<Polygon3>& faces) {
  std::vector<Vec3> points;
  auto id = [&](const Vec3& p) {
    for (std::size_t i = 0; i < points.size(); ++i)
      if ((points[i] - p).norm() <= kTol) return static_cast<int>(i);
    points.push_back(p);
    return static_cast<int>(points.size() - 1);
  };
  std::map<std::pair<int, int>, int> uses;
  for (const Polygon3& f : faces) {
    if (f.size() < 3) return false;
    for (std::size_t i = 0; i < f.size(); ++i) {
      const int a = id(f[i]), b = id(f[(i + 1) % f.size()]);
      if (a == b) return false;
      ++uses[{a, b}];
    }
  }
  for (const auto& [edge, count] : uses) {
    const auto back = uses.find({edge.second, edge.first});
    if (count != 1 || back == uses.end() || back->second != 1) return false;
  }
  return true;
}

bool isVertical(const Polygon3& f) { return std::abs(unitNormal(f).y()) <= kTol; }

bool tiltsBy(const Polygon3& f, double angleDeg) {
  return std::abs(std::acos(unitNormal(f).y()) - angleDeg * kPi / 180.0) <= kTol;
}

// The bottom comes last, faces down, at y = 0.
void checkBottom(const Roof& r) {
  const Polygon3& bottom = r.faces.back();
  CHECK(r.faceEdges.back() == -1);
  CHECK((unitNormal(bottom) - Vec3(0, -1, 0)).norm() <= kTol);
  for (const Vec3& p : bottom) CHECK(std::abs(p.y()) <= kTol);
}

int countVertical(const Roof& r) {
  int n = 0;
  for (std::size_t i = 0; i + 1 < r.faces.size(); ++i) n += isVertical(r.faces[i]);
  return n;
}

void checkSlopedFacesTilt(const Roof& r, double angleDeg) {
  for (std::size_t i = 0; i + 1 < r.faces.size(); ++i) {
    INFO("face " << i);
    CHECK(isPlanar(r.faces[i]));
    if (!isVertical(r.faces[i])) CHECK(tiltsBy(r.faces[i], angleDeg));
  }
}

bool contains(const Polygon3& f, const Vec3& p) {
  for (const Vec3& q : f)
    if ((q - p).norm() <= kTol) return true;
  return false;
}

}  // namespace

TEST_CASE("hipped roof on a rectangle has the formula height and volume", "[cga][roof]") {
  const double w = 10, d = 6, a = 30, h = d / 2 * slopeOf(a);
  const Roof r = build(rectangle(w, d), {}, SkeletonRoofKind::Hipped, a);
  REQUIRE(r.faces.size() == 5);
  CHECK(r.faceEdges == std::vector<int>{0, 1, 2, 3, -1});
  CHECK(r.height == Approx(h).epsilon(1e-12));
  CHECK(volume(r.faces) == Approx(d * h * (3 * w - d) / 6).epsilon(1e-12));
  CHECK(r.faces[0].size() == 3);  // the short edges get the hips' triangles
  CHECK(r.faces[1].size() == 4);
  CHECK(countVertical(r) == 0);
  checkSlopedFacesTilt(r, a);
  checkBottom(r);
  CHECK(isClosedManifold(r.faces));
}

TEST_CASE("roof faces start on their edge and face outwards", "[cga][roof]") {
  const Roof r = build(rectangle(10, 6), {}, SkeletonRoofKind::Hipped, 40);
  // Edge 0 runs (0,0) -> (0,6) along x = 0: its face starts there and faces -X and up.
  CHECK((r.faces[0][0] - Vec3(0, 0, 0)).norm() <= kTol);
  CHECK((r.faces[0][1] - Vec3(0, 0, 6)).norm() <= kTol);
  CHECK(unitNormal(r.faces[0]).x() < 0);
  CHECK(unitNormal(r.faces[0]).y() > 0);
  CHECK(unitNormal(r.faces[1]).z() > 0);  // edge 1 lies on z = 6
}

TEST_CASE("a clockwise footprint keeps its edge order", "[cga][roof]") {
  // Clockwise seen from above: edge 0 is (0,0)-(10,0) on z = 0, edge 1 is x = 10.
  const Roof r = build({{0, 0}, {10, 0}, {10, 6}, {0, 6}}, {}, SkeletonRoofKind::Hipped, 30);
  REQUIRE(r.faces.size() == 5);
  CHECK(contains(r.faces[0], Vec3(0, 0, 0)));
  CHECK(contains(r.faces[0], Vec3(10, 0, 0)));
  CHECK(unitNormal(r.faces[0]).z() < 0);
  CHECK(r.faces[1].size() == 3);
  CHECK(unitNormal(r.faces[1]).x() > 0);
  checkBottom(r);
  CHECK(isClosedManifold(r.faces));
}

TEST_CASE("hipped roof on a rotated rectangle tilts every face by the angle", "[cga][roof]") {
  const double w = 7, d = 3, a = 55, c = std::cos(0.4), s = std::sin(0.4);
  std::vector<Vec2> ring;
  for (const Vec2& p : rectangle(w, d)) ring.push_back(Vec2(c * p.x() - s * p.y() + 2, s * p.x() + c * p.y() - 1));
  const Roof r = build(ring, {}, SkeletonRoofKind::Hipped, a);
  const double h = d / 2 * slopeOf(a);
  CHECK(r.height == Approx(h).epsilon(1e-12));
  CHECK(volume(r.faces) == Approx(d * h * (3 * w - d) / 6).epsilon(1e-12));
  checkSlopedFacesTilt(r, a);
  checkBottom(r);
  CHECK(isClosedManifold(r.faces));
}

TEST_CASE("a point on a straight edge splits its face but not the roof", "[cga][roof]") {
  const double w = 10, d = 6, a = 30, h = d / 2 * slopeOf(a);
  const Roof r = build({{0, 0}, {0, 6}, {4, 6}, {10, 6}, {10, 0}}, {}, SkeletonRoofKind::Hipped, a);
  REQUIRE(r.faces.size() == 6);
  CHECK(volume(r.faces) == Approx(d * h * (3 * w - d) / 6).epsilon(1e-12));
  checkSlopedFacesTilt(r, a);
  CHECK(isClosedManifold(r.faces));
}

TEST_CASE("gable roof on a rectangle has vertical ends and half the box volume", "[cga][roof]") {
  const double w = 10, d = 6, a = 35, h = d / 2 * slopeOf(a);
  const Roof r = build(rectangle(w, d), {}, SkeletonRoofKind::Gable, a);
  REQUIRE(r.faces.size() == 5);
  CHECK(r.height == Approx(h).epsilon(1e-12));
  CHECK(volume(r.faces) == Approx(w * d * h / 2).epsilon(1e-12));
  // The short edges (0 and 2, on x = 0 and x = w) are the vertical triangular ends.
  CHECK(r.faces[0].size() == 3);
  CHECK(r.faces[2].size() == 3);
  CHECK(isVertical(r.faces[0]));
  CHECK(isVertical(r.faces[2]));
  CHECK(unitNormal(r.faces[0]).x() == Approx(-1).epsilon(1e-12));
  CHECK(unitNormal(r.faces[2]).x() == Approx(1).epsilon(1e-12));
  CHECK(countVertical(r) == 2);
  checkSlopedFacesTilt(r, a);
  checkBottom(r);
  CHECK(isClosedManifold(r.faces));
}

TEST_CASE("gable roof on a square runs its ridge along x", "[cga][roof]") {
  const double w = 8, a = 45, h = w / 2 * slopeOf(a);
  for (const auto& ring : {rectangle(w, w), reversed(rectangle(w, w))}) {
    const Roof r = build(ring, {}, SkeletonRoofKind::Gable, a);
    REQUIRE(r.faces.size() == 5);
    CHECK(volume(r.faces) == Approx(w * w * h / 2).epsilon(1e-12));
    CHECK(countVertical(r) == 2);
    for (std::size_t i = 0; i + 1 < r.faces.size(); ++i)
      if (isVertical(r.faces[i])) CHECK(std::abs(unitNormal(r.faces[i]).x()) == Approx(1).epsilon(1e-12));
    checkSlopedFacesTilt(r, a);
    CHECK(isClosedManifold(r.faces));
  }
}

TEST_CASE("gable roof on a rhombus gables one opposite pair", "[cga][roof]") {
  // Four triangles meet at the centre; the ridge joins the midpoints of the gabled edges.
  const Roof r = build({{0, 0}, {4, 2}, {8, 0}, {4, -2}}, {}, SkeletonRoofKind::Gable, 30);
  REQUIRE(r.faces.size() == 5);
  CHECK(countVertical(r) == 2);
  CHECK(isVertical(r.faces[0]) == isVertical(r.faces[2]));
  checkSlopedFacesTilt(r, 30);
  CHECK(isClosedManifold(r.faces));
}

TEST_CASE("gable roof on a tangential trapezoid gables the pair with the longer ridge", "[cga][roof]") {
  // Bases 8 (z = 0) and 2 (z = 4), legs 5: 8 + 2 = 5 + 5, so a circle of radius 2 about
  // (4, 2) touches all four sides and their four triangles meet there. The legs' gable tops
  // lie on the level ridge z = 2 between the parallel bases, at x = 6.5 and 1.5, 2 tan(a)
  // high: a ridge 5 long. The bases' tops lie on the symmetry line x = 4, 16 / 5 and 4 / 5
  // from the legs' lines, so 3.2 tan(a) and 0.8 tan(a) high: a ridge sqrt(16 + (2.4 tan a)^2)
  // long, 4.23 at 30 degrees. The legs (edges 1 and 3) become the gables.
  const double a = 30, s = slopeOf(a);
  const Roof r = build({{0, 0}, {8, 0}, {5, 4}, {3, 4}}, {}, SkeletonRoofKind::Gable, a);
  REQUIRE(r.faces.size() == 5);
  CHECK(r.height == Approx(2 * s).epsilon(1e-12));
  const Vec3 right(6.5, 2 * s, 2), left(1.5, 2 * s, 2);
  CHECK(isVertical(r.faces[1]));
  CHECK(isVertical(r.faces[3]));
  CHECK(countVertical(r) == 2);
  REQUIRE(r.faces[1].size() == 3);
  REQUIRE(r.faces[3].size() == 3);
  CHECK(contains(r.faces[1], Vec3(8, 0, 0)));
  CHECK(contains(r.faces[1], Vec3(5, 0, 4)));
  CHECK(contains(r.faces[1], right));
  CHECK(contains(r.faces[3], Vec3(3, 0, 4)));
  CHECK(contains(r.faces[3], Vec3(0, 0, 0)));
  CHECK(contains(r.faces[3], left));
  for (int e : {0, 2}) {
    INFO("face " << e);
    REQUIRE(r.faces[e].size() == 4);
    CHECK(contains(r.faces[e], right));
    CHECK(contains(r.faces[e], left));
  }
  CHECK(contains(r.faces[0], Vec3(0, 0, 0)));
  CHECK(contains(r.faces[0], Vec3(8, 0, 0)));
  CHECK(contains(r.faces[2], Vec3(5, 0, 4)));
  CHECK(contains(r.faces[2], Vec3(3, 0, 4)));
  checkSlopedFacesTilt(r, a);
  CHECK(isClosedManifold(r.faces));
}

TEST_CASE("gable roof on a trapezoid keeps its faces planar", "[cga][roof]") {
  // The long sides converge towards x = 0, so the ridge falls towards that gable.
  const Roof r = build({{0, 1}, {0, 3}, {12, 4}, {12, 0}}, {}, SkeletonRoofKind::Gable, 30);
  CHECK(countVertical(r) == 2);
  checkSlopedFacesTilt(r, 30);
  CHECK(isClosedManifold(r.faces));
  CHECK(volume(r.faces) > 0);
}

TEST_CASE("pyramid roof on a rectangle has a third of the box volume", "[cga][roof]") {
  const double w = 10, d = 6, a = 30, h = d / 2 * slopeOf(a);
  const Roof r = build(rectangle(w, d), {}, SkeletonRoofKind::Pyramid, a);
  REQUIRE(r.faces.size() == 5);
  CHECK(r.height == Approx(h).epsilon(1e-12));
  CHECK(volume(r.faces) == Approx(w * d * h / 3).epsilon(1e-12));
  CHECK(tiltsBy(r.faces[1], a));  // the long sides are nearest the apex
  CHECK(tiltsBy(r.faces[3], a));
  CHECK(unitNormal(r.faces[0]).y() > std::cos(a * kPi / 180));  // the short sides are flatter
  checkBottom(r);
  CHECK(isClosedManifold(r.faces));
}

TEST_CASE("shed roof on a rectangle rises from edge 0", "[cga][roof]") {
  const double w = 10, d = 6, a = 20, h = w * slopeOf(a);
  const Roof r = build(rectangle(w, d), {}, SkeletonRoofKind::Shed, a);
  REQUIRE(r.faces.size() == 5);  // the top (edge 0), the sides of edges 1-3, the bottom
  CHECK(r.faceEdges == std::vector<int>{0, 1, 2, 3, -1});
  CHECK(r.height == Approx(h).epsilon(1e-12));
  CHECK(volume(r.faces) == Approx(w * d * h / 2).epsilon(1e-12));
  CHECK(tiltsBy(r.faces[0], a));
  CHECK(unitNormal(r.faces[0]).x() < 0);  // the top faces back over edge 0
  for (int i = 1; i <= 3; ++i) CHECK(isVertical(r.faces[i]));
  CHECK(r.faces[1].size() == 3);
  CHECK(r.faces[2].size() == 4);
  checkBottom(r);
  CHECK(isClosedManifold(r.faces));
}

TEST_CASE("shed roof leaves out the sides of edges on the line of edge 0", "[cga][roof]") {
  const double a = 20, h = 10 * slopeOf(a);
  const Roof r = build({{0, 0}, {0, 3}, {0, 6}, {10, 6}, {10, 0}}, {}, SkeletonRoofKind::Shed, a);
  CHECK(r.faceEdges == std::vector<int>{0, 2, 3, 4, -1});
  CHECK(volume(r.faces) == Approx(10 * 6 * h / 2).epsilon(1e-12));
  CHECK(isClosedManifold(r.faces));
}

TEST_CASE("shed roof on a courtyard footprint is closed", "[cga][roof]") {
  const double a = 25;
  const Roof r = build(rectangle(10, 10), {{{3, 3}, {7, 3}, {7, 7}, {3, 7}}}, SkeletonRoofKind::Shed, a);
  REQUIRE(r.faces.size() == 9);
  // Height x * tan(a): the volume is tan(a) times the first moment of the ring's area.
  CHECK(volume(r.faces) == Approx((100 * 5 - 16 * 5) * slopeOf(a)).epsilon(1e-12));
  CHECK(r.height == Approx(10 * slopeOf(a)).epsilon(1e-12));
  checkBottom(r);
  CHECK(isClosedManifold(r.faces));
}

// Ridge roofs (CityEngine's roofRidge): the ridge along x over the middle of the footprint's
// z extent, heights t * (distance in z from the nearer eave line), t = tan(angle).
TEST_CASE("ridge roof on a rectangle runs along x whichever side is longer", "[cga][roof]") {
  const double a = 30, t = slopeOf(a);
  for (const auto& [w, d] : {std::pair{10.0, 6.0}, std::pair{6.0, 10.0}}) {
    const Roof r = build(rectangle(w, d), {}, SkeletonRoofKind::Ridge, a);
    // Two slopes, the gable triangles of edges 0 (x = 0) and 2 (x = w), the bottom; edges
    // 1 and 3 lie on the eave lines z = d and z = 0.
    REQUIRE(r.faces.size() == 5);
    CHECK(r.faceEdges == std::vector<int>{-2, -2, 0, 2, -1});
    CHECK(r.height == Approx(d / 2 * t).epsilon(1e-12));
    CHECK(volume(r.faces) == Approx(w * d * (d / 2 * t) / 2).epsilon(1e-12));
    CHECK(tiltsBy(r.faces[0], a));
    CHECK(tiltsBy(r.faces[1], a));
    CHECK(unitNormal(r.faces[0]).z() > 0);  // the first slope faces +z, over the greater z
    CHECK(newellNormal(r.faces[0]).norm() / 2 == Approx(w * d / 2 / std::cos(a * kPi / 180)).epsilon(1e-12));
    for (int i = 2; i <= 3; ++i) {
      CHECK(isVertical(r.faces[i]));
      CHECK(r.faces[i].size() == 3);
      CHECK(newellNormal(r.faces[i]).norm() / 2 == Approx(d * (d / 2 * t) / 2).epsilon(1e-12));
    }
    CHECK(contains(r.faces[0], Vec3(0, d / 2 * t, d / 2)));
    CHECK(contains(r.faces[0], Vec3(w, d / 2 * t, d / 2)));
    checkBottom(r);
    CHECK(isClosedManifold(r.faces));
  }
}

TEST_CASE("ridge roof on an L has one ridge and upright sides where the slopes stand over the outline",
          "[cga][roof]") {
  // kLShape spans z 0 .. 10: the ridge at z = 5, 5 t high. Volume: the integral of
  // t min(z, 10 - z) over the L, whose width is 10 for z < 4 and 4 above:
  // t (10 * 8 + 4 * 4.5 + 4 * 12.5) = 148 t.
  const double a = 30, t = slopeOf(a);
  const Roof r = build(kLShape, {}, SkeletonRoofKind::Ridge, a);
  REQUIRE(r.faces.size() == 7);
  // Edges 0 (z = 0) and 4 (z = 10) are on the eave lines; 1 (x = 10, z 0..4) a triangle,
  // 2 (z = 4) a 6 x 4t rectangle, 3 (x = 4, z 4..10) and 5 (x = 0) cross the ridge.
  CHECK(r.faceEdges == std::vector<int>{-2, -2, 1, 2, 3, 5, -1});
  CHECK(r.height == Approx(5 * t).epsilon(1e-12));
  CHECK(volume(r.faces) == Approx(148 * t).epsilon(1e-12));
  const double sideAreas[] = {8 * t, 24 * t, 17 * t, 25 * t};
  for (int i = 0; i < 4; ++i) {
    CHECK(isVertical(r.faces[2 + i]));
    CHECK(newellNormal(r.faces[2 + i]).norm() / 2 == Approx(sideAreas[i]).epsilon(1e-12));
  }
  CHECK(r.faces[4].size() == 4);  // edge 3: its end at z = 10 has no height
  const double c = std::cos(a * kPi / 180);
  CHECK(newellNormal(r.faces[0]).norm() / 2 == Approx(20 / c).epsilon(1e-12));  // z 5..10: 4 x 5
  CHECK(newellNormal(r.faces[1]).norm() / 2 == Approx(44 / c).epsilon(1e-12));  // z 0..5: 10 x 4 + 4 x 1
  checkSlopedFacesTilt(r, a);
  checkBottom(r);
  CHECK(isClosedManifold(r.faces));
  // An L whose inner edge (20, 9)-(9, 9) lies on the ridge line z = 9: under it an upright
  // 11 x 9t rectangle, no needle of the north slope along it. Volume t (20 + 9) * 40.5.
  const Roof onRidge = build({{0, 0}, {20, 0}, {20, 9}, {9, 9}, {9, 18}, {0, 18}}, {}, SkeletonRoofKind::Ridge, a);
  REQUIRE(onRidge.faces.size() == 7);
  CHECK(onRidge.faceEdges == std::vector<int>{-2, -2, 1, 2, 3, 5, -1});
  CHECK(volume(onRidge.faces) == Approx(29 * 40.5 * t).epsilon(1e-12));
  CHECK(onRidge.faces[0].size() == 4);  // the north slope: 9 x 9
  CHECK(newellNormal(onRidge.faces[0]).norm() / 2 == Approx(81 / c).epsilon(1e-12));
  CHECK(newellNormal(onRidge.faces[3]).norm() / 2 == Approx(99 * t).epsilon(1e-12));
  checkSlopedFacesTilt(onRidge, a);
  CHECK(isClosedManifold(onRidge.faces));
}

TEST_CASE("ridge roof on a courtyard footprint and on a U", "[cga][roof]") {
  const double a = 25, t = slopeOf(a);
  // The ring's volume: t (10 * 25 - 4 * 16) = 186 t; the hole's four edges all have sides.
  const Roof ring = build(rectangle(10, 10), {{{3, 3}, {7, 3}, {7, 7}, {3, 7}}}, SkeletonRoofKind::Ridge, a);
  REQUIRE(ring.faces.size() == 9);
  CHECK(volume(ring.faces) == Approx(186 * t).epsilon(1e-12));
  CHECK(ring.height == Approx(5 * t).epsilon(1e-12));
  checkSlopedFacesTilt(ring, a);
  checkBottom(ring);
  CHECK(isClosedManifold(ring.faces));
  // A U open towards z = 10: the ridge (z = 5) cuts its two legs apart, one slope polygon
  // joined by a bridge along the ridge. t (10 * 2 + 4 * 10.5 + 4 * 12.5) = 112 t.
  const std::vector<Vec2> u = {{0, 0}, {10, 0}, {10, 10}, {8, 10}, {8, 2}, {2, 2}, {2, 10}, {0, 10}};
  const Roof open = build(u, {}, SkeletonRoofKind::Ridge, a);
  REQUIRE(open.faces.size() == 8);
  CHECK(open.faceEdges == std::vector<int>{-2, -2, 1, 3, 4, 5, 7, -1});
  CHECK(volume(open.faces) == Approx(112 * t).epsilon(1e-12));
  checkSlopedFacesTilt(open, a);
  checkBottom(open);
  CHECK(isClosedManifold(open.faces));
}

TEST_CASE("hipped roof on an L has valleys and the formula volume", "[cga][roof]") {
  const double a = 30, t = slopeOf(a);
  const Roof r = build(kLShape, {}, SkeletonRoofKind::Hipped, a);
  REQUIRE(r.faces.size() == 7);
  CHECK(r.height == Approx(2 * t).epsilon(1e-12));
  // Integrating each face's distance to its edge over the face: 176/3.
  CHECK(volume(r.faces) == Approx(176.0 / 3.0 * t).epsilon(1e-12));
  CHECK(countVertical(r) == 0);
  checkSlopedFacesTilt(r, a);
  checkBottom(r);
  CHECK(isClosedManifold(r.faces));
}

TEST_CASE("gable roof on an L has gables at both leg ends", "[cga][roof]") {
  const double a = 30, t = slopeOf(a);
  const Roof r = build(kLShape, {}, SkeletonRoofKind::Gable, a);
  REQUIRE(r.faces.size() == 7);
  // The leg ends are edges 1 (x = 10) and 4 (z = 10).
  CHECK(countVertical(r) == 2);
  CHECK(isVertical(r.faces[1]));
  CHECK(isVertical(r.faces[4]));
  CHECK(r.height == Approx(2 * t).epsilon(1e-12));
  // Each gable adds d^2 h / 12 to the hipped volume (d = 4, h = 2 tan a).
  CHECK(volume(r.faces) == Approx((176.0 / 3.0 + 2 * 16.0 * 2.0 / 12.0) * t).epsilon(1e-12));
  checkSlopedFacesTilt(r, a);
  checkBottom(r);
  CHECK(isClosedManifold(r.faces));
}

TEST_CASE("gable roof on a T has gables at its three ends", "[cga][roof]") {
  const std::vector<Vec2> t = {{0, 0}, {14, 0}, {14, 4}, {9, 4}, {9, 12}, {5, 12}, {5, 4}, {0, 4}};
  const Roof r = build(t, {}, SkeletonRoofKind::Gable, 40);
  REQUIRE(r.faces.size() == 9);
  CHECK(countVertical(r) == 3);
  CHECK(isVertical(r.faces[1]));
  CHECK(isVertical(r.faces[4]));
  CHECK(isVertical(r.faces[7]));
  CHECK(r.height == Approx(2 * slopeOf(40)).epsilon(1e-12));
  checkSlopedFacesTilt(r, 40);
  CHECK(isClosedManifold(r.faces));
}

TEST_CASE("hipped roof on a courtyard footprint has the ring formula", "[cga][roof]") {
  // Ring width r = 3, mid-line square side m = 7: volume r^2 m tan(a), height r/2 tan(a).
  const double a = 30, t = slopeOf(a);
  const std::vector<Vec2> hole = {{3, 3}, {7, 3}, {7, 7}, {3, 7}};
  for (const auto& h : {hole, reversed(hole)}) {
    const Roof r = build(rectangle(10, 10), {h}, SkeletonRoofKind::Hipped, a);
    REQUIRE(r.faces.size() == 9);
    CHECK(r.faceEdges == std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, -1});
    CHECK(r.height == Approx(1.5 * t).epsilon(1e-12));
    CHECK(volume(r.faces) == Approx(9 * 7 * t).epsilon(1e-12));
    checkSlopedFacesTilt(r, a);
    for (int i = 4; i < 8; ++i) CHECK(unitNormal(r.faces[i]).y() > 0);
    checkBottom(r);
    CHECK(isClosedManifold(r.faces));
  }
}

TEST_CASE("gable roof on a courtyard footprint with two holes is closed", "[cga][roof]") {
  const Roof r = build(rectangle(20, 10), {{{3, 3}, {7, 3}, {7, 7}, {3, 7}}, {{12, 2}, {17, 2}, {17, 8}, {12, 8}}},
                       SkeletonRoofKind::Gable, 30);
  REQUIRE(r.faces.size() == 13);
  checkSlopedFacesTilt(r, 30);
  checkBottom(r);
  CHECK(isClosedManifold(r.faces));
  CHECK(volume(r.faces) > 0);
}

TEST_CASE("footprints the roof cannot stand on are errors", "[cga][roof]") {
  const std::vector<Vec2> square = rectangle(4, 4);
  CHECK(failure({{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}, SkeletonRoofKind::Hipped, 30).find("intersects itself") !=
        std::string::npos);
  CHECK(failure({{0, 0}, {2, 2}}, {}, SkeletonRoofKind::Hipped, 30).find("3 distinct points") != std::string::npos);
  CHECK(failure({{0, 0}, {3, 3}, {3, 0}, {0, 1}}, {}, SkeletonRoofKind::Hipped, 30).find("intersects itself") !=
        std::string::npos);
  CHECK(failure({{0, 0}, {1, 0}, {1, 1e-13}, {0, 0}}, {}, SkeletonRoofKind::Hipped, 30).find("3 distinct points") !=
        std::string::npos);
  CHECK(failure({{0, 0}, {1, 0}, {0.5, 1.5e-9}}, {}, SkeletonRoofKind::Hipped, 30).find("no area") !=
        std::string::npos);
  CHECK(failure({{0, 0}, {1, NAN}, {1, 1}}, {}, SkeletonRoofKind::Hipped, 30).find("non-finite") != std::string::npos);
  CHECK(failure(square, {{{5, 5}, {6, 5}, {6, 6}}}, SkeletonRoofKind::Hipped, 30).find("hole 0") != std::string::npos);
  CHECK(failure(square, {{{1, 1}, {5, 1}, {1, 3}}}, SkeletonRoofKind::Hipped, 30).find("hole 0") != std::string::npos);
}

TEST_CASE("angles outside the open range 0 to 90 are errors", "[cga][roof]") {
  for (double a : {0.0, 90.0, -10.0, 120.0, double(NAN)})
    CHECK(failure(rectangle(4, 3), {}, SkeletonRoofKind::Gable, a).find("angle") != std::string::npos);
}

TEST_CASE("pyramid and shed roofs reject footprints they cannot cover", "[cga][roof]") {
  const std::vector<Vec2> u = {{0, 0}, {10, 0}, {10, 10}, {8, 10}, {8, 2}, {2, 2}, {2, 10}, {0, 10}};
  CHECK(failure(u, {}, SkeletonRoofKind::Pyramid, 30).find("centroid") != std::string::npos);
  CHECK(failure(rectangle(10, 10), {{{3, 3}, {7, 3}, {7, 7}, {3, 7}}}, SkeletonRoofKind::Pyramid, 30)
            .find("holes") != std::string::npos);
  // Edge 0 of this L is the inner edge (10,4)-(4,4): the footprint lies on both sides.
  const std::vector<Vec2> l = {{10, 4}, {4, 4}, {4, 10}, {0, 10}, {0, 0}, {10, 0}};
  CHECK(failure(l, {}, SkeletonRoofKind::Shed, 30).find("edge 0") != std::string::npos);
}
