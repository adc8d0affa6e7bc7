// Whole grammars through the JIT (deriveCompiled) against the interpreter: the same
// instances bit for bit, the same statistics and the same messages, also where direct
// derivation must give way to the engine's own order (limits, errors); the object
// cache; a program that does not belong to the grammar.
#include "backend/interp/interpreter.h"
#include "backend/jit/jit.h"
#include "backend/native/object_cache.h"
#include "frontend/diagnostics.h"
#include "ir/pipeline.h"
#include "ir/program_layout.h"
#include "runtime/abi.h"

#include <catch2/catch.hpp>

#include <Eigen/Core>

#include <filesystem>
#include <map>
#include <fstream>
#include <iostream>
#include <random>
#include <string>

namespace {

using namespace fgsg;

ir::Module compile(const std::string& text) {
  auto file = frontend::SourceFile::make("test.fgsg", text);
  frontend::Diagnostics diags(&file);
  ir::Module m;
  if (!ir::compileSource(file, m, diags)) {
    diags.print(std::cerr);
    FAIL("the test grammar does not compile");
  }
  return m;
}

const backend::native::ObjectCache kNoCache{std::string()};

void requireSame(const rt::DeriveResult& a, const rt::DeriveResult& b) {
  REQUIRE(a.ok == b.ok);
  REQUIRE(a.messages.size() == b.messages.size());
  for (size_t i = 0; i < a.messages.size(); ++i) {
    CHECK(a.messages[i].code == b.messages[i].code);
    CHECK(a.messages[i].line == b.messages[i].line);
    CHECK(a.messages[i].message == b.messages[i].message);
  }
  CHECK(a.stats.shapesCreated == b.stats.shapesCreated);
  CHECK(a.stats.rewrites == b.stats.rewrites);
  CHECK(a.stats.terminals == b.stats.terminals);
  REQUIRE(a.instances.instances.size() == b.instances.instances.size());
  for (size_t i = 0; i < a.instances.instances.size(); ++i) {
    CHECK(a.instances.instances[i].transform == b.instances.instances[i].transform);
    CHECK(a.instances.instances[i].asset == b.instances.instances[i].asset);
    CHECK(a.instances.instances[i].color == b.instances.instances[i].color);
  }
  CHECK(a.instances.params == b.instances.params);
}

// Derives `text` both ways with `options`; returns the interpreter's result.
rt::DeriveResult bothEngines(const std::string& text, const rt::DeriveOptions& options = {}) {
  const ir::Module m = compile(text);
  backend::jit::Jit jit;
  const auto code = jit.compileProgram(m, text, kNoCache);
  rt::AssetLibrary assets;
  rt::DeriveResult interp = backend::interpret(m, options, assets);
  rt::DeriveResult jitted = backend::deriveCompiled(m, code.program(), options, assets);
  requireSame(interp, jitted);
  return interp;
}

// Direct symbols (A, B) feeding symbols that place instances, with random weights.
const char* kMixed = R"(
  attr depth = 9;
  Axiom ~> A(0) T(3, 0, 0) Tree(0);
  A(n) : n < depth ~> [ Rz(Rand(20, 40)) T(0.5, 0, 0) A(n + 1) ] [ Rz(-50) T(0.5, 0, 0) A(n + 1) ] B(n + 1) : 0.9
                   ~> [ Rz(-30) S(1r, 0.5r, 1r) T(0.4, 0, 0) A(n + 2) ] : 0.1;
  A(n) ~> Leaf;
  B(n) ~> R(10, 20, 30) A(n + 1);
  Tree(n) : n < 5 ~> [ Rz(25) T(0, 1, 0) Tree(n + 1) ] [ Rz(-25) T(0, 1, 0) Tree(n + 1) ] I("cube");
  Tree(n) ~> S(0.3, 0.3, 0.3) I("sphere");
)";

}  // namespace

TEST_CASE("compiled grammars derive exactly what the interpreter derives") {
  SECTION("direct symbols next to instancing ones") {
    const auto r = bothEngines(kMixed);
    CHECK(r.stats.shapesCreated > 1000);
    CHECK(r.instances.instances.size() == 63);
  }
  SECTION("several seeds") {
    for (uint64_t seed : {1u, 7u, 12345u}) {
      rt::DeriveOptions o;
      o.seed = seed;
      bothEngines(kMixed, o);
    }
  }
  SECTION("instances placed at every depth come out in breadth-first order") {
    // Direct code derives depth-first; the engine puts the instances back in order.
    const auto r = bothEngines(R"(
      Axiom ~> I("sphere") Tree(0) T(5, 0, 0) Tree(1);
      Tree(n) : n < 6 ~> I("cube") [ Rz(30) T(0, 1, 0) Tree(n + 1) ] [ Rz(-30) T(0, 1, 0) Tree(n + 2) ]
                         S(0.2, 0.2, 0.2) I("cube");
      Tree(n) ~> S(0.3, 0.3, 0.3) I("sphere");
    )");
    CHECK(r.instances.instances.size() == 99);
  }
  SECTION("depth-first derivation") {
    bothEngines(R"(
      derive depthfirst;
      Axiom ~> Tree(0) I("sphere");
      Tree(n) : n < 6 ~> [ Rz(30) T(0, 1, 0) Tree(n + 1) ] I("cube") [ Rz(-30) T(0, 1, 0) Tree(n + 2) ];
      Tree(n) ~> S(0.3, 0.3, 0.3) I("sphere");
    )");
  }
  SECTION("priorities: the order is the engine's own") {
    bothEngines(R"(
      Axiom ~> Low(0) High(0);
      priority 1:
      High(n) : n < 4 ~> [ T(1, 0, 0) High(n + 1) ] I("cube") Low(n);
      priority 0:
      Low(n) : n < 3 ~> T(0, 1, 0) I("sphere") Low(n + 1);
    )");
  }
  SECTION("model synthesis in the axiom, its pieces' symbols placing instances") {
    const auto dir = std::filesystem::temp_directory_path() / "fgsg-test-jit-synthesis";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "stripes.txt") << "label g quad\nlabel W cube\nsize 4 2 1\nlayer 0\ng W g W\ng W g W\n";
    rt::DeriveOptions o;
    o.assetDirs = {dir.string()};
    const auto r = bothEngines(R"(
      axiom: S(8, 1, 6) Synthesize("stripes.txt", 8, 6, 1) T(0, 2, 0) W;
      W ~> I("sphere") T(0, 0, 1) V;
      V ~> I("cube");
    )", o);
    CHECK(r.instances.instances.size() == 24 + 2 * 25);
    std::filesystem::remove_all(dir);
  }
  SECTION("splits, components and parameters of every type") {
    bothEngines(R"(
      Lot ~> S(10, 8, 6) Mass("brick", (1, 2, 3), true);
      Mass(s, v, b) : b ~> Comp("faces") { Face(2) };
      Face(k) ~> Subdiv("X", 1r, 2, ~1) { Tile(k) | Tile(k * 2) | I("cube") };
      Tile(k) : Scope.sx > 1 ~> Repeat("Y", 1.5) { I("cube") } : k ~> T(0, 0, 0.1) I("sphere") : 1;
      Tile(k) ~> I("cube");
    )");
  }
  SECTION("an L-system with context") {
    bothEngines(R"(
      derive parallel 5;
      axiom: B(1) A A A;
      B(x) < A -> B(x + 1) F(x);
      A -> A [ +(20) F(1) ];
    )");
  }
  SECTION("an L-system's instances record the parameters of the module that placed them") {
    const auto r = bothEngines(R"(
      derive parallel 3;
      axiom: A(1, 10) I("cube");
      A(x, y) -> I("cube") T(1, 0, 0) A(x + 1, y * 2);
    )");
    REQUIRE(r.instances.instances.size() == 4);
    // In the final string's order: A(1, 10)'s cube, A(2, 20)'s, A(3, 40)'s, the axiom's.
    const std::vector<double> expected{1, 10, 2, 20, 3, 40};
    std::vector<double> got;
    uint32_t axiomParams = 99;
    for (const auto& inst : r.instances.instances) {
      if (r.instances.symbols[inst.symbol] == "axiom") axiomParams = inst.paramCount;
      else got.insert(got.end(), r.instances.params.begin() + inst.firstParam,
                      r.instances.params.begin() + inst.firstParam + inst.paramCount);
    }
    CHECK(got == expected);
    CHECK(axiomParams == 0);
  }
  SECTION("collision omit: a rejected instance is dropped and the production goes on") {
    bothEngines(R"(
      collision omit centre 0.5;
      Axiom ~> Row(0);
      Row(i) : i < 30 ~> IC("cube") T(Rand(0, 0.6), 0, 0) IC("sphere") Row(i + 1);
    )");
  }
  SECTION("colours, random ones too, through splits and brackets") {
    bothEngines(R"(
      Axiom ~> S(4, 1, 1) Color(Rand(0, 1), 0.5, 0) Repeat("X", 1){ Tile };
      Tile ~> [ Color(1, Rand(0, 1), 0) I("cube") ] I("sphere");
    )");
  }
  SECTION("an attr gives the number of parallel steps, --set changes it") {
    const char* grammar = R"(
      attr n = 3;
      derive parallel n;
      axiom: F(1);
      F(x) -> F(x) F(x);
    )";
    CHECK(bothEngines(grammar).stats.terminals == 8);
    rt::DeriveOptions o;
    o.attrOverrides = {{"n", "5"}};
    CHECK(bothEngines(grammar, o).stats.terminals == 32);
    o.attrOverrides = {{"n", "0"}};
    CHECK(bothEngines(grammar, o).stats.terminals == 1);
    o.attrOverrides = {{"n", "2.5"}};
    const auto bad = bothEngines(grammar, o);
    REQUIRE_FALSE(bad.ok);
    REQUIRE(bad.messages.size() == 1);
    CHECK(bad.messages[0].code == "R010");
    CHECK(bad.messages[0].message == "--set n=2.5: `derive parallel n` needs a whole number from 0 to 2147483647");
  }
  SECTION("the shape limit: direct derivation gives way to the engine's order") {
    rt::DeriveOptions o;
    o.maxShapes = 500;
    const auto r = bothEngines(kMixed, o);
    REQUIRE(!r.messages.empty());
    CHECK(r.messages.back().code == "R004");
  }
  SECTION("the depth limit") {
    rt::DeriveOptions o;
    o.maxDepth = 4;
    const auto r = bothEngines(kMixed, o);
    REQUIRE(!r.messages.empty());
    CHECK(r.messages[0].code == "R004");
  }
  SECTION("a negative probability in a direct symbol is the interpreter's R008") {
    const auto r = bothEngines(R"(
      Axiom ~> I("cube") A(3);
      A(n) ~> T(1, 0, 0) A(n - 1) : n - 4 ~> B : 1;
      B ~> Leaf;
    )");
    REQUIRE(!r.ok);
    CHECK(r.messages[0].code == "R008");
  }
}

namespace {

// A random grammar of the kind direct derivation handles (scope commands, brackets,
// instances, guards, weights including 0, Rand), sometimes depth-first.
std::string randomGrammar(uint32_t seed) {
  std::mt19937 rng(seed);
  auto pick = [&](std::initializer_list<const char*> options) {
    return std::string(options.begin()[rng() % options.size()]);
  };
  auto chance = [&](double p) { return (rng() % 1000) < p * 1000; };
  const int symbols = 2 + static_cast<int>(rng() % 4);
  auto symbol = [&] { return "S" + std::to_string(rng() % symbols); };
  auto successor = [&] {
    std::string out;
    const int ops = 1 + static_cast<int>(rng() % 5);
    for (int i = 0; i < ops; ++i) {
      const uint32_t k = rng() % 10;
      if (k < 2) out += "T(" + pick({"0.5", "Rand(0, 1)", "n * 0.1"}) + ", " + pick({"0", "0.3"}) + ", 0) ";
      else if (k < 4) out += "Rz(" + pick({"30", "-45", "Rand(-90, 90)", "n * 7"}) + ") ";
      else if (k < 5) out += "S(" + pick({"0.9", "1r"}) + ", " + pick({"0.5r", "1"}) + ", 1r) ";
      else if (k < 6) out += "I(\"" + pick({"cube", "sphere"}) + "\") ";
      else if (k < 8) out += symbol() + "(n + 1) ";
      else out += "[ Rz(" + pick({"20", "-20"}) + ") T(0, 1, 0) " + symbol() + "(n + 1) ] ";
    }
    return out;
  };
  std::string g = chance(0.5) ? "derive depthfirst;\n" : "";
  g += "attr lim = " + std::to_string(2 + rng() % 4) + ";\nAxiom ~> ";
  for (uint32_t i = 0, n = 1 + rng() % 3; i < n; ++i) g += symbol() + "(0) ";
  g += chance(0.5) ? "I(\"cube\");\n" : ";\n";
  for (int s = 0; s < symbols; ++s) {
    const std::string name = "S" + std::to_string(s);
    if (chance(0.8)) {
      g += name + "(n) : n < lim";
      for (uint32_t a = 0, n = 1 + rng() % 3; a < n; ++a) g += " ~> " + successor() + ": " + pick({"1", "0.5", "2", "0"});
      g += ";\n";
    }
    if (chance(0.7)) g += name + "(n) ~> " + (chance(0.5) ? successor() : std::string("I(\"sphere\")")) + ";\n";
  }
  return g;
}

}  // namespace

TEST_CASE("random grammars derive alike with both engines, also where limits stop them") {
  for (uint32_t seed = 1; seed <= 60; ++seed) {
    INFO("grammar " << seed << ":\n" << randomGrammar(seed));
    rt::DeriveOptions free;
    free.maxShapes = 100000;
    free.maxDepth = 40;
    bothEngines(randomGrammar(seed), free);
    rt::DeriveOptions tight;
    tight.maxShapes = 2000;
    tight.maxDepth = 8;
    tight.seed = seed;
    bothEngines(randomGrammar(seed), tight);
  }
}

TEST_CASE("the program layout numbers every block and op once") {
  const ir::Module m = compile(kMixed);
  const ir::ProgramLayout layout = ir::layoutProgram(m);
  CHECK(layout.blocks[0] == &m.axiom);
  CHECK(layout.alternativeCount == 7);
  CHECK(layout.blocks.size() == 1 + layout.alternativeCount);  // no split bodies here
  for (uint32_t id = 0; id < layout.ops.size(); ++id) CHECK(layout.opId(*layout.ops[id]) == id);
}

TEST_CASE("the object cache answers the second compile with optimised code and survives a damaged file") {
  const auto folder = std::filesystem::temp_directory_path() / "fgsg-test-object-cache";
  std::filesystem::remove_all(folder);
  const backend::native::ObjectCache cache(folder.string());
  const ir::Module m = compile(kMixed);
  backend::jit::Jit jit;
  rt::AssetLibrary assets;
  const rt::DeriveResult reference = backend::interpret(m, {}, assets);
  {
    // A miss runs the first tier at once; the optimised object reaches the cache later.
    const auto first = jit.compileProgram(m, kMixed, cache);
    CHECK_FALSE(first.fromCache());
    CHECK_FALSE(first.optimized());
    requireSame(reference, backend::deriveCompiled(m, first.program(), {}, assets));
    jit.waitForCache();
    const auto second = jit.compileProgram(m, kMixed, cache);
    CHECK(second.fromCache());
    CHECK(second.optimized());
    requireSame(reference, backend::deriveCompiled(m, second.program(), {}, assets));
  }
  // Another grammar text is another key.
  const std::string other = std::string(kMixed) + "\n// a comment\n";
  CHECK(backend::native::ObjectCache::key(m, other) != backend::native::ObjectCache::key(m, kMixed));
  // A file cut short is a miss: the grammar is compiled again and the file replaced.
  const auto file = folder / (backend::native::ObjectCache::key(m, kMixed) + ".o");
  REQUIRE(std::filesystem::exists(file));
  std::filesystem::resize_file(file, 100);
  const auto again = jit.compileProgram(m, kMixed, cache);
  CHECK_FALSE(again.fromCache());
  requireSame(reference, backend::deriveCompiled(m, again.program(), {}, assets));
  jit.waitForCache();
  CHECK(std::filesystem::file_size(file) > 100);
  std::filesystem::remove_all(folder);
}

TEST_CASE("the cache's shared library holds the optimised code and loads without the JIT") {
  const auto folder = std::filesystem::temp_directory_path() / "fgsg-test-object-cache-library";
  std::filesystem::remove_all(folder);
  const backend::native::ObjectCache cache(folder.string());
  const ir::Module m = compile(kMixed);
  rt::AssetLibrary assets;
  const rt::DeriveResult reference = backend::interpret(m, {}, assets);
  const std::string key = backend::native::ObjectCache::key(m, kMixed);
  CHECK_FALSE(cache.loadLibrary(key));  // a miss
  {
    backend::jit::Jit jit;
    jit.compileProgram(m, kMixed, cache, backend::native::Tiering::Optimized);
  }
  REQUIRE(std::filesystem::exists(folder / (key + ".so")));
  {
    const auto code = cache.loadLibrary(key);  // the JIT is gone: dlopen alone
    REQUIRE(code);
    CHECK(code->fromCache());
    CHECK(code->optimized());
    requireSame(reference, backend::deriveCompiled(m, code->program(), {}, assets));
  }
  // A damaged file is a miss, not a crash (unloaded first: the cache replaces files
  // by renaming, never in place under a process that has them loaded).
  std::filesystem::resize_file(folder / (key + ".so"), 100);
  CHECK_FALSE(cache.loadLibrary(key));
  std::filesystem::remove_all(folder);
}

TEST_CASE("a program compiled from another grammar is refused") {
  const ir::Module m = compile(kMixed);
  const std::string otherText = "Axiom ~> A; A ~> I(\"cube\");";
  const ir::Module other = compile(otherText);
  backend::jit::Jit jit;
  const auto code = jit.compileProgram(other, otherText, kNoCache);
  rt::AssetLibrary assets;
  const rt::DeriveResult r = backend::deriveCompiled(m, code.program(), {}, assets);
  REQUIRE_FALSE(r.ok);
  CHECK(r.messages[0].code == "R900");
  CHECK_THAT(r.messages[0].message, Catch::Contains("does not match this grammar"));
}

TEST_CASE("each instance's origin: the rule that placed it and its shape's depth, alike in both engines") {
  // fgsg view's picking (DeriveOptions::recordOrigins); Tree is derived by direct code in
  // the JIT, and a Lock derives its set where it is written.
  const std::string text = R"(
    Axiom ~> I("sphere") Tree(0);
    Tree(n) : n < 2 ~> [ T(0, 1, 0) Tree(n + 1) ] I("cube");
    Tree(n) ~> S(0.3, 0.3, 0.3) Lock{ Leaf } ;
    Leaf ~> S(Shape.depth + 1, 1, 1) I("ico");
  )";
  const ir::Module m = compile(text);
  backend::jit::Jit jit;
  const auto code = jit.compileProgram(m, text, kNoCache);
  rt::AssetLibrary assets;
  rt::DeriveOptions options;
  options.recordOrigins = true;
  const rt::DeriveResult interp = backend::interpret(m, options, assets);
  const rt::DeriveResult jitted = backend::deriveCompiled(m, code.program(), options, assets);
  requireSame(interp, jitted);
  // Rules: 0 the axiom, 1 and 2 Tree's, 3 Leaf's; depths as the grammar's `depth` reads them.
  const std::vector<rt::InstanceOrigin> expected = {{0, 0}, {1, 1}, {1, 2}, {3, 4}};
  REQUIRE(interp.instances.instances.size() == expected.size());
  auto text_of = [](const std::vector<rt::InstanceOrigin>& list) {
    std::string out;
    for (const auto& o : list)
      out += "(" + (o.rule == UINT32_MAX ? std::string("axiom") : std::to_string(o.rule)) + "," +
             (o.depth == UINT32_MAX ? std::string("?") : std::to_string(o.depth)) + ")";
    return out;
  };
  CHECK(text_of(interp.instances.origins) == text_of(expected));
  CHECK(text_of(jitted.instances.origins) == text_of(expected));
  CHECK(Eigen::Map<const Eigen::Matrix4d>(interp.instances.instances[3].transform.data()).col(0).norm() ==
        Approx(5.0));  // Leaf's S(depth + 1, ...): depth 4 there too
  // Not asked: nothing recorded.
  CHECK(backend::interpret(m, {}, assets).instances.origins.empty());
}

TEST_CASE("overlapping guards without probabilities: the first rule that applies is taken, with R029") {
  // P(k) for k = 0..5: both guards hold for k = 0 and 3; the first rule wins on every
  // seed, and the one warning names both rules. Both engines (direct code gives way to
  // the engine's own order at the overlap).
  const std::string text = R"(
    Axiom ~> P(0) P(1) P(2) P(3) P(4) P(5);
    P(k) : k % 3 == 0 ~> I("disc");
    P(k) : k < 4 ~> I("cube");
    P(k) ~> I("sphere");
  )";
  for (uint64_t seed : {1, 2, 3, 4, 5}) {
    rt::DeriveOptions options;
    options.seed = seed;
    const rt::DeriveResult r = bothEngines(text, options);
    REQUIRE(r.ok);
    std::map<std::string, int> counts;
    for (const auto& inst : r.instances.instances) ++counts[r.instances.assets[inst.asset]];
    CHECK(counts["disc"] == 2);    // k = 0, 3
    CHECK(counts["cube"] == 2);    // k = 1, 2
    CHECK(counts["sphere"] == 2);  // k = 4, 5
    REQUIRE(r.messages.size() == 1);
    CHECK(r.messages[0].code == "R029");
    CHECK_FALSE(r.messages[0].isError);
    CHECK(r.messages[0].line == 3);
    CHECK(r.messages[0].message.find("'P#0' (line 3) and 'P#1' (line 4)") != std::string::npos);
  }
  // Guards that exclude each other: no warning.
  const rt::DeriveResult apart = bothEngines(R"(
    Axiom ~> P(0) P(1);
    P(k) : k == 0 ~> I("disc");
    P(k) : k == 1 ~> I("cube");
  )");
  CHECK(apart.messages.empty());
  // Probabilities ask for a draw among every rule that applies: over 200 shapes with
  // both guards holding, both rules are taken, about half each, and nothing is warned.
  const rt::DeriveResult drawn = bothEngines(R"(
    Axiom ~> Row(200);
    Row(n) : n > 0 ~> P Row(n - 1);
    P : true ~> I("disc") : 1;
    P : 1 > 0 ~> I("cube") : 1;
  )");
  REQUIRE(drawn.ok);
  CHECK(drawn.messages.empty());
  size_t discs = 0;
  for (const auto& inst : drawn.instances.instances) discs += drawn.instances.assets[inst.asset] == "disc";
  CHECK(discs > 60);
  CHECK(discs < 140);
}

TEST_CASE("an L-system takes its first matching production, as lpfg does") {
  // In a parallel derivation both context rules match the middle B; the first wins.
  const rt::DeriveResult r = bothEngines(R"(
    derive parallel 1;
    axiom: A B C;
    A < B ~> I("disc");
    B > C ~> I("cube");
  )");
  REQUIRE(r.ok);
  REQUIRE(r.instances.instances.size() == 1);
  CHECK(r.instances.assets[r.instances.instances[0].asset] == "disc");
  REQUIRE(r.messages.size() == 1);
  CHECK(r.messages[0].code == "R029");
}
