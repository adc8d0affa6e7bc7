#include "ir/builtins.h"

#include <cmath>

namespace fgsg::ir {

namespace {

constexpr Type N = Type::Num;
constexpr Type V = Type::Vec3;

// In the order of enum Builtin.
constexpr BuiltinSignature kBuiltins[] = {
    {"sin", 1, {N}, N},          {"cos", 1, {N}, N},
    {"tan", 1, {N}, N},          {"asin", 1, {N}, N},
    {"acos", 1, {N}, N},         {"atan", 1, {N}, N},
    {"atan2", 2, {N, N}, N},     {"sqrt", 1, {N}, N},
    {"abs", 1, {N}, N},          {"min", 2, {N, N}, N},
    {"max", 2, {N, N}, N},       {"floor", 1, {N}, N},
    {"ceil", 1, {N}, N},         {"round", 1, {N}, N},
    {"clamp", 3, {N, N, N}, N},  {"lerp", 3, {N, N, N}, N},
    {"pow", 2, {N, N}, N},       {"exp", 1, {N}, N},
    {"log", 1, {N}, N},          {"sign", 1, {N}, N},
    {"length", 1, {V}, N},       {"dot", 2, {V, V}, N},
    {"normalize", 1, {V}, V},
};
static_assert(std::size(kBuiltins) == kBuiltinCount, "one signature per Builtin");

// In the order of enum Query.
constexpr QuerySignature kQueries[] = {
    {"Scope", "sx", 0, N, N, true},
    {"Scope", "sy", 0, N, N, true},
    {"Scope", "sz", 0, N, N, true},
    {"Scope", "px", 0, N, N, true},
    {"Scope", "py", 0, N, N, true},
    {"Scope", "pz", 0, N, N, true},
    {"Shape", "depth", 0, N, N, true},
    {"Shape", "index", 0, N, N, true},
    {"Shape", "visible", 1, Type::Str, Type::Bool, true},
    {"Scope", "occ", 1, Type::Str, Type::Str, true},
    {"", "", 0, N, N, false},   // Field: F1.vector1 is Vec3, F1.value1 Num ...
    {"", "", -1, N, N, false},  // Texture: context.mask(uv)
    {"", "", -1, N, N, false},  // Feature: Feature.edge is Bool, Feature.index Num, Feature.label("x") Bool
    {"Shape", "splitIndex", 0, N, N, true},
    {"Shape", "splitTotal", 0, N, N, true},
    {"Shape", "compIndex", 0, N, N, true},
    {"Shape", "compTotal", 0, N, N, true},
    {"Geometry", "area", 0, N, N, true},
    {"Geometry", "height", 0, N, N, true},
    {"Geometry", "nVertices", 0, N, N, true},
    {"Geometry", "nFaces", 0, N, N, true},
    {"Geometry", "isPlanar", 1, N, Type::Bool, true},
    {"Geometry", "isConcave", 0, N, Type::Bool, true},
    {"Geometry", "boundaryLength", 0, N, N, true},
    {"Shape", "inside", 1, Type::Str, Type::Bool, true},
    {"Shape", "overlaps", 1, Type::Str, Type::Bool, true},
    {"Shape", "touches", 1, Type::Str, Type::Bool, true},
    {"Shape", "minimumDistance", 1, Type::Str, N, true},
    {"Shape", "contextCount", 1, Type::Str, N, true},
    {"Geometry", "angle", 0, N, N, true},  // the selector in extra
    {"Geometry", "du", 0, N, N, true},     // uv set 0, uvSpace: checked by the compiler
    {"Geometry", "dv", 0, N, N, true},
    {"Shape", "contextCompare", 1, Type::Str, N, true},  // target and comparison in extra
    {"Shape", "compSel", 0, N, Type::Str, true},         // "" (no comp) in extra
};
static_assert(std::size(kQueries) == static_cast<size_t>(kLastQuery) + 1,
              "one signature per Query");

double deg(double radians) { return radians / kRadiansPerDegree; }
double rad(double degrees) { return degrees * kRadiansPerDegree; }

// NaN-propagation of min/max is pinned here (a < b ? a : b) rather than left to fmin.
double minOf(double a, double b) { return b < a ? b : a; }
double maxOf(double a, double b) { return a < b ? b : a; }

double dot3(const Lanes& a, const Lanes& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

const BuiltinSignature& builtinSignature(Builtin b) {
  return kBuiltins[static_cast<size_t>(b)];
}

std::optional<Builtin> findBuiltin(std::string_view name) {
  for (int i = 0; i < kBuiltinCount; ++i)
    if (name == kBuiltins[i].name) return static_cast<Builtin>(i);
  return std::nullopt;
}

const QuerySignature& querySignature(Query q) { return kQueries[static_cast<size_t>(q)]; }

Lanes evalBuiltin(Builtin b, const Lanes* args) {
  const double x = args[0][0];
  auto num = [](double v) { return Lanes{v, 0, 0}; };
  switch (b) {
    case Builtin::Sin: return num(std::sin(rad(x)));
    case Builtin::Cos: return num(std::cos(rad(x)));
    case Builtin::Tan: return num(std::tan(rad(x)));
    case Builtin::Asin: return num(deg(std::asin(x)));
    case Builtin::Acos: return num(deg(std::acos(x)));
    case Builtin::Atan: return num(deg(std::atan(x)));
    case Builtin::Atan2: return num(deg(std::atan2(x, args[1][0])));
    case Builtin::Sqrt: return num(std::sqrt(x));
    case Builtin::Abs: return num(std::fabs(x));
    case Builtin::Min: return num(minOf(x, args[1][0]));
    case Builtin::Max: return num(maxOf(x, args[1][0]));
    case Builtin::Floor: return num(std::floor(x));
    case Builtin::Ceil: return num(std::ceil(x));
    case Builtin::Round: return num(std::round(x));  // halves away from zero
    case Builtin::Clamp: return num(minOf(maxOf(x, args[1][0]), args[2][0]));
    case Builtin::Lerp: return num(x + (args[1][0] - x) * args[2][0]);
    case Builtin::Pow: return num(std::pow(x, args[1][0]));
    case Builtin::Exp: return num(std::exp(x));
    case Builtin::Log: return num(std::log(x));
    case Builtin::Sign: return num((x > 0) - (x < 0));  // +0 for ±0 and NaN
    case Builtin::Length: return num(std::sqrt(dot3(args[0], args[0])));
    case Builtin::Dot: return num(dot3(args[0], args[1]));
    case Builtin::Normalize: {
      const double len = std::sqrt(dot3(args[0], args[0]));
      if (!(len > 0)) return args[0];  // a zero vector stays as it is rather than NaN
      return Lanes{args[0][0] / len, args[0][1] / len, args[0][2] / len};
    }
  }
  return num(0);
}

std::optional<Type> unaryResultType(ExprOp op, Type a) {
  switch (op) {
    case ExprOp::Neg:
      if (a == Type::Num || a == Type::Vec3) return a;
      return std::nullopt;
    case ExprOp::Not:
      if (a == Type::Bool) return Type::Bool;
      return std::nullopt;
    default: return std::nullopt;
  }
}

std::optional<Type> binaryResultType(ExprOp op, Type a, Type b) {
  const bool nn = a == N && b == N;
  switch (op) {
    case ExprOp::Add:
    case ExprOp::Sub:
      if (nn || (a == V && b == V)) return a;
      return std::nullopt;
    case ExprOp::Mul:
      if (nn) return N;
      if ((a == V && b == N) || (a == N && b == V)) return V;
      return std::nullopt;
    case ExprOp::Div:
      if (nn) return N;
      if (a == V && b == N) return V;
      return std::nullopt;
    case ExprOp::Mod:
    case ExprOp::Pow:
      if (nn) return N;
      return std::nullopt;
    case ExprOp::Eq:
    case ExprOp::Ne:
      if (a == b) return Type::Bool;
      return std::nullopt;
    case ExprOp::Lt:
    case ExprOp::Le:
    case ExprOp::Gt:
    case ExprOp::Ge:
      if (nn) return Type::Bool;
      return std::nullopt;
    case ExprOp::And:
    case ExprOp::Or:
      if (a == Type::Bool && b == Type::Bool) return Type::Bool;
      return std::nullopt;
    default: return std::nullopt;
  }
}

double modulo(double a, double b) { return std::fmod(a, b); }

const char* operatorSpelling(ExprOp op) {
  switch (op) {
    case ExprOp::Neg: return "-";
    case ExprOp::Not: return "!";
    case ExprOp::Add: return "+";
    case ExprOp::Sub: return "-";
    case ExprOp::Mul: return "*";
    case ExprOp::Div: return "/";
    case ExprOp::Mod: return "%";
    case ExprOp::Pow: return "^";
    case ExprOp::Eq: return "==";
    case ExprOp::Ne: return "!=";
    case ExprOp::Lt: return "<";
    case ExprOp::Le: return "<=";
    case ExprOp::Gt: return ">";
    case ExprOp::Ge: return ">=";
    case ExprOp::And: return "&&";
    case ExprOp::Or: return "||";
    case ExprOp::Join: return "+";
    default: return "";
  }
}

}  // namespace fgsg::ir
