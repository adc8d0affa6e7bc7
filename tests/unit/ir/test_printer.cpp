#include <catch2/catch.hpp>

#include <string>

#include "ir/builtins.h"
#include "ir/printer.h"

#include "ir_test_helpers.h"

using namespace fgsg::ir;
using testing::binary;
using testing::param;

namespace {

Expr unary(ExprOp op, Type t, Expr a) {
  Expr e;
  e.op = op;
  e.type = t;
  e.args = {std::move(a)};
  return e;
}

Expr call(Builtin b, std::vector<Expr> args) {
  Expr e;
  e.op = ExprOp::Call;
  e.index = static_cast<uint32_t>(b);
  e.type = builtinSignature(b).result;
  e.args = std::move(args);
  return e;
}

Expr query(Query q, Type t, std::vector<Expr> args = {}) {
  Expr e;
  e.op = ExprOp::Query;
  e.index = static_cast<uint32_t>(q);
  e.type = t;
  e.args = std::move(args);
  return e;
}

// A rule whose parameters are a, b, c in slots 0..2, for printing names.
Rule abcRule() {
  Rule r;
  r.params = {{"a", Type::Num, 0}, {"b", Type::Num, 1}, {"c", Type::Num, 2}};
  r.slotCount = 3;
  return r;
}

}  // namespace

TEST_CASE("printer: whole module, exact text", "[ir][printer]") {
  const std::string expected = R"(module "fig4.fgsg"
derive breadthfirst
attr height: num = 12
symbol Axiom()  priority 0  rules [0]
symbol A(num, num)  priority 0  rules [1]
symbol wall()  priority 0  rules []
axiom
  emit Axiom()
rule 0 "Axiom#1" Axiom()  priority 0
  alt weight 1
    emit A(height, 2)
rule 1 "3" A(x: num @0, y: num @1)  priority 0  guard (x > 0)
  alt weight 0.5
    push
    translate 0.6, 0, 0
    rotate z 60
    emit A(x + 1, y * 0.5)
    pop
    subdiv x [1r, 2, ~1]
      body 0:
        emit wall()
      body 1:
        (empty)
      body 2:
        instance "torus" plain
  alt weight 0.5
    emit wall()
)";
  const Module m = testing::sampleModule();
  CHECK(printModule(m) == expected);
  CHECK(printModule(m) == printModule(m));  // deterministic
}

TEST_CASE("printer: one rule", "[ir][printer]") {
  const Module m = testing::sampleModule();
  CHECK(printRule(m, m.rules[0]) ==
        "rule 0 \"Axiom#1\" Axiom()  priority 0\n  alt weight 1\n    emit A(height, 2)\n");
}

TEST_CASE("printer: shortest round-trip numbers", "[ir][printer]") {
  CHECK(printNumber(0.6) == "0.6");
  CHECK(printNumber(1e-9) == "1e-09");
  CHECK(printNumber(12) == "12");
  CHECK(printNumber(-0.5) == "-0.5");
  CHECK(printNumber(0.1 + 0.2) == "0.30000000000000004");
  CHECK(printNumber(1e21) == "1e+21");
}

TEST_CASE("printer: parentheses follow precedence and associativity", "[ir][printer]") {
  const Module m;
  const Rule r = abcRule();
  auto p = [&](const Expr& e) { return printExpr(m, &r, e); };
  const Type N = Type::Num;
  const Expr a = param(0), b = param(1), c = param(2);

  CHECK(p(binary(ExprOp::Mul, N, binary(ExprOp::Add, N, a, b), c)) == "(a + b) * c");
  CHECK(p(binary(ExprOp::Add, N, a, binary(ExprOp::Mul, N, b, c))) == "a + b * c");
  CHECK(p(binary(ExprOp::Sub, N, binary(ExprOp::Sub, N, a, b), c)) == "a - b - c");
  CHECK(p(binary(ExprOp::Sub, N, a, binary(ExprOp::Sub, N, b, c))) == "a - (b - c)");
  CHECK(p(unary(ExprOp::Neg, N, binary(ExprOp::Add, N, a, Expr::number(1)))) == "-(a + 1)");
  CHECK(p(unary(ExprOp::Neg, N, a)) == "-a");
  CHECK(p(binary(ExprOp::Pow, N, Expr::number(-1), Expr::number(2))) == "(-1) ^ 2");
  CHECK(p(binary(ExprOp::Pow, N, binary(ExprOp::Pow, N, a, b), c)) == "(a ^ b) ^ c");
  CHECK(p(binary(ExprOp::Sub, N, a, Expr::number(-1))) == "a - -1");

  const Type B = Type::Bool;
  const Expr lt = binary(ExprOp::Lt, B, a, b);
  const Expr gt = binary(ExprOp::Gt, B, c, Expr::number(0));
  CHECK(p(binary(ExprOp::Or, B, binary(ExprOp::And, B, lt, gt), lt)) == "a < b && c > 0 || a < b");
  CHECK(p(binary(ExprOp::And, B, binary(ExprOp::Or, B, lt, gt), lt)) == "(a < b || c > 0) && a < b");
  CHECK(p(unary(ExprOp::Not, B, lt)) == "!(a < b)");

  Expr sel;
  sel.op = ExprOp::Select;
  sel.type = N;
  sel.args = {lt, a, binary(ExprOp::Add, N, b, c)};
  CHECK(p(sel) == "a < b ? a : b + c");
  CHECK(p(binary(ExprOp::Mul, N, sel, Expr::number(2))) == "(a < b ? a : b + c) * 2");
}

TEST_CASE("printer: calls, queries, vectors, constants", "[ir][printer]") {
  Module m;
  const uint32_t street = m.internString("street");
  const uint32_t vector1 = m.internString("vector1");
  m.environment.push_back({"surface", "", "bunny.off", {}});
  m.environment.push_back({"field", "F1", "tensor(\"foot.tfield\")", {}});
  m.environment.push_back({"texture", "mask", "paint.png", {}});
  m.attrs.push_back({"height", Type::Num, Expr::number(12), {}, false, {}});
  const Rule r = abcRule();
  auto p = [&](const Expr& e) { return printExpr(m, &r, e); };

  CHECK(p(call(Builtin::Sin, {param(0)})) == "sin(a)");
  CHECK(p(call(Builtin::Atan2, {param(0), Expr::number(1)})) == "atan2(a, 1)");
  Expr rnd;
  rnd.op = ExprOp::Rand;
  rnd.args = {Expr::number(1), Expr::number(2)};
  CHECK(p(rnd) == "rand(1, 2)");
  CHECK(p(query(Query::ScopeSx, Type::Num)) == "Scope.sx");
  CHECK(p(query(Query::ShapeDepth, Type::Num)) == "Shape.depth");
  CHECK(p(query(Query::ShapeVisible, Type::Bool, {Expr::string(street)})) ==
        "Shape.visible(\"street\")");
  Expr field = query(Query::Field, Type::Vec3);
  field.env = 1;
  field.extra = vector1;
  CHECK(p(field) == "F1.vector1");
  Expr tex = query(Query::Texture, Type::Num, {param(0)});
  tex.env = 2;
  CHECK(p(tex) == "context.mask(a)");
  tex.args.clear();
  CHECK(p(tex) == "context.mask(texCoord)");

  Expr vec;
  vec.type = Type::Vec3;
  vec.vec[0] = 1;
  vec.vec[1] = 0.5;
  vec.vec[2] = -2;
  CHECK(p(vec) == "(1, 0.5, -2)");
  Expr make;
  make.op = ExprOp::MakeVec;
  make.type = Type::Vec3;
  make.args = {param(0), Expr::number(0), Expr::number(1)};
  CHECK(p(make) == "(a, 0, 1)");
  Expr elem;
  elem.op = ExprOp::VecElem;
  elem.index = 2;
  elem.args = {binary(ExprOp::Add, Type::Vec3, make, vec)};
  CHECK(p(elem) == "((a, 0, 1) + (1, 0.5, -2)).z");

  CHECK(p(Expr::boolean(true)) == "true");
  CHECK(p(Expr::string(street)) == "\"street\"");
  Expr attr;
  attr.op = ExprOp::Attr;
  CHECK(p(attr) == "height");
  // Without a rule, parameters print by slot.
  CHECK(printExpr(m, nullptr, param(1)) == "@1");
}

TEST_CASE("printer: header fields and remaining ops", "[ir][printer]") {
  Module m;
  m.sourceName = "abop.fgsg";
  m.mode = DeriveMode::Parallel;
  m.steps = 5;
  m.turtle.angle = 25.7;
  m.environment.push_back({"surface", "", "bunny.off", {}});
  m.internAsset("wall.obj");
  const uint32_t side = m.internString("sidefaces");
  m.symbols.push_back({"F", {Type::Num}, 1, {}, {}, {}});

  Op turtle;
  turtle.kind = OpKind::Turtle;
  turtle.index = static_cast<uint32_t>(TurtleOp::Left);
  turtle.args = {Expr::number(30)};
  Op back;
  back.kind = OpKind::Turtle;
  back.index = static_cast<uint32_t>(TurtleOp::RollLeft);
  Op im;
  im.kind = OpKind::Instance;
  im.mode = InstanceMode::Merge;
  im.args = {Expr::number(0.1), Expr::number(30)};
  Op rep;
  rep.kind = OpKind::Repeat;
  rep.index = 5;
  rep.sizes = {{Size::Floating, Expr::number(2)}, {Size::Absolute, Expr::number(3)}};
  rep.bodies = {{}};
  Op comp;
  comp.kind = OpKind::Comp;
  comp.str = side;
  comp.bodies = {{}};
  Op scale;
  scale.kind = OpKind::Scale;
  scale.sizes = {{Size::Relative, Expr::number(1)},
                 {Size::Relative, Expr::number(0.5)},
                 {Size::Absolute, Expr::number(2)}};
  Op un;
  un.kind = OpKind::Unsupported;
  un.name = "Synthesize";
  un.why = "model synthesis arrives later";
  Op bad;
  bad.kind = OpKind::Emit;
  bad.index = 9;  // out of range: printed, not dereferenced
  m.axiom = {turtle, back, im, rep, comp, scale, un, bad};

  CHECK(printModule(m) == R"(module "abop.fgsg"
derive parallel 5
turtle angle 25.7 step 1 width 0.1
env surface "bunny.off"
symbol F(num)  priority 0  rules []
axiom
  turtle +(30)
  turtle \
  instance "wall.obj" merge 0.1, 30
  repeat xz [~2, 3]
    body 0:
      (empty)
  comp "sidefaces"
    body 0:
      (empty)
  scale [1r, 0.5r, 2]
  unsupported "Synthesize" "model synthesis arrives later"
  emit sym#9()
)");
}

TEST_CASE("printer: context rules", "[ir][printer]") {
  Module m;
  m.symbols.push_back({"A", {Type::Num}, 1, {0}, {}, {}});
  m.symbols.push_back({"B", {Type::Num}, 1, {}, {}, {}});
  Rule r;
  r.symbol = 0;
  r.label = "p1";
  r.params = {{"x", Type::Num, 0}, {"l", Type::Num, 1}, {"rr", Type::Num, 2}};
  r.slotCount = 3;
  r.left = {{1, 0, {1}}};
  r.right = {{~0u, 1, {}}, {1, 0, {2}}};
  r.alternatives.push_back({Expr::number(1), {}, {}});
  m.rules.push_back(r);
  CHECK(printRule(m, m.rules[0]) ==
        "rule 0 \"p1\" B(l: num @1) < A(x: num @0) > [ B(rr: num @2)  priority 0\n"
        "  alt weight 1\n"
        "    (empty)\n");
}

TEST_CASE("printer: surface and fields, one line each", "[ir][printer][environment]") {
  Module m;
  m.sourceName = "t.fgsg";
  m.surface.present = true;
  m.surface.generator = "torus";
  m.surface.args = {2, 0.6};
  FieldSpec file;
  file.name = "F1";
  file.source = "file";
  file.kind = "tensor";
  file.path = "foot \"1\".tfield";
  FieldSpec design;
  design.name = "F2";
  design.source = "design";
  design.kind = "tensor";
  design.design = {{"wedge", {{"vertex", {120}}, {"decay", {2}}}, {}},
                   {"regular", {{"at", {0.2, -0.1, 0.9}}, {"direction", {1, 0, 0}}}, {}},
                   {"smooth", {{"iterations", {300}}}, {}}};
  FieldSpec curvature;
  curvature.name = "K";
  curvature.source = "curvature";
  curvature.kind = "tensor";
  FieldSpec vec;
  vec.name = "V";
  vec.source = "file";
  vec.kind = "vector";
  vec.path = "v.vfield";
  FieldSpec empty;
  empty.name = "E";
  empty.source = "design";
  empty.kind = "vector";
  m.fields = {file, design, curvature, vec, empty};
  m.axiom = {};
  CHECK(printModule(m) == R"(module "t.fgsg"
derive breadthfirst
surface torus(2, 0.6)
field F1 = tensor("foot \"1\".tfield")
field F2 = design tensor { wedge vertex 120 decay 2; regular at (0.2, -0.1, 0.9) direction (1, 0, 0); smooth iterations 300 }
field K = curvature
field V = vector("v.vfield")
field E = design vector { }
axiom
  (empty)
)");

  Module f;
  f.surface.present = true;
  f.surface.path = "bunny.off";
  CHECK(printModule(f).find("\nsurface \"bunny.off\"\n") != std::string::npos);
  f.surface = {};
  f.surface.present = true;
  f.surface.generator = "genus2";
  CHECK(printModule(f).find("\nsurface genus2()\n") != std::string::npos);
  f.surface.present = false;
  CHECK(printModule(f).find("surface") == std::string::npos);
}
