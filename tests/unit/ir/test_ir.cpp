// Module tables, expression factories, the builtin tables, and the sample module the
// printer, verifier and fold tests share (declared in ir_test_helpers.h, defined here).
#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <string>

#include "ir/builtins.h"
#include "ir/ir.h"
#include "ir_test_helpers.h"

namespace fgsg::ir::testing {

Expr param(uint32_t slot, Type t) {
  Expr e;
  e.op = ExprOp::Param;
  e.type = t;
  e.index = slot;
  return e;
}

Expr binary(ExprOp op, Type t, Expr a, Expr b) {
  Expr e;
  e.op = op;
  e.type = t;
  e.args = {std::move(a), std::move(b)};
  return e;
}

Op simpleOp(OpKind kind) {
  Op op;
  op.kind = kind;
  return op;
}

Op emitOp(uint32_t symbol, std::vector<Expr> args) {
  Op op;
  op.kind = OpKind::Emit;
  op.index = symbol;
  op.args = std::move(args);
  return op;
}

// A small valid module in the shape of the papers' figures:
//   attr height = 12;
//   Axiom ~> A(height, 2);
//   3: A(x, y) : x > 0 ~> [ T(0.6,0,0) Rz(60) A(x+1, y*0.5) ]
//                          Subdiv("X", 1r, 2, ~1){ wall | | I("torus") } : 0.5
//                     ~> wall : 0.5 ;
Module sampleModule() {
  Module m;
  m.sourceName = "fig4.fgsg";
  m.attrs.push_back({"height", Type::Num, Expr::number(12), {}, false, {}});
  m.internAsset("torus");
  m.symbols.push_back({"Axiom", {}, 0, {0}, {}, {}});
  m.symbols.push_back({"A", {Type::Num, Type::Num}, 2, {1}, {}, {}});
  m.symbols.push_back({"wall", {}, 0, {}, {}, {}});

  Rule axiomRule;
  axiomRule.symbol = 0;
  axiomRule.label = "Axiom#1";
  Expr height;
  height.op = ExprOp::Attr;
  height.index = 0;
  axiomRule.alternatives.push_back({Expr::number(1), {emitOp(1, {height, Expr::number(2)})}, {}});
  m.rules.push_back(axiomRule);

  Rule r;
  r.symbol = 1;
  r.label = "3";
  r.params = {{"x", Type::Num, 0}, {"y", Type::Num, 1}};
  r.slotCount = 2;
  r.hasGuard = true;
  r.guard = binary(ExprOp::Gt, Type::Bool, param(0), Expr::number(0));

  Block ops;
  ops.push_back(simpleOp(OpKind::Push));
  Op t;
  t.kind = OpKind::Translate;
  t.args = {Expr::number(0.6), Expr::number(0), Expr::number(0)};
  ops.push_back(t);
  Op rz;
  rz.kind = OpKind::Rotate;
  rz.index = 2;
  rz.args = {Expr::number(60)};
  ops.push_back(rz);
  ops.push_back(emitOp(1, {binary(ExprOp::Add, Type::Num, param(0), Expr::number(1)),
                           binary(ExprOp::Mul, Type::Num, param(1), Expr::number(0.5))}));
  ops.push_back(simpleOp(OpKind::Pop));
  Op subdiv;
  subdiv.kind = OpKind::Subdiv;
  subdiv.index = 0;
  subdiv.sizes = {{Size::Relative, Expr::number(1)},
                  {Size::Absolute, Expr::number(2)},
                  {Size::Floating, Expr::number(1)}};
  Op inst;
  inst.kind = OpKind::Instance;
  inst.index = 0;
  subdiv.bodies = {{emitOp(2, {})}, {}, {inst}};
  ops.push_back(subdiv);
  r.alternatives.push_back({Expr::number(0.5), ops, {}});
  r.alternatives.push_back({Expr::number(0.5), {emitOp(2, {})}, {}});
  m.rules.push_back(r);

  m.axiom = {emitOp(0, {})};
  return m;
}

}  // namespace fgsg::ir::testing

using namespace fgsg::ir;

TEST_CASE("type names and slot widths", "[ir]") {
  CHECK(std::string(typeName(Type::Num)) == "num");
  CHECK(std::string(typeName(Type::Bool)) == "bool");
  CHECK(std::string(typeName(Type::Str)) == "str");
  CHECK(std::string(typeName(Type::Vec3)) == "vec3");
  CHECK(slotWidth(Type::Vec3) == 3);
  CHECK(slotWidth(Type::Str) == 1);
}

TEST_CASE("constant factories", "[ir]") {
  const Expr n = Expr::number(2.5);
  CHECK(n.isConst());
  CHECK(n.type == Type::Num);
  CHECK(n.num == 2.5);
  const Expr t = Expr::boolean(true), f = Expr::boolean(false);
  CHECK(t.type == Type::Bool);
  CHECK(t.num == 1.0);
  CHECK(f.num == 0.0);
  const Expr s = Expr::string(7);
  CHECK(s.type == Type::Str);
  CHECK(s.num == 7.0);
  CHECK(s.args.empty());
}

TEST_CASE("interning dedupes strings and assets separately", "[ir]") {
  Module m;
  CHECK(m.internString("street") == 0);
  CHECK(m.internString("roof") == 1);
  CHECK(m.internString("street") == 0);
  CHECK(m.strings.size() == 2);
  CHECK(m.internAsset("roof") == 0);  // assets are their own table
  CHECK(m.internAsset("torus") == 1);
  CHECK(m.internAsset("roof") == 0);
  CHECK(m.assets.size() == 2);
}

TEST_CASE("symbol and attribute lookup", "[ir]") {
  const Module m = testing::sampleModule();
  CHECK(m.findSymbol("A") == 1);
  CHECK(m.findSymbol("wall") == 2);
  CHECK(m.findSymbol("B") == -1);
  CHECK(m.findAttr("height") == 0);
  CHECK(m.findAttr("width") == -1);
}

TEST_CASE("builtin table covers every builtin once, by name", "[ir][builtins]") {
  std::set<std::string> names;
  for (int i = 0; i < kBuiltinCount; ++i) {
    const auto b = static_cast<Builtin>(i);
    const BuiltinSignature& sig = builtinSignature(b);
    CHECK(names.insert(sig.name).second);
    REQUIRE(findBuiltin(sig.name).has_value());
    CHECK(*findBuiltin(sig.name) == b);
    CHECK(sig.arity >= 1);
    CHECK(sig.arity <= 3);
  }
  CHECK(!findBuiltin("frobnicate").has_value());
  CHECK(builtinSignature(Builtin::Atan2).arity == 2);
  CHECK(builtinSignature(Builtin::Normalize).result == Type::Vec3);
  CHECK(builtinSignature(Builtin::Dot).args[1] == Type::Vec3);
}

TEST_CASE("builtins evaluate in degrees with pinned edge cases", "[ir][builtins]") {
  auto eval1 = [](Builtin b, double x) {
    const Lanes a[1] = {{x, 0, 0}};
    return evalBuiltin(b, a)[0];
  };
  CHECK(eval1(Builtin::Sin, 90) == Approx(1.0));
  CHECK(eval1(Builtin::Cos, 0) == 1.0);
  CHECK(eval1(Builtin::Asin, 1) == Approx(90.0));
  const Lanes yx[2] = {{1, 0, 0}, {1, 0, 0}};
  CHECK(evalBuiltin(Builtin::Atan2, yx)[0] == Approx(45.0));
  CHECK(eval1(Builtin::Round, 2.5) == 3.0);
  CHECK(eval1(Builtin::Round, -2.5) == -3.0);
  CHECK(eval1(Builtin::Sign, -4) == -1.0);
  CHECK(eval1(Builtin::Sign, 0) == 0.0);
  const Lanes clampArgs[3] = {{5, 0, 0}, {0, 0, 0}, {2, 0, 0}};
  CHECK(evalBuiltin(Builtin::Clamp, clampArgs)[0] == 2.0);
  const Lanes zero[1] = {{0, 0, 0}};
  CHECK(evalBuiltin(Builtin::Normalize, zero) == Lanes{0, 0, 0});
  const Lanes v[1] = {{3, 0, 4}};
  CHECK(evalBuiltin(Builtin::Length, v)[0] == 5.0);
  CHECK(evalBuiltin(Builtin::Normalize, v) == Lanes{0.6, 0, 0.8});
  CHECK(modulo(-7, 3) == -1.0);
}

TEST_CASE("operator typing", "[ir][builtins]") {
  CHECK(binaryResultType(ExprOp::Add, Type::Vec3, Type::Vec3) == Type::Vec3);
  CHECK(!binaryResultType(ExprOp::Add, Type::Vec3, Type::Num));
  CHECK(binaryResultType(ExprOp::Mul, Type::Num, Type::Vec3) == Type::Vec3);
  CHECK(binaryResultType(ExprOp::Div, Type::Vec3, Type::Num) == Type::Vec3);
  CHECK(!binaryResultType(ExprOp::Div, Type::Num, Type::Vec3));
  CHECK(binaryResultType(ExprOp::Eq, Type::Str, Type::Str) == Type::Bool);
  CHECK(!binaryResultType(ExprOp::Lt, Type::Str, Type::Str));
  CHECK(!binaryResultType(ExprOp::And, Type::Num, Type::Bool));
  CHECK(unaryResultType(ExprOp::Neg, Type::Vec3) == Type::Vec3);
  CHECK(!unaryResultType(ExprOp::Not, Type::Num));
}
