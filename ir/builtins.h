// Signatures of everything built into the expression language: operators, functions
// and queries. Sema, the verifier, the printer, constant folding and the runtimes all
// read these tables, so a builtin's name, typing and meaning are stated once.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "ir/ir.h"

namespace fgsg::ir {

// ---------------------------------------------------------------- functions

struct BuiltinSignature {
  const char* name;  // source spelling (lower case): "sin", "atan2"
  int arity;
  Type args[3];
  Type result;
};

inline constexpr int kBuiltinCount = static_cast<int>(Builtin::Normalize) + 1;

const BuiltinSignature& builtinSignature(Builtin b);
std::optional<Builtin> findBuiltin(std::string_view name);

// Angles of sin cos tan and the results of asin acos atan atan2 are in degrees, like
// every other angle of the language (Rz, RS, turtle turns) and CGA's math functions.
inline constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

// A value as the evaluators see it: Num/Bool/Str in lane 0, Vec3 in lanes 0..2.
using Lanes = std::array<double, 3>;

// The meaning of every builtin function (all are pure). Interpreter, JIT helpers and
// constant folding call this one definition so that they agree to the last bit.
Lanes evalBuiltin(Builtin b, const Lanes* args);

// ---------------------------------------------------------------- queries

struct QuerySignature {
  const char* object;  // "Scope", "Shape"; empty for Field/Texture (named by the module)
  const char* member;  // "sx", "visible"; empty when the module names it
  int arity;           // -1: any number of arguments
  Type arg;            // type of every argument, when typed
  Type result;         // when typed
  bool typed;          // false: argument and result types depend on the member/texture
};

const QuerySignature& querySignature(Query q);

// ---------------------------------------------------------------- operators

// Result type of a unary (Neg, Not) or binary (Add .. Or) operator applied to operands
// of the given types; nullopt when the combination is ill-typed. Vector arithmetic:
// v+v, v-v, -v, v*n, n*v, v/n; equality on any two values of one type.
std::optional<Type> unaryResultType(ExprOp op, Type a);
std::optional<Type> binaryResultType(ExprOp op, Type a, Type b);

// The language's `%`: remainder with the sign of the dividend (C's fmod), so that
// interpreter, JIT and folding agree on negative operands.
double modulo(double a, double b);

// Textual operator for printing ("+", "&&"); "" when `op` is not an operator.
const char* operatorSpelling(ExprOp op);

}  // namespace fgsg::ir
