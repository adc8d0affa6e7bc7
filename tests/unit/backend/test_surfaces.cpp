// Grammars on surfaces (FGSG §4.3): scopes stand on the surface, T traces along it (and
// along the first field), RS turns about the normal, field queries read the fields at
// the scope's point; on a flat surface everything is as on the plane.
#include "derive_helpers.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace fgsg;
using namespace fgsg::test;

namespace {

// FGSG Fig. 4, rules 1-4, as printed.
const std::string kFig4 = R"(
1: Axiom ~> P;
2: P ~> [ RZ(30) T(0.6, 0, 0) A ] [ RZ(150) T(0.6, 0, 0) A ] [ RZ(-90) T(0.6, 0, 0) A ];
3: A ~> B [ T(0.6, 0, 0) RZ(60) T(0.6, 0, 0) A ] [ T(0.6, 0, 0) RZ(-60) T(0.6, 0, 0) A ];
4: B ~> S(1.0, 1.0, 0.6) I("torus");
)";

rt::DeriveOptions depth(uint32_t d) {
  rt::DeriveOptions o;
  o.maxDepth = d;
  return o;
}

}  // namespace

TEST_CASE("On a flat surface a grammar grows exactly as on the plane", "[surface]") {
  auto plane = deriveText(kFig4, depth(7));
  auto flat = deriveText("surface plane(40, 40);\n" + kFig4, depth(7));
  REQUIRE(plane.ok);
  REQUIRE(flat.ok);
  // The flat surface's own mesh comes last.
  REQUIRE(flat.instances.instances.size() == plane.instances.instances.size() + 1);
  CHECK(flat.instances.assets[flat.instances.instances.back().asset] == "<surface>");
  for (size_t i = 0; i < plane.instances.instances.size(); ++i) {
    const auto& a = plane.instances.instances[i].transform;
    const auto& b = flat.instances.instances[i].transform;
    for (int k = 0; k < 16; ++k) CHECK(b[k] == Approx(a[k]).margin(1e-9));
  }
}

TEST_CASE("On a torus every shape stands on the surface, upright", "[surface]") {
  const double R = 2, r = 0.7;
  auto res = deriveText("surface torus(2, 0.7);\n" + kFig4, depth(9));
  REQUIRE(res.ok);
  size_t checked = 0;
  for (const auto& inst : res.instances.instances) {
    if (res.instances.symbols[inst.symbol] != "B") continue;
    const Eigen::Vector3d p = unitPoint(inst, 0, 0, 0);  // the scope's origin
    // Distance to the tube's centre circle is r, up to the mesh's polygonal sag.
    const double toAxis = std::hypot(p.x(), p.y());
    const double tube = std::hypot(toAxis - R, p.z());
    CHECK(tube == Approx(r).margin(0.01));
    // The scope's Z (the instance's third axis) is the outward normal of the tube.
    const Eigen::Vector3d z = (unitPoint(inst, 0, 0, 1) - p).normalized();
    const Eigen::Vector3d centre = R * Eigen::Vector3d(p.x(), p.y(), 0) / toAxis;
    CHECK(z.dot((p - centre).normalized()) > 0.99);
    ++checked;
  }
  CHECK(checked > 50);
}

TEST_CASE("T follows the first field and keeps the scope's angle to it", "[surface][field]") {
  // A regular field at 30 degrees on a flat surface: RS(F1.Xangle1) turns X onto it,
  // and T then moves along it.
  auto res = deriveText(R"(
surface plane(10, 10);
field F1 = design tensor { regular at (0, 0, 0) angle 30 decay 0.01; };
Axiom ~> RS(F1.Xangle1) T(2, 0, 0) A(F1.Xangle1, F1.value1)
A(x, v) ~> I("cube")
)");
  REQUIRE(res.ok);
  const auto& inst = res.instances.instances.at(0);
  const Eigen::Vector3d p = unitPoint(inst, 0, 0, 0);
  const double a = 30 * M_PI / 180;
  CHECK(p.x() == Approx(2 * std::cos(a)).margin(1e-6));
  CHECK(p.y() == Approx(2 * std::sin(a)).margin(1e-6));
  const double* params = res.instances.params.data() + inst.firstParam;
  CHECK(params[0] == Approx(0).margin(1e-6));  // aligned: the angle to the field is gone
  CHECK(params[1] > 0);
}

TEST_CASE("Curvature fields answer principal curvatures in guards", "[surface][field]") {
  auto res = deriveText(R"(
surface sphere(2);
field K = curvature;
Axiom ~> G(K.mincurv, K.maxcurv, K.gausscurv)
G(a, b, g) : a > 0.4 && b < 0.6 ~> I("cube")
G(a, b, g) ~> I("sphere")
)");
  REQUIRE(res.ok);
  REQUIRE(res.instances.instances.size() == 2);  // the glyph and the surface
  CHECK(res.instances.assets[res.instances.instances[0].asset] == "cube");
  const double* k = res.instances.params.data() + res.instances.instances[0].firstParam;
  CHECK(k[0] == Approx(0.5).epsilon(0.05));
  CHECK(k[1] == Approx(0.5).epsilon(0.05));
  CHECK(k[2] == Approx(0.25).epsilon(0.1));
}

TEST_CASE("Surface problems are errors at the declaration", "[surface][errors]") {
  auto missing = deriveText("surface \"no-such-mesh.off\";\nAxiom ~> I(\"cube\")");
  CHECK_FALSE(missing.ok);
  REQUIRE(missing.messages.size() == 1);
  CHECK(missing.messages[0].code == "R015");
  CHECK(missing.messages[0].line == 1);
  CHECK(missing.messages[0].message.find("no-such-mesh.off") != std::string::npos);
  // A curvature query of a designed field is caught before running (E025 at 4:12), not
  // at run time (R016); tests/cases/error_field_member_source has the other members.
  CHECK_THROWS_WITH(compileText(R"(
surface sphere(1);
field F = design tensor { regular at (1, 0, 0); };
Axiom ~> A(F.mincurv)
A(x) ~> I("cube")
)"),
                    Catch::Contains("test.fgsg:4:12: error[E025]: 'F.mincurv': curvatures are answered by a "
                                    "curvature field only"));
}

TEST_CASE("Design element points are in the surface's units after --surface-size", "[surface][field]") {
  // plane(2, 2) scaled to 4 spans -2..2. A source (node) at x = 1 in the scaled units
  // makes the field at x = 1.5 point along +X (Xangle 0); were the point read in the
  // mesh file's units it would sit at x = 2 and the field would point along -X (180).
  rt::DeriveOptions opt;
  opt.surfaceSize = 4;
  opt.hasStart = true;
  opt.start[0] = 1.5;
  opt.start[1] = 0;
  opt.start[2] = 0;
  auto res = deriveText(R"(
surface plane(2, 2);
field V = design vector { node at (1, 0, 0) decay 0.5; };
Axiom ~> A(V.Xangle1)
A(a) ~> I("cube")
)",
                        opt);
  REQUIRE(res.ok);
  const auto& inst = res.instances.instances.at(0);
  CHECK(unitPoint(inst, 0, 0, 0).x() == Approx(1.5).margin(1e-9));
  CHECK(res.instances.params[inst.firstParam] == Approx(0).margin(1e-6));
}

TEST_CASE("Geodesic centre distance measures along the surface", "[surface][collision]") {
  // On the unit sphere, 2.2 along a great circle is 1.78 straight through: closer than
  // 1.9 in space, farther along the surface.
  const std::string rules = R"(
Axiom ~> Size(0.01, 0.01, 0.01) I("cube") T(2.2, 0, 0) I("cube")
)";
  auto straight = deriveText("surface sphere(1);\ncollision all centre 1.9;\n" + rules);
  auto along = deriveText("surface sphere(1);\ncollision all geodesic 1.9;\n" + rules);
  REQUIRE(straight.ok);
  REQUIRE(along.ok);
  CHECK(straight.instances.instances.size() == 2);  // one cube and the sphere
  CHECK(straight.stats.collisions == 1);
  CHECK(along.instances.instances.size() == 3);
  CHECK(along.stats.collisions == 0);
  // And 1.7 along the surface does collide.
  auto near = deriveText("surface sphere(1);\ncollision all geodesic 1.9;\n"
                         "Axiom ~> Size(0.01, 0.01, 0.01) I(\"cube\") T(1.7, 0, 0) I(\"cube\")");
  CHECK(near.stats.collisions == 1);
}

TEST_CASE("IM merges by distance along the surface under collision geodesic", "[surface][collision]") {
  // Two small cubes 2.2 apart along a great circle of the unit sphere, 1.78 apart in
  // space: IM with maxDist 1.9 merges them straight, not along the surface.
  const std::string rules = R"(
Axiom ~> Size(0.01, 0.01, 0.01) IM("cube", 1.9, 180) T(2.2, 0, 0) IM("cube", 1.9, 180)
)";
  auto straight = deriveText("surface sphere(1);\ncollision centre 0.001;\n" + rules);
  auto along = deriveText("surface sphere(1);\ncollision geodesic 0.001;\n" + rules);
  REQUIRE(straight.ok);
  REQUIRE(along.ok);
  CHECK(straight.stats.merges == 1);
  CHECK(straight.instances.instances.size() == 2);  // the merged cube and the sphere
  CHECK(along.stats.merges == 0);
  CHECK(along.instances.instances.size() == 3);
  // 1.7 along the surface is within 1.9 either way.
  auto near = deriveText("surface sphere(1);\ncollision geodesic 0.001;\n"
                         "Axiom ~> Size(0.01, 0.01, 0.01) IM(\"cube\", 1.9, 180) T(1.7, 0, 0) IM(\"cube\", 1.9, 180)");
  CHECK(near.stats.merges == 1);
}
