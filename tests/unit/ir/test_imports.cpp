// `import`: modules' names qualified `as` a name, attrs set by the importer and by --set,
// a module's start and program-wide settings left to the importer, hooks the importer
// fills, errors located in the file they are in (cycles, clashes, missing modules), and a
// grammar's text carrying its modules so that it compiles again without their files.
#include "backend/interp/interpreter.h"
#include "frontend/diagnostics.h"
#include "frontend/imports.h"
#include "frontend/parse.h"
#include "ir/pipeline.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace fs = std::filesystem;
using namespace fgsg;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(FGSG_BINARY_DIR) / "test-scratch" / "imports" / (std::to_string(::getpid()) + "-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

struct Compiled {
  frontend::SourceFile file;
  ir::Module module;
  bool ok = false;
  std::string diagnostics;
};

Compiled compile(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  Compiled c;
  c.file = frontend::SourceFile::make(path.string(), text.str());
  frontend::Diagnostics diags(&c.file);
  c.ok = ir::compileSource(c.file, c.module, diags);
  std::ostringstream out;
  diags.print(out);
  c.diagnostics = out.str();
  return c;
}

// The symbols of the instances a compiled grammar places, with each one's X size.
std::string placed(const ir::Module& m, const std::vector<std::pair<std::string, std::string>>& set = {}) {
  rt::DeriveOptions options;
  options.attrOverrides = set;
  rt::AssetLibrary assets;
  const rt::DeriveResult r = backend::interpret(m, options, assets);
  std::string out;
  for (const auto& inst : r.instances.instances) {
    std::ostringstream one;
    one << r.instances.symbols[inst.symbol] << ":" << inst.transform[0] << " ";
    out += one.str();
  }
  return out;
}

const char* kBox = R"(// a module with its own demo
attr size = 2;
const half = 0.5;
derive depthfirst;
Axiom ~> Box(3);
Box(n) : n > 0 ~> S(size, half, 1) I("cube") T(size + 1, 0, 0) Box(n - 1);
Box(n) ~> Cap;
)";

}  // namespace

TEST_CASE("an imported module's names are qualified and its attrs set by the importer") {
  const fs::path dir = scratch("qualified");
  write(dir / "lib" / "box.fgsg", kBox);
  write(dir / "main.fgsg", "import \"lib/box\" as box (size = 1.5);\n"
                           "axiom: box.Box(2) Tower;\n"
                           "Tower ~> S(box.size * 2, 1, 1) I(\"cube\");\n"
                           "box.Cap ~> S(0.25, 1, 1) I(\"sphere\");\n");
  const Compiled c = compile(dir / "main.fgsg");
  INFO(c.diagnostics);
  REQUIRE(c.ok);
  CHECK(c.diagnostics.empty());  // the module's unused demo start is no W002
  // Breadth-first (the importer's order, not the module's depthfirst): the module's
  // Box(2), the importer's Tower, then Box(1), Box(0)'s hook Cap given rules here.
  CHECK(placed(c.module) == "box.Box:1.5 Tower:3 box.Box:1.5 box.Cap:0.25 ");
  CHECK(placed(c.module, {{"box.size", "3"}}) == "box.Box:3 Tower:6 box.Box:3 box.Cap:0.25 ");
  CHECK(c.module.findAttr("box.size") >= 0);
  CHECK(c.module.findSymbol("Axiom") < 0);  // the module's start stays its own
}

TEST_CASE("a grammar carries its modules: it compiles again without their files") {
  const fs::path dir = scratch("bundle");
  write(dir / "lib" / "box.fgsg", kBox);
  write(dir / "lib" / "row.fgsg", "import \"box\" as b;\nRow ~> b.Box(1) T(0, 2, 0) b.Box(1);\n");
  write(dir / "main.fgsg", "import \"lib/row\" as row;\naxiom: row.Row;\n");
  const Compiled first = compile(dir / "main.fgsg");
  INFO(first.diagnostics);
  REQUIRE(first.ok);
  CHECK(placed(first.module) == "row.b.Box:2 row.b.Box:2 ");
  fs::remove_all(dir / "lib");
  frontend::SourceFile again = frontend::SourceFile::make((dir / "main.fgsg").string(), first.file.text);
  REQUIRE(again.modules.size() == 2);
  frontend::Diagnostics diags(&again);
  ir::Module m;
  REQUIRE(ir::compileSource(again, m, diags));
  CHECK(placed(m) == placed(first.module));
  CHECK(again.text == first.file.text);  // the same text: the same JIT cache key
  // A module edited: the grammar's text (the JIT cache key's) changes with it.
  write(dir / "lib" / "box.fgsg", std::string(kBox) + "// edited\n");
  write(dir / "lib" / "row.fgsg", "import \"box\" as b;\nRow ~> b.Box(1) T(0, 2, 0) b.Box(1);\n");
  const Compiled edited = compile(dir / "main.fgsg");
  REQUIRE(edited.ok);
  CHECK(edited.file.text != first.file.text);
  CHECK(edited.file.mainText() == first.file.mainText());
}

TEST_CASE("import errors name the file and line they are in") {
  const fs::path dir = scratch("errors");
  SECTION("a module that is not there") {
    write(dir / "g.fgsg", "import \"nothing\" as n;\naxiom: n.A;\n");
    const Compiled c = compile(dir / "g.fgsg");
    CHECK_FALSE(c.ok);
    CHECK_THAT(c.diagnostics, Catch::Contains("g.fgsg:1:8: error[E060]: cannot find the module 'nothing'"));
  }
  SECTION("a cycle, with the import that leaves the first file") {
    write(dir / "a.fgsg", "import \"b\";\nA ~> I(\"cube\");\n");
    write(dir / "b.fgsg", "import \"a\";\nB ~> I(\"cube\");\n");
    const Compiled c = compile(dir / "a.fgsg");
    CHECK_FALSE(c.ok);
    CHECK_THAT(c.diagnostics, Catch::Contains("b.fgsg:1:8: error[E061]: import cycle: a.fgsg imports b.fgsg imports "
                                              "a.fgsg again"));
    CHECK_THAT(c.diagnostics, Catch::Contains("a.fgsg:1:8: note: the cycle leaves a.fgsg here"));
  }
  SECTION("two modules declaring one name, both imports shown") {
    write(dir / "m1.fgsg", "attr w = 1;\nWin ~> S(w, 1, 1) I(\"cube\");\n");
    write(dir / "m2.fgsg", "Win ~> I(\"sphere\");\n");
    write(dir / "g.fgsg", "import \"m1\";\nimport \"m2\";\naxiom: Win;\n");
    const Compiled c = compile(dir / "g.fgsg");
    CHECK_FALSE(c.ok);
    CHECK_THAT(c.diagnostics, Catch::Contains("g.fgsg:2:1: error[E063]: 'Win' comes from both 'm2' (imported at line 2) "
                                              "and 'm1' (imported at line 1)"));
    CHECK_THAT(c.diagnostics, Catch::Contains("g.fgsg:1:1: note: 'Win' first comes from here"));
    // The same modules `as` names do not clash.
    write(dir / "h.fgsg", "import \"m1\" as one;\nimport \"m2\" as two;\naxiom: one.Win two.Win;\n");
    const Compiled h = compile(dir / "h.fgsg");
    INFO(h.diagnostics);
    CHECK(h.ok);
  }
  SECTION("a mistake inside a module, at its own line") {
    write(dir / "m.fgsg", "// a module\n\nBad ~> S(1, 2;\n");
    write(dir / "g.fgsg", "import \"m\" as m;\naxiom: m.Bad;\n");
    const Compiled c = compile(dir / "g.fgsg");
    CHECK_FALSE(c.ok);
    CHECK_THAT(c.diagnostics, Catch::Contains("m.fgsg:3:14: error[E002]"));
    CHECK_THAT(c.diagnostics, Catch::Contains("Bad ~> S(1, 2;"));
  }
  SECTION("an alias that would swallow a query or a name of the grammar") {
    write(dir / "lib.fgsg", kBox);
    write(dir / "g.fgsg", "import \"lib\" as Scope;\naxiom: S(Scope.sx, 1, 1) I(\"cube\");\n");
    const Compiled c = compile(dir / "g.fgsg");
    CHECK_FALSE(c.ok);
    CHECK_THAT(c.diagnostics, Catch::Contains("g.fgsg:1:1: error[E062]: 'Scope' cannot name a module here: it is a query"));
  }
  SECTION("a setting for an attr the module does not have") {
    write(dir / "lib.fgsg", kBox);
    write(dir / "g.fgsg", "import \"lib\" as box (nosuch = 1);\naxiom: box.Box(1);\n");
    const Compiled c = compile(dir / "g.fgsg");
    CHECK_FALSE(c.ok);
    CHECK_THAT(c.diagnostics, Catch::Contains("g.fgsg:1:22: error[E062]: the module 'lib' has no attr 'nosuch'"));
  }
}

TEST_CASE("std/ names the standard library, FGSG_PATH adds folders") {
  const fs::path dir = scratch("search");
  write(dir / "std" / "shapes" / "ring.fgsg", "Ring ~> I(\"torus\");\n");
  write(dir / "extra" / "dot.fgsg", "Dot ~> I(\"sphere\");\n");
  write(dir / "g.fgsg", "import \"std/shapes/ring\" as ring;\nimport \"dot\" as dot;\naxiom: ring.Ring dot.Dot;\n");
  frontend::ImportSearch search;
  search.stdlib = (dir / "std").string();
  search.path = {(dir / "extra").string()};
  std::ifstream in(dir / "g.fgsg");
  std::stringstream text;
  text << in.rdbuf();
  frontend::SourceFile file = frontend::SourceFile::make((dir / "g.fgsg").string(), text.str());
  frontend::Diagnostics diags(&file);
  frontend::Program program;
  REQUIRE(frontend::parseProgram(file, program, diags));
  CHECK(frontend::resolveImports(file, program, diags, search));
  REQUIRE(file.modules.size() == 2);
  CHECK(file.modules[0].name == "std/shapes/ring.fgsg");  // named as written, wherever installed
  REQUIRE(program.rules.size() == 2);
  CHECK(program.rules[0].predecessor.name == "ring.Ring");
  CHECK(program.rules[1].predecessor.name == "dot.Dot");
}

TEST_CASE("a module's asset files are found beside the module") {
  const fs::path dir = scratch("assets");
  write(dir / "lib" / "assets" / "knob.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  write(dir / "lib" / "knob.fgsg", "Knob ~> I(\"knob.obj\") T(2, 0, 0) I(\"cube\");\n");
  write(dir / "app" / "g.fgsg", "import \"../lib/knob\" as k;\naxiom: k.Knob;\n");
  const Compiled c = compile(dir / "app" / "g.fgsg");
  INFO(c.diagnostics);
  REQUIRE(c.ok);
  const std::string knob = fs::absolute(dir / "lib" / "assets" / "knob.obj").lexically_normal().string();
  CHECK(std::find(c.module.assets.begin(), c.module.assets.end(), knob) != c.module.assets.end());
  CHECK(std::find(c.module.assets.begin(), c.module.assets.end(), "cube") != c.module.assets.end());
}

TEST_CASE("Feature.label names a module's piece by its qualified name") {
  const fs::path dir = scratch("labels");
  const std::string cells = "W ~> S(2, 1.5, 0) Cells(0.01, 0.09){ P | G };\n"
                            "P ~> Subdiv(\"X\", 1r, 0.6, 1r){ wall | Subdiv(\"Y\", 0.5, 0.6, 1r){ wall | Win | wall } | wall };\n"
                            "Win ~> T(0, 0, -0.1) Extrude(0.1) Comp(\"sidefaces\"){ window } Comp(\"bottom\"){ window };\n"
                            "G : Feature.face && Feature.label(\"window\") -> epsilon;\n"
                            "G -> I(\"cube\");\n";
  write(dir / "wall.fgsg", "axiom: W;\n" + cells);
  write(dir / "g.fgsg", "import \"wall\" as m;\naxiom: m.W;\n");
  const Compiled alone = compile(dir / "wall.fgsg");
  const Compiled imported = compile(dir / "g.fgsg");
  INFO(alone.diagnostics << imported.diagnostics);
  REQUIRE(alone.ok);
  REQUIRE(imported.ok);
  rt::AssetLibrary assets;
  const size_t n = backend::interpret(alone.module, {}, assets).instances.instances.size();
  CHECK(n > 0);
  CHECK(backend::interpret(imported.module, {}, assets).instances.instances.size() == n);
}

TEST_CASE("a module's Synthesize labels and Evolve loci find the module's own rules first") {
  const fs::path dir = scratch("labels_run_time");
  write(dir / "lib" / "land.txt",
        "label . none empty\nlabel G cube\nsize 3 3 1\nlayer 0\nG G G\nG G G\nG G G\n");
  write(dir / "lib" / "syn.fgsg", "Land ~> Synthesize(\"land.txt\", 3, 3, 1);\nG ~> S(1r, 1r, 0.2) I(\"sphere\");\n");
  write(dir / "g.fgsg", "import \"lib/syn\" as syn;\naxiom: S(3, 3, 1) syn.Land;\n");
  const Compiled c = compile(dir / "g.fgsg");
  INFO(c.diagnostics);
  REQUIRE(c.ok);
  // The label G is the module's syn.G (a sphere), not the example's own cube.
  std::string nine;
  for (int i = 0; i < 9; ++i) nine += "syn.G:1 ";
  CHECK(placed(c.module) == nine);
  CHECK(c.module.findSymbolFrom(uint32_t(c.module.findSymbol("syn.Land")), "G") == c.module.findSymbol("syn.G"));
  CHECK(c.module.findSymbolFrom(uint32_t(c.module.findSymbol("syn.Land")), "Land") == c.module.findSymbol("syn.Land"));
}
