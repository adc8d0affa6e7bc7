// lpfg's and L-Py's generalized cylinders (@Gs, @Gc, @Ge; issue 48): the sweep itself in
// doubles, and the tube a derivation writes. Expected values worked by hand from the
// cubic Hermite pieces (end tangents: the headings, 1.2 times the chord long).
#include "backend/commands/generalized_cylinder.h"
#include "derive_helpers.h"

#include <catch2/catch.hpp>
#include <cmath>

using namespace fgsg;
using backend::CylinderControlPoint;
using Catch::Matchers::Contains;

namespace {

// The one tube a derivation drew (its mesh in world coordinates).
const rt::Mesh& tubeOf(const rt::DeriveResult& r) {
  REQUIRE(r.ok);
  const rt::Mesh* tube = nullptr;
  for (const auto& inst : r.instances.instances)
    if (inst.geometry != UINT32_MAX) {
      REQUIRE(tube == nullptr);
      REQUIRE(r.instances.symbols[inst.symbol] == "F");
      tube = &r.instances.geometries[inst.geometry];
      // Placed in world coordinates: the instance's box is the unit box.
      CHECK(test::transformOf(inst).isApprox(Eigen::Matrix4d::Identity()));
    }
  REQUIRE(tube != nullptr);
  return *tube;
}

Eigen::Vector3d vertex(const rt::Mesh& m, size_t v) {
  return {m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
}

Eigen::Vector3d ringCentre(const rt::Mesh& m, size_t ring, size_t sides) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (size_t j = 0; j < sides; ++j) c += vertex(m, ring * sides + j);
  return c / double(sides);
}

}  // namespace

TEST_CASE("a straight generalized cylinder: rings at the Hermite samples, all at the radius", "[lsystem][cylinder]") {
  // Two pieces of length 1 along +Y, 4 strips each: ring heights y(t) = 1.2 (h10 + h11) +
  // h01 on each piece: t = 1/4 gives 1.2 (0.140625 - 0.046875) + 0.15625 = 0.26875.
  const std::vector<double> heights = {0, 0.26875, 0.5, 0.73125, 1, 1.26875, 1.5, 1.73125, 2};
  std::vector<CylinderControlPoint> points = {{{0, 0, 0}, {0, 1, 0}, 0.15, 1},
                                              {{0, 1, 0}, {0, 1, 0}, 0.15, 4},
                                              {{0, 2, 0}, {0, 1, 0}, 0.15, 4}};
  const auto sweep = backend::sweepGeneralizedCylinder(points, {0, 0, 1}, 6);
  REQUIRE(sweep.rings == 9);
  REQUIRE(sweep.vertices.size() == 9 * 6);
  CHECK(sweep.triangles.size() == 3 * 2 * 6 * 8);
  for (size_t v = 0; v < sweep.vertices.size(); ++v) {
    const rt::Vec3 p = sweep.vertices[v];
    CHECK(std::hypot(p.x(), p.z()) == Approx(0.15).margin(1e-12));
    CHECK(p.y() == Approx(heights[v / 6]).margin(1e-12));
  }
  // The first ring's vertex 0 lies along the given up vector, the next turned about +Y.
  CHECK((sweep.vertices[0] - rt::Vec3(0, 0, 0.15)).norm() < 1e-12);
  CHECK((sweep.vertices[1] - rt::Vec3(0.15 * std::sin(M_PI / 3), 0, 0.15 * std::cos(M_PI / 3))).norm() < 1e-12);

  // The same through a derivation: width 0.3, `turtle sides 6`, no segment of its own.
  const auto r = test::deriveText("derive parallel 0;\nturtle width 0.3 sides 6;\n"
                                  "axiom: @Gs F(1) @Gc(4) F(1) @Ge(4);");
  const rt::Mesh& tube = tubeOf(r);
  CHECK(test::countAsset(r, "cylinder") == 0);
  REQUIRE(tube.vertexCount() == 9 * 6);
  CHECK(tube.triangleCount() == 2 * 6 * 8);
  for (size_t v = 0; v < tube.vertexCount(); ++v) {
    const Eigen::Vector3d p = vertex(tube, v);
    CHECK(std::hypot(p.x(), p.z()) == Approx(0.15).margin(1e-6));  // 32-bit floats
    CHECK(p.y() == Approx(heights[v / 6]).margin(1e-6));
  }
  // Normals face out, away from the axis.
  for (size_t v = 0; v < tube.vertexCount(); ++v)
    CHECK(tube.normals[3 * v] * tube.positions[3 * v] + tube.normals[3 * v + 2] * tube.positions[3 * v + 2] > 0);
}

TEST_CASE("a generalized cylinder bent through 90 degrees follows the Hermite curve", "[lsystem][cylinder]") {
  // @Gs F(1) @Gc +(90) F(1) @Ge(8): the second piece runs from (0, 1, 0) heading +Y to
  // (-1, 1, 0) heading -X (+ turns H towards L = -X), chord 1, tangents m0 = 1.2 Y and
  // m1 = -1.2 X. At t = 1/2: (P0 + P1) / 2 + (m0 - m1) / 8 = (-0.5, 1, 0) + 0.15 (1, 1, 0)
  // and the derivative 1.5 (P1 - P0) - (m0 + m1) / 4 = (-1.5 + 0.3, -0.3, 0).
  const Eigen::Vector3d middle(-0.35, 1.15, 0), direction(-1.2, -0.3, 0);
  const auto r = test::deriveText("derive parallel 0;\nturtle width 0.2 sides 8;\n"
                                  "axiom: @Gs F(1) @Gc +(90) F(1) @Ge(8);");
  const rt::Mesh& tube = tubeOf(r);
  REQUIRE(tube.vertexCount() == (1 + 1 + 8) * 8);
  const Eigen::Vector3d c = ringCentre(tube, 1 + 4, 8);
  CHECK((c - middle).norm() < 1e-6);
  for (size_t ring = 0; ring < 10; ++ring) {
    const Eigen::Vector3d centre = ringCentre(tube, ring, 8);
    for (size_t j = 0; j < 8; ++j) CHECK((vertex(tube, ring * 8 + j) - centre).norm() == Approx(0.1).margin(1e-6));
  }
  for (size_t j = 0; j < 8; ++j)  // the middle ring stands across the curve
    CHECK((vertex(tube, 5 * 8 + j) - middle).dot(direction.normalized()) == Approx(0).margin(1e-6));
  // The tube ends where the turtle ends, its last ring across -X.
  CHECK((ringCentre(tube, 9, 8) - Eigen::Vector3d(-1, 1, 0)).norm() < 1e-6);
  for (size_t j = 0; j < 8; ++j) CHECK(vertex(tube, 9 * 8 + j).x() == Approx(-1).margin(1e-6));

  // In doubles: every ring's vertices at the radius from the curve, to 1e-9.
  std::vector<CylinderControlPoint> points = {{{0, 1, 0}, {0, 1, 0}, 0.1, 1}, {{-1, 1, 0}, {-1, 0, 0}, 0.1, 8}};
  const auto sweep = backend::sweepGeneralizedCylinder(points, {0, 0, 1}, 8);
  REQUIRE(sweep.rings == 9);
  CHECK((sweep.centres[4] - middle).norm() < 1e-12);
  CHECK((sweep.tangents[4] - direction.normalized()).norm() < 1e-12);
  for (size_t v = 0; v < sweep.vertices.size(); ++v) {
    const rt::Vec3 d = sweep.vertices[v] - sweep.centres[v / 8];
    CHECK(d.norm() == Approx(0.1).margin(1e-9));
    CHECK(d.dot(sweep.tangents[v / 8]) == Approx(0).margin(1e-9));
  }
  // Parallel transport keeps +Z (square to the plane of the bend) as vertex 0's direction.
  for (size_t ring = 0; ring < 9; ++ring)
    CHECK((sweep.vertices[ring * 8] - sweep.centres[ring] - rt::Vec3(0, 0, 0.1)).norm() < 1e-12);
}

TEST_CASE("the radius follows the turtle's width from one control point to the next", "[lsystem][cylinder]") {
  const auto r = test::deriveText("derive parallel 0;\nturtle sides 4;\naxiom: !(0.2) @Gs F(1) !(0.6) @Ge(2);");
  const rt::Mesh& tube = tubeOf(r);
  REQUIRE(tube.vertexCount() == 3 * 4);
  const double radius[] = {0.1, 0.2, 0.3};  // linear in t: the middle ring at t = 1/2
  for (size_t v = 0; v < 12; ++v)
    CHECK(std::hypot(vertex(tube, v).x(), vertex(tube, v).z()) == Approx(radius[v / 4]).margin(1e-6));
}

TEST_CASE("L-Py's @Gc ... @Ge: each F a control point", "[lsystem][cylinder]") {
  // L-Py's form draws the tube lpfg's @Gs F @Gc F @Ge draws.
  const auto lpy = test::deriveText("derive parallel 0;\naxiom: @Gc F(1) +(30) F(2) @Ge;");
  const auto lpfg = test::deriveText("derive parallel 0;\naxiom: @Gs F(1) @Gc +(30) F(2) @Ge;");
  const rt::Mesh& a = tubeOf(lpy);
  const rt::Mesh& b = tubeOf(lpfg);
  REQUIRE(a.vertexCount() == 3 * 8);  // `turtle sides` 8 by default
  REQUIRE(b.vertexCount() == a.vertexCount());
  for (size_t i = 0; i < a.positions.size(); ++i) CHECK(a.positions[i] == Approx(b.positions[i]).margin(1e-6));
}

TEST_CASE("generalized cylinders in branches, and what draws nothing", "[lsystem][cylinder]") {
  // A branch inside the cylinder draws its own segment; the tube goes on after it.
  const auto r = test::deriveText("derive parallel 0;\naxiom: @Gs F(1) [ + F(1) ] @Gc F(1) @Ge;");
  CHECK(tubeOf(r).vertexCount() == 3 * 8);
  CHECK(test::countAsset(r, "cylinder") == 1);
  // Every control point in one place: nothing to draw, no error.
  const auto still = test::deriveText("derive parallel 0;\naxiom: @Gs @Gc(3) @Ge(2) F;");
  REQUIRE(still.ok);
  CHECK(still.instances.geometries.empty());
  CHECK(test::countAsset(still, "cylinder") == 1);
}

TEST_CASE("degenerate generalized cylinders: no NaN", "[lsystem][cylinder]") {
  // A zero-length piece adds no ring; a 180-degree turn makes a cusp the frame passes.
  for (const char* axiom : {"@Gs F(0) @Gc F(1) @Ge(3)", "@Gs F(1) @Gc(2) | F(1) @Ge(8)",
                            "@Gs F(1) @Gc(2) | @Ge(4)", "@Gs F(1) | F(1) @Gc(5) F(1) @Ge(5)"}) {
    INFO(axiom);
    const auto r = test::deriveText(std::string("derive parallel 0;\naxiom: ") + axiom + ";");
    const rt::Mesh& tube = tubeOf(r);
    CHECK(tube.vertexCount() > 0);
    for (float x : tube.positions) CHECK(std::isfinite(x));
    for (float x : tube.normals) CHECK(std::isfinite(x));
  }
  // A turn right round at one point: the cusp ring and its neighbours keep the radius.
  std::vector<CylinderControlPoint> points = {{{0, 0, 0}, {0, 1, 0}, 0.05, 1}, {{0, 1, 0}, {0, -1, 0}, 0.05, 4}};
  const auto sweep = backend::sweepGeneralizedCylinder(points, {0, 0, 1}, 5);
  REQUIRE(sweep.rings == 5);
  for (size_t v = 0; v < sweep.vertices.size(); ++v) {
    REQUIRE(sweep.vertices[v].allFinite());
    CHECK((sweep.vertices[v] - sweep.centres[v / 5]).norm() == Approx(0.05).margin(1e-12));
  }
}

TEST_CASE("generalized cylinder errors and warnings are located", "[lsystem][cylinder]") {
  const auto unended = test::deriveText("derive parallel 0;\naxiom: F [ @Gs F ] F;");
  REQUIRE(unended.ok);
  REQUIRE(unended.messages.size() == 1);
  CHECK(unended.messages[0].code == "R032");
  CHECK_FALSE(unended.messages[0].isError);
  CHECK(unended.messages[0].line == 2);
  CHECK(unended.messages[0].col == 12);
  CHECK(unended.instances.geometries.empty());
  CHECK(test::countAsset(unended, "cylinder") == 2);  // the two F outside; the branch's F is the tube's

  const auto lone = test::deriveText("derive parallel 0;\naxiom: F @Ge;");
  REQUIRE_FALSE(lone.ok);
  CHECK(lone.messages[0].code == "R027");
  CHECK(lone.messages[0].col == 10);
  // @Ge in a branch inside the cylinder is not the cylinder's.
  const auto inner = test::deriveText("derive parallel 0;\naxiom: @Gs F [ F @Ge ];");
  REQUIRE_FALSE(inner.ok);
  CHECK_THAT(inner.messages[0].message, Contains("in this branch"));
  const auto twice = test::deriveText("derive parallel 0;\naxiom: @Gs F @Gs F @Ge;");
  REQUIRE_FALSE(twice.ok);
  CHECK_THAT(twice.messages[0].message, Contains("line 2:8"));
  const auto strips = test::deriveText("derive parallel 0;\naxiom: @Gs F @Ge(0.5);");
  REQUIRE_FALSE(strips.ok);
  CHECK_THAT(strips.messages[0].message, Contains("whole number"));
  const auto point = test::deriveText("derive parallel 0;\naxiom: F @Gc(3) F @Ge;");
  REQUIRE_FALSE(point.ok);
  CHECK_THAT(point.messages[0].message, Contains("@Gs"));
}
