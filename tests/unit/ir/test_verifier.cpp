#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "ir/builtins.h"
#include "ir/verifier.h"

#include "ir_test_helpers.h"

using namespace fgsg::ir;
using testing::binary;
using testing::param;

namespace {

const Type N = Type::Num;
const Type B = Type::Bool;

// The sample module's rule 1, first alternative: [push, translate, rotate, emit A, pop, subdiv].
Block& ops(Module& m) { return m.rules[1].alternatives[0].ops; }
Op& emitA(Module& m) { return ops(m)[3]; }
Op& subdiv(Module& m) { return ops(m)[5]; }

std::string joined(const std::vector<std::string>& problems) {
  std::string s;
  for (const std::string& p : problems) s += p + "\n";
  return s;
}

// The module must fail verification with a problem mentioning `needle`.
void expectProblem(const Module& m, const std::string& needle) {
  std::vector<std::string> problems;
  CHECK(!verifyModule(m, problems));
  INFO(joined(problems));
  CHECK(joined(problems).find(needle) != std::string::npos);
}

Expr call(Builtin b, std::vector<Expr> args) {
  Expr e;
  e.op = ExprOp::Call;
  e.index = static_cast<uint32_t>(b);
  e.type = builtinSignature(b).result;
  e.args = std::move(args);
  return e;
}

}  // namespace

TEST_CASE("verifier: the sample module is valid", "[ir][verifier]") {
  std::vector<std::string> problems;
  CHECK(verifyModule(testing::sampleModule(), problems));
  INFO(joined(problems));
  CHECK(problems.empty());
}

TEST_CASE("verifier: symbol index out of range", "[ir][verifier]") {
  Module m = testing::sampleModule();
  emitA(m).index = 42;
  expectProblem(m, "rule 1 \"3\" alt 0 op 3 (emit): symbol 42 out of range");
}

TEST_CASE("verifier: asset index out of range", "[ir][verifier]") {
  Module m = testing::sampleModule();
  subdiv(m).bodies[2][0].index = 3;
  expectProblem(m, "op 5 (subdiv) body 2 op 0 (instance): asset 3 out of range");
}

TEST_CASE("verifier: string constant out of range", "[ir][verifier]") {
  Module m = testing::sampleModule();
  m.internString("street");
  Expr e = binary(ExprOp::Eq, B, Expr::string(0), Expr::string(1));
  m.rules[1].guard = e;
  expectProblem(m, "guard: string constant 1");
}

TEST_CASE("verifier: comp selector string out of range", "[ir][verifier]") {
  Module m = testing::sampleModule();
  Op comp;
  comp.kind = OpKind::Comp;
  comp.str = 5;
  comp.bodies = {{}};
  m.axiom.push_back(comp);
  expectProblem(m, "axiom op 1 (comp): string 5 out of range");
}

TEST_CASE("verifier: attribute index out of range", "[ir][verifier]") {
  Module m = testing::sampleModule();
  m.rules[0].alternatives[0].ops[0].args[0].index = 1;
  expectProblem(m, "attr 1 out of range");
}

TEST_CASE("verifier: attribute read with the wrong type", "[ir][verifier]") {
  Module m = testing::sampleModule();
  m.attrs[0].type = B;
  m.attrs[0].value = Expr::boolean(true);
  expectProblem(m, "attr height is bool, read as num");
}

TEST_CASE("verifier: param slot beyond slotCount", "[ir][verifier]") {
  Module m = testing::sampleModule();
  emitA(m).args[0].args[0].index = 2;
  expectProblem(m, "slot 2 holds no parameter (slotCount 2)");
}

TEST_CASE("verifier: param read with the wrong type", "[ir][verifier]") {
  Module m = testing::sampleModule();
  m.rules[1].guard.args[0].type = Type::Vec3;
  expectProblem(m, "parameter x is num, read as vec3");
}

TEST_CASE("verifier: parameter outside a rule", "[ir][verifier]") {
  Module m = testing::sampleModule();
  m.rules[0].alternatives[0].ops[0].args[1] = param(0);
  m.axiom[0] = m.rules[0].alternatives[0].ops[0];
  expectProblem(m, "axiom op 0 (emit): parameter outside a rule");
}

TEST_CASE("verifier: arithmetic on the wrong types", "[ir][verifier]") {
  Module m = testing::sampleModule();
  emitA(m).args[0].args[1] = Expr::boolean(true);
  expectProblem(m, "num + bool typed num");
}

TEST_CASE("verifier: vector arithmetic typing", "[ir][verifier]") {
  Module m = testing::sampleModule();
  Expr v;
  v.type = Type::Vec3;
  Expr elem;
  elem.op = ExprOp::VecElem;
  elem.args = {binary(ExprOp::Mul, Type::Vec3, v, Expr::number(2))};  // valid: v * n
  emitA(m).args[1] = elem;
  std::vector<std::string> problems;
  CHECK(verifyModule(m, problems));
  INFO(joined(problems));
  emitA(m).args[1].args[0].op = ExprOp::Sub;  // v - n is not
  expectProblem(m, "vec3 - num typed vec3");
}

TEST_CASE("verifier: comparison must give bool", "[ir][verifier]") {
  Module m = testing::sampleModule();
  m.rules[1].guard.type = N;
  expectProblem(m, "num > num typed num");
}

TEST_CASE("verifier: logic on numbers", "[ir][verifier]") {
  Module m = testing::sampleModule();
  m.rules[1].guard = binary(ExprOp::And, B, m.rules[1].guard, Expr::number(1));
  expectProblem(m, "bool && num typed bool");
}

TEST_CASE("verifier: select branches of different types", "[ir][verifier]") {
  Module m = testing::sampleModule();
  Expr sel;
  sel.op = ExprOp::Select;
  sel.type = N;
  sel.args = {m.rules[1].guard, param(0), Expr::boolean(false)};
  emitA(m).args[0] = sel;
  expectProblem(m, "branches num and bool typed num");
}

TEST_CASE("verifier: builtin arity", "[ir][verifier]") {
  Module m = testing::sampleModule();
  emitA(m).args[0] = call(Builtin::Atan2, {param(0)});
  expectProblem(m, "atan2 with 1 operands, expected 2");
}

TEST_CASE("verifier: builtin argument type", "[ir][verifier]") {
  Module m = testing::sampleModule();
  emitA(m).args[0] = call(Builtin::Length, {param(0)});
  expectProblem(m, "length argument 0 is num, expected vec3");
}

TEST_CASE("verifier: query typing and environment", "[ir][verifier]") {
  Module m = testing::sampleModule();
  Expr q;
  q.op = ExprOp::Query;
  q.index = static_cast<uint32_t>(Query::ShapeVisible);
  q.type = B;
  q.args = {Expr::number(1)};
  m.rules[1].guard = q;
  expectProblem(m, "query argument is num, expected str");

  Module m2 = testing::sampleModule();
  Expr f;
  f.op = ExprOp::Query;
  f.index = static_cast<uint32_t>(Query::Field);
  f.type = N;
  f.env = 0;
  f.extra = m2.internString("value1");
  m2.environment.push_back({"texture", "mask", "paint.png", {}});
  emitA(m2).args[0] = f;
  expectProblem(m2, "environment entry 0 is not a field");
}

TEST_CASE("verifier: emit argument count", "[ir][verifier]") {
  Module m = testing::sampleModule();
  emitA(m).args.pop_back();
  expectProblem(m, "1 arguments for A, which has 2");
}

TEST_CASE("verifier: emit argument type", "[ir][verifier]") {
  Module m = testing::sampleModule();
  emitA(m).args[1] = Expr::boolean(true);
  expectProblem(m, "argument 1 is bool, A takes num");
}

TEST_CASE("verifier: subdiv bodies must match sizes", "[ir][verifier]") {
  Module m = testing::sampleModule();
  subdiv(m).bodies.pop_back();
  expectProblem(m, "op 5 (subdiv): 2 bodies, expected 3");
}

TEST_CASE("verifier: repeat sizes must match the axes mask", "[ir][verifier]") {
  Module m = testing::sampleModule();
  Op rep;
  rep.kind = OpKind::Repeat;
  rep.index = 3;  // X and Y
  rep.sizes = {{Size::Floating, Expr::number(2)}};
  rep.bodies = {{}};
  m.axiom.push_back(rep);
  expectProblem(m, "1 sizes for axes mask 3");
}

TEST_CASE("verifier: unbalanced push and pop", "[ir][verifier]") {
  Module m = testing::sampleModule();
  ops(m).erase(ops(m).begin() + 4);  // the pop
  expectProblem(m, "rule 1 \"3\" alt 0: 1 push without pop");

  Module m2 = testing::sampleModule();
  Op pop;
  pop.kind = OpKind::Pop;
  subdiv(m2).bodies[1].push_back(pop);
  expectProblem(m2, "body 1 op 0 (pop): pop without push");
}

TEST_CASE("verifier: a rule's parameter slots must fit its block", "[ir][verifier]") {
  Module m = testing::sampleModule();
  m.rules[1].slotCount = 1;
  expectProblem(m, "parameter y (slot 1) outside slotCount 1");

  Module m2 = testing::sampleModule();
  m2.rules[1].params[1].slot = 0;
  expectProblem(m2, "parameter y in slot 0, expected 1");
}

TEST_CASE("verifier: predecessor parameters match the symbol", "[ir][verifier]") {
  Module m = testing::sampleModule();
  m.rules[1].params.pop_back();
  expectProblem(m, "1 parameters, symbol A has 2");
}

TEST_CASE("verifier: symbol slotCount is the sum of widths", "[ir][verifier]") {
  Module m = testing::sampleModule();
  m.symbols[1].slotCount = 3;
  expectProblem(m, "symbol A: slotCount 3, parameters take 2");
}

TEST_CASE("verifier: symbol rules point back to the symbol", "[ir][verifier]") {
  Module m = testing::sampleModule();
  m.symbols[2].rules = {1};
  expectProblem(m, "symbol wall: lists rule 1 of another symbol");

  Module m2 = testing::sampleModule();
  m2.symbols[1].rules.clear();
  expectProblem(m2, "rule 1 \"3\": not listed in the rules of symbol A");
}

TEST_CASE("verifier: symbol priority is its rules' highest", "[ir][verifier]") {
  Module m = testing::sampleModule();
  m.rules[1].priority = 2;
  expectProblem(m, "symbol A: priority 0, its rules' highest is 2");
}

TEST_CASE("verifier: every rule has an alternative", "[ir][verifier]") {
  Module m = testing::sampleModule();
  m.rules[1].alternatives.clear();
  expectProblem(m, "rule 1 \"3\": no alternative");
}

TEST_CASE("verifier: guard is bool and probability num", "[ir][verifier]") {
  Module m = testing::sampleModule();
  m.rules[1].guard = param(0);
  expectProblem(m, "guard is num, expected bool");

  Module m2 = testing::sampleModule();
  m2.rules[1].alternatives[1].probability = Expr::boolean(true);
  expectProblem(m2, "alt 1: probability is bool, expected num");
}

TEST_CASE("verifier: op arguments", "[ir][verifier]") {
  Module m = testing::sampleModule();
  ops(m)[1].args.pop_back();  // translate with 2 arguments
  expectProblem(m, "op 1 (translate): 2 arguments, expected 3");

  Module m2 = testing::sampleModule();
  ops(m2)[2].index = 4;  // rotate about axis 4
  expectProblem(m2, "op 2 (rotate): axis 4 out of range");
}

TEST_CASE("verifier: context modules", "[ir][verifier]") {
  Module m = testing::sampleModule();
  Rule& r = m.rules[1];
  r.params.push_back({"l", N, 2});
  r.slotCount = 3;
  r.left = {{1, 0, {2}}};  // A(l) < A(x, y): A has two parameters
  expectProblem(m, "left context: 1 parameters for A, which has 2");

  Module m2 = testing::sampleModule();
  m2.rules[1].right = {{~0u, 0, {}}};
  expectProblem(m2, "right context: bracket must be 1 or -1");
}

TEST_CASE("verifier: attribute default must be a constant of its type", "[ir][verifier]") {
  Module m = testing::sampleModule();
  m.attrs[0].value = binary(ExprOp::Add, N, Expr::number(1), Expr::number(2));
  expectProblem(m, "attr height: default value is not a constant");
}

namespace {
Module withSurface() {
  Module m = testing::sampleModule();
  m.surface.present = true;
  m.surface.generator = "torus";
  m.surface.args = {2, 0.6};
  FieldSpec f;
  f.name = "F";
  f.source = "design";
  f.kind = "tensor";
  f.design = {{"wedge", {{"vertex", {3}}, {"decay", {2}}}, {}},
              {"regular", {{"at", {0, 0, 1}}, {"angle", {30}}}, {}},
              {"smooth", {{"iterations", {10}}}, {}}};
  m.fields.push_back(f);
  FieldSpec k;
  k.name = "K";
  k.source = "curvature";
  k.kind = "tensor";
  m.fields.push_back(k);
  return m;
}
}  // namespace

TEST_CASE("verifier: surface", "[ir][verifier][environment]") {
  std::vector<std::string> problems;
  Module ok = withSurface();
  CHECK(verifyModule(ok, problems));
  INFO(joined(problems));

  Module file = testing::sampleModule();
  file.surface.present = true;
  file.surface.path = "bunny.off";
  CHECK(verifyModule(file, problems));

  Module m = withSurface();
  m.surface.generator = "klein";
  expectProblem(m, "surface: unknown generator 'klein'");
  m = withSurface();
  m.surface.args = {2};
  expectProblem(m, "surface: torus takes 2 arguments, has 1");
  m = withSurface();
  m.surface.args[1] = std::nan("");
  expectProblem(m, "surface: argument nan is not finite");
  m = withSurface();
  m.surface.path = "b.off";
  expectProblem(m, "surface: needs exactly one of a path and a generator");
  m = withSurface();
  m.surface.generator.clear();
  m.surface.path = "b.off";
  expectProblem(m, "surface: a file surface has no arguments");
  Module absent = testing::sampleModule();
  absent.surface.path = "b.off";
  expectProblem(absent, "surface: not present");
}

TEST_CASE("verifier: fields", "[ir][verifier][environment]") {
  Module m = withSurface();
  m.surface = {};
  expectProblem(m, "fields without a surface");

  m = withSurface();
  m.fields[1].name = "F";
  expectProblem(m, "field F: name is not unique");
  m = withSurface();
  m.fields[0].kind = "matrix";
  expectProblem(m, "field F: bad kind 'matrix'");
  m = withSurface();
  m.fields[1].source = "blend";
  expectProblem(m, "field K: bad source 'blend'");
  m = withSurface();
  m.fields[1].kind = "vector";
  expectProblem(m, "field K: a curvature field is a tensor field");
  m = withSurface();
  m.fields[1].source = "file";
  expectProblem(m, "field K: file source without a path");
  m = withSurface();
  m.fields[1].path = "k.tfield";
  expectProblem(m, "field K: a path on a curvature field");
  m = withSurface();
  m.fields[1].design = m.fields[0].design;
  expectProblem(m, "field K: design items on a curvature field");

  m = withSurface();
  m.fields[0].design[0].kind = "center";
  expectProblem(m, "field F design center: unknown kind");
  m = withSurface();
  m.fields[0].design[0].words[1].first = "decai";
  expectProblem(m, "field F design wedge: unknown keyword 'decai'");
  m = withSurface();
  m.fields[0].design[0].words[1].second = {1, 2, 3};
  expectProblem(m, "field F design wedge: 'decay' has 3 values, expected 1");
  m = withSurface();
  m.fields[0].design[0].words[1].second = {std::numeric_limits<double>::infinity()};
  expectProblem(m, "field F design wedge: 'decay' value inf is not finite");
  m = withSurface();
  m.fields[0].design[0].words[1].second = {0};
  expectProblem(m, "field F design wedge: decay 0 is not positive");
  m = withSurface();
  m.fields[0].design[0].words[0].second = {2.5};
  expectProblem(m, "field F design wedge: 'vertex' 2.5 is not a whole number >= 0");
  m = withSurface();
  m.fields[0].design[0].words.erase(m.fields[0].design[0].words.begin());
  expectProblem(m, "field F design wedge: has no position (vertex or at)");
  m = withSurface();
  m.fields[0].design[0].words.push_back({"angle", {30}});
  expectProblem(m, "field F design wedge: keyword 'angle' is for regular elements only");
  m = withSurface();
  m.fields[0].design[2].words[0].first = "decay";
  expectProblem(m, "field F design smooth: keyword 'decay' does not belong to a smooth");
  m = withSurface();
  m.fields[0].design[1].words.push_back({"iterations", {3}});
  expectProblem(m, "field F design regular: keyword 'iterations' does not belong to a regular");
}
