// Tiles and alleles (Chan & Hui 2013 §3.1.1, Eq. 2) and the tile file: reading, and the
// errors a bad file gives.
#include "runtime/evolve/tiles.h"

#include <catch2/catch.hpp>

#include <string>

using namespace fgsg::rt::evolve;

namespace {

const std::string kData = std::string(FGSG_SOURCE_DIR) + "/tests/data/evolve/";

// The message parseTileSet throws for `json`, or "" when it parses.
std::string errorOf(const std::string& json) {
  try {
    parseTileSet(json, "t.json");
  } catch (const TileFileError& e) {
    return e.what();
  }
  return "";
}

const char* kTwoSections = R"({
  "loci": [ {"name": "line", "polyline": [[0, 0.5], [1, 0.5]]},
            {"name": "diag", "polyline": [[0, 0], [0.5, 0.5], [1, 1]]} ],
  "sections": [ {"name": "flat", "polyline": [[-1, 0], [1, 0]]},
                {"name": "bump", "cubic": [[-1, 0], [-0.5, 1], [0.5, 1], [1, 0]]} ],
  "orientations": [0, 180]
})";

}  // namespace

TEST_CASE("the paper's tile file: 2 loci x 1 cross-section x 4 orientations = 8 alleles", "[evolve][tiles]") {
  const TileSet ts = readTileFile(kData + "paper_tiles.json");
  REQUIRE(ts.loci.size() == 2);
  REQUIRE(ts.sections.size() == 1);
  CHECK(ts.letters() == "AB");
  CHECK(ts.loci[0].name == "arc");
  CHECK(ts.loci[0].curve.kind == Curve::Kind::kCubic);
  CHECK(ts.loci[1].curve.kind == Curve::Kind::kPolyline);
  CHECK(ts.orientations == std::vector<int>{0, 1, 2, 3});
  const std::vector<Allele> alleles = ts.alleles();
  REQUIRE(alleles.size() == 8);
  CHECK(alleles[0] == Allele{0, 0});
  CHECK(alleles[5] == Allele{1, 1});
  // The same tiles as exampleTileSet().
  const TileSet ex = exampleTileSet();
  for (const Allele a : alleles) CHECK(ts.endpoints(a) == ex.endpoints(a));
}

TEST_CASE("symbols are locus x cross-section pairs, locus-major, and orientations turn the locus", "[evolve][tiles]") {
  const TileSet ts = parseTileSet(kTwoSections, "two.json");
  REQUIRE(ts.tiles.size() == 4);
  CHECK(ts.letters() == "ABCD");
  CHECK(ts.tiles[1].locus == 0);
  CHECK(ts.tiles[1].section == 1);
  CHECK(ts.tiles[2].locus == 1);
  CHECK(ts.tiles[2].section == 0);
  CHECK(ts.orientations == std::vector<int>{0, 2});
  CHECK(ts.alleles().size() == 2 * 2 * 2);  // Eq. 2

  // A quarter turn counter-clockwise about (0.5, 0.5): (x, y) -> (1 - y, x).
  CHECK(turnInTile({1, 0.5}, 1) == Point2{0.5, 1});
  CHECK(turnInTile({0.25, 0}, 2) == Point2{0.75, 1});
  CHECK(turnInTile({0.25, 0}, 3) == Point2{0, 0.75});
  const TileSet ex = exampleTileSet();
  // Locus A runs from the middle of the bottom edge to the middle of the right edge.
  CHECK(ex.endpoints({0, 0}) == std::array<Point2, 2>{Point2{0.5, 0}, Point2{1, 0.5}});
  CHECK(ex.endpoints({0, 1}) == std::array<Point2, 2>{Point2{1, 0.5}, Point2{0.5, 1}});
  const std::vector<Point2> pts = ex.locusPoints({1, 1}, 3);  // B turned: vertical
  REQUIRE(pts.size() == 3);
  CHECK(pts[0] == Point2{0.5, 0});
  CHECK(pts[1] == Point2{0.5, 0.5});
  CHECK(pts[2] == Point2{0.5, 1});
  // Cubic evaluation: the Bezier curve's midpoint.
  const Curve cubic{Curve::Kind::kCubic, {{0, 0}, {0, 1}, {1, 1}, {1, 0}}};
  CHECK(cubic.at(0.5) == Point2{0.5, 0.75});
  const Curve poly{Curve::Kind::kPolyline, {{0, 0}, {1, 0}, {1, 2}}};
  CHECK(poly.at(0.75) == Point2{1, 1});
}

TEST_CASE("bad tile files give located, clear errors", "[evolve][tiles]") {
  // Files.
  try {
    readTileFile(kData + "bad_syntax.json");
    FAIL("bad_syntax.json was accepted");
  } catch (const TileFileError& e) {
    const std::string m = e.what();
    CHECK(m.find("bad_syntax.json:5:") != std::string::npos);
    CHECK(m.find("not valid JSON") != std::string::npos);
    CHECK(e.part.empty());
  }
  try {
    readTileFile(kData + "bad_cubic.json");
    FAIL("bad_cubic.json was accepted");
  } catch (const TileFileError& e) {
    CHECK(std::string(e.what()).find("bad_cubic.json: loci[0].cubic: a cubic needs 4 points, got 3") != std::string::npos);    CHECK(e.part == "loci");  // the part, for a grammar's tileset to blame its item
    CHECK(e.index == 0);
  }
  try {
    readTileFile(kData);  // a directory
    FAIL("a directory was read as a tile file");
  } catch (const TileFileError& e) {
    CHECK(std::string(e.what()).find("tile file") != std::string::npos);
  }
  CHECK_THROWS_AS(readTileFile(kData + "no_such_file.json"), TileFileError);

  // Contents.
  const std::string line = R"({"name": "l", "polyline": [[0, 0.5], [1, 0.5]]})";
  const std::string section = R"({"polyline": [[-1, 0], [0, 1], [1, 0]]})";
  auto file = [&](const std::string& loci, const std::string& sections, const std::string& extra = "") {
    return "{\"loci\": [" + loci + "], \"sections\": [" + sections + "]" + extra + "}";
  };
  CHECK(errorOf(file(line, section)).empty());
  CHECK(errorOf("[1, 2]") == "t.json: a tile file is a JSON object, got an array");
  CHECK(errorOf(R"({"sections": [)" + section + "]}") == "t.json: missing \"loci\"");
  CHECK(errorOf(file(line, section, R"(, "orientation": [0])")) ==
        "t.json: unknown key \"orientation\" (expected \"loci\", \"sections\", \"orientations\", \"symbols\")");
  CHECK(errorOf(file(R"({"polyline": [[0, 0.5], [1.5, 0.5]]})", section)) ==
        "t.json: loci[0].polyline[1]: point (1.5, 0.5) is outside the tile's unit square [0,1] x [0,1]");
  CHECK(errorOf(file(R"({"polyline": [[0, 0.5]]})", section)) ==
        "t.json: loci[0].polyline: a polyline needs at least 2 points, got 1");
  CHECK(errorOf(file(R"({"polyline": [[0, 0.5], [1]]})", section)) ==
        "t.json: loci[0].polyline[1]: a point is an array of two numbers [x, y], got an array of 1");
  CHECK(errorOf(file(R"({"name": "x"})", section)) == "t.json: loci[0]: needs a curve: \"polyline\" or \"cubic\"");
  CHECK(errorOf(file(R"({"polyline": [[0, 0], [1, 1]], "spline": []})", section)) ==
        "t.json: loci[0]: unknown key \"spline\" (expected \"name\" and one of \"polyline\", \"cubic\")");
  CHECK(errorOf(file(line, R"({"polyline": [[-1, 0], [0, 1], [1, 0.5]]})")) ==
        "t.json: sections[0].polyline: a cross-section runs from (-1, 0) to (1, 0) (Elber's blending, paper §2.4); "
        "this one runs from (-1, 0) to (1, 0.5)");
  CHECK(errorOf(file(line, section, R"(, "orientations": [0, 45])")) ==
        "t.json: orientations[1]: an orientation is 0, 90, 180 or 270, got 45");
  CHECK(errorOf(file(line, section, R"(, "orientations": [90, 90])")) ==
        "t.json: orientations: an orientation is listed twice");
  CHECK(errorOf(file(line + "," + line, section, R"(, "symbols": "A")")) ==
        "t.json: symbols: needs one letter per locus x cross-section: 2 x 1 = 2, got 1");
  CHECK(errorOf(file(line + "," + line, section, R"(, "symbols": "AA")")) ==
        "t.json: symbols[1]: letter 'A' is used twice");
  CHECK(errorOf(file(line, section, R"(, "symbols": "7")")) ==
        "t.json: symbols[0]: a symbol is a letter A-Z or a-z, not '7'");
  CHECK(errorOf(file("", section)) == "t.json: loci: at least one locus is needed");
}
