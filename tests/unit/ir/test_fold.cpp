#include <catch2/catch.hpp>

#include <string>

#include "ir/builtins.h"
#include "ir/fold.h"
#include "ir/printer.h"
#include "ir/verifier.h"

#include "ir_test_helpers.h"

using namespace fgsg::ir;
using testing::binary;
using testing::param;

namespace {

const Type N = Type::Num;
const Type B = Type::Bool;

// A module whose one rule A(x: num, v: vec3, ok: bool) has a single alternative whose
// probability is the expression under test; folding then runs over the whole module.
struct Harness {
  Module m;
  Harness() {
    m.symbols.push_back({"A", {N, Type::Vec3, B}, 5, {0}, {}, {}});
    m.attrs.push_back({"height", N, Expr::number(12), {}, false, {}});
    Rule r;
    r.symbol = 0;
    r.label = "A#1";
    r.params = {{"x", N, 0}, {"v", Type::Vec3, 1}, {"ok", B, 4}};
    r.slotCount = 5;
    r.alternatives.push_back({Expr::number(1), {}, {}});
    m.rules.push_back(r);
  }
  // Folds `e` in place of the probability (or guard, when Bool); returns the count.
  int fold(Expr e) {
    Rule& r = m.rules[0];
    if (e.type == B) {
      r.hasGuard = true;
      r.guard = std::move(e);
    } else {
      r.alternatives[0].probability = std::move(e);
    }
    return foldConstants(m);
  }
  std::string result() const {
    const Rule& r = m.rules[0];
    if (r.hasGuard) return printExpr(m, &r, r.guard);
    return printExpr(m, &r, r.alternatives[0].probability);
  }
};

Expr x() { return param(0); }
Expr v() { return param(1, Type::Vec3); }
Expr ok() { return param(4, B); }

Expr call(Builtin b, std::vector<Expr> args) {
  Expr e;
  e.op = ExprOp::Call;
  e.index = static_cast<uint32_t>(b);
  e.type = builtinSignature(b).result;
  e.args = std::move(args);
  return e;
}

Expr select(Expr c, Expr a, Expr b) {
  Expr e;
  e.op = ExprOp::Select;
  e.type = a.type;
  e.args = {std::move(c), std::move(a), std::move(b)};
  return e;
}

Expr rnd() {
  Expr e;
  e.op = ExprOp::Rand;
  e.args = {Expr::number(0), Expr::number(1)};
  return e;
}

Expr vec(double a, double b, double c) {
  Expr e;
  e.type = Type::Vec3;
  e.vec[0] = a;
  e.vec[1] = b;
  e.vec[2] = c;
  return e;
}

Expr neg(Expr a) {
  Expr e;
  e.op = ExprOp::Neg;
  e.type = a.type;
  e.args = {std::move(a)};
  return e;
}

}  // namespace

TEST_CASE("fold: arithmetic on constants", "[ir][fold]") {
  Harness h;
  CHECK(h.fold(binary(ExprOp::Add, N, binary(ExprOp::Mul, N, Expr::number(2), Expr::number(3)), x())) == 1);
  CHECK(h.result() == "6 + x");

  Harness h2;
  CHECK(h2.fold(binary(ExprOp::Sub, N, Expr::number(1),
                       binary(ExprOp::Div, N, Expr::number(1), Expr::number(4)))) == 2);
  CHECK(h2.result() == "0.75");

  Harness h3;
  CHECK(h3.fold(binary(ExprOp::Mod, N, Expr::number(-7), Expr::number(3))) == 1);
  CHECK(h3.result() == "-1");

  Harness h4;
  CHECK(h4.fold(neg(Expr::number(2))) == 1);
  CHECK(h4.result() == "-2");
}

TEST_CASE("fold: pure builtins, not rand", "[ir][fold]") {
  Harness h;
  CHECK(h.fold(call(Builtin::Sin, {Expr::number(0)})) == 1);
  CHECK(h.result() == "0");

  Harness h2;
  CHECK(h2.fold(call(Builtin::Max, {Expr::number(1), call(Builtin::Sqrt, {Expr::number(16)})})) == 2);
  CHECK(h2.result() == "4");

  Harness h3;
  CHECK(h3.fold(binary(ExprOp::Add, N, rnd(), Expr::number(1))) == 0);
  CHECK(h3.result() == "rand(0, 1) + 1");

  Harness h4;  // sin(x) stays, its constant-folded argument does not
  CHECK(h4.fold(call(Builtin::Sin, {binary(ExprOp::Mul, N, x(), Expr::number(2))})) == 0);
}

TEST_CASE("fold: attributes and queries stay", "[ir][fold]") {
  Harness h;
  Expr attr;
  attr.op = ExprOp::Attr;
  CHECK(h.fold(binary(ExprOp::Mul, N, attr, Expr::number(2))) == 0);
  CHECK(h.result() == "height * 2");

  Harness h2;
  Expr q;
  q.op = ExprOp::Query;
  q.index = static_cast<uint32_t>(Query::ScopeSx);
  CHECK(h2.fold(binary(ExprOp::Add, N, q, binary(ExprOp::Add, N, Expr::number(1), Expr::number(1)))) == 1);
  CHECK(h2.result() == "Scope.sx + 2");
}

TEST_CASE("fold: domain errors are left for sema", "[ir][fold]") {
  Harness h;
  CHECK(h.fold(binary(ExprOp::Div, N, Expr::number(1), Expr::number(0))) == 0);
  CHECK(h.result() == "1 / 0");

  Harness h2;
  CHECK(h2.fold(binary(ExprOp::Mod, N, Expr::number(1), Expr::number(0))) == 0);

  Harness h3;
  CHECK(h3.fold(call(Builtin::Sqrt, {Expr::number(-1)})) == 0);
  CHECK(h3.result() == "sqrt(-1)");

  Harness h4;  // overflow to inf is not a number either
  CHECK(h4.fold(binary(ExprOp::Mul, N, Expr::number(1e308), Expr::number(10))) == 0);
}

TEST_CASE("fold: comparisons and select", "[ir][fold]") {
  Harness h;
  // 1 < 2 ? x : x + 1  ->  x  (the comparison, then the select)
  CHECK(h.fold(select(binary(ExprOp::Lt, B, Expr::number(1), Expr::number(2)), x(),
                      binary(ExprOp::Add, N, x(), Expr::number(1)))) == 2);
  CHECK(h.result() == "x");

  Harness h2;
  CHECK(h2.fold(select(Expr::boolean(false), x(), Expr::number(3))) == 1);
  CHECK(h2.result() == "3");

  Harness h3;  // the discarded branch draws a random number: kept
  CHECK(h3.fold(select(Expr::boolean(true), x(), rnd())) == 0);

  Harness h4;
  CHECK(h4.fold(binary(ExprOp::Eq, B, Expr::string(0), Expr::string(0))) == 2);  // Eq, then guard
  CHECK(!h4.m.rules[0].hasGuard);

  Harness h5;
  CHECK(h5.fold(binary(ExprOp::Ne, B, binary(ExprOp::Ge, B, Expr::number(2), Expr::number(3)), ok())) == 1);
  CHECK(h5.result() == "false != ok");
}

TEST_CASE("fold: short-circuit logic", "[ir][fold]") {
  auto guard = [](Expr e, std::string expect, int count) {
    Harness h;
    CHECK(h.fold(std::move(e)) == count);
    CHECK((h.m.rules[0].hasGuard ? h.result() : std::string("<no guard>")) == expect);
  };
  const Expr xPos = binary(ExprOp::Gt, B, x(), Expr::number(0));
  const Expr randPos = binary(ExprOp::Gt, B, rnd(), Expr::number(0.5));
  guard(binary(ExprOp::And, B, Expr::boolean(false), randPos), "false", 1);
  guard(binary(ExprOp::Or, B, Expr::boolean(true), randPos), "<no guard>", 2);  // true guard dropped
  guard(binary(ExprOp::And, B, Expr::boolean(true), xPos), "x > 0", 1);
  guard(binary(ExprOp::Or, B, xPos, Expr::boolean(false)), "x > 0", 1);
  guard(binary(ExprOp::And, B, xPos, Expr::boolean(false)), "false", 1);
  guard(binary(ExprOp::And, B, randPos, Expr::boolean(false)), "rand(0, 1) > 0.5 && false", 0);
  Expr notNot;
  notNot.op = ExprOp::Not;
  notNot.type = B;
  notNot.args = {Expr::boolean(true)};
  guard(notNot, "false", 1);
}

TEST_CASE("fold: only IEEE-exact identities", "[ir][fold]") {
  auto prob = [](Expr e, std::string expect, int count) {
    Harness h;
    CHECK(h.fold(std::move(e)) == count);
    CHECK(h.result() == expect);
  };
  prob(binary(ExprOp::Mul, N, x(), Expr::number(1)), "x", 1);
  prob(binary(ExprOp::Mul, N, Expr::number(1), x()), "x", 1);
  prob(binary(ExprOp::Div, N, x(), Expr::number(1)), "x", 1);
  prob(binary(ExprOp::Sub, N, x(), Expr::number(0)), "x", 1);
  prob(binary(ExprOp::Add, N, x(), neg(Expr::number(0))), "x", 2);  // -0, then x + -0
  prob(binary(ExprOp::Add, N, x(), Expr::number(0)), "x + 0", 0);    // -0 + 0 is +0
  prob(binary(ExprOp::Mul, N, x(), Expr::number(0)), "x * 0", 0);    // inf * 0 is NaN
  prob(binary(ExprOp::Sub, N, Expr::number(0), x()), "0 - x", 0);    // 0 - 0 is +0, -0 is -0
  prob(neg(neg(x())), "x", 1);
}

TEST_CASE("fold: vectors", "[ir][fold]") {
  Harness h;
  Expr make;
  make.op = ExprOp::MakeVec;
  make.type = Type::Vec3;
  make.args = {Expr::number(1), binary(ExprOp::Add, N, Expr::number(1), Expr::number(1)), Expr::number(3)};
  Expr scaled = binary(ExprOp::Mul, Type::Vec3, make, Expr::number(2));
  Expr sum = binary(ExprOp::Add, Type::Vec3, scaled, vec(0.5, 0, 0));
  Expr elem;
  elem.op = ExprOp::VecElem;
  elem.index = 0;
  elem.args = {sum};
  CHECK(h.fold(elem) == 5);  // 1+1, make, *2, +vec, .x
  CHECK(h.result() == "2.5");

  Harness h2;
  Expr lenV = call(Builtin::Length, {vec(3, 0, 4)});
  CHECK(h2.fold(binary(ExprOp::Add, N, lenV, x())) == 1);
  CHECK(h2.result() == "5 + x");

  Harness h3;  // v * 1 is exactly v
  Expr elem3;
  elem3.op = ExprOp::VecElem;
  elem3.index = 1;
  elem3.args = {binary(ExprOp::Mul, Type::Vec3, Expr::number(1), v())};
  CHECK(h3.fold(elem3) == 1);
  CHECK(h3.result() == "v.y");

  Harness h4;  // (x, rand, 0).x must keep drawing the random number
  Expr make4;
  make4.op = ExprOp::MakeVec;
  make4.type = Type::Vec3;
  make4.args = {x(), rnd(), Expr::number(0)};
  Expr elem4;
  elem4.op = ExprOp::VecElem;
  elem4.args = {make4};
  CHECK(h4.fold(elem4) == 0);
  elem4.index = 1;
  Harness h5;
  make4.args = {x(), rnd(), Expr::number(0)};
  elem4.args = {make4};
  CHECK(h5.fold(elem4) == 1);
  CHECK(h5.result() == "rand(0, 1)");
}

TEST_CASE("fold: reaches every expression of a module", "[ir][fold]") {
  Module m = testing::sampleModule();
  auto two = [] { return binary(ExprOp::Add, N, Expr::number(1), Expr::number(1)); };
  m.rules[1].guard = binary(ExprOp::Gt, B, param(0), two());               // guard
  m.rules[1].alternatives[1].probability = two();                          // probability
  Op& subdiv = m.rules[1].alternatives[0].ops[5];
  subdiv.sizes[1].value = two();                                           // size
  Op t;
  t.kind = OpKind::Translate;
  t.args = {two(), two(), two()};
  subdiv.bodies[1].push_back(t);                                           // nested body
  m.axiom.push_back(t);                                                    // axiom
  CHECK(foldConstants(m) == 1 + 1 + 1 + 3 + 3);
  std::vector<std::string> problems;
  CHECK(verifyModule(m, problems));
  const std::string text = printModule(m);
  CHECK(text.find("1 + 1") == std::string::npos);
  CHECK(text.find("guard (x > 2)") != std::string::npos);
  CHECK(text.find("subdiv x [1r, 2, ~1]") != std::string::npos);
  CHECK(foldConstants(m) == 0);  // a fixed point
}

TEST_CASE("fold: keeps a valid module valid", "[ir][fold]") {
  Harness h;
  h.fold(select(binary(ExprOp::Lt, B, Expr::number(1), Expr::number(2)),
                call(Builtin::Clamp, {x(), Expr::number(0), binary(ExprOp::Mul, N, Expr::number(2), Expr::number(3))}),
                Expr::number(0)));
  CHECK(h.result() == "clamp(x, 0, 6)");
  std::vector<std::string> problems;
  CHECK(verifyModule(h.m, problems));
  CHECK(problems.empty());
}
