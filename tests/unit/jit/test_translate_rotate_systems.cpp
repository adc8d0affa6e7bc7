// CityEngine's translate(mode, system, x, y, z) and rotate(mode, system, ax, ay, az) in
// every mode and coordinate system (issue #44; docs/cga.md), in the `.cga` dialect and in
// fgsg's (Translate / Rotate), derived by the interpreter and the JIT: each leaf's scope
// origin, axes and size, and its geometry's corners, against values worked out by hand on
// a lot that is turned and moved in the world, so that the scope, object (= pivot) and
// world systems all differ.
#include "turned_lot_leaves.h"

#include <catch2/catch.hpp>

#include <map>
#include <string>

namespace {

using namespace fgsg;
using V = Eigen::Vector3d;

// The turned lot (turned_lot_leaves.h), in the world: the object system has its origin at
// O = (10, 0, -20), x along (0.6, 0, -0.8), y up, z = x × y = (0.8, 0, 0.6); the lot lies
// at object z in [-10, 0], so its scope starts at the fourth corner, (2, 0, -26), with the
// object's axes.
const V kObjO(10, 0, -20), kObjX(0.6, 0, -0.8), kObjY(0, 1, 0), kObjZ(0.8, 0, 0.6);
const V kLotP(2, 0, -26);

using LeafScope = turned_lot::Leaf;

std::map<std::string, LeafScope> deriveSystemsBothEngines(const std::string& text, const std::string& name) {
  return turned_lot::deriveBothEngines(text, name);
}

bool near12(const V& a, const V& b) { return (a - b).cwiseAbs().maxCoeff() <= 1e-12; }

bool sameScope(const LeafScope& l, const V& P, const V& X, const V& Y, const V& Z, const V& S) {
  INFO("P " << l.P.transpose() << " X " << l.X.transpose() << " Y " << l.Y.transpose() << " Z " << l.Z.transpose()
            << " S " << l.S.transpose());
  CHECK(near12(l.P, P));
  CHECK(near12(l.X, X));
  CHECK(near12(l.Y, Y));
  CHECK(near12(l.Z, Z));
  CHECK(near12(l.S, S));
  return near12(l.P, P) && near12(l.X, X) && near12(l.Y, Y) && near12(l.Z, Z) && near12(l.S, S);
}

// Every corner of the leaf's geometry is one of `expected`, and every one of `expected` is
// a corner, to `tolerance`.
void cornersAre(const LeafScope& l, const std::vector<V>& expected, double tolerance = 1e-12) {
  REQUIRE(!l.corners.empty());
  auto near = [&](const V& a, const V& b) { return (a - b).cwiseAbs().maxCoeff() <= tolerance; };
  for (const V& c : l.corners) {
    bool found = false;
    for (const V& e : expected) found = found || near(c, e);
    INFO("corner " << c.transpose());
    CHECK(found);
  }
  for (const V& e : expected) {
    bool found = false;
    for (const V& c : l.corners) found = found || near(c, e);
    INFO("expected corner " << e.transpose());
    CHECK(found);
  }
}

// The `.cga` leaf's scope is (P; X, Y, Z) with size S, and its geometry (the 5 x 2 x 10
// box the lot was extruded to, filling the scope) has its corners at
// P + S.x u X + S.y v Y + S.z w Z, u v w in {0, 1}.
void checkLeaf(const std::map<std::string, LeafScope>& leaves, const std::string& symbol, const V& P, const V& X,
               const V& Y, const V& Z, const V& S = V(5, 2, 10)) {
  INFO("leaf " << symbol);
  REQUIRE(leaves.count(symbol) == 1);
  const LeafScope& l = leaves.at(symbol);
  sameScope(l, P, X, Y, Z, S);
  std::vector<V> expected;
  for (int k = 0; k < 8; ++k) expected.push_back(P + S.x() * (k & 1) * X + S.y() * ((k >> 1) & 1) * Y + S.z() * (k >> 2) * Z);
  cornersAre(l, expected);
}

// The fgsg leaf's scope is (P; X, Y, Z), its size `reference`'s, and its geometry is
// `reference`'s carried along rigidly: each corner c to P + (X Y Z) (Xr Yr Zr)^T (c - Pr).
void checkMovedLeaf(const std::map<std::string, LeafScope>& leaves, const std::string& symbol,
                    const LeafScope& reference, const V& P, const V& X, const V& Y, const V& Z) {
  INFO("leaf " << symbol);
  REQUIRE(leaves.count(symbol) == 1);
  const LeafScope& l = leaves.at(symbol);
  sameScope(l, P, X, Y, Z, reference.S);
  Eigen::Matrix3d to, from;
  to << X, Y, Z;
  from << reference.X, reference.Y, reference.Z;
  REQUIRE(l.corners.size() == reference.corners.size());
  for (size_t i = 0; i < l.corners.size(); ++i) {
    INFO("corner " << i << " " << l.corners[i].transpose());
    CHECK(near12(l.corners[i], P + to * from.transpose() * (reference.corners[i] - reference.P)));
  }
}

}  // namespace

TEST_CASE("cga translate and rotate in the scope and pivot and object and world systems", "[cga][translate]") {
  // N: the extruded lot turned 90 degrees about its own z: X = y up, Y = -(0.6, 0, -0.8),
  // Z = (0.8, 0, 0.6), origin still (2, 0, -26), size 5 x 2 x 10.
  const auto leaves = deriveSystemsBothEngines(R"(@StartRule
Lot --> extrude(2) M
M --> [ N0 ] r(0, 0, 90) N
N --> [ translate(rel, object, 1, 2, 3) TRelObject ]
      [ translate(abs, object, 1, 2, 3) TAbsObject ]
      [ translate(rel, pivot, 1, 2, 3) TRelPivot ]
      [ translate(abs, pivot, 1, 2, 3) TAbsPivot ]
      [ translate(rel, scope, 1, 2, 3) TRelScope ]
      [ translate(abs, scope, 1, 2, 3) TAbsScope ]
      [ translate(rel, world, 1, 2, 3) TRelWorld ]
      [ translate(abs, world, 1, 2, 3) TAbsWorld ]
      [ rotate(rel, object, 90, 0, 0) RRelObjectX ]
      [ rotate(rel, object, 0, 0, 90) RRelObjectZ ]
      [ rotate(abs, object, 90, 0, 0) RAbsObjectX ]
      [ rotate(abs, object, 90, 90, 0) RAbsObjectXY ]
      [ rotate(rel, pivot, 90, 0, 0) RRelPivotX ]
      [ rotate(abs, pivot, 90, 90, 0) RAbsPivotXY ]
      [ rotate(rel, scope, 0, 0, 90) RRelScope ]
      [ rotate(abs, scope, 0, 0, 90) RAbsScope ]
      [ rotate(rel, world, 0, 90, 0) RRelWorld ]
      [ rotate(abs, world, 0, 90, 0) RAbsWorld ]
)",
                                               "test.cga");
  // The lot's own scope: the object's axes, at its fourth corner.
  checkLeaf(leaves, "N0", kLotP, kObjX, kObjY, kObjZ);
  const V X1 = kObjY, Y1 = -kObjX, Z1 = kObjZ;
  // Moves: rel adds x Xo + y Yo + z Zo = (0.6, 0, -0.8) + (0, 2, 0) + (2.4, 0, 1.8) =
  // (3, 2, 1) to the origin; abs puts the origin at O + (3, 2, 1) = (13, 2, -19).
  checkLeaf(leaves, "TRelObject", V(5, 2, -25), X1, Y1, Z1);
  checkLeaf(leaves, "TAbsObject", V(13, 2, -19), X1, Y1, Z1);
  checkLeaf(leaves, "TRelPivot", V(5, 2, -25), X1, Y1, Z1);
  checkLeaf(leaves, "TAbsPivot", V(13, 2, -19), X1, Y1, Z1);
  // In the scope's axes: X1 + 2 Y1 + 3 Z1 = (0, 1, 0) + (-1.2, 0, 1.6) + (2.4, 0, 1.8).
  checkLeaf(leaves, "TRelScope", V(3.2, 1, -22.6), X1, Y1, Z1);
  checkLeaf(leaves, "TAbsScope", V(3.2, 1, -22.6), X1, Y1, Z1);
  checkLeaf(leaves, "TRelWorld", V(3, 2, -23), X1, Y1, Z1);
  checkLeaf(leaves, "TAbsWorld", V(1, 2, 3), X1, Y1, Z1);
  // Turns about the object's x by 90: Yo -> Zo, Zo -> -Yo (Xo stays).
  checkLeaf(leaves, "RRelObjectX", kLotP, kObjZ, -kObjX, -kObjY);
  checkLeaf(leaves, "RRelPivotX", kLotP, kObjZ, -kObjX, -kObjY);
  // About the object's z by 90: Xo -> Yo, Yo -> -Xo.
  checkLeaf(leaves, "RRelObjectZ", kLotP, -kObjX, -kObjY, kObjZ);
  // abs: the object's axes turned: by Rx(90): (Xo, Zo, -Yo); by Ry(90) Rx(90) (x first):
  // e1 -> -e3, e2 -> e1, e3 -> -e2, so (-Zo, Xo, -Yo).
  checkLeaf(leaves, "RAbsObjectX", kLotP, kObjX, kObjZ, -kObjY);
  checkLeaf(leaves, "RAbsObjectXY", kLotP, -kObjZ, kObjX, -kObjY);
  checkLeaf(leaves, "RAbsPivotXY", kLotP, -kObjZ, kObjX, -kObjY);
  // The scope's own z by 90 (abs = rel there): X1 -> Y1, Y1 -> -X1.
  checkLeaf(leaves, "RRelScope", kLotP, Y1, -X1, Z1);
  checkLeaf(leaves, "RAbsScope", kLotP, Y1, -X1, Z1);
  // The world's y by 90: (x, y, z) -> (z, y, -x).
  checkLeaf(leaves, "RRelWorld", kLotP, V(0, 1, 0), V(0.8, 0, 0.6), V(0.6, 0, -0.8));
  checkLeaf(leaves, "RAbsWorld", kLotP, V(0, 0, -1), V(0, 1, 0), V(1, 0, 0));
}

TEST_CASE("fgsg Translate and Rotate in the pivot and object systems", "[cga][translate]") {
  // fgsg's lot is its footprint polygon; the object system is the same (the lot's first
  // corner and edge, y up), whatever axes fgsg's own scope has.
  const auto leaves = deriveSystemsBothEngines(R"(
Lot ~> Extrude(2) M;
M ~> [ Translate("abs", "object", 1, 2, 3) MovedAbs ]
     [ Rotate("abs", "pivot", 90, 90, 0) TurnedAbs ]
     [ Translate("abs", "object", 0, 0, 0) Rotate("abs", "object", 0, 0, 0) Start ]
     [ Translate("abs", "object", 0, 0, 0) Rotate("abs", "object", 0, 0, 0) Translate("rel", "pivot", 1, 2, 3)
       Rotate("rel", "object", 90, 0, 0) Moved ]
     [ Translate("abs", "scope", 1, 0, 0) Rotate("abs", "scope", 0, 0, 90) Own ]
     Plain;
)",
                                               "test.fgsg");
  REQUIRE(leaves.count("Plain") == 1);
  const LeafScope& plain = leaves.at("Plain");
  // The untouched extrusion: the lot's four corners at heights 0 and 2 (to the float
  // precision of the mesh's coordinates in the scope's unit box, the lot lying slanted in
  // fgsg's scope; the leaves below are compared with it exactly).
  cornersAre(plain,
             {V(10, 0, -20), V(13, 0, -24), V(5, 0, -30), V(2, 0, -26), V(10, 2, -20), V(13, 2, -24), V(5, 2, -30),
              V(2, 2, -26)},
             1e-5);
  checkMovedLeaf(leaves, "MovedAbs", plain, V(13, 2, -19), plain.X, plain.Y, plain.Z);
  checkMovedLeaf(leaves, "TurnedAbs", plain, plain.P, -kObjZ, kObjX, -kObjY);
  checkMovedLeaf(leaves, "Start", plain, kObjO, kObjX, kObjY, kObjZ);
  checkMovedLeaf(leaves, "Moved", plain, V(13, 2, -19), kObjX, kObjZ, -kObjY);
  // In the scope's own system abs is rel: 1 m along X, then a quarter turn about Z.
  checkMovedLeaf(leaves, "Own", plain, plain.P + plain.X, plain.Y, -plain.X, plain.Z);
}

TEST_CASE("a bad mode or coordinate system of translate or rotate is a located error", "[cga][translate]") {
  auto messages = [](const std::string& text, const std::string& name) {
    auto file = frontend::SourceFile::make(name, text);
    frontend::Diagnostics diags(&file);
    ir::Module m;
    CHECK_FALSE(ir::compileSource(file, m, diags));
    std::ostringstream out;
    diags.print(out);
    return out.str();
  };
  const std::string cga = messages("@StartRule\nLot --> translate(rel, parent, 1, 2, 3) A\n", "test.cga");
  CHECK(cga.find("test.cga:2:24: error[E028]: translate's coordinate system is scope, pivot, object or world, "
                 "not 'parent'") != std::string::npos);
  const std::string mode = messages("@StartRule\nLot --> rotate(relative, object, 1, 2, 3) A\n", "test.cga");
  CHECK(mode.find("test.cga:2:16: error[E028]: rotate's mode is rel or abs, not 'relative'") != std::string::npos);
  const std::string fgsg = messages("Lot ~> Rotate(\"rel\", \"parent\", 0, 90, 0) A;\n", "test.fgsg");
  CHECK(fgsg.find("test.fgsg:1:22: error[E028]: 'Rotate' takes scope, pivot, object, world here, not \"parent\"") !=
        std::string::npos);
}
