// Lowering from source: the `collision` declaration and the Line / LineSeg commands, through
// the whole pipeline (parse, sema, lower, fold, verify), then printed and verified.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>

#include "frontend/diagnostics.h"
#include "ir/pipeline.h"
#include "ir/printer.h"
#include "ir/verifier.h"

using namespace fgsg::ir;

namespace {

Module compile(const std::string& text) {
  auto file = fgsg::frontend::SourceFile::make("t.fgsg", text);
  fgsg::frontend::Diagnostics diags(&file);
  Module m;
  const bool ok = compileSource(file, m, diags);
  std::ostringstream printed;
  diags.print(printed);
  INFO(printed.str());
  REQUIRE(ok);
  return m;
}

std::string joined(const std::vector<std::string>& problems) {
  std::string s;
  for (const std::string& p : problems) s += p + "\n";
  return s;
}

void expectProblem(const Module& m, const std::string& needle) {
  std::vector<std::string> problems;
  CHECK(!verifyModule(m, problems));
  INFO(joined(problems));
  CHECK(joined(problems).find(needle) != std::string::npos);
}

}  // namespace

TEST_CASE("lower: collision settings", "[ir][lower][collision]") {
  Module none = compile("A ~> I(\"cube\");");
  CHECK_FALSE(none.collision.all);
  CHECK(none.collision.metric == CollisionMetric::Mesh);
  CHECK(none.collision.radius == 0);
  CHECK(none.collision.loc.line == 0);

  Module all = compile("A ~> I(\"cube\");\ncollision all;");
  CHECK(all.collision.all);
  CHECK(all.collision.metric == CollisionMetric::Mesh);
  CHECK(all.collision.loc.line == 2);
  CHECK(all.collision.loc.col == 1);

  Module centre = compile("collision all centre 0.25;\nA ~> I(\"cube\");");
  CHECK(centre.collision.all);
  CHECK(centre.collision.metric == CollisionMetric::Centre);
  CHECK(centre.collision.radius == 0.25);

  Module center = compile("collision center 2;\nA ~> I(\"cube\");");
  CHECK_FALSE(center.collision.all);
  CHECK(center.collision.metric == CollisionMetric::Centre);
  CHECK(center.collision.radius == 2);

  Module geodesic = compile("const r = 0.3;\ncollision geodesic r;\nA ~> I(\"cube\");");
  CHECK(geodesic.collision.metric == CollisionMetric::Geodesic);
  CHECK(geodesic.collision.radius == 0.3);

  Module distance = compile("collision omit distance 0.05;\nA ~> I(\"cube\");");
  CHECK(distance.collision.metric == CollisionMetric::Distance);
  CHECK(distance.collision.radius == 0.05);
  CHECK(distance.collision.omit);

  Module mesh = compile("collision mesh;\nA ~> I(\"cube\");");
  CHECK_FALSE(mesh.collision.all);
  CHECK(mesh.collision.metric == CollisionMetric::Mesh);
  CHECK(mesh.collision.loc.line == 1);
}

TEST_CASE("lower: Line always has width and merge, LineSeg 0 or 1 argument", "[ir][lower][lines]") {
  Module m = compile(
      "Axiom ~> Line() LineSeg() Line(0.2) LineSeg(1.5) Line(0.3, false) Grow(0.1);\n"
      "Grow(w) ~> Line(w) LineSeg(w * 2);");
  const Block& axiom = m.rules[0].alternatives[0].ops;  // the rule for Axiom
  REQUIRE(axiom.size() == 6);
  auto num = [](const Expr& e) {
    CHECK(e.isConst());
    CHECK(e.type == Type::Num);
    return e.num;
  };
  auto flag = [](const Expr& e) {
    CHECK(e.isConst());
    CHECK(e.type == Type::Bool);
    return e.num != 0;
  };
  CHECK(axiom[0].kind == OpKind::Line);
  REQUIRE(axiom[0].args.size() == 2);
  CHECK(num(axiom[0].args[0]) == 0.05);
  CHECK(flag(axiom[0].args[1]) == true);
  CHECK(axiom[0].bodies.empty());
  CHECK(axiom[0].loc.line == 1);
  CHECK(axiom[0].loc.col == 10);

  CHECK(axiom[1].kind == OpKind::LineSeg);
  CHECK(axiom[1].args.empty());

  CHECK(axiom[2].kind == OpKind::Line);
  REQUIRE(axiom[2].args.size() == 2);
  CHECK(num(axiom[2].args[0]) == 0.2);
  CHECK(flag(axiom[2].args[1]) == true);

  CHECK(axiom[3].kind == OpKind::LineSeg);
  REQUIRE(axiom[3].args.size() == 1);
  CHECK(num(axiom[3].args[0]) == 1.5);

  CHECK(axiom[4].kind == OpKind::Line);
  REQUIRE(axiom[4].args.size() == 2);
  CHECK(num(axiom[4].args[0]) == 0.3);
  CHECK(flag(axiom[4].args[1]) == false);

  // A parameter width stays an expression; merge still gets its default.
  const Block& grow = m.rules[1].alternatives[0].ops;
  REQUIRE(grow.size() == 2);
  CHECK(grow[0].kind == OpKind::Line);
  REQUIRE(grow[0].args.size() == 2);
  CHECK(grow[0].args[0].op == ExprOp::Param);
  CHECK(flag(grow[0].args[1]) == true);
  CHECK(grow[1].kind == OpKind::LineSeg);
  REQUIRE(grow[1].args.size() == 1);
  CHECK(grow[1].args[0].op == ExprOp::Mul);
}

TEST_CASE("lower: IC and IM are collide / merge instances, with nothing left to wait for",
          "[ir][lower][collision]") {
  Module m = compile("axiom: IC(\"cube\") IM(\"ico\", 0.1, 30) I(\"cube\");");
  const Block& ops = m.axiom;
  REQUIRE(ops.size() == 3);
  CHECK(ops[0].kind == OpKind::Instance);
  CHECK(ops[0].mode == InstanceMode::Collide);
  CHECK(ops[0].args.empty());
  CHECK(ops[0].why.empty());
  CHECK(ops[1].kind == OpKind::Instance);
  CHECK(ops[1].mode == InstanceMode::Merge);
  CHECK(ops[1].args.size() == 2);
  CHECK(ops[1].why.empty());
  CHECK(ops[2].mode == InstanceMode::Plain);
}

TEST_CASE("printer: collision settings and lines, exact text", "[ir][printer][lower]") {
  Module m = compile(
      "collision all centre 0.25;\n"
      "Axiom ~> Line() LineSeg() Line(0.2, false) LineSeg(1.5);");
  CHECK(printModule(m) == R"(module "t.fgsg"
derive breadthfirst
collision all centre 0.25
symbol Axiom()  priority 0  rules [0]
axiom
  emit Axiom()
rule 0 "Axiom#0" Axiom()  priority 0
  alt weight 1
    line 0.05, true
    lineseg
    line 0.2, false
    lineseg 1.5
)");

  // The default (mesh, not all) prints nothing; each other setting prints its line.
  auto collisionLine = [](const std::string& decl) {
    const std::string text = printModule(compile(decl + "\nA ~> I(\"cube\");"));
    const size_t at = text.find("collision");
    return at == std::string::npos ? std::string() : text.substr(at, text.find('\n', at) - at);
  };
  CHECK(collisionLine("") == "");
  CHECK(collisionLine("collision mesh;") == "");
  CHECK(collisionLine("collision all;") == "collision all");
  CHECK(collisionLine("collision all mesh;") == "collision all");
  CHECK(collisionLine("collision center 1;") == "collision centre 1");
  CHECK(collisionLine("collision geodesic 0.3;") == "collision geodesic 0.3");
  CHECK(collisionLine("collision geodesic 0.3 all;") == "collision all geodesic 0.3");
}

TEST_CASE("verifier: collision radius and Line / LineSeg arguments", "[ir][verifier][lower]") {
  Module base = compile("Axiom ~> Line(0.2) LineSeg(1);");
  std::vector<std::string> problems;
  CHECK(verifyModule(base, problems));
  INFO(joined(problems));

  Module centre = base;
  centre.collision.metric = CollisionMetric::Centre;
  expectProblem(centre, "collision: radius 0 must be positive for the centre metric");
  Module geodesic = base;
  geodesic.collision.metric = CollisionMetric::Geodesic;
  geodesic.collision.radius = -1;
  expectProblem(geodesic, "collision: radius -1 must be positive for the geodesic metric");
  Module distance = base;
  distance.collision.metric = CollisionMetric::Distance;
  expectProblem(distance, "collision: radius 0 must be positive for the distance metric");
  Module badMetric = base;
  badMetric.collision.metric = static_cast<CollisionMetric>(7);
  expectProblem(badMetric, "collision: bad metric 7");
  Module meshAll = base;
  meshAll.collision.all = true;
  CHECK(verifyModule(meshAll, problems));

  Block& ops = base.rules[0].alternatives[0].ops;
  REQUIRE(ops.size() == 2);
  Module oneArg = base;
  oneArg.rules[0].alternatives[0].ops[0].args.pop_back();
  expectProblem(oneArg, "op 0 (line): 1 arguments, expected 2 (width, merge)");
  Module numMerge = base;
  numMerge.rules[0].alternatives[0].ops[0].args[1] = Expr::number(1);
  expectProblem(numMerge, "op 0 (line): merge is num, expected bool");
  Module boolWidth = base;
  boolWidth.rules[0].alternatives[0].ops[0].args[0] = Expr::boolean(true);
  expectProblem(boolWidth, "op 0 (line): width is bool, expected num");
  Module lineBody = base;
  lineBody.rules[0].alternatives[0].ops[0].bodies.push_back({});
  expectProblem(lineBody, "op 0 (line): 1 bodies, expected 0");
  Module twoLengths = base;
  twoLengths.rules[0].alternatives[0].ops[1].args.push_back(Expr::number(2));
  expectProblem(twoLengths, "op 1 (lineseg): 2 arguments, expected 0 or 1 (length)");
  Module boolLength = base;
  boolLength.rules[0].alternatives[0].ops[1].args[0] = Expr::boolean(false);
  expectProblem(boolLength, "op 1 (lineseg): argument is bool, expected num");
}

TEST_CASE("lower: surface and fields, evaluated, in declaration order", "[ir][lower][environment]") {
  Module plane = compile("A ~> I(\"cube\");");
  CHECK_FALSE(plane.surface.present);
  CHECK(plane.fields.empty());

  Module file = compile("surface \"meshes/bunny.off\";\nA ~> I(\"cube\");");
  CHECK(file.surface.present);
  CHECK(file.surface.path == "meshes/bunny.off");
  CHECK(file.surface.generator.empty());
  CHECK(file.surface.args.empty());
  CHECK(file.surface.loc.line == 1);
  CHECK(file.surface.loc.col == 1);

  Module m = compile(R"(const R = 2;
const n = 120;
surface torus(R, R * 0.3);
field F1 = tensor("foot.tfield");
field F2 = design tensor { center at vertex n; wedge at (0.2,0.1,0.9) decay 2; smooth 300; };
field K = curvature;
field V = design vector { regular at vertex 4 angle 45 strength 2; saddle at (0, 0, 1); };
A : F1.value1 > K.mincurv ~> T(V.length, 0, 0) I("cube");
)");
  CHECK(m.surface.present);
  CHECK(m.surface.generator == "torus");
  CHECK(m.surface.path.empty());
  REQUIRE(m.surface.args.size() == 2);
  CHECK(m.surface.args[0] == 2);
  CHECK(m.surface.args[1] == Approx(0.6));
  CHECK(m.surface.loc.line == 3);

  using Words = std::vector<std::pair<std::string, std::vector<double>>>;
  REQUIRE(m.fields.size() == 4);
  CHECK(m.fields[0].name == "F1");
  CHECK(m.fields[0].source == "file");
  CHECK(m.fields[0].kind == "tensor");
  CHECK(m.fields[0].path == "foot.tfield");
  CHECK(m.fields[0].design.empty());
  CHECK(m.fields[0].loc.line == 4);

  const FieldSpec& f2 = m.fields[1];
  CHECK(f2.name == "F2");
  CHECK(f2.source == "design");
  CHECK(f2.kind == "tensor");
  CHECK(f2.path.empty());
  REQUIRE(f2.design.size() == 3);
  CHECK(f2.design[0].kind == "centre");
  CHECK(f2.design[0].words == Words{{"vertex", {120}}});
  CHECK(f2.design[0].loc.line == 5);
  CHECK(f2.design[0].loc.col == 28);
  CHECK(f2.design[1].kind == "wedge");
  CHECK(f2.design[1].words == Words{{"at", {0.2, 0.1, 0.9}}, {"decay", {2}}});
  CHECK(f2.design[1].loc.col == 48);
  CHECK(f2.design[2].kind == "smooth");
  CHECK(f2.design[2].words == Words{{"iterations", {300}}});

  CHECK(m.fields[2].name == "K");
  CHECK(m.fields[2].source == "curvature");
  CHECK(m.fields[2].kind == "tensor");

  const FieldSpec& v = m.fields[3];
  CHECK(v.kind == "vector");
  REQUIRE(v.design.size() == 2);
  CHECK(v.design[0].words == Words{{"vertex", {4}}, {"angle", {45}}, {"strength", {2}}});
  CHECK(v.design[1].kind == "saddle");
  CHECK(v.design[1].words == Words{{"at", {0, 0, 1}}});

  // The environment entries the queries name are kept as they were.
  REQUIRE(m.environment.size() == 5);
  CHECK(m.environment[0].kind == "surface");
  CHECK(m.environment[1].kind == "field");
  CHECK(m.environment[1].name == "F1");
  CHECK(m.environment[4].name == "V");
  const Expr& guard = m.rules[0].guard;
  REQUIRE(guard.args.size() == 2);
  CHECK(guard.args[0].env == 1);
  CHECK(guard.args[1].env == 3);

  std::vector<std::string> problems;
  CHECK(verifyModule(m, problems));

  const std::string printed = printModule(m);
  CHECK(printed.find("\nsurface torus(2, 0.6)\n"
                     "field F1 = tensor(\"foot.tfield\")\n"
                     "field F2 = design tensor { centre vertex 120; wedge at (0.2, 0.1, 0.9) decay 2; "
                     "smooth iterations 300 }\n"
                     "field K = curvature\n"
                     "field V = design vector { regular vertex 4 angle 45 strength 2; saddle at (0, 0, 1) }\n"
                     "env surface torus \"procedural\"\n") != std::string::npos);
}
