#include "ir/fold.h"

#include <cmath>
#include <optional>
#include <utility>

#include "ir/builtins.h"

namespace fgsg::ir {

namespace {

bool isNum(const Expr& e) { return e.isConst() && e.type == Type::Num; }
bool isNum(const Expr& e, double v) { return isNum(e) && e.num == v; }
bool isBool(const Expr& e) { return e.isConst() && e.type == Type::Bool; }

// Rand advances the shape's random stream, so dropping an expression that contains
// one would shift every later draw: such expressions are never discarded.
bool hasRand(const Expr& e) {
  if (e.op == ExprOp::Rand) return true;
  for (const Expr& a : e.args)
    if (hasRand(a)) return true;
  return false;
}

Lanes lanes(const Expr& e) {
  if (e.type == Type::Vec3) return {e.vec[0], e.vec[1], e.vec[2]};
  return {e.num, 0, 0};
}

// A constant of type `t` holding `v`, or nothing when a lane is not finite: inf and
// NaN come from domain errors (x/0, sqrt(-1)) that must stay visible.
std::optional<Expr> constant(Type t, const Lanes& v) {
  const int n = t == Type::Vec3 ? 3 : 1;
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return std::nullopt;
  Expr e;
  e.type = t;
  if (t == Type::Vec3)
    for (int i = 0; i < 3; ++i) e.vec[i] = v[i];
  else
    e.num = v[0];
  return e;
}

std::optional<Expr> num(double v) { return constant(Type::Num, {v, 0, 0}); }
Expr boolean(bool v) { return Expr::boolean(v); }

// Applies a binary arithmetic operator lane-wise; scalars broadcast.
std::optional<Lanes> arith(ExprOp op, const Expr& a, const Expr& b) {
  const Lanes x = lanes(a), y = lanes(b);
  Lanes r{};
  for (int i = 0; i < 3; ++i) {
    const double p = a.type == Type::Vec3 ? x[i] : x[0];
    const double q = b.type == Type::Vec3 ? y[i] : y[0];
    switch (op) {
      case ExprOp::Add: r[i] = p + q; break;
      case ExprOp::Sub: r[i] = p - q; break;
      case ExprOp::Mul: r[i] = p * q; break;
      case ExprOp::Div: r[i] = p / q; break;
      case ExprOp::Mod: r[i] = modulo(p, q); break;
      case ExprOp::Pow: r[i] = std::pow(p, q); break;
      default: return std::nullopt;
    }
  }
  return r;
}

bool sameValue(const Expr& a, const Expr& b) {
  if (a.type == Type::Vec3) return a.vec[0] == b.vec[0] && a.vec[1] == b.vec[1] && a.vec[2] == b.vec[2];
  return a.num == b.num;  // Num, Bool, and Str (interned: equal ids, equal strings)
}

class Folder {
 public:
  int rewrites() const { return count_; }

  void module(Module& m) {
    block(m.axiom);
    for (Rule& r : m.rules) {
      if (r.hasGuard) {
        expr(r.guard);
        if (isBool(r.guard) && r.guard.num != 0) {  // always true: no guard at all
          r.hasGuard = false;
          r.guard = Expr::boolean(true);
          ++count_;
        }
      }
      for (Alternative& alt : r.alternatives) {
        expr(alt.probability);
        block(alt.ops);
      }
    }
  }

 private:
  void block(Block& ops) {
    for (Op& op : ops) {
      for (Expr& a : op.args) expr(a);
      for (Size& s : op.sizes) expr(s.value);
      for (Block& b : op.bodies) block(b);
    }
  }

  void expr(Expr& e) {
    for (Expr& a : e.args) expr(a);
    if (std::optional<Expr> r = rewrite(e)) {
      r->loc = e.loc;
      e = std::move(*r);
      ++count_;
    }
  }

  // Moves operand `i` out as the replacement of its parent.
  static std::optional<Expr> take(Expr& e, size_t i) { return std::move(e.args[i]); }

  // Operand count each rewrite relies on; the verifier checks it, folding just skips.
  static size_t operands(ExprOp op) {
    switch (op) {
      case ExprOp::Neg:
      case ExprOp::Not:
      case ExprOp::VecElem: return 1;
      case ExprOp::Select:
      case ExprOp::MakeVec: return 3;
      case ExprOp::Call: return ~size_t{0};  // checked against the signature below
      default: return 2;
    }
  }

  std::optional<Expr> rewrite(Expr& e) {
    if (e.op <= ExprOp::Attr || e.op == ExprOp::Rand || e.op == ExprOp::Query)
      return std::nullopt;  // leaves, and what only the running shape can answer
    if (operands(e.op) != ~size_t{0} && e.args.size() != operands(e.op)) return std::nullopt;
    switch (e.op) {
      case ExprOp::Neg: {
        Expr& a = e.args[0];
        if (a.isConst()) {
          Lanes v = lanes(a);
          for (double& x : v) x = -x;
          return constant(e.type, v);
        }
        if (a.op == ExprOp::Neg) return take(a, 0);  // -(-x) == x exactly
        return std::nullopt;
      }
      case ExprOp::Not:
        if (isBool(e.args[0])) return boolean(e.args[0].num == 0);
        if (e.args[0].op == ExprOp::Not) return take(e.args[0], 0);
        return std::nullopt;
      case ExprOp::Add:
      case ExprOp::Sub:
      case ExprOp::Mul:
      case ExprOp::Div:
      case ExprOp::Mod:
      case ExprOp::Pow: return arithmetic(e);
      case ExprOp::Eq:
      case ExprOp::Ne:
        if (e.args[0].isConst() && e.args[1].isConst())
          return boolean(sameValue(e.args[0], e.args[1]) == (e.op == ExprOp::Eq));
        return std::nullopt;
      case ExprOp::Lt:
      case ExprOp::Le:
      case ExprOp::Gt:
      case ExprOp::Ge: return comparison(e);
      case ExprOp::And:
      case ExprOp::Or: return logic(e);
      case ExprOp::Select: {
        if (!isBool(e.args[0])) return std::nullopt;
        const size_t kept = e.args[0].num != 0 ? 1 : 2;
        if (hasRand(e.args[3 - kept])) return std::nullopt;  // in case a runtime is eager
        return take(e, kept);
      }
      case ExprOp::Call: {
        if (e.index >= static_cast<uint32_t>(kBuiltinCount) ||
            e.args.size() != static_cast<size_t>(builtinSignature(static_cast<Builtin>(e.index)).arity))
          return std::nullopt;
        Lanes args[3] = {};
        for (size_t i = 0; i < e.args.size(); ++i) {
          if (!e.args[i].isConst()) return std::nullopt;
          args[i] = lanes(e.args[i]);
        }
        return constant(e.type, evalBuiltin(static_cast<Builtin>(e.index), args));
      }
      case ExprOp::MakeVec:
        for (const Expr& a : e.args)
          if (!isNum(a)) return std::nullopt;
        return constant(Type::Vec3, {e.args[0].num, e.args[1].num, e.args[2].num});
      case ExprOp::VecElem: {
        Expr& v = e.args[0];
        if (e.index > 2) return std::nullopt;
        if (v.isConst()) return num(v.vec[e.index]);
        if (v.op == ExprOp::MakeVec && v.args.size() == 3 && !hasRand(v.args[(e.index + 1) % 3]) &&
            !hasRand(v.args[(e.index + 2) % 3]))
          return take(v, e.index);
        return std::nullopt;
      }
      default: return std::nullopt;
    }
  }

  std::optional<Expr> arithmetic(Expr& e) {
    Expr& a = e.args[0];
    Expr& b = e.args[1];
    if (a.isConst() && b.isConst()) {
      if (std::optional<Lanes> v = arith(e.op, a, b)) return constant(e.type, *v);
      return std::nullopt;
    }
    // Identities exact for every IEEE x, including -0, inf and NaN. Not x+0 (-0+0 is +0)
    // and not x*0 (inf*0 is NaN).
    switch (e.op) {
      case ExprOp::Mul:
        if (isNum(b, 1) && a.type == e.type) return take(e, 0);
        if (isNum(a, 1) && b.type == e.type) return take(e, 1);
        break;
      case ExprOp::Div:
        if (isNum(b, 1)) return take(e, 0);
        break;
      case ExprOp::Sub:
        if (isNum(b, 0) && !std::signbit(b.num)) return take(e, 0);
        break;
      case ExprOp::Add:
        if (isNum(b, 0) && std::signbit(b.num)) return take(e, 0);
        if (isNum(a, 0) && std::signbit(a.num)) return take(e, 1);
        break;
      default: break;
    }
    return std::nullopt;
  }

  static std::optional<Expr> comparison(const Expr& e) {
    const Expr& a = e.args[0];
    const Expr& b = e.args[1];
    if (!isNum(a) || !isNum(b)) return std::nullopt;
    switch (e.op) {
      case ExprOp::Lt: return boolean(a.num < b.num);
      case ExprOp::Le: return boolean(a.num <= b.num);
      case ExprOp::Gt: return boolean(a.num > b.num);
      case ExprOp::Ge: return boolean(a.num >= b.num);
      default: return std::nullopt;
    }
  }

  // Short-circuit: the right operand runs only when the left one does not decide.
  static std::optional<Expr> logic(Expr& e) {
    const bool isAnd = e.op == ExprOp::And;
    Expr& a = e.args[0];
    Expr& b = e.args[1];
    if (isBool(a)) {
      const bool decides = (a.num != 0) != isAnd;  // false && x, true || x
      return decides ? boolean(!isAnd) : take(e, 1);
    }
    if (isBool(b)) {
      if ((b.num != 0) == isAnd) return take(e, 0);       // x && true, x || false
      if (!hasRand(a)) return boolean(!isAnd);            // x && false, x || true
    }
    return std::nullopt;
  }

  int count_ = 0;
};

}  // namespace

int foldConstants(Module& m) {
  Folder f;
  f.module(m);
  return f.rewrites();
}

}  // namespace fgsg::ir
