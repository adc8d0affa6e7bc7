#include "derive_helpers.h"
#include "runtime/io/write_instances.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <cmath>
#include <set>

using namespace fgsg;
using fgsg::test::deriveText;
using fgsg::test::unitPoint;

TEST_CASE("Repeat X 2 on a 10-wide scope gives 5 tiles at known positions", "[cga]") {
  auto r = deriveText(R"(
    axiom: S(10, 1, 1) Wall;
    Wall ~> Repeat("X", 2){ Tile };
    Tile ~> I("cube");
  )");
  REQUIRE(r.ok);
  const auto& insts = r.instances.instances;
  REQUIRE(insts.size() == 5);
  for (size_t i = 0; i < 5; ++i) {
    auto lo = unitPoint(insts[i], 0, 0, 0), hi = unitPoint(insts[i], 1, 1, 1);
    CHECK(lo.x() == Approx(2.0 * i).margin(1e-12));
    CHECK(hi.x() == Approx(2.0 * i + 2).margin(1e-12));
    CHECK(hi.y() == Approx(1.0));
  }
}

TEST_CASE("Subdiv shares the remaining length among relative sizes", "[cga]") {
  auto r = deriveText(R"(
    axiom: S(10, 3, 1) Facade;
    Facade ~> Subdiv("X", 1r, 2, 1r){ Side | Middle | Side };
    Side ~> I("cube");
    Middle ~> I("sphere");
  )");
  REQUIRE(r.ok);
  const auto& insts = r.instances.instances;
  REQUIRE(insts.size() == 3);
  CHECK(unitPoint(insts[0], 0, 0, 0).x() == Approx(0.0).margin(1e-12));
  CHECK(unitPoint(insts[0], 1, 0, 0).x() == Approx(4.0));
  CHECK(unitPoint(insts[1], 0, 0, 0).x() == Approx(4.0));
  CHECK(unitPoint(insts[1], 1, 0, 0).x() == Approx(6.0));
  CHECK(unitPoint(insts[2], 1, 0, 0).x() == Approx(10.0));
  CHECK(r.instances.assets[insts[1].asset] == "sphere");
}

TEST_CASE("Center lines the scope up with the centre of the scope its successor or body started with", "[cga]") {
  auto r = deriveText(R"(
    axiom: S(10, 6, 4) Lot;
    Lot ~> Subdiv("X", 4, 6){ S(1, 1, 1) Center("xyz") I("cube") | Turned };
    Turned ~> Rz(90) S(2, 2, 2) Center("xz") I("cube");
  )");
  REQUIRE(r.ok);
  const auto& insts = r.instances.instances;
  REQUIRE(insts.size() == 2);
  // The first body starts on the part 0..4 x 0..6 x 0..4: a unit cube centred in it.
  const auto mid = unitPoint(insts[0], 0.5, 0.5, 0.5);
  CHECK(mid.x() == Approx(2.0));
  CHECK(mid.y() == Approx(3.0));
  CHECK(mid.z() == Approx(2.0));
  // Turned starts on the part 4..10: centred along its own X (world +Y) and Z only;
  // along its Y (world -X) the cube stays where Rz left it, centre x = 4 - 1.
  const auto turned = unitPoint(insts[1], 0.5, 0.5, 0.5);
  CHECK(turned.x() == Approx(3.0));
  CHECK(turned.y() == Approx(3.0));
  CHECK(turned.z() == Approx(2.0));
  CHECK((unitPoint(insts[1], 1, 0, 0) - unitPoint(insts[1], 0, 0, 0)).y() == Approx(2.0));
}

TEST_CASE("Center is refused where there is no scope to centre in, or it would leave the surface", "[errors]") {
  auto parallel = deriveText("derive parallel 2;\naxiom: A;\nA ~> Center(\"x\") F;");
  CHECK_FALSE(parallel.ok);
  REQUIRE(parallel.messages.size() == 1);
  CHECK(parallel.messages[0].code == "R009");
  CHECK(parallel.messages[0].line == 3);
  CHECK(parallel.messages[0].col == 6);
  auto surface = deriveText("surface plane(4, 4);\naxiom: A;\nA ~> S(1, 1, 1) Center(\"xy\") I(\"cube\");");
  CHECK_FALSE(surface.ok);
  REQUIRE(surface.messages.size() == 1);
  CHECK(surface.messages[0].code == "R009");
  CHECK(surface.messages[0].message.find("along the surface with T") != std::string::npos);
}

TEST_CASE("Scope commands compose as in FGSG Fig. 4: rotate, then translate along the new X", "[scope]") {
  auto r = deriveText(R"(
    Axiom ~> [ Rz(90) T(2, 0, 0) I("cube") ] T(0, 0, 5) S(1, 2, 3) I("cube");
  )");
  REQUIRE(r.ok);
  const auto& insts = r.instances.instances;
  REQUIRE(insts.size() == 2);
  auto p = unitPoint(insts[0], 0, 0, 0);
  CHECK(p.x() == Approx(0.0).margin(1e-12));
  CHECK(p.y() == Approx(2.0));
  // The bracket restored the scope: the second cube sits at z = 5 with size 1 x 2 x 3.
  auto q0 = unitPoint(insts[1], 0, 0, 0), q1 = unitPoint(insts[1], 1, 1, 1);
  CHECK(q0.z() == Approx(5.0));
  CHECK((q1 - q0).x() == Approx(1.0));
  CHECK((q1 - q0).y() == Approx(2.0));
  CHECK((q1 - q0).z() == Approx(3.0));
}

TEST_CASE("A Koch curve has 4^n segments joining its end points", "[lsystem]") {
  auto r = deriveText(R"(
    derive parallel 3;
    turtle angle 60 width 0.01;
    axiom: F(1);
    F(l) -> F(l / 3) + F(l / 3) - - F(l / 3) + F(l / 3);
  )");
  REQUIRE(r.ok);
  const auto& segs = r.instances.instances;
  REQUIRE(segs.size() == 64);
  // A segment's axis runs through the middle of its unit box along Y.
  auto start = [&](size_t i) { return unitPoint(segs[i], 0.5, 0, 0.5); };
  auto end = [&](size_t i) { return unitPoint(segs[i], 0.5, 1, 0.5); };
  CHECK(start(0).norm() == Approx(0.0).margin(1e-12));
  CHECK((end(63) - Eigen::Vector3d(0, 1, 0)).norm() == Approx(0.0).margin(1e-9));
  double total = 0;
  for (size_t i = 0; i < segs.size(); ++i) {
    CHECK((end(i) - start(i)).norm() == Approx(1.0 / 27.0));
    if (i > 0) CHECK((start(i) - end(i - 1)).norm() == Approx(0.0).margin(1e-12));
    total += (end(i) - start(i)).norm();
  }
  CHECK(total == Approx(std::pow(4.0 / 3.0, 3)));
}

TEST_CASE("Probabilities are honoured among the alternatives", "[random]") {
  auto r = deriveText(R"(
    Axiom ~> Many(0);
    Many(i) : i < 4000 ~> Pick Many(i + 1);
    Pick ~> I("cube") : 0.25 ~> I("sphere") : 0.75;
  )");
  REQUIRE(r.ok);
  const double cubes = static_cast<double>(test::countAsset(r, "cube"));
  const double spheres = static_cast<double>(test::countAsset(r, "sphere"));
  REQUIRE(cubes + spheres == 4000);
  // 4000 draws: the standard deviation of the fraction is 0.0068; allow 4.4 sigma.
  CHECK(cubes / 4000 == Approx(0.25).margin(0.03));
}

TEST_CASE("Rand draws uniformly between its bounds", "[random]") {
  auto r = deriveText(R"(
    Axiom ~> Many(0);
    Many(i) : i < 2000 ~> [ T(Rand(2, 4), 0, 0) I("cube") ] Many(i + 1);
  )");
  REQUIRE(r.ok);
  double sum = 0, lo = 1e9, hi = -1e9;
  for (const auto& inst : r.instances.instances) {
    double x = unitPoint(inst, 0, 0, 0).x();
    sum += x, lo = std::min(lo, x), hi = std::max(hi, x);
  }
  CHECK(lo >= 2.0);
  CHECK(hi < 4.0);
  CHECK(sum / 2000 == Approx(3.0).margin(0.06));
}

namespace {

std::multiset<std::vector<double>> transforms(const rt::DeriveResult& r) {
  std::multiset<std::vector<double>> out;
  for (const auto& inst : r.instances.instances) {
    std::vector<double> t(inst.transform.begin(), inst.transform.end());
    for (double& v : t) v = std::round(v * 1e9) / 1e9;
    out.insert(t);
  }
  return out;
}

const char* kBranchy = R"(
  Axiom ~> S(0.5, 0.5, 0.5) A(0);
  A(n) : n < 7 ~> [ Rz(Rand(-40, 40)) T(Rand(0.5, 1), 0, 0) I("cube") A(n + 1) ]
                  [ Rz(Rand(140, 220)) T(1, 0, 0) A(n + 1) ] : 0.7
               ~> [ T(0, 1, 0) I("sphere") A(n + 1) ] : 0.3;
)";

}  // namespace

TEST_CASE("The same seed gives the same result, another seed another", "[random]") {
  rt::DeriveOptions a;
  a.seed = 11;
  auto r1 = deriveText(kBranchy, a), r2 = deriveText(kBranchy, a);
  a.seed = 12;
  auto r3 = deriveText(kBranchy, a);
  REQUIRE(r1.instances.instances.size() > 10);
  CHECK(transforms(r1) == transforms(r2));
  CHECK(transforms(r1) != transforms(r3));
}

TEST_CASE("Random streams follow the derivation path, not the derivation order", "[random]") {
  std::string depthFirst = std::string("derive depthfirst;\n") + kBranchy;
  auto bfs = deriveText(kBranchy), dfs = deriveText(depthFirst);
  REQUIRE(bfs.instances.instances.size() == dfs.instances.instances.size());
  CHECK(transforms(bfs) == transforms(dfs));
}

TEST_CASE("A guarded rule that holds is preferred to an unguarded one", "[rules]") {
  auto r = deriveText(R"(
    Axiom ~> P(0) P(1) P(2) P(3) P(4) P(5);
    P(k) : k % 3 == 0 ~> I("disc");
    P(k) ~> I("sphere");
  )");
  REQUIRE(r.ok);
  CHECK(test::countAsset(r, "disc") == 2);
  CHECK(test::countAsset(r, "sphere") == 4);
}

TEST_CASE("Higher priority is derived first", "[rules]") {
  // Low-priority shapes wait until every high-priority shape is done, whatever the
  // breadth-first order says; Shape.index shows the order through instance order.
  auto r = deriveText(R"(
    Axiom ~> Low High;
    priority 1:
    Low ~> I("cube");
    priority 2:
    High ~> I("sphere");
  )");
  REQUIRE(r.ok);
  REQUIRE(r.instances.instances.size() == 2);
  CHECK(r.instances.assets[r.instances.instances[0].asset] == "sphere");
}

TEST_CASE("Parallel derivation: ABOP context skips branches", "[lsystem]") {
  // B signals rightwards, one module per step; every B then turns into a cube.
  auto r = deriveText(R"(
    derive parallel 3;
    axiom: B A [ A ] A A;
    B < A -> B;
    B -> I("cube");
  )");
  REQUIRE(r.ok);
  // Step 1: only the A right after B has it as left context (2 rewrites with B's).
  // Step 2: the branch's A sees its parent B; the A after the branch sees B across
  // the skipped branch; B becomes a cube (3). Step 3: the two new Bs and the last A (3).
  CHECK(r.stats.rewrites == 2 + 3 + 3);
  CHECK(test::countAsset(r, "cube") == 4);

  auto right = deriveText(R"(
    derive parallel 1;
    axiom: A [ B ] C  D [ E ] G;
    A > [ B ] C -> I("cube");
    D > G -> I("sphere");
  )");
  REQUIRE(right.ok);
  CHECK(test::countAsset(right, "cube") == 1);
  CHECK(test::countAsset(right, "sphere") == 1);
}

TEST_CASE("Attributes take --set values by type", "[attrs]") {
  rt::DeriveOptions o;
  o.attrOverrides = {{"count", "7"}};
  auto r = deriveText(R"(
    attr count = 3;
    Axiom ~> Row(0);
    Row(i) : i < count ~> I("cube") T(1, 0, 0) Row(i + 1);
  )", o);
  REQUIRE(r.ok);
  CHECK(r.instances.instances.size() == 7);
  o.attrOverrides = {{"count", "lots"}};
  auto bad = deriveText("attr count = 3; Axiom ~> I(\"cube\");", o);
  CHECK_FALSE(bad.ok);
  REQUIRE(bad.messages.size() == 1);
  CHECK(bad.messages[0].message.find("expected a number") != std::string::npos);
}

TEST_CASE("Limits stop a runaway grammar, name its rule and keep the result", "[limits]") {
  rt::DeriveOptions o;
  o.maxShapes = 1000;
  auto r = deriveText("Axiom ~> A; grow: A ~> I(\"cube\") A A;", o);
  CHECK(r.ok);
  CHECK(r.instances.instances.size() > 400);
  REQUIRE(r.messages.size() == 1);
  CHECK_FALSE(r.messages[0].isError);
  CHECK(r.messages[0].message.find("'grow'") != std::string::npos);
  CHECK(r.messages[0].line == 1);

  rt::DeriveOptions d;
  d.maxDepth = 5;
  auto deep = deriveText("Axiom ~> A;\nchain: A ~> I(\"cube\") T(1,0,0) A;", d);
  CHECK(deep.ok);
  CHECK(deep.instances.instances.size() == 4);  // depths 1..4: the Axiom shape is depth 0
  REQUIRE(deep.messages.size() == 1);
  CHECK(deep.messages[0].message.find("'chain'") != std::string::npos);
  CHECK(deep.messages[0].line == 2);
}

TEST_CASE("A grammar's own depth bound ends it quietly, a smaller --max-depth still warns", "[limits]") {
  const std::string chain = "derive depthfirst 3;\naxiom: A(0);\nA(k) ~> I(\"cube\") T(1, 0, 0) A(k + 1);";
  auto own = deriveText(chain);
  REQUIRE(own.ok);
  CHECK(own.messages.empty());
  CHECK(own.instances.instances.size() == 3);
  CHECK(own.stats.terminals == 1);
  rt::DeriveOptions shallow;
  shallow.maxDepth = 2;
  auto flag = deriveText(chain, shallow);
  REQUIRE(flag.ok);
  CHECK(flag.instances.instances.size() == 2);
  REQUIRE(flag.messages.size() == 1);
  CHECK(flag.messages[0].code == "R004");
  CHECK(flag.messages[0].message.find("depth limit 2 (--max-depth)") != std::string::npos);
  rt::DeriveOptions deep;
  deep.maxDepth = 10;  // the grammar's 3 is smaller: it applies, without a warning
  auto both = deriveText(chain, deep);
  CHECK(both.messages.empty());
  CHECK(both.instances.instances.size() == 3);
}

TEST_CASE("Cells runs: the shape's own box in bricks, and Feature outside Cells is a located error", "[errors][cells]") {
  auto r = deriveText("Axiom ~> S(2, 1, 1) Cells(0.01){ F };\nF ~> BrickBond(0.2, 0.1, 0.1){ B };\nB ~> I(\"cube\");");
  CHECK(r.ok);
  CHECK(r.instances.instances.size() > 100);
  auto outside = deriveText("Axiom ~> Top;\nTop : Feature.edge ~> I(\"cube\");\nTop ~> I(\"cube\");");
  CHECK_FALSE(outside.ok);
  REQUIRE(outside.messages.size() == 1);
  CHECK(outside.messages[0].code == "R026");
  CHECK(outside.messages[0].line == 2);  // deriveText has no comment line
  CHECK(outside.messages[0].col == 7);
}

TEST_CASE("Cells' base part: a split's pieces are the base mesh and their symbols its labels", "[cells]") {
  // A 3 x 3 facade with a window in the middle; the window piece is a label, not a box.
  const std::string grammar =
      "Axiom ~> S(3, 3, 0) Cells(0.01){ Facade | Feature };\n"
      "Facade ~> Subdiv(\"X\", 1, 1, 1){ wall | Subdiv(\"Y\", 1, 1, 1){ wall | window | wall } | wall };\n"
      "Feature : Feature.face && Feature.label(\"window\") ~> I(\"sphere\");\n"
      "Feature : Feature.face && Feature.label(\"wall\") ~> I(\"disc\");\n"
      "Feature : Feature.edge && Feature.label(\"window\") && Feature.label(\"wall\") ~> I(\"ico\");\n"
      "Feature : Feature.edge && Feature.boundary ~> I(\"cube\");\n"
      "Feature ~> ε;";
  auto r = deriveText(grammar);
  REQUIRE(r.ok);
  CHECK(test::countAsset(r, "sphere") == 1);  // the window, one face
  CHECK(test::countAsset(r, "disc") == 1);    // the wall around it, one face with a hole
  CHECK(test::countAsset(r, "ico") == 4);    // its four sides, each between window and wall
  CHECK(test::countAsset(r, "cube") == 4);   // the facade's outline
  CHECK(r.stats.terminals == 5);
  // Pieces that cannot make a surface: a located R026 naming the edge.
  auto bad = deriveText("Axiom ~> S(1, 1, 0) Cells(0.01){ [ A ] [ A ] [ Rx(90) A ] | Feature };\nFeature ~> ε;");
  REQUIRE_FALSE(bad.ok);
  REQUIRE(bad.messages.size() == 1);
  CHECK(bad.messages[0].code == "R026");
  CHECK(bad.messages[0].line == 1);
  CHECK(bad.messages[0].col == 21);
  CHECK(bad.messages[0].message.find("three or more base pieces meet at the edge from (0, 0, 0) to (1, 0, 0)") !=
        std::string::npos);
}

TEST_CASE("Color: instances take the scope's colour, inherited by parts, restored at a bracket's end", "[color]") {
  auto r = deriveText(
      "Axiom ~> S(2, 2, 2) Color(0.5, 0.25, 1) [ Color(\"#ff8000\") I(\"cube\") ] I(\"sphere\") Top Loud;\n"
      "Top ~> Comp(\"top\"){ Face };\n"
      "Face ~> I(\"disc\");\n"
      "Loud ~> Color(2, -1, 0.5) I(\"ico\");");
  REQUIRE(r.ok);
  std::map<std::string, std::array<float, 3>> colour;
  for (const auto& inst : r.instances.instances) colour[r.instances.assets[inst.asset]] = inst.color;
  const std::array<float, 3> set{0.5f, 0.25f, 1.0f};
  CHECK(colour["cube"] == std::array<float, 3>{1.0f, float(128 / 255.0), 0.0f});
  CHECK(colour["sphere"] == set);  // the bracket's colour ended with it
  CHECK(colour["disc"] == set);    // through the shape Top and its Comp face
  CHECK(colour["ico"] == std::array<float, 3>{1.0f, 0.0f, 0.5f});  // clamped to 0..1
  // Without Color an instance keeps its symbol's colour.
  auto plain = deriveText("Axiom ~> A;\nA ~> I(\"cube\");");
  REQUIRE(plain.ok);
  CHECK(plain.instances.instances[0].color != set);
  auto nan = deriveText("Axiom ~> A(-1);\nA(x) ~> Color(0, sqrt(x), 0) I(\"cube\");");
  REQUIRE_FALSE(nan.ok);
  REQUIRE(nan.messages.size() == 1);
  CHECK(nan.messages[0].code == "R027");
  CHECK(nan.messages[0].line == 2);
  CHECK(nan.messages[0].col == 9);
  CHECK(nan.messages[0].message.find("colour's g is not a number") != std::string::npos);
}

TEST_CASE("Color in an L-system colours the turtle's segments, a bracket's end restores it", "[color]") {
  auto r = deriveText("derive parallel 1;\naxiom: A;\nA -> Color(1, 0, 0) F(1) [ Color(0, 0, 1) F(1) ] F(1);");
  REQUIRE(r.ok);
  REQUIRE(r.instances.instances.size() == 3);
  CHECK(r.instances.instances[0].color == std::array<float, 3>{1, 0, 0});
  CHECK(r.instances.instances[1].color == std::array<float, 3>{0, 0, 1});
  CHECK(r.instances.instances[2].color == std::array<float, 3>{1, 0, 0});
}

TEST_CASE("Marching on the plane is a located error asking for a surface", "[errors][marching]") {
  auto r = deriveText("Axiom ~> Marching(0.1, 30, true){ Top, Ext };\nTop ~> I(\"cube\");\nExt ~> I(\"cube\");");
  CHECK_FALSE(r.ok);
  REQUIRE(r.messages.size() == 1);
  CHECK(r.messages[0].code == "R022");
  CHECK(r.messages[0].line == 1);
  CHECK(r.messages[0].col == 10);
  CHECK(r.messages[0].message.find("need a surface") != std::string::npos);
}

TEST_CASE("A missing asset is reported at its I()", "[errors]") {
  auto r = deriveText("Axiom ~> T(1,0,0)\n  I(\"nowhere.obj\");");
  CHECK_FALSE(r.ok);
  REQUIRE(r.messages.size() == 1);
  CHECK(r.messages[0].code == "R003");
  CHECK(r.messages[0].line == 2);
}

TEST_CASE("Occlusion queries see the instances placed so far", "[queries]") {
  auto r = deriveText(R"(
    Axiom ~> Blocker Probe;
    priority 2:
    Blocker ~> S(2, 2, 2) I("cube");
    priority 1:
    Probe ~> [ T(1, 1, 1) S(0.5, 0.5, 0.5) Test ] [ T(5, 0, 0) Test ] [ T(1.5, 1.5, 1.5) Test ];
    Test : Scope.occ("noparent") == "full" ~> I("sphere");
    Test : Scope.occ("noparent") == "part" ~> I("disc");
    Test ~> I("ico");
  )");
  REQUIRE(r.ok);
  CHECK(test::countAsset(r, "sphere") == 1);
  CHECK(test::countAsset(r, "disc") == 1);
  CHECK(test::countAsset(r, "ico") == 1);
}

TEST_CASE("The Müller building example derives one door on the street side", "[examples]") {
  ir::Module m;
  frontend::SourceFile file;
  std::string error;
  REQUIRE(ir::readSourceFile(std::string(FGSG_SOURCE_DIR) + "/examples/mueller_building.fgsg", file, error));
  frontend::Diagnostics diags(&file);
  REQUIRE(ir::compileSource(file, m, diags));
  rt::AssetLibrary assets;
  assets.addSearchDir(std::string(FGSG_SOURCE_DIR) + "/examples/assets");
  auto r = backend::interpret(m, {}, assets);
  REQUIRE(r.ok);
  CHECK(test::countAsset(r, "door.obj") == 1);
  CHECK(test::countAsset(r, "win.obj") > 8);
  CHECK(test::countAsset(r, "flatbrick.obj") > 100);
  // The door faces the street: its box's outward axis is +Z.
  for (const auto& inst : r.instances.instances)
    if (r.instances.assets[inst.asset] == "door.obj") {
      Eigen::Vector3d out = unitPoint(inst, 0, 0, 1) - unitPoint(inst, 0, 0, 0);
      CHECK(out.normalized().z() == Approx(1.0));
    }
}

TEST_CASE("Synthesize fills the scope with pieces, labels with rules become shapes", "[synthesis]") {
  // Columns of wall and ground alternate along X in the example, so they do in any
  // consistent model.
  const std::string dir = std::string(FGSG_BINARY_DIR) + "/test-scratch";
  std::filesystem::create_directories(dir);
  {
    std::ofstream ex(dir + "/stripes.txt");
    ex << "label g quad\nlabel W cube\nsize 4 2 1\nlayer 0\ng W g W\ng W g W\n";
  }
  rt::DeriveOptions o;
  o.assetDirs = {dir};
  const std::string grammar = R"(
    axiom: S(8, 1, 6) Lot;
    Lot ~> Synthesize("stripes.txt", 8, 6, 1);
    W ~> I("sphere");
  )";
  auto r = deriveText(grammar, o);
  REQUIRE(r.ok);
  CHECK(test::countAsset(r, "sphere") == 24);  // 4 wall columns of 6 cells
  CHECK(test::countAsset(r, "quad") == 24);
  CHECK(r.stats.shapesCreated == 1 + 24);      // Lot, then one W shape per wall cell
  for (const auto& inst : r.instances.instances) {
    Eigen::Vector3d c = unitPoint(inst, 0.5, 0.5, 0.5);
    CHECK(c.x() > 0);
    CHECK(c.x() < 8);
    CHECK(c.z() > 0);
    CHECK(c.z() < 6);
    CHECK(c.y() == Approx(0.5));
  }
  auto again = deriveText(grammar, o);
  CHECK(transforms(r) == transforms(again));

  auto missing = deriveText("Lot ~> Synthesize(\"nowhere.txt\", 4, 4, 1);", o);
  CHECK_FALSE(missing.ok);
  REQUIRE(missing.messages.size() == 1);
  CHECK(missing.messages[0].code == "R013");
}

TEST_CASE("Depth-first derives a shape's successors before its siblings", "[order]") {
  const std::string rules = R"(
    Axiom ~> A B;
    A ~> I("cube") C D;
    C ~> I("sphere");
    D ~> I("ico");
    B ~> I("disc");
  )";
  auto order = [](const rt::DeriveResult& r) {
    std::string s;
    for (const auto& inst : r.instances.instances) s += r.instances.assets[inst.asset] + " ";
    return s;
  };
  CHECK(order(deriveText(rules)) == "cube disc sphere ico ");
  CHECK(order(deriveText("derive depthfirst;\n" + rules)) == "cube sphere ico disc ");
}

TEST_CASE("Instances JSON writes parameters by their type", "[output]") {
  auto r = deriveText(R"(
    Axiom ~> A("door", true, (1, 2, 3), 4.5);
    A(name, open, v, n) ~> I("cube");
  )");
  REQUIRE(r.ok);
  const std::string json = rt::io::encodeInstancesJson(r.instances);
  CHECK(json.find("\"params\":[\"door\",true,[1,2,3],4.5]") != std::string::npos);
}
