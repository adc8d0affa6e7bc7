// Example formats: the label-grid text format, WFC tile sets, labelled images; and the
// errors bad input gives.
#include "test_helpers.h"

#include <set>

using namespace synth_test;

namespace {
const char* kSmall = R"(# a small example
size 4 3
label . none empty
label A cube
label B cube rot=1 color=#ff0000 weight=2
. A A .
. B B .
. . . .
)";
}

TEST_CASE("label grid text format: parse, transition pairs, round trip", "[synthesis][format]") {
  Example ex = parse(kSmall);
  REQUIRE(ex.labelCount() == 3);
  CHECK(ex.emptyLabel == 0);
  CHECK(ex.dims == 2);
  const LabelGrid& g = *ex.grid;
  // First row of the file is y = ny-1.
  CHECK(g.at(1, 2, 0) == 1);
  CHECK(g.at(1, 1, 0) == 2);
  CHECK(g.at(0, 0, 0) == 0);
  CHECK(ex.labels[2].rotation == 1);
  CHECK(ex.labels[2].hasColor);
  CHECK(ex.labels[2].weight == 2.0);
  // T_x: A A, . A, A ., B B, ...
  std::set<std::pair<int, int>> tx(ex.allowed[0].begin(), ex.allowed[0].end());
  CHECK(tx.count({1, 1}));
  CHECK(tx.count({0, 1}));
  CHECK(!tx.count({1, 2}));
  std::set<std::pair<int, int>> ty(ex.allowed[1].begin(), ex.allowed[1].end());
  CHECK(ty.count({2, 1}));  // B below A: A at +y of B
  CHECK(!ty.count({1, 2}));

  const std::string text = writeLabelGridText(g, ex);
  Example back = parse(text);
  CHECK(*back.grid == g);
  REQUIRE(back.labelCount() == ex.labelCount());
  for (int l = 0; l < ex.labelCount(); ++l) {
    CHECK(back.labels[size_t(l)].name == ex.labels[size_t(l)].name);
    CHECK(back.labels[size_t(l)].asset == ex.labels[size_t(l)].asset);
    CHECK(back.labels[size_t(l)].rotation == ex.labels[size_t(l)].rotation);
  }
  CHECK(back.emptyLabel == ex.emptyLabel);
}

TEST_CASE("label grid: CSV rows and undeclared labels", "[synthesis][format]") {
  Example ex = parse("size 3 2\n0,1,0\n0,0,0\n");
  CHECK(ex.labelCount() == 2);
  CHECK(ex.emptyLabel == 0);
  CHECK(ex.labels[1].asset == "cube");
  CHECK(ex.labels[0].asset.empty());
}

TEST_CASE("label grid: errors point at file:line:col", "[synthesis][format][errors]") {
  auto errorOf = [](const std::string& text) {
    Example ex;
    Diagnostics d;
    CHECK_FALSE(parseExampleText(text, "bad.txt", ex, d));
    REQUIRE(!d.empty());
    return formatDiagnostic(d[0]);
  };
  CHECK_THAT(errorOf("size 3 1\nlabel . none\n. X .\n"),
             Catch::Contains("bad.txt:3:3: error[E707]: unknown label `X`"));
  CHECK_THAT(errorOf("size 3 1\n. . . .\n"), Catch::Contains("bad.txt:2:7: error[E706]: row has 4 labels, expected 3"));
  CHECK_THAT(errorOf("size 3 -1\n"), Catch::Contains("bad.txt:1:8: error[E702]"));
  CHECK_THAT(errorOf("size 2 2\n. .\n"), Catch::Contains("error[E706]: grid ends after 1 rows, expected 2"));
  CHECK_THAT(errorOf(". .\n"), Catch::Contains("bad.txt:1:1: error[E705]"));
  CHECK_THAT(errorOf("size 2 1\nlabel A cube rot=7\nA A\n"), Catch::Contains("bad.txt:2:14: error[E703]: bad label option `rot=7`"));
  CHECK_THAT(errorOf("size 2 1 2\nlayer 1\n. .\n"), Catch::Contains("bad.txt:2:1: error[E705]: expected `layer 0`"));
  CHECK_THAT(errorOf("size 2 1\nborder top .\n. .\n"), Catch::Contains("bad.txt:2:8: error[E704]: unknown face"));
  Example ex;
  Diagnostics d;
  CHECK_FALSE(loadExample(examplePath("does_not_exist.txt"), ex, d));
  REQUIRE(d.size() == 1);
  CHECK(d[0].code == "E701");
}

TEST_CASE("tile set: symmetry classes expand to orientations, rules closed under D4", "[synthesis][format]") {
  Example ex = load("roads.json");
  // empty(X) 1 + line(I) 2 + corner(L) 4 + tee(T) 4 + cross(X) 1.
  CHECK(ex.labelCount() == 12);
  CHECK(ex.dims == 2);
  CHECK(ex.labels[ex.findLabel("corner.3")].rotation == 3);
  CHECK(ex.findLabel("line.1") >= 0);
  CHECK(ex.findLabel("line.2") < 0);
  // The file lists every valid left/right pair; the D4 closure must add none of its own.
  CHECK(ex.allowed[0].size() == 74);
  // Rotating the x rules by 90° gives the y rules.
  std::set<std::pair<int, int>> ty(ex.allowed[1].begin(), ex.allowed[1].end());
  for (auto [b, c] : ex.allowed[0]) CHECK(ty.count({ex.rot90[size_t(b)], ex.rot90[size_t(c)]}));
  // Mirror maps are involutions.
  for (int l = 0; l < ex.labelCount(); ++l) CHECK(ex.mirrorX[size_t(ex.mirrorX[size_t(l)])] == l);
}

TEST_CASE("tile set: malformed JSON and bad rules are reported", "[synthesis][format][errors]") {
  Example ex;
  Diagnostics d;
  CHECK_FALSE(parseTileSetJson("{\n \"tiles\": [ {\"name\": \"a\",, } ]\n}", "t.json", ex, d));
  REQUIRE(!d.empty());
  CHECK(d[0].line == 2);
  CHECK(d[0].code == "E711");
  d.clear();
  CHECK_FALSE(parseTileSetJson(R"({"tiles":[{"name":"a","symmetry":"Q"}]})", "t.json", ex, d));
  CHECK_THAT(formatDiagnostics(d), Catch::Contains("unknown symmetry class `Q`"));
  d.clear();
  CHECK_FALSE(parseTileSetJson(R"({"tiles":[{"name":"a"}],"neighbors":[{"left":"a","right":"zz"}]})", "t.json", ex, d));
  CHECK_THAT(formatDiagnostics(d), Catch::Contains("bad neighbour rule"));
}

namespace {
// The diagnostics of a tile set that must not load: one or more, each E712 (bad content)
// or E711 (not JSON), never an exception.
std::string tileSetErrors(const std::string& json) {
  Example ex;
  Diagnostics d;
  bool ok = true;
  REQUIRE_NOTHROW(ok = parseTileSetJson(json, "t.json", ex, d));
  CHECK_FALSE(ok);
  REQUIRE(!d.empty());
  return formatDiagnostics(d);
}
}  // namespace

TEST_CASE("tile set: a field of the wrong type is a located error naming the tile and key",
          "[synthesis][format][errors]") {
  const std::string rules = R"(, "neighbors": [{"left": "a", "right": "a"}]})";
  struct Case {
    const char* tiles;
    const char* expected;
  };
  const Case cases[] = {
      {R"({"tiles": [{"name": "a", "symmetry": 3}])",
       "tile `a`: \"symmetry\" must be a symmetry class X, L, T, I, \\ or F (a string), got number (3)"},
      {R"({"tiles": [{"name": "a", "asset": 5}])",
       "tile `a`: \"asset\" must be an asset name (a string; \"none\" for no asset), got number (5)"},
      {R"({"tiles": [{"name": "a", "empty": "yes"}])", "tile `a`: \"empty\" must be true or false, got string (\"yes\")"},
      {R"({"tiles": [{"name": "a", "connect": 1}])", "tile `a`: \"connect\" must be true or false, got number (1)"},
      {R"({"tiles": [{"name": "a", "background": 0}])", "tile `a`: \"background\" must be true or false, got number (0)"},
      {R"({"tiles": [{"name": "a", "weight": "heavy"}])", "tile `a`: \"weight\" must be a number >= 0, got string (\"heavy\")"},
      {R"({"tiles": [{"name": "a", "color": 255}])", "tile `a`: \"color\" must be a string \"#rrggbb\", got number (255)"},
  };
  for (const Case& c : cases) {
    INFO(c.tiles);
    const std::string errors = tileSetErrors(std::string(c.tiles) + rules);
    CHECK(errors.rfind("t.json:1:", 0) == 0);  // the file and the tile's line
    CHECK_THAT(errors, Catch::Contains("error[E712]: " + std::string(c.expected)));
  }
  // In a file of several lines, the line is the key's, within its tile (before or after
  // the name); for a border entry, within the entry.
  const std::string errors = tileSetErrors(
      "{\"tiles\": [\n  {\"name\": \"b\", \"connect\": true,\n   \"weight\": -1},\n  {\"symmetry\": \"X\",\n"
      "   \"connect\": 2,\n   \"name\": \"a\"}\n]}");
  CHECK_THAT(errors, Catch::Contains("t.json:3: error[E712]: tile `b`: \"weight\" must be a number >= 0, got number (-1)"));
  CHECK_THAT(errors, Catch::Contains("t.json:5: error[E712]: tile `a`: \"connect\" must be true or false, got number (2)"));
  CHECK_THAT(tileSetErrors("{\"tiles\": [{\"name\": \"a\"}],\n \"border\": {\"xmax\": {\"label\": \"a\", \"fixed\": true},\n"
                           "  \"xmin\": {\"label\": \"a\",\n   \"fixed\": 1}}}"),
             Catch::Contains("t.json:4: error[E712]: border entry `xmin`: \"fixed\" must be true or false"));
}

TEST_CASE("tile set: bad border entries and values JSON cannot hold are errors", "[synthesis][format][errors]") {
  const std::string tiles = R"({"tiles": [{"name": "a"}], "neighbors": [{"left": "a", "right": "a"}])";
  CHECK_THAT(tileSetErrors(tiles + R"(, "border": {"xmin": {"label": "a", "fixed": "yes"}}})"),
             Catch::Contains("border entry `xmin`: \"fixed\" must be true or false, got string (\"yes\")"));
  CHECK_THAT(tileSetErrors(tiles + R"(, "border": {"xmin": {"label": 7}}})"), Catch::Contains("bad border entry `xmin`"));
  CHECK_THAT(tileSetErrors(tiles + R"(, "border": ["xmin"]})"),
             Catch::Contains("\"border\" must be an object {\"FACE\": \"LABEL\", ...}, got array"));
  CHECK_THAT(tileSetErrors(tiles + R"(, "neighbors": 5})"), Catch::Contains("\"neighbors\" must be an array"));
  CHECK_THAT(tileSetErrors(R"({"tiles": [{"name": 1}]})"), Catch::Contains("every tile needs a \"name\" string"));
  CHECK_THAT(tileSetErrors(R"({"tiles": {"name": "a"}})"), Catch::Contains("a tile set is an object with a \"tiles\" array"));
  // A number beyond a double is reported by the reader, not thrown.
  CHECK_THAT(tileSetErrors(R"({"tiles": [{"name": "a", "weight": 1e400}]})"), Catch::Contains("error[E711]"));
  // Good values of every field still load.
  Example ex;
  Diagnostics d;
  CHECK(parseTileSetJson(R"({"tiles": [{"name": "a", "symmetry": "L", "asset": "none", "empty": true,
      "connect": false, "background": true, "weight": 2, "color": "#ff0000"}],
      "border": {"xmin": {"label": "a", "fixed": true}, "xmax": "a.1"}})", "t.json", ex, d));
  CHECK(d.empty());
  CHECK(ex.labelCount() == 4);
  CHECK(ex.border.fixed[0] == 0);
}

TEST_CASE("example image: each colour a label", "[synthesis][format]") {
  Example ex = load("flowers.png");
  CHECK(ex.labelCount() == 6);
  CHECK(ex.grid->size() == GridSize{12, 11, 1});
  CHECK(ex.labels[size_t(ex.emptyLabel)].name == "ebf0fa");
  CHECK(ex.dims == 2);
}
