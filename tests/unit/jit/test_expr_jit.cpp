// The JIT's expressions against the interpreter's Evaluator: the same bits (memcmp,
// NaN included) and the same random draws, over random expression trees and inputs.
#include "backend/interp/eval.h"
#include "backend/jit/jit.h"
#include "backend/native/query_bridge.h"
#include "ir/printer.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>

namespace {

using namespace fgsg;
using ir::Builtin;
using ir::Expr;
using ir::ExprOp;
using ir::Type;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Parameter block: 8 numbers, then a vector at slot 8. Attributes: two numbers, a vector.
constexpr uint32_t kNumParams = 8;
constexpr uint32_t kVecParam = 8;
constexpr uint32_t kSlots = 11;

Expr node(ExprOp op, Type t, std::vector<Expr> args, uint32_t index = 0) {
  Expr e;
  e.op = op;
  e.type = t;
  e.args = std::move(args);
  e.index = index;
  return e;
}
Expr num(double v) { return Expr::number(v); }
Expr param(uint32_t slot) { return node(ExprOp::Param, Type::Num, {}, slot); }
Expr vparam() { return node(ExprOp::Param, Type::Vec3, {}, kVecParam); }
Expr call(Builtin b, std::vector<Expr> args, Type t = Type::Num) {
  return node(ExprOp::Call, t, std::move(args), static_cast<uint32_t>(b));
}
Expr rand(Expr lo, Expr hi) { return node(ExprOp::Rand, Type::Num, {std::move(lo), std::move(hi)}); }

double interesting(std::mt19937_64& g) {
  static const double values[] = {0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 1.5, 2.5, -2.5, 90.0, 180.0,
                                  45.0, 1e-310, 1e308, -1e308, kInf, -kInf, kNaN, 3.0, 1e-3};
  std::uniform_int_distribution<int> pick(0, 3);
  if (pick(g) == 0) return values[std::uniform_int_distribution<size_t>(0, std::size(values) - 1)(g)];
  return std::uniform_real_distribution<double>(-200.0, 200.0)(g);
}

// Random well-typed expression trees covering every op and builtin.
class Gen {
 public:
  explicit Gen(uint64_t seed) : g_(seed) {}

  Expr numExpr(int depth) {
    if (depth <= 0 || chance(0.15)) return leaf();
    const int kinds = 24;
    switch (uni(kinds)) {
      case 0: return node(ExprOp::Neg, Type::Num, {numExpr(depth - 1)});
      case 1: return node(ExprOp::Not, Type::Bool, {numExpr(depth - 1)});
      case 2: case 3: case 4: case 5: case 6: case 7: {
        static const ExprOp ops[] = {ExprOp::Add, ExprOp::Sub, ExprOp::Mul, ExprOp::Div, ExprOp::Mod, ExprOp::Pow};
        return node(ops[uni(6)], Type::Num, {numExpr(depth - 1), numExpr(depth - 1)});
      }
      case 8: case 9: {
        static const ExprOp ops[] = {ExprOp::Eq, ExprOp::Ne, ExprOp::Lt, ExprOp::Le, ExprOp::Gt, ExprOp::Ge};
        if (chance(0.2))
          return node(ops[uni(2)], Type::Bool, {vecExpr(depth - 1), vecExpr(depth - 1)});
        return node(ops[uni(6)], Type::Bool, {numExpr(depth - 1), numExpr(depth - 1)});
      }
      case 10: return node(chance(0.5) ? ExprOp::And : ExprOp::Or, Type::Bool, {numExpr(depth - 1), numExpr(depth - 1)});
      case 11: return node(ExprOp::Select, Type::Num, {numExpr(depth - 1), numExpr(depth - 1), numExpr(depth - 1)});
      case 12: case 13: case 14: case 15: return builtin(depth - 1);
      case 16: case 17: case 18: return rand(numExpr(depth - 1), numExpr(depth - 1));
      case 19: return node(ExprOp::VecElem, Type::Num, {vecExpr(depth - 1)}, uni(3));
      default: return leaf();
    }
  }

  Expr vecExpr(int depth) {
    if (depth <= 0 || chance(0.15)) {
      switch (uni(3)) {
        case 0: {
          Expr e = node(ExprOp::Const, Type::Vec3, {});
          for (double& v : e.vec) v = interesting(g_);
          return e;
        }
        case 1: return vparam();
        default: return node(ExprOp::Attr, Type::Vec3, {}, 2);
      }
    }
    switch (uni(8)) {
      case 0: return node(ExprOp::MakeVec, Type::Vec3, {numExpr(depth - 1), numExpr(depth - 1), numExpr(depth - 1)});
      case 1: return node(ExprOp::Neg, Type::Vec3, {vecExpr(depth - 1)});
      case 2: return node(chance(0.5) ? ExprOp::Add : ExprOp::Sub, Type::Vec3, {vecExpr(depth - 1), vecExpr(depth - 1)});
      case 3:
        if (chance(0.5)) return node(ExprOp::Mul, Type::Vec3, {vecExpr(depth - 1), numExpr(depth - 1)});
        return node(ExprOp::Mul, Type::Vec3, {numExpr(depth - 1), vecExpr(depth - 1)});
      case 4: return node(ExprOp::Div, Type::Vec3, {vecExpr(depth - 1), numExpr(depth - 1)});
      case 5: return node(ExprOp::Select, Type::Vec3, {numExpr(depth - 1), vecExpr(depth - 1), vecExpr(depth - 1)});
      case 6: return call(Builtin::Normalize, {vecExpr(depth - 1)}, Type::Vec3);
      default: return node(ExprOp::MakeVec, Type::Vec3, {rand(num(-1), num(1)), numExpr(depth - 1), rand(num(0), numExpr(depth - 1))});
    }
  }

  double input() { return interesting(g_); }

 private:
  bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(g_) < p; }
  uint32_t uni(uint32_t n) { return std::uniform_int_distribution<uint32_t>(0, n - 1)(g_); }

  Expr leaf() {
    switch (uni(4)) {
      case 0: return num(interesting(g_));
      case 1: return node(ExprOp::Attr, Type::Num, {}, uni(2));
      default: return param(uni(kNumParams));
    }
  }

  Expr builtin(int depth) {
    auto n = [&] { return numExpr(depth); };
    const auto b = static_cast<Builtin>(uni(static_cast<uint32_t>(Builtin::Normalize)));  // all but Normalize
    switch (b) {
      case Builtin::Atan2: case Builtin::Min: case Builtin::Max: case Builtin::Pow:
        return call(b, {n(), n()});
      case Builtin::Clamp: case Builtin::Lerp: return call(b, {n(), n(), n()});
      case Builtin::Length: return call(b, {vecExpr(depth)});
      case Builtin::Dot: return call(b, {vecExpr(depth), vecExpr(depth)});
      default: return call(b, {n()});
    }
  }

  std::mt19937_64 g_;
};

struct Inputs {
  double params[kSlots];
  std::vector<double> attrs;  // three slots per attribute
};

// Evaluates e with the interpreter and with the compiled function on the same input
// and stream key; requires the same bits and the same number of draws.
void checkSame(const ir::Module& m, const Expr& e, const backend::jit::CompiledExprs& code, size_t i,
               const Inputs& in, uint64_t key) {
  backend::Evaluator ev(m, in.attrs);
  rt::RandomStream interpRng{key, 0}, jitRng{key, 0};
  backend::Frame frame;
  frame.params = in.params;
  frame.rng = &interpRng;
  double want[3] = {0, 0, 0}, got[3] = {0, 0, 0};
  ev.store(e, frame, want);

  FgsgContext ctx;
  ctx.rng = &jitRng;
  if (code.isVec(i)) code.vec(i)(in.params, in.attrs.data(), &ctx, got);
  else got[0] = code.num(i)(in.params, in.attrs.data(), &ctx);

  const int width = ir::slotWidth(e.type);
  // Bit for bit, except the sign and payload of a NaN: LLVM does not preserve them
  // through arithmetic (LangRef, "Behavior of Floating-Point NaN values"; e.g.
  // InstCombine rewrites -(a * b) to (-a) * b), so a NaN result must be NaN in both.
  bool same = true;
  for (int k = 0; k < width; ++k)
    same = same && (std::memcmp(&want[k], &got[k], sizeof(double)) == 0 ||
                    (std::isnan(want[k]) && std::isnan(got[k])));
  if (!same || interpRng.counter != jitRng.counter) {
    std::ostringstream msg;
    msg.precision(17);
    msg << "expression " << i << ": interpreter";
    for (int k = 0; k < width; ++k) msg << ' ' << want[k];
    msg << " (" << interpRng.counter << " draws), jit";
    for (int k = 0; k < width; ++k) msg << ' ' << got[k];
    msg << " (" << jitRng.counter << " draws)\n  " << ir::printExpr(m, nullptr, e) << "\n  params";
    for (double p : in.params) msg << ' ' << p;
    msg << "\n  attrs";
    for (double a : in.attrs) msg << ' ' << a;
    FAIL(msg.str());
  }
  REQUIRE(ctx.errorCode == FGSG_OK);
}

void checkAll(const std::vector<Expr>& exprs, uint64_t seed, int inputsPerExpr) {
  ir::Module m;
  backend::jit::Jit jit;
  std::vector<const Expr*> ptrs;
  for (const Expr& e : exprs) ptrs.push_back(&e);
  backend::jit::CompiledExprs code = jit.compile(ptrs);
  REQUIRE(code.size() == exprs.size());
  Gen g(seed);
  std::mt19937_64 keys(seed ^ 0x5eed);
  for (int n = 0; n < inputsPerExpr; ++n) {
    Inputs in;
    for (double& p : in.params) p = g.input();
    in.attrs.resize(9);
    for (double& a : in.attrs) a = g.input();
    const uint64_t key = keys();
    for (size_t i = 0; i < exprs.size(); ++i) checkSame(m, exprs[i], code, i, in, key);
  }
}

}  // namespace

TEST_CASE("jit: every builtin and operator on its own matches the interpreter", "[jit]") {
  std::vector<Expr> exprs;
  const Expr x = param(0), y = param(1), z = param(2);
  for (ExprOp op : {ExprOp::Add, ExprOp::Sub, ExprOp::Mul, ExprOp::Div, ExprOp::Mod, ExprOp::Pow})
    exprs.push_back(node(op, Type::Num, {x, y}));
  for (ExprOp op : {ExprOp::Eq, ExprOp::Ne, ExprOp::Lt, ExprOp::Le, ExprOp::Gt, ExprOp::Ge, ExprOp::And, ExprOp::Or})
    exprs.push_back(node(op, Type::Bool, {x, y}));
  exprs.push_back(node(ExprOp::Neg, Type::Num, {x}));
  exprs.push_back(node(ExprOp::Not, Type::Bool, {x}));
  exprs.push_back(node(ExprOp::Select, Type::Num, {x, y, z}));
  for (uint32_t b = 0; b < static_cast<uint32_t>(Builtin::Length); ++b) {
    const auto bi = static_cast<Builtin>(b);
    if (bi == Builtin::Atan2 || bi == Builtin::Min || bi == Builtin::Max || bi == Builtin::Pow)
      exprs.push_back(call(bi, {x, y}));
    else if (bi == Builtin::Clamp || bi == Builtin::Lerp)
      exprs.push_back(call(bi, {x, y, z}));
    else
      exprs.push_back(call(bi, {x}));
  }
  exprs.push_back(call(Builtin::Length, {vparam()}));
  exprs.push_back(call(Builtin::Dot, {vparam(), node(ExprOp::Attr, Type::Vec3, {}, 2)}));
  exprs.push_back(call(Builtin::Normalize, {vparam()}, Type::Vec3));
  exprs.push_back(node(ExprOp::Attr, Type::Num, {}, 1));
  exprs.push_back(rand(x, y));
  exprs.push_back(node(ExprOp::VecElem, Type::Num, {vparam()}, 2));
  checkAll(exprs, 1, 4000);
}

TEST_CASE("jit: short-circuit and selects draw only on the side taken", "[jit]") {
  const Expr r = node(ExprOp::Gt, Type::Bool, {rand(num(0), num(1)), num(0.5)});
  std::vector<Expr> exprs = {
      node(ExprOp::And, Type::Bool, {param(0), r}),
      node(ExprOp::Or, Type::Bool, {param(0), r}),
      node(ExprOp::Select, Type::Num, {param(0), rand(num(0), num(10)), num(-1)}),
      node(ExprOp::Select, Type::Num, {param(0), num(-1), rand(param(1), param(2))}),
      node(ExprOp::Select, Type::Vec3, {param(0), vparam(), node(ExprOp::MakeVec, Type::Vec3, {rand(num(0), num(1)), num(2), rand(num(3), num(4))})}),
      // Operand order of the draws: left to right, for every operator and function.
      node(ExprOp::Sub, Type::Num, {rand(num(0), num(1)), rand(num(10), num(11))}),
      node(ExprOp::Mod, Type::Num, {rand(num(0), num(1)), rand(num(10), num(11))}),
      node(ExprOp::Pow, Type::Num, {rand(num(0), num(1)), rand(num(10), num(11))}),
      call(Builtin::Atan2, {rand(num(0), num(1)), rand(num(10), num(11))}),
  };
  Expr mk = node(ExprOp::MakeVec, Type::Vec3, {rand(num(0), num(1)), rand(num(2), num(3)), rand(num(4), num(5))});
  exprs.push_back(node(ExprOp::Sub, Type::Vec3, {mk, mk}));
  exprs.push_back(node(ExprOp::Mul, Type::Vec3, {mk, rand(num(7), num(8))}));
  exprs.push_back(node(ExprOp::Mul, Type::Vec3, {rand(num(7), num(8)), mk}));
  exprs.push_back(node(ExprOp::Div, Type::Vec3, {mk, rand(num(7), num(8))}));
  exprs.push_back(node(ExprOp::Eq, Type::Bool, {mk, mk}));
  exprs.push_back(call(Builtin::Dot, {mk, mk}));
  checkAll(exprs, 2, 2000);

  // And directly: false && rand(...) draws nothing.
  backend::jit::Jit jit;
  const Expr e = node(ExprOp::And, Type::Bool, {num(0), r});
  auto code = jit.compile({&e});
  rt::RandomStream rng{42, 0};
  FgsgContext ctx;
  ctx.rng = &rng;
  const double params[kSlots] = {};
  CHECK(code.num(0)(params, nullptr, &ctx) == 0.0);
  CHECK(rng.counter == 0);
}

TEST_CASE("jit: random expression trees match the interpreter bit for bit", "[jit]") {
  for (uint64_t seed : {11u, 12u, 13u}) {
    Gen g(seed);
    std::vector<Expr> exprs;
    for (int i = 0; i < 150; ++i) {
      if (i % 4 == 3) exprs.push_back(g.vecExpr(5));
      else exprs.push_back(g.numExpr(6));
    }
    checkAll(exprs, seed, 60);
  }
}

namespace {

struct Host : backend::QueryHost {
  double visible(const rt::Scope&, const std::string& target, ir::Loc at) override {
    if (target == "refused") throw backend::DeriveError{at, "R042", "no visibility for you"};
    return target.size();
  }
  double occlusion(const rt::Scope&, ir::Loc) override { return 7; }
  double fieldNumber(const rt::Scope&, uint32_t env, const std::string& member, ir::Loc) override {
    return 100.0 * env + member.size();
  }
  rt::Vec3 fieldVector(const rt::Scope&, uint32_t, const std::string&, ir::Loc) override {
    return rt::Vec3(1, 2, 3);
  }
  double texture(const rt::Scope&, uint32_t env, ir::Loc) override { return 0.5 + env; }
  double feature(const std::string& member, const std::string& arg, ir::Loc) override {
    return double(member.size() + arg.size());
  }
};

Expr query(ir::Query q, std::vector<Expr> args = {}) {
  Expr e = node(ExprOp::Query, Type::Num, std::move(args), static_cast<uint32_t>(q));
  e.loc = {3, 14};
  return e;
}

}  // namespace

TEST_CASE("jit: queries go through the host, a refused query is an error in the context", "[jit]") {
  ir::Module m;
  const uint32_t street = m.internString("street"), refused = m.internString("refused");
  rt::Scope scope;
  scope.S = rt::Vec3(2, 3, 4);
  scope.P = rt::Vec3(-1, 0.5, 9);
  Host host;
  rt::RandomStream rng{7, 0};
  backend::Frame frame;
  const double params[kSlots] = {};
  frame.params = params;
  frame.rng = &rng;
  frame.scope = &scope;
  frame.depth = 5;
  frame.index = 2;
  frame.host = &host;
  backend::Evaluator ev(m, {});

  std::vector<Expr> exprs;
  for (uint32_t q = 0; q <= static_cast<uint32_t>(ir::Query::ShapeIndex); ++q)
    exprs.push_back(node(ExprOp::Add, Type::Num, {query(static_cast<ir::Query>(q)), rand(num(0), num(1))}));
  exprs.push_back(query(ir::Query::ShapeVisible, {Expr::string(street)}));
  exprs.push_back(query(ir::Query::ScopeOcc, {Expr::string(street)}));
  Expr field = query(ir::Query::Field);  // the host answers 100 * env + the member's length
  field.env = 2;
  field.extra = refused;
  exprs.push_back(field);
  Expr vq = node(ExprOp::Query, Type::Vec3, {}, static_cast<uint32_t>(ir::Query::Field));
  vq.loc = {3, 14};
  exprs.push_back(call(Builtin::Length, {vq}));
  const size_t firstError = exprs.size();
  exprs.push_back(node(ExprOp::Add, Type::Num, {query(ir::Query::ShapeVisible, {Expr::string(refused)}), rand(num(0), num(1))}));

  backend::jit::Jit jit;
  std::vector<const Expr*> ptrs;
  for (const Expr& e : exprs) ptrs.push_back(&e);
  auto code = jit.compile(ptrs);

  for (size_t i = 0; i < exprs.size(); ++i) {
    CAPTURE(i);
    rt::RandomStream interpRng{7, 0}, jitRng{7, 0};
    frame.rng = &interpRng;
    std::optional<backend::DeriveError> want;
    double wantValue = 0;
    try {
      wantValue = ev.num(exprs[i], frame);
    } catch (const backend::DeriveError& e) {
      want = e;
    }
    backend::Frame jitFrame = frame;
    jitFrame.rng = &jitRng;
    backend::native::QueryBridge bridge(m, jitFrame);
    FgsgContext ctx;
    bridge.attach(ctx);
    const double got = code.num(i)(params, nullptr, &ctx);
    REQUIRE((i >= firstError) == want.has_value());
    if (!want) {
      CHECK(ctx.errorCode == FGSG_OK);
      CHECK(std::memcmp(&got, &wantValue, sizeof got) == 0);
      CHECK(interpRng.counter == jitRng.counter);
    } else {
      REQUIRE(ctx.errorCode != FGSG_OK);
      const backend::DeriveError e = bridge.error(ctx);
      CHECK(e.code == want->code);
      CHECK(e.message == want->message);
      CHECK(e.loc.line == want->loc.line);
      CHECK(e.loc.col == want->loc.col);
      CHECK(std::isnan(got));
      CHECK(jitRng.counter == 0);  // returned at once: the draw after the query never ran
    }
  }

  // Without a scope (a parallel rewriting step): R006, like the interpreter.
  frame.scope = nullptr;
  backend::Frame jitFrame = frame;
  backend::native::QueryBridge bridge(m, jitFrame);
  FgsgContext ctx;
  bridge.attach(ctx);
  code.num(0)(params, nullptr, &ctx);
  CHECK(bridge.error(ctx).code == "R006");
  CHECK_THROWS_AS(ev.num(exprs[0], frame), backend::DeriveError);
}

TEST_CASE("jit: units are independent and released with their code", "[jit]") {
  backend::jit::Jit jit;
  const Expr a = node(ExprOp::Add, Type::Num, {param(0), num(1)});
  const Expr b = node(ExprOp::Mul, Type::Num, {param(0), num(3)});
  const double params[kSlots] = {2};
  FgsgContext ctx;
  {
    auto first = jit.compile({&a});
    CHECK(first.num(0)(params, nullptr, &ctx) == 3.0);
  }
  auto second = jit.compile({&b});
  CHECK(second.num(0)(params, nullptr, &ctx) == 6.0);
  CHECK(jit.lastIR().find("fmul") != std::string::npos);
}
