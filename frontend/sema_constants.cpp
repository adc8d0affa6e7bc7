// Constant expressions: evaluating numbers, strings, booleans, vectors, earlier constants
// and math functions at compile time, finding a constant zero divisor (E027), and the
// number formatting messages use.

#include "frontend/sema_analyzer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

namespace fgsg::frontend::sema_detail {

// The divisor of a `/` or `%` inside `e` that is a constant zero, if any: why a constant
// expression has no value (E027 rather than "not a constant expression").
const Expr* Analyzer::zeroDivisor(const Expr& e) const {
  ConstValue divisor;
  if (e.kind == ExprKind::Binary && (e.text == "/" || e.text == "%") && e.args.size() == 2 &&
      evalConst(*e.args[1], divisor) && divisor.type == ValueType::Num && divisor.num == 0)
    return e.args[1].get();
  for (const auto& arg : e.args)
    if (arg)
      if (const Expr* zero = zeroDivisor(*arg)) return zero;
  return nullptr;
}

bool Analyzer::evalConst(const Expr& e, ConstValue& out) const {
  switch (e.kind) {
    case ExprKind::Number: out = {}; out.num = e.number; return true;
    case ExprKind::Bool: out = {}; out.type = ValueType::Bool; out.num = e.boolean; return true;
    case ExprKind::String: out = {}; out.type = ValueType::Str; out.str = e.text; return true;
    case ExprKind::Ident: {
      auto c = res_.constants.find(e.text);
      if (c != res_.constants.end()) return out = c->second, true;
      if (e.text == "pi" || e.text == "PI") return out = {}, out.num = kPi, true;
      return false;
    }
    case ExprKind::Unary: {
      ConstValue a;
      if (!evalConst(*e.args[0], a)) return false;
      if (e.text == "!" && a.type == ValueType::Bool) return out = a, out.num = !a.num, true;
      if (e.text == "-" && a.type == ValueType::Num) return out = a, out.num = -a.num, true;
      if (e.text == "+" && a.type == ValueType::Num) return out = a, true;
      return false;
    }
    case ExprKind::Binary: {
      ConstValue a, b;
      if (!evalConst(*e.args[0], a) || !evalConst(*e.args[1], b)) return false;
      if (a.type != ValueType::Num || b.type != ValueType::Num) return false;
      out = {};
      const std::string& op = e.text;
      double x = a.num, y = b.num;
      if (op == "+") out.num = x + y;
      else if (op == "-") out.num = x - y;
      else if (op == "*") out.num = x * y;
      else if (op == "/") { if (y == 0) return false; out.num = x / y; }
      else if (op == "%") { if (y == 0) return false; out.num = std::fmod(x, y); }
      else if (op == "^") out.num = std::pow(x, y);
      else {
        out.type = ValueType::Bool;
        if (op == "<") out.num = x < y;
        else if (op == "<=") out.num = x <= y;
        else if (op == ">") out.num = x > y;
        else if (op == ">=") out.num = x >= y;
        else if (op == "==") out.num = x == y;
        else if (op == "!=") out.num = x != y;
        else return false;
      }
      return true;
    }
    case ExprKind::Vector: {
      if (e.args.size() != 3) return false;
      out = {};
      out.type = ValueType::Vec3;
      for (int k = 0; k < 3; ++k) {
        ConstValue c;
        if (!evalConst(*e.args[k], c) || c.type != ValueType::Num) return false;
        out.vec[k] = c.num;
      }
      return true;
    }
    case ExprKind::Call: {
      if (e.args.size() == 2) {
        ConstValue a, b;
        if (!evalConst(*e.args[0], a) || !evalConst(*e.args[1], b) || a.type != ValueType::Num ||
            b.type != ValueType::Num)
          return false;
        out = {};
        if (e.text == "min") out.num = std::min(a.num, b.num);
        else if (e.text == "max") out.num = std::max(a.num, b.num);
        else if (e.text == "pow") out.num = std::pow(a.num, b.num);
        else return false;
        return true;
      }
      if (e.args.size() != 1) return false;
      ConstValue a;
      if (!evalConst(*e.args[0], a) || a.type != ValueType::Num) return false;
      static const std::map<std::string, double (*)(double)> kFns = {
          {"sin", [](double v) { return std::sin(v * kPi / 180); }},
          {"cos", [](double v) { return std::cos(v * kPi / 180); }},
          {"tan", [](double v) { return std::tan(v * kPi / 180); }},
          {"sqrt", [](double v) { return std::sqrt(v); }},
          {"abs", [](double v) { return std::abs(v); }},
          {"floor", [](double v) { return std::floor(v); }},
          {"ceil", [](double v) { return std::ceil(v); }},
          {"round", [](double v) { return std::round(v); }},
          {"exp", [](double v) { return std::exp(v); }},
          {"log", [](double v) { return std::log(v); }}};
      auto it = kFns.find(e.text);
      if (it == kFns.end()) return false;
      out = {};
      out.num = it->second(a.num);
      return true;
    }
    default: return false;
  }
}

// All the digits of a large whole number (4294967297, not 4.29497e+09).
std::string Analyzer::wholeNumberText(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  return buf;
}

std::string Analyzer::formatNumber(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace fgsg::frontend::sema_detail
