// CGA's split syntax: sizes written on the parts (`Subdiv("Y"){ 4: Ground | ~3: Floor }`)
// and repeated patterns (`{ ~1: Wall | 1.4: Window }*`), checked by where the pieces land.
#include "derive_helpers.h"

#include <catch2/catch.hpp>

#include <vector>

using namespace fgsg;

namespace {

struct Piece {
  std::string symbol;
  double x, width;  // along X
};

// The leaves in order, each with its scope's start and length along X.
std::vector<Piece> piecesAlongX(const rt::DeriveResult& r) {
  REQUIRE(r.ok);
  std::vector<Piece> out;
  for (const rt::Instance& inst : r.instances.instances) {
    const Eigen::Vector3d a = test::unitPoint(inst, 0, 0, 0), b = test::unitPoint(inst, 1, 0, 0);
    out.push_back({r.instances.symbols[inst.symbol], a.x(), b.x() - a.x()});
  }
  return out;
}

}  // namespace

TEST_CASE("sizes on the parts are the split's sizes", "[cga][split]") {
  const auto written = test::deriveText("Lot ~> S(10, 7, 0) Subdiv(\"X\"){ 4: A | ~3: B | 1r: C };");
  const auto args = test::deriveText("Lot ~> S(10, 7, 0) Subdiv(\"X\", 4, ~3, 1r){ A | B | C };");
  const auto p = piecesAlongX(written), q = piecesAlongX(args);
  REQUIRE(p.size() == 3);
  REQUIRE(q.size() == 3);
  for (size_t i = 0; i < 3; ++i) {
    CHECK(p[i].symbol == q[i].symbol);
    CHECK(p[i].x == Approx(q[i].x));
    CHECK(p[i].width == Approx(q[i].width));
  }
  CHECK(p[0].width == Approx(4));
  CHECK(p[1].width == Approx(3));
  CHECK(p[2].width == Approx(3));
  // A bare name is the value it names.
  const auto named = piecesAlongX(test::deriveText("attr w = 2.5;\nLot ~> S(10, 7, 0) Subdiv(\"X\"){ w: A | 1r: B };"));
  REQUIRE(named.size() == 2);
  CHECK(named[0].width == Approx(2.5));
}

TEST_CASE("a repeated pattern with a floating size fills the scope", "[cga][split]") {
  // Nominal 2.4 m on 10 m: round(4.17) = 4 repeats; each wall (10 - 4 * 1.4) / 4 = 1.1 m.
  const auto p = piecesAlongX(test::deriveText("Lot ~> S(10, 7, 0) Subdiv(\"X\"){ ~1: Wall | 1.4: Window }*;"));
  REQUIRE(p.size() == 8);
  for (size_t k = 0; k < 4; ++k) {
    CHECK(p[2 * k].symbol == "Wall");
    CHECK(p[2 * k].width == Approx(1.1));
    CHECK(p[2 * k + 1].symbol == "Window");
    CHECK(p[2 * k + 1].x == Approx(1.1 + 2.5 * double(k)));
    CHECK(p[2 * k + 1].width == Approx(1.4));
  }
  // CGA's `{ ~3: Window }*`: a pattern of one floating part is a Repeat that rounds.
  const auto one = piecesAlongX(test::deriveText("Lot ~> S(10, 7, 0) Subdiv(\"X\"){ ~3: Window }*;"));
  REQUIRE(one.size() == 3);
  CHECK(one[2].x == Approx(20.0 / 3));
  // Shorter than one pattern: it is squeezed in once.
  CHECK(piecesAlongX(test::deriveText("Lot ~> S(1, 7, 0) Subdiv(\"X\"){ ~2: Window }*;")).size() == 1);
}

TEST_CASE("a repeated pattern of absolute sizes repeats as often as it fits whole", "[cga][split]") {
  const auto p = piecesAlongX(test::deriveText("Lot ~> S(7, 1, 0) Subdiv(\"X\"){ 2: A }*;"));
  REQUIRE(p.size() == 3);  // 0-2, 2-4, 4-6; the last metre stays empty
  CHECK(p[2].x == Approx(4));
  CHECK(p[2].width == Approx(2));
  CHECK(piecesAlongX(test::deriveText("Lot ~> S(1, 1, 0) Subdiv(\"X\"){ 2: A }*;")).empty());
}

TEST_CASE("a repeated split tiles every facade of a polygon prism", "[cga][split]") {
  // An L-shaped footprint's facades, each tiled by the pattern.
  const auto r = test::deriveText(
      "Lot ~> Footprint(0, 0, 20, 0, 20, 9, 9, 9, 9, 18, 0, 18) Extrude(6) Comp(\"sidefaces\"){ Facade };\n"
      "Facade ~> Subdiv(\"X\"){ ~1: Wall | 1.5: Window }*;");
  REQUIRE(r.ok);
  size_t windows = 0;
  for (const rt::Instance& inst : r.instances.instances) windows += r.instances.symbols[inst.symbol] == "Window";
  // Facades 20, 9, 11, 9, 9, 18 m long; nominal 2.5: 8 + 4 + 4 + 4 + 4 + 7 windows.
  CHECK(windows == 31);
}
