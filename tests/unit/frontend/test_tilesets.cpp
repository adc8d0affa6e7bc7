// `tileset NAME { ... }` (frontend/sema_tilesets.cpp): the tiles of Chan & Hui as
// constants, Evolve naming them, and every error (E041, E022, E017) at its place. Whether
// the tiles make a valid tile set is the runtime's check (test_evolve_command.cpp).
#include "sema_helpers.h"

#include <catch2/catch.hpp>

using namespace fgsg::frontend;
using namespace fgsg::frontend::test;

namespace {

// A tileset whose body is `items`, used by Evolve so that only the items can be wrong.
Analysed tileset(const std::string& items) {
  return analyse("tileset t {\n  " + items + "\n}\naxiom: Evolve(t, 2)");
}
constexpr int kItems = 3;  // the column where `items` starts on line 2

const std::string kCurves = "locus a = polyline((0, 0.5), (1, 0.5)); section r = polyline((-1, 0), (0, 1), (1, 0));";

}  // namespace

TEST_CASE("a tileset's curves, orientations and letters become constants", "[sema][tileset]") {
  const Analysed a = analyse(
      "const h = 0.5;\n"
      "tileset ornament {\n"
      "  locus arc = cubic((0.5, 0), (0.5, 0.276), (0.724, h), (1, h));\n"
      "  locus line = polyline((0, h), (2 * h, h));\n"
      "  section round = polyline((-1, 0), (0, 1), (1, 0));\n"
      "  orientations 0, 180;\n"
      "  symbols \"XY\";\n"
      "}\n"
      "axiom: S(6, 6, 1) Evolve(ornament, 3, 3, true)");
  INFO(a.printed);
  REQUIRE(a.ok);
  REQUIRE(a.sema.tilesets.size() == 1);
  const TilesetInfo& t = a.sema.tilesets[0];
  CHECK(t.name == "ornament");
  REQUIRE(t.loci.size() == 2);
  CHECK(t.loci[0].name == "arc");
  CHECK(t.loci[0].cubic);
  CHECK(t.loci[0].points == std::vector<std::array<double, 2>>{{0.5, 0}, {0.5, 0.276}, {0.724, 0.5}, {1, 0.5}});
  CHECK_FALSE(t.loci[1].cubic);
  CHECK(t.loci[1].points == std::vector<std::array<double, 2>>{{0, 0.5}, {1, 0.5}});
  REQUIRE(t.sections.size() == 1);
  CHECK(t.sections[0].points.size() == 3);
  CHECK(t.orientations == std::vector<int>{0, 180});
  CHECK(t.symbols == "XY");
  CHECK(t.range.begin.line == 2);
}

TEST_CASE("a tileset needs neither names nor orientations nor letters", "[sema][tileset]") {
  const Analysed a = tileset("locus polyline((0, 0), (1, 1)); section polyline((-1, 0), (1, 0));");
  INFO(a.printed);
  REQUIRE(a.ok);
  CHECK(a.sema.tilesets[0].orientations.empty());
  CHECK(a.sema.tilesets[0].symbols.empty());
  CHECK(a.sema.tilesets[0].loci[0].name.empty());
}

TEST_CASE("tileset items that are not tiles (E041)", "[sema][tileset]") {
  onlyError(tileset(kCurves + " colour 3;"), "E041", 2, kItems + int(kCurves.size()) + 1,
            "unknown tileset item 'colour' (expected locus, section, orientations, symbols, or a GA setting: ");
  onlyError(tileset("locus a = line((0, 0), (1, 1)); section r = polyline((-1, 0), (1, 0));"), "E041", 2,
            kItems + 10, "a locus is one curve: polyline((x, y), (x, y), ...) or cubic(p0, p1, p2, p3)");
  onlyError(tileset("locus a = cubic((0, 0), (1, 1)); section r = polyline((-1, 0), (1, 0));"), "E041", 2,
            kItems + 10, "a cubic has 4 points (p0, two control points, p3), got 2");
  onlyError(tileset("locus a = polyline((0, 0)); section r = polyline((-1, 0), (1, 0));"), "E041", 2, kItems + 10,
            "a polyline needs 2 or more points, got 1");
  onlyError(tileset("locus a = polyline((0, 0), (1, 1, 0)); section r = polyline((-1, 0), (1, 0));"), "E041", 2,
            kItems + 27, "a point of a locus is (x, y): two constant numbers in parentheses");
  onlyError(tileset("locus a = polyline((0, 0), 1); section r = polyline((-1, 0), (1, 0));"), "E041", 2,
            kItems + 27, "a point of a locus is (x, y)");
  onlyError(tileset(kCurves + " orientations 0, 45;"), "E041", 2, kItems + int(kCurves.size()) + 17,
            "an orientation is 0, 90, 180 or 270 (degrees), got 45");
  onlyError(tileset(kCurves + " orientations 90, 90;"), "E041", 2, kItems + int(kCurves.size()) + 18,
            "orientation 90 is listed twice");
  onlyError(tileset(kCurves + " orientations 0; orientations 90;"), "E041", 2, kItems + int(kCurves.size()) + 17,
            "'orientations' is given twice in tileset 't'");
  onlyError(tileset(kCurves + " symbols 3;"), "E041", 2, kItems + int(kCurves.size()) + 9,
            "'symbols' is one constant string");
  onlyError(tileset(kCurves + " symbols s = \"A\";"), "E041", 2, kItems + int(kCurves.size()) + 9,
            "'symbols' takes no name");
  onlyError(tileset(kCurves + " locus a = polyline((0, 0), (1, 1));"), "E041", 2, kItems + int(kCurves.size()) + 7,
            "locus 'a' is declared twice in tileset 't'");
  onlyError(tileset("locus a = polyline((0, 0), (1, 1));"), "E041", 1, 9,
            "tileset 't' needs at least one locus and one section");
}

TEST_CASE("tileset names: unique among declarations, and what Evolve may name (E022, E017)", "[sema][tileset]") {
  onlyError(analyse("const t = 1;\ntileset t { " + kCurves + " }\naxiom: Evolve(t, 2)"), "E022", 2, 9,
            "tileset 't' is declared twice");
  onlyError(analyse("tileset t { " + kCurves + " }\ntileset t { " + kCurves + " }\naxiom: Evolve(t, 2)"), "E022", 2, 9,
            "tileset 't' is declared twice");
  onlyError(analyse("tileset t { " + kCurves + " }\naxiom: Evolve(u, 2)"), "E017", 2, 15,
            "'u' is no tileset declared in this grammar");
  // A string constant still names a tile file.
  const Analysed file = analyse("const tiles = \"t.json\";\naxiom: Evolve(tiles, 2)");
  INFO(file.printed);
  CHECK(file.ok);
}

TEST_CASE("a tileset may give the genetic algorithm's settings", "[sema][tileset]") {
  const Analysed a = tileset(kCurves +
                             " population 40; max_generations 7; threshold 0.5; weights 1, 2, 3; crossover 0.8;"
                             " mutation 0.05; parents 10; elite 1;");
  INFO(a.printed);
  REQUIRE(a.ok);
  using Settings = std::vector<std::pair<std::string, std::vector<double>>>;
  CHECK(a.sema.tilesets[0].settings == Settings{{"population", {40}}, {"max_generations", {7}}, {"threshold", {0.5}},
                                                {"weights", {1, 2, 3}}, {"crossover", {0.8}}, {"mutation", {0.05}},
                                                {"parents", {10}}, {"elite", {1}}});
  const int at = kItems + int(kCurves.size()) + 1;
  onlyError(tileset(kCurves + " population 1;"), "E041", 2, at + 11,
            "'population' takes whole numbers from 2 to 100000, got 1: `population 100;`");
  onlyError(tileset(kCurves + " threshold 1.5;"), "E041", 2, at + 10, "'threshold' takes numbers from 0 to 1, got 1.5");
  onlyError(tileset(kCurves + " elite 2.5;"), "E041", 2, at + 6, "'elite' takes whole numbers");
  onlyError(tileset(kCurves + " weights 1, 2;"), "E041", 2, at, "'weights' takes 3 or 4 numbers: `weights 1, 1, 1, 3;`");
  onlyError(tileset(kCurves + " weights 0, 0, 0, 1;"), "E041", 2, at, "cannot all be 0");
  onlyError(tileset(kCurves + " mutation 0.1; mutation 0.2;"), "E041", 2, at + 14, "'mutation' is given twice");
}
