// The solver: every output passes the independent checker; blocks never break consistency;
// a seed gives one model; constraints (border, periodic, symmetry, mask, connectivity)
// hold; failures say where and why; limits stop a run.
#include "test_helpers.h"

#include <cstdio>

using namespace synth_test;

namespace {

struct Case {
  const char* file;
  GridSize size;
};
const Case kCases[] = {
    {"castle.txt", {24, 24, 6}},   {"city.txt", {24, 24, 5}},   {"landscape.txt", {24, 24, 6}},
    {"roads.json", {24, 24, 1}},   {"flowers.png", {24, 24, 1}},
};

SynthesisResult runChecked(const Example& ex, const SynthesisOptions& o) {
  SynthesisResult r = synthesize(ex, o);
  if (r.consistent) {
    auto v = checkModel(r.labels, ex, specFor(o));
    INFO(violations(v));
    CHECK(v.empty());
  }
  return r;
}

// Whole-grid minimum-entropy order, one attempt: what the order tests below vary by seed.
SynthesisOptions minEntropy(GridSize size, uint64_t seed) {
  SynthesisOptions o;
  o.size = size;
  o.order = CellOrder::kMinEntropy;
  o.seed = seed;
  return o;
}

int nonEmpty(const LabelGrid& g, const Example& ex) {
  int n = 0;
  for (int32_t l : g.data()) n += l != ex.emptyLabel;
  return n;
}

}  // namespace

TEST_CASE("every example synthesizes a checker-clean model (whole grid and blocks)", "[synthesis][solver]") {
  for (const auto& c : kCases) {
    INFO(c.file);
    Example ex = load(c.file);
    SynthesisOptions o;
    o.size = c.size;
    o.attempts = 20;
    o.seed = 11;
    SynthesisResult whole = runChecked(ex, o);
    INFO(whole.failure.message);
    CHECK(whole.ok);
    o.block = {10, 10, 10};
    SynthesisResult blocks = runChecked(ex, o);
    CHECK(blocks.ok);
    CHECK(blocks.consistent);
    CHECK(nonEmpty(blocks.labels, ex) > 0);
  }
}

TEST_CASE("minimum-entropy order gives checker-clean models", "[synthesis][solver]") {
  Example ex = load("castle.txt");
  SynthesisOptions o;
  o.size = {20, 20, 6};
  o.attempts = 20;
  o.order = CellOrder::kMinEntropy;
  CHECK(runChecked(ex, o).ok);
  o.block = {8, 8, 6};
  CHECK(runChecked(ex, o).ok);
}

TEST_CASE("minimum-entropy order backtracks: undone decisions leave checker-clean models", "[synthesis][solver]") {
  // The Summer-like tile set (no diagonal tiles) makes whole-grid entropy order meet
  // contradictions; one attempt per seed, so each success with backtracks is a model
  // rebuilt from undone decisions.
  Example ex = load("summer_like.json");
  int succeededAfterBacktracking = 0, succeeded = 0;
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    const SynthesisOptions o = minEntropy({40, 40, 1}, seed);
    const SynthesisResult r = runChecked(ex, o);
    CHECK(r.stats.attempts == 1);
    succeeded += r.ok;
    succeededAfterBacktracking += r.ok && r.stats.backtracks > 0;
    const SynthesisResult again = synthesize(ex, o);  // a seed gives one model, backtracks included
    CHECK(again.labels.data() == r.labels.data());
    CHECK(again.stats.backtracks == r.stats.backtracks);
  }
  CHECK(succeeded >= 6);
  CHECK(succeededAfterBacktracking >= 2);
}

TEST_CASE("minimum-entropy order repairs what backtracking cannot: the Summer-like set at 100x100", "[synthesis][solver]") {
  // Chronological backtracking alone succeeded on 31 % of first attempts here; reopening
  // the neighbourhood of a stubborn contradiction makes every seed succeed, and every
  // model passes the independent checker.
  Example ex = load("summer_like.json");
  uint64_t repairs = 0;
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    INFO("seed " << seed);
    const SynthesisResult r = runChecked(ex, minEntropy({100, 100, 1}, seed));
    CHECK(r.ok);
    CHECK(r.stats.attempts == 1);
    repairs += r.stats.repairs;
  }
  CHECK(repairs > 0);
}

TEST_CASE("minimum-entropy order breaks ties by position: the city succeeds on the first attempt", "[synthesis][solver]") {
  // Random ties succeeded on 70-90 % of first attempts here (bench_synthesis
  // --orientations: every axis order, now 100 %).
  Example ex = load("city.txt");
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    INFO("seed " << seed);
    CHECK(runChecked(ex, minEntropy({40, 40, 5}, seed)).ok);
  }
}

TEST_CASE("block modification never breaks consistency, even when blocks fail", "[synthesis][solver][blocks]") {
  // Large blocks fail often; each failure must leave the model as it was.
  Example ex = load("castle.txt");
  int failedBlocks = 0;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    SynthesisOptions o;
    o.size = {30, 30, 6};
    o.block = {24, 24, 6};
    o.blockRetries = 0;
    o.seed = seed;
    SynthesisResult r = runChecked(ex, o);
    CHECK(r.consistent);
    failedBlocks += r.stats.blocksFailed;
    for (const auto& f : r.blockFailures) CHECK_THAT(f.message, Catch::Contains("in block #"));
  }
  INFO("failed blocks over 10 seeds: " << failedBlocks);
  // A block stopped half-way (here by the step limit) is reverted: the model stays whole.
  for (uint64_t steps : {6000u, 8000u, 12000u}) {  // the trivial model takes 5400
    SynthesisOptions o;
    o.size = {30, 30, 6};
    o.block = {10, 10, 6};
    o.maxAssignments = steps;
    SynthesisResult r = runChecked(ex, o);
    CHECK_FALSE(r.ok);
    CHECK(r.failure.kind == SynthesisFailure::kStepLimit);
    CHECK(r.consistent);
    CHECK_THAT(r.failure.message, Catch::Contains("in block #"));
  }
}

TEST_CASE("determinism: a seed gives one model, seeds differ", "[synthesis][solver]") {
  for (const auto& c : kCases) {
    Example ex = load(c.file);
    SynthesisOptions o;
    o.size = c.size;
    o.block = {8, 8, 8};
    o.seed = 5;
    SynthesisResult a = synthesize(ex, o), b = synthesize(ex, o);
    CHECK(a.labels == b.labels);
    o.seed = 6;
    SynthesisResult d = synthesize(ex, o);
    CHECK(d.labels != a.labels);
  }
}

TEST_CASE("border constraints: closed faces, fixed ground, outside labels", "[synthesis][constraints]") {
  Example ex = load("castle.txt");
  SynthesisOptions o;
  o.size = {20, 16, 6};
  o.block = {10, 10, 10};
  SynthesisResult r = runChecked(ex, o);
  REQUIRE(r.ok);
  const int32_t g = ex.findLabel("g");
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 20; ++x) CHECK(r.labels.at(x, y, 0) == g);
  // Roads tile set: outside every face is grass, so no road leaves the grid.
  Example roads = load("roads.json");
  SynthesisOptions q;
  q.size = {20, 20, 1};
  q.attempts = 20;
  SynthesisResult rr = runChecked(roads, q);
  CHECK(rr.ok);
}

TEST_CASE("periodic output wraps around", "[synthesis][constraints]") {
  Example ex = load("roads.json");
  SynthesisOptions o;
  o.size = {16, 16, 1};
  o.periodic = {true, true, false};
  o.border = BorderSpec{};
  o.attempts = 20;
  SynthesisResult r = runChecked(ex, o);
  CHECK(r.ok);
  o.block = {8, 8, 1};
  CHECK(runChecked(ex, o).ok);
}

TEST_CASE("symmetry constraints: mirror, rotation, translation", "[synthesis][constraints][symmetry]") {
  Example ex = load("roads.json");
  const SymmetrySpec::Kind kinds[] = {SymmetrySpec::kMirrorX, SymmetrySpec::kMirrorY, SymmetrySpec::kRotate90,
                                      SymmetrySpec::kRotate180};
  for (auto kind : kinds) {
    INFO(symmetryName(kind));
    SynthesisOptions o;
    o.size = {20, 20, 1};
    o.symmetry = {{kind, 0}};
    o.attempts = 30;
    SynthesisResult r = runChecked(ex, o);
    CHECK(r.ok);
    o.block = {8, 8, 1};
    SynthesisResult b = runChecked(ex, o);
    CHECK(b.ok);
    CHECK(nonEmpty(b.labels, ex) > 0);
  }
  SynthesisOptions t;
  t.size = {24, 12, 1};
  t.symmetry = {{SymmetrySpec::kTranslateX, 8}};
  t.attempts = 30;
  CHECK(runChecked(ex, t).ok);
  // Mirror symmetry of a 3D example with mirrored pieces declared in the file.
  Example castle = load("castle.txt");
  SynthesisOptions m;
  m.size = {24, 24, 6};
  m.block = {10, 10, 6};
  m.symmetry = {{SymmetrySpec::kMirrorX, 0}, {SymmetrySpec::kMirrorY, 0}};
  SynthesisResult cr = runChecked(castle, m);
  CHECK(cr.ok);
  CHECK(nonEmpty(cr.labels, castle) > 24 * 24);
}

TEST_CASE("the checker catches broken models", "[synthesis][checker]") {
  Example ex = load("roads.json");
  SynthesisOptions o;
  o.size = {12, 12, 1};
  o.symmetry = {{SymmetrySpec::kMirrorX, 0}};
  o.attempts = 30;
  SynthesisResult r = synthesize(ex, o);
  REQUIRE(r.ok);
  REQUIRE(checkModel(r.labels, ex, specFor(o)).empty());
  LabelGrid broken = r.labels;
  broken.at(3, 5, 0) = ex.findLabel("cross");
  CHECK(!checkModel(broken, ex, specFor(o)).empty());
  broken = r.labels;
  broken.at(0, 0, 0) = ex.findLabel("line");
  CHECK(!checkModel(broken, ex, specFor(o)).empty());
}

TEST_CASE("a mask shapes the model like a letter", "[synthesis][constraints][mask]") {
  Example ex = load("city.txt");
  SynthesisOptions o;
  o.size = {36, 36, 5};
  o.block = {10, 10, 5};
  std::string err;
  REQUIRE(maskFromImage(examplePath("letter_f.png"), o.size, ex, 4.0, o.weights, err));
  SynthesisResult r = runChecked(ex, o);
  REQUIRE(r.ok);
  int inside = 0, outside = 0;
  for (int64_t c = 0; c < r.labels.cellCount(); ++c) {
    if (ex.labels[size_t(r.labels[c])].background) continue;
    (o.weights.region[size_t(c)] ? inside : outside)++;
  }
  CHECK(outside == 0);
  CHECK(inside > 100);
}

TEST_CASE("connectivity: connect labels grow from one seed into one group", "[synthesis][constraints][connectivity]") {
  Example ex = load("roads.json");
  int ok = 0;
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    SynthesisOptions o;
    o.size = {24, 24, 1};
    o.seed = seed;
    o.connectivity.enabled = true;
    o.connectivity.seeds = 1;
    o.attempts = 20;
    SynthesisResult r = runChecked(ex, o);
    if (!r.ok) continue;
    ++ok;
    std::vector<uint8_t> conn(size_t(ex.labelCount()));
    for (int l = 0; l < ex.labelCount(); ++l) conn[size_t(l)] = ex.labels[size_t(l)].connect;
    CHECK(countConnectedGroups(r.labels, conn, o.periodic) == 1);
  }
  CHECK(ok >= 8);
}

TEST_CASE("failure reports say where and why, limits stop runs", "[synthesis][errors]") {
  // A 2-label alternation with nothing to end it: no 3-wide model exists.
  Example ex = parse("size 2 1\nA B\n");
  SynthesisOptions o;
  o.size = {3, 1, 1};
  SynthesisResult r = synthesize(ex, o);
  CHECK_FALSE(r.ok);
  CHECK(r.failure.kind == SynthesisFailure::kContradiction);
  CHECK_THAT(r.failure.message, Catch::Contains("contradiction at cell ("));
  CHECK_THAT(r.failure.message, Catch::Contains("assignments"));

  Example castle = load("castle.txt");
  SynthesisOptions s;
  s.size = {30, 30, 6};
  s.maxAssignments = 100;
  r = synthesize(castle, s);
  CHECK_FALSE(r.ok);
  CHECK(r.failure.kind == SynthesisFailure::kStepLimit);
  CHECK(r.stats.assignments <= 100);
  s.maxAssignments = 0;
  s.timeLimitSeconds = 0;
  s.block = {10, 10, 10};
  r = synthesize(castle, s);
  CHECK_FALSE(r.ok);
  CHECK(r.failure.kind == SynthesisFailure::kTimeLimit);
  CHECK_THAT(r.failure.message, Catch::Contains("time limit"));

  SynthesisOptions bad;
  bad.size = {10, 10, 3};
  r = synthesize(load("roads.json"), bad);
  CHECK(r.failure.kind == SynthesisFailure::kBadOptions);
  CHECK_THAT(r.failure.message, Catch::Contains("planar"));
  bad.size = {10, 12, 1};
  bad.symmetry = {{SymmetrySpec::kRotate90, 0}};
  r = synthesize(load("roads.json"), bad);
  CHECK(r.failure.kind == SynthesisFailure::kBadOptions);
}

TEST_CASE("piece placements: asset, quarter turns, cell box", "[synthesis][placements]") {
  Example ex = parse("size 3 1\nlabel . none empty\nlabel A cube rot=1\n. A .\n");
  LabelGrid g(GridSize{3, 1, 1}, 0);
  g.at(1, 0, 0) = 1;
  PlacementFrame f;
  f.cellSize = {2, 2, 3};
  f.yUp = false;
  auto p = piecePlacements(g, ex, f);
  REQUIRE(p.size() == 1);
  CHECK(p[0].asset == "cube");
  CHECK(p[0].rotation == 1);
  CHECK(p[0].boxMin == std::array<double, 3>{2, 0, 0});
  CHECK(p[0].boxMax == std::array<double, 3>{4, 2, 3});
  // The unit box corner (0,0,0) stands upright at (0,1,0) (the asset's y along the grid's
  // z: its z goes to 1 - z along y), then turned a quarter about the cell centre, (x, y)
  // -> (1 - y, x): (0,0,0), scaled by 2 and moved to the cell: (2,0,0).
  CHECK(p[0].transform[12] == Approx(2));
  CHECK(p[0].transform[13] == Approx(0));
  CHECK(p[0].transform[14] == Approx(0));
  f.yUp = true;
  p = piecePlacements(g, ex, f);
  CHECK(p[0].boxMin[1] == Approx(0));  // grid z -> world y
  CHECK(p[0].boxMax[1] == Approx(3));
  CHECK(p[0].boxMin[2] == Approx(-2)); // grid y -> world -z
  fgsg::rt::InstanceList list;
  appendInstances(p, "Synth", list);
  CHECK(list.instances.size() == 1);
  CHECK(list.assets == std::vector<std::string>{"cube"});
}

TEST_CASE("piece placements: a cylinder stands upright, a quad lies on the floor", "[synthesis][placements]") {
  // #46: the built-in cylinder's axis is its y; in the y-up output it must stay world Y
  // (it lay along -Z). A quad (facing +z) stays a floor tile facing world +Y.
  Example ex = parse("size 2 1\nlabel T cylinder\nlabel Q quad\nT Q\n");
  LabelGrid g(GridSize{2, 1, 1}, 0);
  g.at(1, 0, 0) = 1;
  PlacementFrame f;
  f.cellSize = {1, 1, 3};  // tall cells: a standing asset is 3 high
  auto p = piecePlacements(g, ex, f);
  REQUIRE(p.size() == 2);
  // Column k of the 4x4 column-major transform is where the asset's axis k goes.
  const auto& t = p[0].transform;
  CHECK(t[4] == Approx(0));  // asset y -> world (0, 3, 0): up, the cell's height
  CHECK(t[5] == Approx(3));
  CHECK(t[6] == Approx(0));
  CHECK(t[0] == Approx(1));  // asset x -> world x
  CHECK(t[8] == Approx(0));  // asset z -> world +z, one cell deep
  CHECK(t[9] == Approx(0));
  CHECK(t[10] == Approx(1));
  CHECK(t[12] == Approx(0));  // corner (0,0,0) -> world (0, 0, -1): the cell spans z -1..0
  CHECK(t[13] == Approx(0));
  CHECK(t[14] == Approx(-1));
  const auto& q = p[1].transform;
  CHECK(q[8] == Approx(0));  // the quad's normal (its z) -> world +Y
  CHECK(q[9] == Approx(3));
  CHECK(q[10] == Approx(0));
  CHECK(q[13] == Approx(0));  // on the floor
}
