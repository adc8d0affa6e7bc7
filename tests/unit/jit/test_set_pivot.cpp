// CityEngine's setPivot(axisMap, cornerIndex) (issue #44; docs/cga.md): the pivot at a
// corner of the scope, its axes in the order named and pointing into the scope, the scope
// made that frame, and translate / rotate in `pivot` then using it, in this shape and the
// shapes it creates. Both dialects, the interpreter and the JIT bit for bit, against
// values worked out by hand (in the comments) on a lot turned by 53.13 degrees (cos 0.6,
// sin 0.8) and moved away from the origin, so that the pivot, object and world differ.
#include "turned_lot_leaves.h"

#include <catch2/catch.hpp>

#include <map>
#include <sstream>
#include <string>

namespace {

using namespace fgsg;
using PivotV = Eigen::Vector3d;

// The turned lot (turned_lot_leaves.h): the `.cga` lot's scope starts at (2, 0, -26) with
// x (0.6, 0, -0.8), y up, z (0.8, 0, 0.6), extruded to 5 x 2 x 10.
using PivotLeaf = turned_lot::Leaf;
using turned_lot::deriveBothEngines;

bool pivotNear(const PivotV& a, const PivotV& b, double tolerance = 1e-12) {
  return (a - b).cwiseAbs().maxCoeff() <= tolerance;
}

// The leaf's scope is (P; X, Y, Z) with size S, and its geometry's corners are exactly
// `corners` (each one of them, all of them), to 1e-5 m for a mesh (its coordinates are
// floats in the scope's unit box) and 1e-12 for a box.
void checkPivotLeaf(const std::map<std::string, PivotLeaf>& leaves, const std::string& symbol, const PivotV& P,
                    const PivotV& X, const PivotV& Y, const PivotV& Z, const PivotV& S,
                    const std::vector<PivotV>& corners, double cornerTolerance = 1e-5) {
  INFO("leaf " << symbol);
  REQUIRE(leaves.count(symbol) == 1);
  const PivotLeaf& l = leaves.at(symbol);
  INFO("P " << l.P.transpose() << " X " << l.X.transpose() << " Y " << l.Y.transpose() << " Z " << l.Z.transpose()
            << " S " << l.S.transpose());
  CHECK(pivotNear(l.P, P));
  CHECK(pivotNear(l.X, X));
  CHECK(pivotNear(l.Y, Y));
  CHECK(pivotNear(l.Z, Z));
  CHECK(pivotNear(l.S, S));
  for (const PivotV& c : l.corners) {
    bool found = false;
    for (const PivotV& e : corners) found = found || pivotNear(c, e, cornerTolerance);
    INFO("corner " << c.transpose());
    CHECK(found);
  }
  for (const PivotV& e : corners) {
    bool found = false;
    for (const PivotV& c : l.corners) found = found || pivotNear(c, e, cornerTolerance);
    INFO("expected corner " << e.transpose());
    CHECK(found);
  }
}

// The extruded lot's eight corners, moved by `by`.
std::vector<PivotV> pivotLotCorners(const PivotV& by = PivotV::Zero()) {
  std::vector<PivotV> out;
  for (double h : {0.0, 2.0})
    for (const PivotV& c : {PivotV(10, 0, -20), PivotV(13, 0, -24), PivotV(5, 0, -30), PivotV(2, 0, -26)})
      out.push_back(c + PivotV(0, h, 0) + by);
  return out;
}

// The corners of the box at P with edges S.x X, S.y Y, S.z Z.
std::vector<PivotV> pivotBoxCorners(const PivotV& P, const PivotV& X, const PivotV& Y, const PivotV& Z,
                                    const PivotV& S) {
  std::vector<PivotV> out;
  for (int k = 0; k < 8; ++k) out.push_back(P + S.x() * (k & 1) * X + S.y() * ((k >> 1) & 1) * Y + S.z() * (k >> 2) * Z);
  return out;
}

}  // namespace

TEST_CASE("cga setPivot puts the pivot at a scope corner and translate and rotate use it", "[cga][setPivot]") {
  const auto leaves = deriveBothEngines(R"(@StartRule
Lot --> extrude(2) setPivot(yzx, 2) A
A --> [ Here ]
      [ translate(rel, pivot, 1, 2, 3) MovedRel ]
      [ rotate(rel, pivot, 90, 0, 0) TurnedRel ]
      [ translate(abs, object, 1, 2, 3) ObjectAbs ]
      [ comp(f) { top : rotate(abs, pivot, 0, 0, 0) translate(abs, pivot, 0, 0, 0) TopAtPivot } ]
      split(x) { 4 : B | ~1 : C }
C --> [ translate(abs, pivot, 1, 2, 3) ChildAbs ]
      [ translate(rel, pivot, 1, 2, 3) ChildRel ]
      [ rotate(abs, pivot, 0, 90, 0) ChildTurned ]
      CPlain
)",
                                             "test.cga");
  // Corner 2 is the scope's (1, 0, 1): (2, 0, -26) + 5 (0.6, 0, -0.8) + 10 (0.8, 0, 0.6) =
  // (13, 0, -24), the lot's second corner. It lies at the far end of the scope's x and z,
  // so they point in reversed. yzx: the pivot's x along the scope's z, y along x, z along y:
  // X' = -(0.8, 0, 0.6), Y' = -(0.6, 0, -0.8), Z' = (0, 1, 0) (X' x Y' = Z': right-handed as
  // it is). The scope becomes that frame around the same box: size (sz, sx, sy) = (10, 5, 2).
  const PivotV P1(13, 0, -24), X1(-0.8, 0, -0.6), Y1(-0.6, 0, 0.8), Z1(0, 1, 0), S1(10, 5, 2);
  checkPivotLeaf(leaves, "Here", P1, X1, Y1, Z1, S1, pivotLotCorners());
  // rel in the pivot's axes: X' + 2 Y' + 3 Z' = (-2, 3, 1), so the origin goes to (11, 3, -23)
  // and every corner of the geometry moves by (-2, 3, 1).
  checkPivotLeaf(leaves, "MovedRel", PivotV(11, 3, -23), X1, Y1, Z1, S1, pivotLotCorners(PivotV(-2, 3, 1)));
  // A quarter turn about the pivot's x: (X', Y', Z') -> (X', Z', -Y'), about the origin.
  const std::vector<PivotV> turnedCorners =
      pivotBoxCorners(P1, X1, Z1, -Y1, S1);  // the box (the lot is a rectangle) turned with the scope
  checkPivotLeaf(leaves, "TurnedRel", P1, X1, Z1, -Y1, S1, turnedCorners);
  // The object system is still the lot's: (10, 0, -20) + 1 (0.6, 0, -0.8) + 2 (0, 1, 0) +
  // 3 (0.8, 0, 0.6) = (13, 2, -19).
  checkPivotLeaf(leaves, "ObjectAbs", PivotV(13, 2, -19), X1, Y1, Z1, S1, pivotLotCorners(PivotV(0, 2, 5)));
  // A comp face keeps the pivot too: turned to the pivot's axes and moved to its origin.
  {
    REQUIRE(leaves.count("TopAtPivot") == 1);
    const PivotLeaf& top = leaves.at("TopAtPivot");
    INFO("TopAtPivot P " << top.P.transpose() << " X " << top.X.transpose() << " Y " << top.Y.transpose());
    CHECK(pivotNear(top.P, P1));
    CHECK(pivotNear(top.X, X1));
    CHECK(pivotNear(top.Y, Y1));
  }
  // C: the part of the split from 4 m along X' on: origin (13, 0, -24) + 4 X' =
  // (9.8, 0, -26.4), size 6 x 5 x 2. It keeps the pivot: abs puts its origin at the pivot's
  // (1, 2, 3), (11, 3, -23), not at C's own origin moved.
  const PivotV PC(9.8, 0, -26.4), SC(6, 5, 2);
  checkPivotLeaf(leaves, "CPlain", PC, X1, Y1, Z1, SC, pivotBoxCorners(PC, X1, Y1, Z1, SC));
  checkPivotLeaf(leaves, "ChildAbs", PivotV(11, 3, -23), X1, Y1, Z1, SC,
                 pivotBoxCorners(PivotV(11, 3, -23), X1, Y1, Z1, SC));
  checkPivotLeaf(leaves, "ChildRel", PivotV(7.8, 3, -25.4), X1, Y1, Z1, SC,
                 pivotBoxCorners(PivotV(7.8, 3, -25.4), X1, Y1, Z1, SC));
  // abs turn: the pivot's axes turned by Ry(90): e1 -> -e3, e3 -> e1, so (-Z', Y', X').
  checkPivotLeaf(leaves, "ChildTurned", PC, -Z1, Y1, X1, SC, pivotBoxCorners(PC, -Z1, Y1, X1, SC));
}

TEST_CASE("fgsg SetPivot on a box: each axis order and a corner that swaps x and z", "[cga][setPivot]") {
  // Without lots the axiom is the unit box at the origin (the object system is the world's).
  const auto leaves = deriveBothEngines(R"(
Start ~> [ S(4, 3, 2) SetPivot("xyz", 1) Corner1 ]
         [ S(4, 3, 2) T(1, 2, 3) R(0, 90, 0) SetPivot("zxy", 5) Turned ]
         [ S(4, 3, 2) T(1, 2, 3) R(0, 90, 0) SetPivot("zxy", 5) Translate("rel", "pivot", 1, 2, 3) Moved ]
         [ S(4, 3, 2) T(1, 2, 3) R(0, 90, 0) SetPivot("zxy", 5) Rotate("rel", "pivot", 0, 0, 90) Spun ]
         [ S(4, 3, 2) SetPivot("yzx", 0) T(1, 1, 1) Child ];
Child ~> Translate("abs", "pivot", 0, 0, 0) Back;
)",
                                             "test.fgsg", false);
  // Corner 1 is (4, 0, 0): x points in reversed, so (-X, Y, Z) would be left-handed; x and
  // z swap: X' = Z = (0, 0, 1), Y' = (0, 1, 0), Z' = -X = (-1, 0, 0), size (2, 3, 4).
  checkPivotLeaf(leaves, "Corner1", PivotV(4, 0, 0), PivotV(0, 0, 1), PivotV(0, 1, 0), PivotV(-1, 0, 0),
                 PivotV(2, 3, 4), pivotBoxCorners(PivotV(0, 0, 0), PivotV(1, 0, 0), PivotV(0, 1, 0), PivotV(0, 0, 1),
                                                  PivotV(4, 3, 2)),
                 1e-12);
  // R(0, 90, 0) at (1, 2, 3): X = (0, 0, -1), Y = (0, 1, 0), Z = (1, 0, 0). Corner 5 is
  // (1, 1, 0): P + 4 X + 3 Y = (1, 5, -1); x and y point in reversed. zxy: x along -Y,
  // y along +Z, z along -X: (0, -1, 0), (1, 0, 0), (0, 0, 1) (right-handed), size
  // (sy, sz, sx) = (3, 2, 4).
  const PivotV P5(1, 5, -1), X5(0, -1, 0), Y5(1, 0, 0), Z5(0, 0, 1), S5(3, 2, 4);
  const std::vector<PivotV> box5 =
      pivotBoxCorners(PivotV(1, 2, 3), PivotV(0, 0, -1), PivotV(0, 1, 0), PivotV(1, 0, 0), PivotV(4, 3, 2));
  checkPivotLeaf(leaves, "Turned", P5, X5, Y5, Z5, S5, box5, 1e-12);
  // rel: X5 + 2 Y5 + 3 Z5 = (2, -1, 3): origin (3, 4, 2).
  std::vector<PivotV> moved = box5;
  for (PivotV& c : moved) c += PivotV(2, -1, 3);
  checkPivotLeaf(leaves, "Moved", PivotV(3, 4, 2), X5, Y5, Z5, S5, moved, 1e-12);
  // A quarter turn about the pivot's z: (X5, Y5) -> (Y5, -X5).
  checkPivotLeaf(leaves, "Spun", P5, Y5, -X5, Z5, S5, pivotBoxCorners(P5, Y5, -X5, Z5, S5), 1e-12);
  // yzx at corner 0 of the 4 x 3 x 2 box: axes (Z, X, Y), size (2, 4, 3). T(1, 1, 1) moves
  // the scope to Z + X + Y = (1, 1, 1); the child rule keeps the pivot, and abs (0, 0, 0)
  // there is the pivot's origin, the corner (0, 0, 0).
  checkPivotLeaf(leaves, "Back", PivotV(0, 0, 0), PivotV(0, 0, 1), PivotV(1, 0, 0), PivotV(0, 1, 0), PivotV(2, 4, 3),
                 pivotBoxCorners(PivotV(0, 0, 0), PivotV(0, 0, 1), PivotV(1, 0, 0), PivotV(0, 1, 0), PivotV(2, 4, 3)),
                 1e-12);
}

TEST_CASE("setPivot's bad axis order is a located error and a bad corner a run-time one naming the rule",
          "[cga][setPivot]") {
  auto messages = [](const std::string& text, const std::string& name) {
    auto file = frontend::SourceFile::make(name, text);
    frontend::Diagnostics diags(&file);
    ir::Module m;
    CHECK_FALSE(ir::compileSource(file, m, diags));
    std::ostringstream out;
    diags.print(out);
    return out.str();
  };
  const std::string cga = messages("@StartRule\nLot --> setPivot(xzy, 2) A\n", "test.cga");
  INFO(cga);
  CHECK(cga.find("test.cga:2:18: error[E028]: setPivot's axisMap is xyz, yzx or zxy, not 'xzy'") != std::string::npos);
  const std::string fgsg = messages("Lot ~> SetPivot(\"xy\", 2) A;\n", "test.fgsg");
  INFO(fgsg);
  CHECK(fgsg.find("test.fgsg:1:17: error[E028]: 'SetPivot' takes xyz, yzx, zxy here, not \"xy\"") != std::string::npos);
  // A corner index known only while deriving: R002 at the operation, in both engines.
  for (const bool compiled : {false, true}) {
    const std::string text = "@StartRule\nLot --> extrude(2) Mass(8)\nMass(k) --> setPivot(xyz, k) A\n";
    const ir::Module m = turned_lot::compile(text, "test.cga");
    rt::DeriveOptions options;
    rt::AssetLibrary assets;
    rt::DeriveResult r;
    if (compiled) {
      backend::jit::Jit jit;
      const auto code = jit.compileProgram(m, text, backend::native::ObjectCache{std::string()});
      r = backend::deriveCompiled(m, code.program(), options, assets);
    } else {
      r = backend::interpret(m, options, assets);
    }
    CHECK_FALSE(r.ok);
    REQUIRE(!r.messages.empty());
    const rt::DeriveMessage& e = r.messages.back();
    CHECK(e.code == "R002");
    CHECK(e.line == 3);
    CHECK(e.col == 13);
    CHECK(e.message == "setPivot in rule 'Mass': the corner index 8 is not a whole number from 0 to 7");
  }
}
