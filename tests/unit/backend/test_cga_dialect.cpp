// The `.cga` dialect derived: CityEngine's split sizing (the rest of the scope left
// empty, overflow cut, floating sizes filling, nested repeats taking what is left),
// `'x` relative sizes, case chains and stochastic choices, start shapes — checked by
// where the leaves land, with exact values.
#include "derive_helpers.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <vector>

using namespace fgsg;

namespace {

rt::DeriveResult deriveCga(const std::string& text, rt::DeriveOptions opt = {}) {
  auto file = frontend::SourceFile::make("test.cga", text);
  frontend::Diagnostics diags(&file);
  ir::Module m;
  if (!ir::compileSource(file, m, diags)) {
    std::ostringstream out;
    diags.print(out);
    FAIL("grammar does not compile:\n" << out.str());
  }
  rt::AssetLibrary assets;
  return backend::interpret(m, opt, assets);
}

struct Piece {
  std::string symbol;
  double x, width;  // along the lot's X
};

std::vector<Piece> pieces(const rt::DeriveResult& r) {
  REQUIRE(r.ok);
  std::vector<Piece> out;
  for (const rt::Instance& inst : r.instances.instances) {
    const Eigen::Vector3d a = test::unitPoint(inst, 0, 0, 0), b = test::unitPoint(inst, 1, 0, 0);
    out.push_back({r.instances.symbols[inst.symbol], a.x(), b.x() - a.x()});
  }
  return out;
}

// A 10 m wide, 3 m high facade on the default lot, split by `split`.
std::vector<Piece> facade(const std::string& split) {
  return pieces(deriveCga("@StartRule\nLot --> s(10, 3, 0) Facade\nFacade --> " + split + "\n"));
}

}  // namespace

TEST_CASE("absolute sizes that do not fill the scope leave the rest empty", "[cga][dialect]") {
  const auto p = facade("split(x) { 3 : A | 3 : B }");
  REQUIRE(p.size() == 2);
  CHECK(p[0].symbol == "A");
  CHECK(p[0].x == Approx(0));
  CHECK(p[0].width == Approx(3));
  CHECK(p[1].symbol == "B");
  CHECK(p[1].x == Approx(3));
  CHECK(p[1].width == Approx(3));  // 6..10 stays empty
}

TEST_CASE("absolute sizes that overflow are cut, and later parts are not generated", "[cga][dialect]") {
  // CityEngine's reference example on a 5 m scope: 2 + 1 + 1, then 2 is cut to 1, the last never made.
  const auto p = pieces(deriveCga("@StartRule\nLot --> s(5, 1, 0) split(x) { 2 : A | 1 : A | 1 : B | 2 : Y | 1 : Z }\n"));
  REQUIRE(p.size() == 4);
  CHECK(p[3].symbol == "Y");
  CHECK(p[3].x == Approx(4));
  CHECK(p[3].width == Approx(1));
  // Sizes <= 0 are not generated and take no room.
  const auto q = pieces(deriveCga("@StartRule\nLot --> s(5, 1, 0) split(x) { 1.5 : A | -2 : Y | 1.5 : B | 0 : Y | 1.5 : C | 1.5 : D }\n"));
  REQUIRE(q.size() == 4);
  CHECK(q[1].symbol == "B");
  CHECK(q[1].x == Approx(1.5));
  CHECK(q[3].symbol == "D");
  CHECK(q[3].width == Approx(0.5));
}

TEST_CASE("floating sizes fill what the absolute ones leave", "[cga][dialect]") {
  const auto p = facade("split(x) { 3 : A | ~1 : B | ~1 : C }");
  REQUIRE(p.size() == 3);
  CHECK(p[1].width == Approx(3.5));
  CHECK(p[2].x == Approx(6.5));
  // No room left: the floating part is not generated.
  const auto q = facade("split(x) { 10 : A | ~1 : B }");
  REQUIRE(q.size() == 1);
  CHECK(q[0].symbol == "A");
}

TEST_CASE("'x is a fraction of the scope", "[cga][dialect]") {
  const auto p = facade("split(x) { '0.3 : A | '0.5 : B }");
  REQUIRE(p.size() == 2);
  CHECK(p[0].width == Approx(3));
  CHECK(p[1].x == Approx(3));
  CHECK(p[1].width == Approx(5));
}

TEST_CASE("repeats: floating patterns fill, absolute ones cut the last", "[cga][dialect]") {
  const auto f = facade("split(x) { ~3 : A }*");  // round(10 / 3) = 3 of 3.33 m
  REQUIRE(f.size() == 3);
  CHECK(f[2].x == Approx(20.0 / 3));
  const auto a = facade("split(x) { 4 : A }*");  // 4, 4 and the last cut to 2
  REQUIRE(a.size() == 3);
  CHECK(a[1].width == Approx(4));
  CHECK(a[2].x == Approx(8));
  CHECK(a[2].width == Approx(2));
  const auto exact = facade("split(x) { 2 : A }*");
  CHECK(exact.size() == 5);
}

TEST_CASE("a repeat nested in a split takes what the other parts leave", "[cga][dialect]") {
  // 10 m: 1 m walls at both ends, 8 m of 2 m tiles between.
  const auto p = facade("split(x) { 1 : W | { ~2 : Tile }* | 1 : W }");
  REQUIRE(p.size() == 6);
  CHECK(p[0].symbol == "W");
  CHECK(p[1].symbol == "Tile");
  CHECK(p[1].x == Approx(1));
  CHECK(p[1].width == Approx(2));
  CHECK(p[4].x == Approx(7));
  CHECK(p[5].symbol == "W");
  CHECK(p[5].x == Approx(9));
}

TEST_CASE("a case chain takes the first condition that holds", "[cga][dialect]") {
  const std::string rules = "@StartRule\nLot --> s(1, 1, 0) Pick\nPick --> case h > 3 : A case h > 1 : B else : C\n";
  auto only = [&](double h) {
    const auto p = pieces(deriveCga("attr h = " + std::to_string(h) + "\n" + rules));
    REQUIRE(p.size() == 1);
    return p[0].symbol;
  };
  CHECK(only(5) == "A");  // h > 1 holds too: the first wins
  CHECK(only(2) == "B");
  CHECK(only(0) == "C");
}

TEST_CASE("stochastic choices follow their percentages", "[cga][dialect]") {
  // 2 000 pieces, each choosing; the counts within 4 standard deviations.
  const auto p = facade("split(x) { 0.005 : Pick }*\nPick --> 30% : A 20% : B else : C");
  REQUIRE(p.size() == 2000);
  std::map<std::string, int> n;
  for (const auto& piece : p) ++n[piece.symbol];
  CHECK(std::abs(n["A"] - 600) < 82);
  CHECK(std::abs(n["B"] - 400) < 72);
  CHECK(std::abs(n["C"] - 1000) < 90);
  const auto q = facade("split(x) { 0.005 : Pick }*\nPick --> case p(0.25) : A else : B");
  std::map<std::string, int> m;
  for (const auto& piece : q) ++m[piece.symbol];
  CHECK(std::abs(m["A"] - 500) < 78);
}

TEST_CASE("without lots the start rule runs on a 20 m square lot", "[cga][dialect]") {
  const auto r = deriveCga("@StartRule\nLot --> extrude(4)\n");
  REQUIRE(r.ok);
  REQUIRE(r.instances.instances.size() == 1);
  CHECK(r.instances.symbols[r.instances.instances[0].symbol] == "Lot.");
  const Eigen::Vector3d far = test::unitPoint(r.instances.instances[0], 1, 1, 1);
  CHECK(std::abs(far.x()) == Approx(20));
  CHECK(far.y() == Approx(4));
}

TEST_CASE("an insert takes the scope operations written after it", "[cga][dialect]") {
  const auto r = deriveCga("@StartRule\nLot --> s(2, 2, 2) i(\"builtin:cube\") s(1, 3, 1) t(1, 0, 0) X.\n");
  REQUIRE(r.ok);
  REQUIRE(r.instances.instances.size() == 1);
  CHECK(r.instances.assets[r.instances.instances[0].asset] == "builtin:cube");  // CityEngine's name, kept
  const Eigen::Vector3d a = test::unitPoint(r.instances.instances[0], 0, 0, 0);
  const Eigen::Vector3d b = test::unitPoint(r.instances.instances[0], 1, 1, 1);
  CHECK(a.x() == Approx(1));
  CHECK((b - a).norm() == Approx(std::sqrt(11.0)));
}

// CityEngine's i(asset, upAxisOfGeometry, insertMode), in the fgsg dialect as I("asset", "zUp",
// "keepSizeAndPosition"). examples/assets/stepped_column.obj spans x, y -0.75 .. 0.75 and z
// 0 .. 3 (a column standing along z); zUp turns it -90 degrees about X, (x, y, z) -> (x, z, -y),
// to x -0.75 .. 0.75, y 0 .. 3, z -0.75 .. 0.75, size 1.5 x 3 x 1.5. Its unit box's corner
// (0, 0, 0) is the file's (-0.75, -0.75, 0), turned (-0.75, 0, 0.75); (0, 0, 1), the file's
// (-0.75, -0.75, 3) on the column's top, turned (-0.75, 3, 0.75).
TEST_CASE("an insert keeps the asset's size and position, turned up from z", "[cga][insert]") {
  using test::deriveText;
  using test::unitPoint;
  // The scope at (1, 0, 2): the turned column where its file puts it, read from there.
  const auto keep = deriveText("axiom: T(1, 0, 2) S(4, 4, 4) I(\"stepped_column.obj\", \"zUp\", \"keepSizeAndPosition\");\n");
  REQUIRE(keep.ok);
  REQUIRE(keep.instances.instances.size() == 1);
  const rt::Instance& k = keep.instances.instances[0];
  CHECK((unitPoint(k, 0, 0, 0) - Eigen::Vector3d(0.25, 0, 2.75)).norm() == Approx(0).margin(1e-12));
  CHECK((unitPoint(k, 0, 0, 1) - Eigen::Vector3d(0.25, 3, 2.75)).norm() == Approx(0).margin(1e-12));
  CHECK((unitPoint(k, 1, 1, 1) - Eigen::Vector3d(1.75, 3, 1.25)).norm() == Approx(0).margin(1e-12));

  // Fitted (alignSizeAndPosition) to a 1 x 6 x 2 scope, zUp: the top (unit z = 1) at y = 6,
  // the file's -y side (unit y = 0) at the scope's far z, 2.
  const auto fit = deriveText("axiom: S(1, 6, 2) I(\"stepped_column.obj\", \"zUp\");\n");
  REQUIRE(fit.ok);
  const rt::Instance& f = fit.instances.instances.at(0);
  CHECK((unitPoint(f, 0, 0, 0) - Eigen::Vector3d(0, 0, 2)).norm() == Approx(0).margin(1e-12));
  CHECK((unitPoint(f, 0, 0, 1) - Eigen::Vector3d(0, 6, 2)).norm() == Approx(0).margin(1e-12));
  CHECK((unitPoint(f, 0, 1, 0) - Eigen::Vector3d(0, 0, 0)).norm() == Approx(0).margin(1e-12));
}

TEST_CASE("an insert keeps the asset's size, centred on the scope's x and z", "[cga][insert]") {
  using test::deriveText;
  using test::unitPoint;
  // yUp: 1.5 x 1.5 x 3 in a 4 x 2 x 6 scope: at ((4 - 1.5) / 2, 0, (6 - 3) / 2) = (1.25, 0, 1.5).
  const auto r = deriveText("axiom: S(4, 2, 6) I(\"stepped_column.obj\", \"yUp\", \"keepSizeAlignPosition\");\n");
  REQUIRE(r.ok);
  const rt::Instance& c = r.instances.instances.at(0);
  CHECK((unitPoint(c, 0, 0, 0) - Eigen::Vector3d(1.25, 0, 1.5)).norm() == Approx(0).margin(1e-12));
  CHECK((unitPoint(c, 1, 1, 1) - Eigen::Vector3d(2.75, 1.5, 4.5)).norm() == Approx(0).margin(1e-12));
  // The scope becomes the asset's box (CityEngine's i()): a cube after it fills the file's
  // box, -0.75 .. 0.75 x -0.75 .. 0.75 x 0 .. 3.
  const auto s = deriveText("axiom: I(\"stepped_column.obj\", \"yUp\", \"keepSizeAndPosition\") I(\"cube\");\n");
  REQUIRE(s.ok);
  const rt::Instance& cube = s.instances.instances.at(1);
  CHECK((unitPoint(cube, 0, 0, 0) - Eigen::Vector3d(-0.75, -0.75, 0)).norm() == Approx(0).margin(1e-12));
  CHECK((unitPoint(cube, 1, 1, 1) - Eigen::Vector3d(0.75, 0.75, 3)).norm() == Approx(0).margin(1e-12));
  // An unknown word is located, not ignored.
  CHECK_THROWS_WITH(deriveText("axiom: I(\"cube\", \"xUp\");\n"), Catch::Matchers::Contains("E028"));
}

TEST_CASE("extrude(world.up h) goes up on a face facing up and is a located error on a wall", "[cga][dialect]") {
  // On the lot (facing up) it is extrude(h): a 20 x 3 x 20 mass.
  const rt::DeriveResult up = deriveCga("@StartRule\nLot --> extrude(world.up, 3) M.\n");
  REQUIRE(up.ok);
  REQUIRE(up.instances.instances.size() == 1);
  const Eigen::Vector3d top = test::unitPoint(up.instances.instances[0], 1, 1, 1);
  CHECK(top.y() == Approx(3));
  // On the front wall CityEngine sweeps the face up; along the wall's normal would be a
  // wrong solid, so the engine refuses it where the operation is written.
  const rt::DeriveResult wall =
      deriveCga("@StartRule\nLot --> extrude(4) comp(f) { front : W }\nW --> extrude(world.up, 2) X.\n");
  CHECK_FALSE(wall.ok);
  REQUIRE_FALSE(wall.messages.empty());
  CHECK(wall.messages[0].code == "R002");
  CHECK(wall.messages[0].line == 3);
  CHECK(wall.messages[0].col == 7);
  CHECK(wall.messages[0].message ==
        "extrude(world.up, h) on a face whose normal (0, 0, 1) is not world up: only faces facing up are "
        "supported (use extrude(h) to go along the normal)");
  // face.normal is extrude(h) on any face.
  CHECK(deriveCga("@StartRule\nLot --> extrude(4) comp(f) { front : W }\nW --> extrude(face.normal, 2) X.\n").ok);
}
