// Roofs by height (CityEngine's roofHip(byHeight, h) ..., issue #44): the roof whose highest
// point stands h above the footprint, its planes at atan(h / t_max), t_max worked out by
// hand for each footprint; each compared with the angle form at that angle, face by face.
#include "runtime/cga/cga.h"
#include "runtime/cga/polygon_clip.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace fgsg::rt;
using namespace fgsg::rt::cga;

namespace {

constexpr double kByHeightTol = 1e-9;
constexpr double kByHeightPi = 3.14159265358979323846;

double degreesOfSlope(double rise, double run) { return std::atan(rise / run) * 180.0 / kByHeightPi; }

Scope byHeightBox(double sx, double sz) {
  Scope s;
  s.S = Vec3(sx, 0, sz);
  return s;
}

// Volume of a closed roof solid from its world faces (divergence theorem).
double byHeightVolume(const Part& p, const GeometryArena& arena) {
  double v = 0.0;
  for (const Polygon3& f : loadGeometry(arena, p.geom).faces) {
    Polygon3 world;
    for (const Vec3& q : f) world.push_back(p.scope.toWorld(p.scope.S.cwiseProduct(q)));
    v += world[0].dot(0.5 * newellNormal(world)) / 3.0;
  }
  return v;
}

// The two roofs are the same: scope, faces and their corners in order.
void requireSameRoof(const Part& a, const Part& b, const GeometryArena& arena) {
  CHECK((a.scope.P - b.scope.P).norm() <= kByHeightTol);
  CHECK((a.scope.S - b.scope.S).norm() <= kByHeightTol);
  CHECK((a.scope.axes - b.scope.axes).norm() <= kByHeightTol);
  const std::vector<Polygon3> fa = loadGeometry(arena, a.geom).faces, fb = loadGeometry(arena, b.geom).faces;
  REQUIRE(fa.size() == fb.size());
  for (size_t i = 0; i < fa.size(); ++i) {
    REQUIRE(fa[i].size() == fb[i].size());
    for (size_t k = 0; k < fa[i].size(); ++k) CHECK((fa[i][k] - fb[i][k]).norm() <= kByHeightTol);
  }
}

}  // namespace

TEST_CASE("roofs by height: the angle form at atan(h / t_max)", "[roof]") {
  GeometryArena arena;
  std::string err;
  Part byHeight, byAngle;
  SECTION("hipped on 10 x 6, h = 3: t_max = 3, 45 degrees") {
    REQUIRE(roofByHeight(byHeightBox(10, 6), GeomRef{}, "hipped", 3, arena, byHeight, err));
    CHECK(byHeight.scope.S.y() == Approx(3).margin(1e-12));
    REQUIRE(roof(byHeightBox(10, 6), GeomRef{}, "hipped", 45, arena, byAngle, err));
    requireSameRoof(byHeight, byAngle, arena);
    // Two trapezoids and two triangles under a 4 m ridge: 4 * 6 * 3 / 2 + 6 * 6 * 3 / 3.
    CHECK(byHeightVolume(byHeight, arena) == Approx(36 + 36).epsilon(1e-12));
  }
  SECTION("gable on 10 x 6, h = 2: atan(2 / 3)") {
    REQUIRE(roofByHeight(byHeightBox(10, 6), GeomRef{}, "gable", 2, arena, byHeight, err));
    CHECK(byHeight.scope.S.y() == Approx(2).margin(1e-12));
    CHECK(byHeightVolume(byHeight, arena) == Approx(10 * 6 * 2 / 2.0).epsilon(1e-12));
    REQUIRE(roof(byHeightBox(10, 6), GeomRef{}, "gable", degreesOfSlope(2, 3), arena, byAngle, err));
    requireSameRoof(byHeight, byAngle, arena);
  }
  SECTION("pyramid on 8 x 8, h = 4: 45 degrees") {
    REQUIRE(roofByHeight(byHeightBox(8, 8), GeomRef{}, "pyramid", 4, arena, byHeight, err));
    CHECK(byHeight.scope.S.y() == Approx(4).margin(1e-12));
    CHECK(byHeightVolume(byHeight, arena) == Approx(8 * 8 * 4 / 3.0).epsilon(1e-12));
    REQUIRE(roof(byHeightBox(8, 8), GeomRef{}, "pyramid", 45, arena, byAngle, err));
    requireSameRoof(byHeight, byAngle, arena);
  }
  SECTION("shed on 10 x 4 (depth 4 from edge 0), h = 2: atan(0.5)") {
    REQUIRE(roofByHeight(byHeightBox(10, 4), GeomRef{}, "shed", 2, arena, byHeight, err));
    CHECK(byHeight.scope.S.y() == Approx(2).margin(1e-12));
    CHECK(byHeightVolume(byHeight, arena) == Approx(10 * 4 * 2 / 2.0).epsilon(1e-12));
    REQUIRE(roof(byHeightBox(10, 4), GeomRef{}, "shed", degreesOfSlope(2, 4), arena, byAngle, err));
    requireSameRoof(byHeight, byAngle, arena);
    // From edge 1 (x = 10) the depth is 10: atan(0.2).
    REQUIRE(roofByHeight(byHeightBox(10, 4), GeomRef{}, "shed", 2, arena, byHeight, err, nullptr, RoofOptions{0, 0, 1}));
    CHECK(byHeight.scope.S.y() == Approx(2).margin(1e-12));
    REQUIRE(roof(byHeightBox(10, 4), GeomRef{}, "shed", degreesOfSlope(2, 10), arena, byAngle, err, nullptr,
                 RoofOptions{0, 0, 1}));
    requireSameRoof(byHeight, byAngle, arena);
  }
  SECTION("ridge on 10 x 6, h = 1.5: half the z extent 3, atan(0.5)") {
    REQUIRE(roofByHeight(byHeightBox(10, 6), GeomRef{}, "ridge", 1.5, arena, byHeight, err));
    CHECK(byHeight.scope.S.y() == Approx(1.5).margin(1e-12));
    CHECK(byHeightVolume(byHeight, arena) == Approx(10 * 6 * 1.5 / 2.0).epsilon(1e-12));
    REQUIRE(roof(byHeightBox(10, 6), GeomRef{}, "ridge", degreesOfSlope(1.5, 3), arena, byAngle, err));
    requireSameRoof(byHeight, byAngle, arena);
  }
  SECTION("hipped on an L with 4 m wide wings, h = 3: the skeleton's largest offset 2, atan(1.5)") {
    Part lot;
    REQUIRE(footprint(Scope{}, {{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}}, {}, arena, lot, err));
    REQUIRE(roofByHeight(lot.scope, lot.geom, "hipped", 3, arena, byHeight, err));
    CHECK(byHeight.scope.S.y() == Approx(3).margin(1e-12));
    REQUIRE(roof(lot.scope, lot.geom, "hipped", degreesOfSlope(3, 2), arena, byAngle, err));
    requireSameRoof(byHeight, byAngle, arena);
  }
  SECTION("overhangs keep the slope and the height above the footprint; the eaves hang below it") {
    REQUIRE(roofByHeight(byHeightBox(10, 6), GeomRef{}, "hipped", 3, arena, byHeight, err, nullptr, RoofOptions{1, 1, -1}));
    // 45 degrees: the eaves 1 m out on the slope, sin 45 below the footprint.
    CHECK(byHeight.scope.P.y() == Approx(-std::sqrt(0.5)).epsilon(1e-12));
    CHECK(byHeight.scope.S.y() == Approx(3 + std::sqrt(0.5)).epsilon(1e-12));
    REQUIRE(roof(byHeightBox(10, 6), GeomRef{}, "hipped", 45, arena, byAngle, err, nullptr, RoofOptions{1, 1, -1}));
    requireSameRoof(byHeight, byAngle, arena);
  }
}

TEST_CASE("roofs by height: errors", "[roof]") {
  GeometryArena arena;
  std::string err;
  Part r;
  for (const double h : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    INFO(h);
    err.clear();
    CHECK_FALSE(roofByHeight(byHeightBox(10, 6), GeomRef{}, "hipped", h, arena, r, err));
    CHECK(err.find("must be a number of metres more than 0") != std::string::npos);
  }
  // So high that atan(h / 3) rounds to 90 degrees: no roof plane is that steep.
  CHECK_FALSE(roofByHeight(byHeightBox(10, 6), GeomRef{}, "hipped", 1e300, arena, r, err));
  CHECK(err.find("is too great for a footprint whose roof planes meet 3 from its edges") != std::string::npos);
  CHECK_FALSE(roofByHeight(byHeightBox(0, 6), GeomRef{}, "gable", 2, arena, r, err));
  CHECK(err == "Roof: the footprint 0 x 6 has no area");
  CHECK_FALSE(roofByHeight(byHeightBox(10, 6), GeomRef{}, "mansard", 2, arena, r, err));
  CHECK(err == "Roof: unknown kind \"mansard\" (expected hipped, gable, pyramid, shed or ridge)");
  CHECK_FALSE(roofByHeight(byHeightBox(10, 6), GeomRef{}, "pyramid", 2, arena, r, err, nullptr, RoofOptions{1, 1, -1}));
  CHECK(err == "Roof: a pyramid roof has no overhang (hipped and gable roofs do)");
}
