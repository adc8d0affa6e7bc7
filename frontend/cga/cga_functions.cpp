// The `.cga` dialect's expressions: CityEngine's operators, built-in functions and shape
// attributes under fgsg's names (`rand` -> Rand, `rint` -> round, `p(x)` -> Rand(0, 1) < x,
// `scope.sx` -> Scope.sx; trigonometry is in degrees in both), user functions and consts
// inlined at each use (their parameters bound to the arguments), `case` and stochastic
// values as conditional expressions.
#include "frontend/cga/cga_translator.h"

#include "frontend/builtins.h"
#include "frontend/did_you_mean.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>

namespace fgsg::frontend::cga {

namespace {

ExprPtr callExpr(const std::string& fn, std::vector<ExprPtr> args, const SourceRange& at) {
  ExprPtr e = makeExpr(ExprKind::Call, at);
  e->text = fn;
  e->args = std::move(args);
  return e;
}

ExprPtr uniform(const SourceRange& at) {
  std::vector<ExprPtr> a;
  a.push_back(number(0, at));
  a.push_back(number(1, at));
  return callExpr("Rand", std::move(a), at);
}

ExprPtr ternary(ExprPtr c, ExprPtr a, ExprPtr b, const SourceRange& at) {
  ExprPtr e = makeExpr(ExprKind::Ternary, at);
  e->args.push_back(std::move(c));
  e->args.push_back(std::move(a));
  e->args.push_back(std::move(b));
  return e;
}

// CityEngine functions with an fgsg function of the same meaning and name.
const char* const kSameFunctions[] = {"sin", "cos",  "tan",  "asin", "acos", "atan", "atan2", "sqrt",
                                      "abs", "min",  "max",  "floor", "ceil", "pow",  "exp"};

// CityEngine functions (and shape attributes) this dialect does not have yet.
const char* const kKnownFunctions[] = {
    "bool", "float", "sel", "len", "count", "find", "substring", "fileExists", "fileSearch",
    "assetInfo", "imageInfo", "assetsSortRatio", "assetsSortSize", "imagesSortRatio",
    "contextCompare", "occlusion", "convert", "listAdd", "listItem", "listSize",
    "listClean", "listLast", "listFirst", "listRandom", "listRange", "listRemove", "listIndex", "replace", "findFirst",
    "findLast", "getPrefix", "getSuffix", "getRange", "index", "size", "transpose", "splitString", "colorRamp",
    "comp", "readTextFile", "readStringTable", "readFloatTable", "readBoolTable", "fileRandom", "filesSearch"};

// CityEngine functions with a translation of their own (Translator::call), as they are written.
const char* const kTranslatedFunctions[][2] = {
    {"rand", "rand(), rand(max), rand(min, max)"},
    {"p", "p(probability)"},
    {"rint", "rint(x)"},
    {"ln", "ln(x)"},
    {"log10", "log10(x)"},
    {"isnan", "isnan(x)"},
    {"isinf", "isinf(x)"},
    {"inside", "inside(intra|inter|all, \"label\")"},
    {"overlaps", "overlaps(intra|inter|all, \"label\")"},
    {"touches", "touches(intra|inter|all, \"label\")"},
    {"minimumDistance", "minimumDistance(intra|inter|all, \"label\")"},
    {"contextCount", "contextCount(intra|inter|all, \"label\")"},
    {"contextCompare", "contextCompare(intra|inter|all, \"label\", world.highest|...)"}};

// geometry.area() ...: fgsg's Geometry queries (Translator::call).
const char* const kCityEngineGeometryMembers[] = {"area",           "height",   "nVertices", "nFaces", "isConcave",
                                                  "boundaryLength", "isPlanar", "angle",     "du",     "dv"};

}  // namespace

std::vector<std::pair<std::string, std::string>> cityEngineFunctions() {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& f : kTranslatedFunctions) out.emplace_back(f[0], f[1]);
  for (const char* same : kSameFunctions) {
    const FunctionInfo* info = findFunction(same);
    std::string signature = std::string(same) + "(";
    for (int i = 0; info && i < info->maxArgs; ++i) signature += (i ? ", " : "") + std::string(1, static_cast<char>('a' + i));
    out.emplace_back(same, signature + ")");
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::string> cityEngineGeometryFunctions() {
  return {std::begin(kCityEngineGeometryMembers), std::end(kCityEngineGeometryMembers)};
}

bool Translator::isRandom(const Expr& e) {
  if (e.kind == ExprKind::Call && (e.text == "Rand" || e.text == "rand")) return true;
  for (const auto& a : e.args)
    if (a && isRandom(*a)) return true;
  return false;
}

ExprPtr Translator::value(P::ValueContext* ctx, const Env& env) {
  if (auto* plain = dynamic_cast<P::PlainValueContext*>(ctx)) return expr(plain->expr(), env);
  const SourceRange at = rangeOf(ctx);
  if (auto* c = dynamic_cast<P::CaseValueContext*>(ctx)) {
    const auto conds = c->expr();
    const auto values = c->value();
    ExprPtr out = value(values.back(), env);
    for (size_t i = conds.size(); i-- > 0;) {
      ExprPtr cond = expr(conds[i], env), v = value(values[i], env);
      if (!cond || !v || !out) return nullptr;
      out = ternary(std::move(cond), std::move(v), std::move(out), at);
    }
    return out;
  }
  // `30% : a 20% : b else : c`: one draw per branch, each with the probability of that
  // branch among those left (0.3, then 0.2 / 0.7), so that the choice has the percentages.
  auto* s = static_cast<P::StochasticValueContext*>(ctx);
  const auto percents = s->PERCENT_LIT();
  const auto values = s->value();
  ExprPtr out;
  if (s->ELSE()) {
    out = value(values.back(), env);
  } else {
    error("E803", at, "a stochastic value needs an `else :` (the value the rest of the time)");
    return nullptr;
  }
  std::vector<double> p;
  for (auto* t : percents) {
    const std::string text = t->getText();
    p.push_back(std::stod(text.substr(0, text.size() - 1)) / 100.0);
  }
  for (size_t i = percents.size(); i-- > 0;) {
    double left = 1.0;
    for (size_t k = 0; k < i; ++k) left -= p[k];
    const double chance = left > 1e-12 ? std::min(1.0, p[i] / left) : 0.0;
    ExprPtr v = value(values[i], env);
    if (!v || !out) return nullptr;
    out = ternary(binary("<", uniform(at), number(chance, at)), std::move(v), std::move(out), at);
  }
  return out;
}

ExprPtr Translator::expr(P::ExprContext* ctx, const Env& env) {
  if (!ctx) return nullptr;
  if (auto* p = dynamic_cast<P::PrimaryExprContext*>(ctx)) return primary(p->primary(), env);
  if (auto* u = dynamic_cast<P::UnaryExprContext*>(ctx)) {
    ExprPtr a = expr(u->expr(), env);
    if (!a) return nullptr;
    if (u->op->getText() == "+") return a;
    ExprPtr e = makeExpr(ExprKind::Unary, rangeOf(ctx));
    e->text = u->op->getText();
    e->args.push_back(std::move(a));
    return e;
  }
  auto* b = static_cast<P::BinaryExprContext*>(ctx);
  ExprPtr l = expr(b->expr(0), env), r = expr(b->expr(1), env);
  if (!l || !r) return nullptr;
  const std::string op = b->op->getText();
  // String concatenation of two constants folds here; any other string `+` joins at run
  // time (ir::ExprOp::Join: "roof.area." + kind, "floor" + 3).
  if (op == "+" && l->kind == ExprKind::String && r->kind == ExprKind::String) {
    l->text += r->text;
    l->range = rangeOf(ctx);
    return l;
  }
  ExprPtr e = binary(op, std::move(l), std::move(r));
  e->range = rangeOf(ctx);
  return e;
}

ExprPtr Translator::primary(P::PrimaryContext* ctx, const Env& env) {
  const SourceRange at = rangeOf(ctx);
  if (auto* n = dynamic_cast<P::NumberPrimaryContext*>(ctx)) {
    const std::string text = n->getText();
    double v = 0;
    try {
      v = std::stod(text);
    } catch (const std::exception&) {
      error("E002", at, "the number " + text + " is out of range");
      return nullptr;
    }
    return number(v, at);
  }
  if (auto* s = dynamic_cast<P::StringPrimaryContext*>(ctx)) {
    ExprPtr e = makeExpr(ExprKind::String, at);
    e->text = stringValue(s->getText());
    return e;
  }
  if (auto* b = dynamic_cast<P::BoolPrimaryContext*>(ctx)) {
    ExprPtr e = makeExpr(ExprKind::Bool, at);
    e->boolean = b->flag->getText() == "true";
    return e;
  }
  if (auto* p = dynamic_cast<P::ParenPrimaryContext*>(ctx)) {
    ExprPtr e = expr(p->expr(), env);
    if (e) e->range = at;
    return e;
  }
  if (dynamic_cast<P::ArrayPrimaryContext*>(ctx)) {
    notSupported(at, "an array");
    return nullptr;
  }
  if (auto* r = dynamic_cast<P::RelativePrimaryContext*>(ctx)) {
    ExprPtr v = primary(r->primary(), env);
    if (!v) return nullptr;
    if (env.relativeAxis < 0) {
      error("E803", at, "a relative size `'x` belongs to a split's sizes and to s() and t() arguments");
      return nullptr;
    }
    if (env.relativeAxis == 3) {  // s('0.5, ...): fgsg's relative size 0.5r
      ExprPtr e = makeExpr(ExprKind::RelSize, at);
      if (v->kind == ExprKind::Number) {
        e->number = v->number;
        return e;
      }
      // A computed fraction: x times the current size.
      ExprPtr size = makeExpr(ExprKind::Member, at);
      size->object = "Scope";
      size->text = std::string("s") + "xyz"[env.relativeIndex];
      return binary("*", std::move(v), std::move(size));
    }
    ExprPtr size = makeExpr(ExprKind::Member, at);
    size->object = env.relativeAxis == 4 ? "Geometry" : "Scope";
    size->text = env.relativeAxis == 4 ? "area" : std::string("s") + "xyz"[env.relativeAxis];
    ExprPtr e = binary("*", std::move(v), std::move(size));
    e->range = at;
    return e;
  }
  if (auto* f = dynamic_cast<P::FloatingPrimaryContext*>(ctx)) {
    ExprPtr v = primary(f->primary(), env);
    if (!v) return nullptr;
    ExprPtr e = makeExpr(ExprKind::FloatSize, at);
    e->args.push_back(std::move(v));
    return e;
  }
  if (auto* c = dynamic_cast<P::CallPrimaryContext*>(ctx))
    return call(c->name->getText(), at, rangeOf(c->name), c->expr(), env);
  auto* n = static_cast<P::NamePrimaryContext*>(ctx);
  return name(n->name->getText(), at, env);
}

ExprPtr Translator::name(const std::string& text, const SourceRange& at, const Env& env) {
  if (auto b = env.bound.find(text); b != env.bound.end()) {
    ExprPtr e = cloneExpr(*b->second);
    return e;
  }
  if (env.ruleParams && env.ruleParams->count(text)) {
    ExprPtr e = makeExpr(ExprKind::Ident, at);
    e->text = text;
    return e;
  }
  if (functions_.count(text)) return call(text, at, at, {}, env);
  if (attrs_.count(text) || text == "pi" || text == "PI") {
    ExprPtr e = makeExpr(ExprKind::Ident, at);
    e->text = text;
    return e;
  }
  const size_t dot = text.find('.');
  if (dot != std::string::npos) {
    const std::string object = text.substr(0, dot), member = text.substr(dot + 1);
    if (object == "scope") {
      static const std::map<std::string, std::string> kScope = {{"sx", "sx"}, {"sy", "sy"}, {"sz", "sz"},
                                                               {"tx", "px"}, {"ty", "py"}, {"tz", "pz"}};
      if (auto m = kScope.find(member); m != kScope.end()) {
        ExprPtr e = makeExpr(ExprKind::Member, at);
        e->object = "Scope";
        e->text = m->second;
        return e;
      }
      notSupported(at, "the shape attribute '" + text + "'");
      return nullptr;
    }
    if (object == "comp" && member == "sel") {
      ExprPtr e = makeExpr(ExprKind::Member, at);  // Shape.compSel: the selector's name
      e->object = "Shape";
      e->text = "compSel";
      return e;
    }
    if ((object == "split" || object == "comp") && (member == "index" || member == "total")) {
      ExprPtr e = makeExpr(ExprKind::Member, at);  // Shape.splitIndex ...
      e->object = "Shape";
      e->text = object + char(std::toupper(static_cast<unsigned char>(member[0]))) + member.substr(1);
      return e;
    }
    if (importAliases_.count(object)) {  // an imported attr or const: `facade.height`
      ExprPtr e = makeExpr(ExprKind::Ident, at);
      e->text = text;
      return e;
    }
    if (object == "initialShape") return initialShapeAttribute(member, at);
    // CGA calls a function without parameters with or without `()`: rule files write
    // `case geometry.area > 200` as often as `geometry.area()`.
    static const char* const kGeometryWithoutArguments[] = {"area", "height", "nVertices", "nFaces",
                                                            "isConcave", "boundaryLength"};
    if (object == "geometry" && std::find(std::begin(kGeometryWithoutArguments), std::end(kGeometryWithoutArguments),
                                          member) != std::end(kGeometryWithoutArguments))
      return call(text, at, at, {}, env);
    static const char* const kAttributes[] = {"split", "comp", "seedian", "geometry", "material",
                                              "pivot", "trim", "world", "object", "street", "uv"};
    for (const char* a : kAttributes)
      if (object == a) {
        notSupported(at, "the shape attribute '" + text + "'");
        return nullptr;
      }
    error("E010", at, "unknown name '" + text + "'");
    return nullptr;
  }
  if (text == "seedian") {
    notSupported(at, "the shape attribute 'seedian'");
    return nullptr;
  }
  error("E010", at, "unknown name '" + text + "' (not a parameter of this rule, an attr, a const or a function)");
  return nullptr;
}

// initialShape.name / .startRule / .origin.p{x,y,z} / .origin.o{x,y,z}. The start rule is
// this file's (a constant: every lot starts with it); the others are the lot's, which
// `--lots` sets per lot as the attrs of Lot.prop("initialShape.name", ...) and so on
// (backend/interp/lot_attributes.cpp); their defaults are the square lot's without
// --lots: no name, the origin at its first corner (0, 0, 0), its first edge east (o = 0).
ExprPtr Translator::initialShapeAttribute(const std::string& member, const SourceRange& at) {
  if (member == "startRule") {
    ExprPtr e = makeExpr(ExprKind::String, at);
    e->text = startRuleOverride_.empty() ? declaredStartRule_ : startRuleOverride_;
    if (e->text.empty() && rules_.count("Lot")) e->text = "Lot";  // startRule()'s choice
    return e;
  }
  static const char* const kLotMembers[] = {"name",      "origin.px", "origin.py", "origin.pz",
                                            "origin.ox", "origin.oy", "origin.oz"};
  if (std::find(std::begin(kLotMembers), std::end(kLotMembers), member) == std::end(kLotMembers)) {
    error("E010", at,
          "unknown attribute 'initialShape." + member +
              "' (initialShape.name, .startRule, .origin.px|py|pz, .origin.ox|oy|oz)");
    return nullptr;
  }
  ExprPtr e = makeExpr(ExprKind::Member, at);
  e->object = "Lot";
  e->text = "prop";
  e->hasCall = true;
  e->args.push_back(makeExpr(ExprKind::String, at));
  e->args.back()->text = "initialShape." + member;
  if (member == "name") {
    e->args.push_back(makeExpr(ExprKind::String, at));
  } else {
    e->args.push_back(number(0, at));
  }
  return e;
}

// CityEngine's occlusion and context queries: fgsg's Shape.overlaps("intra", "tower") ...,
// the target selector (a keyword here) written as its word.
ExprPtr Translator::contextQuery(const std::string& fn, const SourceRange& at, const SourceRange& nameAt,
                                 const std::vector<P::ExprContext*>& argCtx, const Env& env) {
  const bool occlusion = fn == "inside" || fn == "overlaps" || fn == "touches";
  if (fn == "contextCompare" && argCtx.size() != 3) {
    error("E016", nameAt, "'contextCompare' takes 3 arguments (contextCompare(intra|inter|all, \"label\", "
                          "world.highest|...|area.smallest)), got " + std::to_string(argCtx.size()));
    return nullptr;
  }
  if (fn != "contextCompare" && (occlusion ? argCtx.size() > 2 : argCtx.size() != 2)) {
    error("E016", nameAt, "'" + fn + "' takes " + (occlusion ? "at most 2 arguments" : "2 arguments") + " (" +
                              (occlusion ? fn + "(), " + fn + "(intra), " : "") + fn +
                              "(intra|inter|all, \"label\")), got " + std::to_string(argCtx.size()));
    return nullptr;
  }
  ExprPtr e = makeExpr(ExprKind::Member, at);
  e->object = "Shape";
  e->text = fn;
  e->hasCall = true;
  if (!argCtx.empty()) {
    const std::string target = argCtx[0]->getText();
    if (target != "intra" && target != "inter" && target != "all") {
      error("E016", rangeOf(argCtx[0]), "the target of '" + fn + "' is intra, inter or all, not '" + target + "'");
      return nullptr;
    }
    ExprPtr word = makeExpr(ExprKind::String, rangeOf(argCtx[0]));
    word->text = target;
    e->args.push_back(std::move(word));
  }
  if (argCtx.size() >= 2) {
    Env plain = env;
    plain.relativeAxis = -1;
    ExprPtr label = expr(argCtx[1], plain);
    if (!label) return nullptr;
    e->args.push_back(std::move(label));
  }
  if (argCtx.size() == 3) {  // contextCompare's comparison selector, as its word
    const std::string comparison = argCtx[2]->getText();
    static const char* const kComparisons[] = {"world.northernmost", "world.southernmost", "world.easternmost",
                                               "world.westernmost",  "world.highest",      "world.lowest",
                                               "area.largest",       "area.smallest"};
    if (std::find(std::begin(kComparisons), std::end(kComparisons), comparison) == std::end(kComparisons)) {
      error("E016", rangeOf(argCtx[2]),
            "the comparison of 'contextCompare' is world.northernmost, world.southernmost, world.easternmost, "
            "world.westernmost, world.highest, world.lowest, area.largest or area.smallest, not '" + comparison + "'");
      return nullptr;
    }
    ExprPtr word = makeExpr(ExprKind::String, rangeOf(argCtx[2]));
    word->text = comparison;
    e->args.push_back(std::move(word));
  }
  return e;
}

ExprPtr Translator::call(const std::string& fn, const SourceRange& at, const SourceRange& nameAt,
                         const std::vector<P::ExprContext*>& argCtx, const Env& env) {
  // A user function: its body with the parameters bound to the arguments.
  if (auto f = functions_.find(fn); f != functions_.end()) {
    const Function& def = f->second;
    if (argCtx.size() != def.params.size()) {
      error("E016", nameAt, "'" + fn + "' takes " + std::to_string(def.params.size()) + " argument" +
                                (def.params.size() == 1 ? "" : "s") + ", got " + std::to_string(argCtx.size()));
      return nullptr;
    }
    if (std::find(inlining_.begin(), inlining_.end(), fn) != inlining_.end()) {
      error("E802", nameAt, "'" + fn + "' calls itself (through " + inlining_.back() +
                                "): recursive functions are not supported (functions are inlined)");
      return nullptr;
    }
    std::vector<ExprPtr> args;
    for (auto* a : argCtx) {
      args.push_back(expr(a, env));
      if (!args.back()) return nullptr;
    }
    Env inner;  // the body sees its parameters, attrs, consts and functions: not the rule's
    for (size_t k = 0; k < args.size(); ++k) inner.bound[def.params[k]] = args[k].get();
    inlining_.push_back(fn);
    ExprPtr out = value(def.body, inner);
    inlining_.pop_back();
    if (out) out->range = at;
    return out;
  }
  if (fn.rfind("geometry.", 0) == 0) {
    // geometry.area() ...: fgsg's Geometry.area queries; the surface selectors
    // (geometry.area(top)) are not here yet. geometry.angle(maxSlope): Geometry.angle("maxSlope");
    // geometry.du(k, uvSpace): Geometry.du(k, "uvSpace"), k a uv set 0..9 (unitSpace not yet).
    const std::string member = fn.substr(9);
    if (std::find(std::begin(kCityEngineGeometryMembers), std::end(kCityEngineGeometryMembers), member) ==
        std::end(kCityEngineGeometryMembers)) {
      notSupported(nameAt, "the function '" + fn + "'");
      return nullptr;
    }
    const bool spread = member == "du" || member == "dv";
    const size_t want = spread ? 2 : member == "isPlanar" || member == "angle" ? 1 : 0;
    if (argCtx.size() != want) {
      if (want == 0 && argCtx.size() == 1) {
        notSupported(at, "'" + fn + "' with a selector of faces");
        return nullptr;
      }
      error("E016", nameAt,
            "'" + fn + "' takes " +
                (member == "angle" ? "1 argument (maxSlope, azimuth or zenith)"
                 : spread          ? "2 arguments (the uv set and uvSpace or unitSpace)"
                 : want            ? "1 argument (the tolerance in degrees)"
                                   : "no arguments") +
                ", got " + std::to_string(argCtx.size()));
      return nullptr;
    }
    std::vector<ExprPtr> args;
    if (member == "angle") {
      const std::string word = selectorWord(argCtx[0]);
      if (word != "maxSlope" && word != "azimuth" && word != "zenith") {
        error("E028", rangeOf(argCtx[0]),
              "geometry.angle's selector is maxSlope, azimuth or zenith, not '" + argCtx[0]->getText() + "'");
        return nullptr;
      }
      args.push_back(makeExpr(ExprKind::String, rangeOf(argCtx[0])));
      args.back()->text = word;
    } else if (spread) {
      // The uv set is written as a number, as the uv operations' (cga_operations.cpp).
      const std::string setText = argCtx[0]->getText();
      if (setText.size() != 1 || setText[0] < '0' || setText[0] > '9') {
        error("E028", rangeOf(argCtx[0]),
              "a uv set is a whole number from 0 to 9 (CityEngine's texture layers), not '" + setText + "'");
        return nullptr;
      }
      const std::string space = selectorWord(argCtx[1]);
      if (space == "unitSpace") {
        notSupported(rangeOf(argCtx[1]), "'" + fn + "' in unitSpace");
        return nullptr;
      }
      if (space != "uvSpace") {
        error("E028", rangeOf(argCtx[1]),
              fn + "'s surface parameterization is uvSpace or unitSpace, not '" + argCtx[1]->getText() + "'");
        return nullptr;
      }
      args.push_back(makeExpr(ExprKind::Number, rangeOf(argCtx[0])));
      args.back()->number = setText[0] - '0';
      args.push_back(makeExpr(ExprKind::String, rangeOf(argCtx[1])));
      args.back()->text = space;
    } else {
      for (auto* a : argCtx) {
        Env plain = env;
        plain.relativeAxis = -1;
        args.push_back(expr(a, plain));
        if (!args.back()) return nullptr;
      }
    }
    ExprPtr e = makeExpr(ExprKind::Member, at);
    e->object = "Geometry";
    e->text = member;
    e->hasCall = want >= 1;
    e->args = std::move(args);
    return e;
  }
  if (fn == "inside" || fn == "overlaps" || fn == "touches" || fn == "minimumDistance" || fn == "contextCount" ||
      fn == "contextCompare")
    return contextQuery(fn, at, nameAt, argCtx, env);
  if (fn == "occlusion") {  // before its keyword arguments read as names
    notSupported(nameAt, "the function '" + fn + "'");
    return nullptr;
  }
  std::vector<ExprPtr> args;
  Env plain = env;
  plain.relativeAxis = -1;
  for (auto* a : argCtx) {
    args.push_back(expr(a, plain));
    if (!args.back()) return nullptr;
  }
  auto wrongCount = [&](const std::string& forms) {
    error("E016", nameAt, "'" + fn + "' takes " + forms + ", got " + std::to_string(args.size()) + " argument" +
                              (args.size() == 1 ? "" : "s"));
    return nullptr;
  };
  if (fn == "rand") {
    if (args.size() == 0) return uniform(at);
    if (args.size() == 1) args.insert(args.begin(), number(0, at));
    if (args.size() != 2) return wrongCount("0, 1 or 2 arguments");
    return callExpr("Rand", std::move(args), at);
  }
  if (fn == "p") {
    if (args.size() != 1) return wrongCount("1 argument");
    return binary("<", uniform(at), std::move(args[0]));
  }
  if (fn == "rint") {
    if (args.size() != 1) return wrongCount("1 argument");
    return callExpr("round", std::move(args), at);
  }
  if (fn == "ln") {
    if (args.size() != 1) return wrongCount("1 argument");
    return callExpr("log", std::move(args), at);
  }
  if (fn == "log10") {
    if (args.size() != 1) return wrongCount("1 argument");
    std::vector<ExprPtr> ten;
    ten.push_back(number(10, at));
    return binary("/", callExpr("log", std::move(args), at), callExpr("log", std::move(ten), at));
  }
  if (fn == "str") {  // CityEngine's str(): a string `+` prints numbers and truth values as str() does
    if (args.size() != 1) return wrongCount("1 argument");
    ExprPtr empty = makeExpr(ExprKind::String, at);
    ExprPtr e = binary("+", std::move(empty), std::move(args[0]));
    e->range = at;
    return e;
  }
  if (fn == "isnan") {  // NaN is the one number whose size is not >= 0
    if (args.size() != 1) return wrongCount("1 argument");
    ExprPtr notNan = binary(">=", callExpr("abs", std::move(args), at), number(0, at));
    ExprPtr e = makeExpr(ExprKind::Unary, at);
    e->text = "!";
    e->args.push_back(std::move(notNan));
    return e;
  }
  if (fn == "isinf") {
    if (args.size() != 1) return wrongCount("1 argument");
    return binary(">", callExpr("abs", std::move(args), at), number(1.7976931348623157e308, at));
  }
  for (const char* same : kSameFunctions)
    if (fn == same) {
      const FunctionInfo* info = findFunction(fn);
      if (info && (int(args.size()) < info->minArgs || int(args.size()) > info->maxArgs))
        return wrongCount(std::to_string(info->minArgs) + " argument" + (info->minArgs == 1 ? "" : "s"));
      return callExpr(fn, std::move(args), at);
    }
  const size_t dot = fn.find('.');
  if (dot != std::string::npos && importAliases_.count(fn.substr(0, dot))) {
    // An imported function: a call that the import replaces by the function's body
    // (frontend/imported_functions.cpp), which also checks that it exists and its arguments.
    ExprPtr e = callExpr(fn, std::move(args), at);
    e->range.begin = nameAt.begin;
    return e;
  }
  if (dot != std::string::npos) {
    notSupported(nameAt, "the function '" + fn + "'");
    return nullptr;
  }
  for (const char* known : kKnownFunctions)
    if (fn == known) {
      notSupported(nameAt, "the function '" + fn + "'");
      return nullptr;
    }
  std::vector<std::string> known(std::begin(kSameFunctions), std::end(kSameFunctions));
  known.insert(known.end(), std::begin(kKnownFunctions), std::end(kKnownFunctions));
  for (const auto& [name, f] : functions_) known.push_back(name);
  const std::string near = closestName(fn, known);  // "sqr": sqrt, or a slip for one of the file's
  error("E011", nameAt, "unknown function '" + fn + "'" + (near.empty() ? "" : "; did you mean '" + near + "'?") +
                            " (not a function of this file or of CityEngine CGA)");
  return nullptr;
}

}  // namespace fgsg::frontend::cga
