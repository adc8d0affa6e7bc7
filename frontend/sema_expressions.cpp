// Expressions: the type of every expression (recorded in SemaResult::exprTypes), how each
// identifier resolves (SemaResult::names), and the errors of operators, function calls,
// and Scope/Shape/field/texture queries.

#include "frontend/sema_analyzer.h"

#include "frontend/builtins.h"
#include "frontend/did_you_mean.h"

#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace fgsg::frontend::sema_detail {

namespace {

// Why field `name` cannot answer `member` (docs/language.md, Fields), or null when it can
// or its declaration did not check out (already reported). Curvatures come only from a
// `curvature` field, intensity and rgb only from an `image(...)` one.
const char* memberNotAnswered(const std::vector<FieldInfo>& specs, const std::string& name,
                              const std::string& member) {
  for (const FieldInfo& f : specs) {
    if (f.name != name) continue;
    const bool curvature = member == "mincurv" || member == "maxcurv" || member == "meancurv" ||
                           member == "gausscurv";
    if (curvature && f.source != "curvature")
      return "curvatures are answered by a curvature field only (declare one: `field K = curvature;`)";
    if ((member == "intensity" || member == "rgb") && f.source != "image")
      return "only a field made from a picture (`field P = image(\"picture.png\");`) has an intensity and "
             "colours";
    return nullptr;
  }
  return nullptr;
}

}  // namespace

void Analyzer::expect(const Expr& e, const Where& w, ValueType want, const std::string& what) {
  ValueType t = typeOf(e, w, true);
  if (t != ValueType::Unknown && t != want)
    diags_.error(want == ValueType::Bool ? "E014" : "E013", e.range,
                 what + " must be a " + valueTypeName(want) + ", but this is a " +
                     valueTypeName(t));
}

ValueType Analyzer::record(const Expr& e, ValueType t, bool report) {
  if (report) res_.exprTypes[&e] = t;
  return t;
}

ValueType Analyzer::typeOf(const Expr& e, const Where& w, bool report) {
  switch (e.kind) {
    case ExprKind::Number: return record(e, ValueType::Num, report);
    case ExprKind::Bool: return record(e, ValueType::Bool, report);
    case ExprKind::String: return record(e, ValueType::Str, report);
    case ExprKind::RelSize:
    case ExprKind::FloatSize:
      if (e.kind == ExprKind::FloatSize && !e.args.empty()) typeOf(*e.args[0], w, report);
      if (!w.sizeArg && report)
        diags_.error("E026", e.range,
                     "relative (1r) and floating (~s) sizes are only allowed as sizes of S and "
                     "Subdiv");
      return record(e, ValueType::Num, report);
    case ExprKind::Vector: {
      for (const auto& a : e.args) {
        ValueType t = typeOf(*a, w.operand(), report);
        if (report && t != ValueType::Num && t != ValueType::Unknown)
          diags_.error("E013", a->range, "a vector's components must be numbers");
      }
      if (e.args.size() != 3 && report)
        diags_.error("E013", e.range, "a vector literal has exactly three components");
      return record(e, ValueType::Vec3, report);
    }
    case ExprKind::Ident: return typeOfIdent(e, w, report);
    case ExprKind::Unary: {
      ValueType t = typeOf(*e.args[0], w.operand(), report);
      if (e.text == "!") {
        if (report && t != ValueType::Bool && t != ValueType::Unknown)
          diags_.error("E013", e.range, "'!' needs a boolean, got a " + std::string(valueTypeName(t)));
        return record(e, ValueType::Bool, report);
      }
      if (report && t != ValueType::Num && t != ValueType::Vec3 && t != ValueType::Unknown)
        diags_.error("E013", e.range,
                     "'" + e.text + "' needs a number, got a " + std::string(valueTypeName(t)));
      return record(e, t, report);
    }
    case ExprKind::Binary: return typeOfBinary(e, w, report);
    case ExprKind::Ternary: {
      const Where inner = w.operand();
      ValueType c = typeOf(*e.args[0], inner, report);
      if (report && c != ValueType::Bool && c != ValueType::Unknown)
        diags_.error("E014", e.args[0]->range, "the condition of '?:' must be a boolean");
      ValueType a = typeOf(*e.args[1], inner, report), b = typeOf(*e.args[2], inner, report);
      if (a != ValueType::Unknown && b != ValueType::Unknown && a != b) {
        if (report)
          diags_.error("E013", e.range,
                       std::string("both branches of '?:' must have one type, got ") +
                           valueTypeName(a) + " and " + valueTypeName(b));
        return record(e, ValueType::Unknown, report);
      }
      return record(e, a != ValueType::Unknown ? a : b, report);
    }
    case ExprKind::Call: return typeOfCall(e, w, report);
    case ExprKind::Member: return typeOfMember(e, w, report);
  }
  return ValueType::Unknown;
}

ValueType Analyzer::typeOfIdent(const Expr& e, const Where& w, bool report) {
  if (const auto* params = w.rule >= 0 ? &res_.ruleParams[w.rule] : w.bound) {
    for (size_t k = 0; k < params->size(); ++k)
      if ((*params)[k].first == e.text) {
        if (report) res_.names[&e] = NameRef{NameRef::Param, k, {}};
        return record(e, (*params)[k].second, report);
      }
  }
  auto c = res_.constants.find(e.text);
  if (c != res_.constants.end()) {
    if (report) res_.names[&e] = NameRef{NameRef::Const, 0, c->second};
    return record(e, c->second.type, report);
  }
  for (size_t k = 0; k < res_.attrs.size(); ++k)
    if (res_.attrs[k].name == e.text) {
      if (report) res_.names[&e] = NameRef{NameRef::Attr, k, {}};
      return record(e, res_.attrs[k].value.type, report);
    }
  if (e.text == "pi" || e.text == "PI") {
    ConstValue v;
    v.num = kPi;
    if (report) res_.names[&e] = NameRef{NameRef::Builtin, 0, v};
    return record(e, ValueType::Num, report);
  }
  if (failedValues_.count(e.text)) return ValueType::Unknown;  // reported at its declaration
  if (report)
    diags_.error("E010", e.range,
                 "unknown name '" + e.text + "'" +
                     (w.rule >= 0 ? " (not a parameter of this rule, a const or an attr)"
                      : w.bound   ? " (not x, y, z, a const or an attr)"
                                  : " (not a const or an attr)"));
  return ValueType::Unknown;
}

ValueType Analyzer::typeOfBinary(const Expr& e, const Where& w, bool report) {
  const Where inner = w.operand();
  ValueType a = typeOf(*e.args[0], inner, report), b = typeOf(*e.args[1], inner, report);
  const std::string& op = e.text;
  auto bad = [&](const std::string& need) {
    if (report)
      diags_.error("E013", e.range,
                   "'" + op + "' needs " + need + ", got " + valueTypeName(a) + " and " +
                       valueTypeName(b));
    return record(e, ValueType::Unknown, report);
  };
  const bool unknown = a == ValueType::Unknown || b == ValueType::Unknown;
  ConstValue divisor;
  if (report && (op == "/" || op == "%") && evalConst(*e.args[1], divisor) &&
      divisor.type == ValueType::Num && divisor.num == 0)
    diags_.error("E027", e.args[1]->range, "division by zero");
  if (op == "&&" || op == "||") {
    if (!unknown && (a != ValueType::Bool || b != ValueType::Bool)) return bad("booleans");
    return record(e, ValueType::Bool, report);
  }
  if (op == "==" || op == "!=") {
    if (!unknown && a != b) return bad("two values of one type");
    return record(e, ValueType::Bool, report);
  }
  if (op == "<" || op == "<=" || op == ">" || op == ">=") {
    if (!unknown && (a != ValueType::Num || b != ValueType::Num)) return bad("numbers");
    return record(e, ValueType::Bool, report);
  }
  if (unknown) return record(e, a == ValueType::Unknown ? b : a, report);
  if (a == ValueType::Num && b == ValueType::Num) return record(e, ValueType::Num, report);
  // A string joined with a string, number or truth value (CGA's string `+`, "floor" + 3).
  if (op == "+" && (a == ValueType::Str || b == ValueType::Str) && a != ValueType::Vec3 && b != ValueType::Vec3)
    return record(e, ValueType::Str, report);
  if ((op == "+" || op == "-") && a == ValueType::Vec3 && b == ValueType::Vec3)
    return record(e, ValueType::Vec3, report);
  if (op == "*" && ((a == ValueType::Vec3 && b == ValueType::Num) ||
                    (a == ValueType::Num && b == ValueType::Vec3)))
    return record(e, ValueType::Vec3, report);
  if (op == "/" && a == ValueType::Vec3 && b == ValueType::Num)
    return record(e, ValueType::Vec3, report);
  return bad("numbers");
}

ValueType Analyzer::typeOfCall(const Expr& e, const Where& w, bool report) {
  const FunctionInfo* f = findFunction(e.text);
  const Where inner = w.operand();
  std::vector<ValueType> args;
  for (const auto& a : e.args) args.push_back(typeOf(*a, inner, report));
  if (!f) {
    std::vector<std::string> known;
    for (const FunctionInfo& k : allFunctions()) known.push_back(k.name);
    const std::string near = closestName(e.text, known);  // "sqr": sqrt
    if (report)
      diags_.error("E011", e.range,
                   "unknown function '" + e.text + "'" + (near.empty() ? "" : "; did you mean '" + near + "'?") +
                       " (math: sin cos tan asin acos atan atan2 sqrt abs min max floor ceil "
                       "round clamp lerp pow exp log sign; vectors: length dot normalize; "
                       "random: Rand(a, b))");
    return ValueType::Unknown;
  }
  const int n = static_cast<int>(e.args.size());
  if (n < f->minArgs || n > f->maxArgs) {
    if (report)
      diags_.error("E012", e.range,
                   "'" + e.text + "' takes " + std::to_string(f->minArgs) + " argument" +
                       (f->minArgs == 1 ? "" : "s") + ", got " + std::to_string(n));
    return ValueType::Unknown;
  }
  const std::string name = e.text;
  const bool vectorFn = name == "length" || name == "dot" || name == "normalize";
  for (size_t k = 0; k < args.size(); ++k) {
    ValueType want = vectorFn ? ValueType::Vec3 : ValueType::Num;
    if (args[k] != ValueType::Unknown && args[k] != want && report)
      diags_.error("E013", e.args[k]->range,
                   "argument " + std::to_string(k + 1) + " of '" + name + "' must be a " +
                       valueTypeName(want) + ", got a " + valueTypeName(args[k]));
  }
  return record(e, name == "normalize" ? ValueType::Vec3 : ValueType::Num, report);
}

// Lot.area and Lot.prop("height", 14): a lot's area and properties (--lots) as attrs the
// grammar does not declare, named "lot:area" and "lot:height", whose value without lots
// (or without that property) is the default given — the type too. Each name has one
// default wherever it is read.
ValueType Analyzer::typeOfLotQuery(const Expr& e, bool report) {
  auto fail = [&](const std::string& msg) {
    if (report) diags_.error("E025", e.range, msg);
    return ValueType::Unknown;
  };
  std::string name;
  ConstValue value;
  if (e.text == "area" && !e.hasCall) {
    name = "lot:area";
    value.type = ValueType::Num;
  } else if (e.text == "prop" && e.hasCall && e.args.size() == 2) {
    ConstValue key;
    if (!evalConst(*e.args[0], key) || key.type != ValueType::Str || key.str.empty())
      return fail("Lot.prop takes the property's name as a constant string: Lot.prop(\"height\", 14)");
    if (!evalConst(*e.args[1], value) || value.type == ValueType::Unknown)
      return fail("Lot.prop's default (its value without lots) must be a constant: Lot.prop(\"height\", 14)");
    if (report) res_.exprTypes[e.args[0].get()] = ValueType::Str;
    name = "lot:" + key.str;
  } else {
    return fail("unknown lot query 'Lot." + e.text + "' (Lot.area, Lot.prop(\"name\", default))");
  }
  size_t k = 0;
  while (k < res_.attrs.size() && res_.attrs[k].name != name) ++k;
  if (k == res_.attrs.size()) {
    res_.attrs.push_back({name, value, e.range, {}});
  } else if (res_.attrs[k].value.type != value.type || (value.type != ValueType::Num && value.type != ValueType::Bool
                                                         ? res_.attrs[k].value.str != value.str
                                                         : res_.attrs[k].value.num != value.num)) {
    return fail("'" + name.substr(4) + "' has another default at line " +
                std::to_string(res_.attrs[k].range.begin.line) + ": give a lot property one default");
  }
  if (report) res_.names[&e] = NameRef{NameRef::Attr, k, {}};
  return record(e, value.type, report);
}

ValueType Analyzer::typeOfMember(const Expr& e, const Where& w, bool report) {
  const Where inner = w.operand();
  if (e.object == "Lot") return typeOfLotQuery(e, report);
  // context.mask(texCoord): the texture coordinate is the scope's own, named not computed.
  const bool textureLookup = e.object == "context";
  if (!textureLookup)
    for (const auto& a : e.args) typeOf(*a, inner, report);
  auto fail = [&](const std::string& msg) {
    if (report) diags_.error("E025", e.range, msg);
    return ValueType::Unknown;
  };
  if (e.object == "Scope") {
    static const std::set<std::string> kScope = {"sx", "sy", "sz", "px", "py", "pz"};
    if (kScope.count(e.text) && !e.hasCall) return record(e, ValueType::Num, report);
    if (e.text == "occ" && e.hasCall && e.args.size() == 1)
      return record(e, ValueType::Str, report);
    return fail("unknown scope query 'Scope." + e.text +
                "' (Scope.sx sy sz px py pz, Scope.occ(\"noparent\"))");
  }
  if (e.object == "Shape") {
    static const std::set<std::string> kShape = {"depth", "index", "splitIndex", "splitTotal", "compIndex",
                                                 "compTotal"};
    if (kShape.count(e.text) && !e.hasCall) return record(e, ValueType::Num, report);
    if (e.text == "compSel" && !e.hasCall) return record(e, ValueType::Str, report);  // CGA's comp.sel
    if (e.text == "visible" && e.hasCall && e.args.size() == 1)
      return record(e, ValueType::Bool, report);
    // CityEngine's contextCompare: Shape.contextCompare("inter", "lot", "world.highest").
    if (e.text == "contextCompare" && e.hasCall) {
      static const std::set<std::string> kComparisons = {
          "world.northernmost", "world.southernmost", "world.easternmost", "world.westernmost",
          "world.highest",      "world.lowest",       "area.largest",      "area.smallest"};
      const std::string form =
          "Shape.contextCompare(\"intra\" or \"inter\" or \"all\", \"label\", \"world.highest\" or \"area.largest\" ...)";
      if (e.args.size() != 3) return fail("'Shape.contextCompare' takes 3 arguments: " + form);
      ConstValue target, comparison;
      if (!evalConst(*e.args[0], target) || target.type != ValueType::Str ||
          (target.str != "intra" && target.str != "inter" && target.str != "all"))
        return fail("the target of 'Shape.contextCompare' is the constant \"intra\", \"inter\" or \"all\": " + form);
      if (typeOf(*e.args[1], inner, false) != ValueType::Str)
        return fail("the label of 'Shape.contextCompare' is a string: " + form);
      if (!evalConst(*e.args[2], comparison) || comparison.type != ValueType::Str || !kComparisons.count(comparison.str))
        return fail("the comparison of 'Shape.contextCompare' is the constant \"world.northernmost\", "
                    "\"world.southernmost\", \"world.easternmost\", \"world.westernmost\", \"world.highest\", "
                    "\"world.lowest\", \"area.largest\" or \"area.smallest\"");
      if (report) res_.exprTypes[e.args[0].get()] = res_.exprTypes[e.args[2].get()] = ValueType::Str;
      return record(e, ValueType::Num, report);
    }
    // CityEngine's context queries: Shape.overlaps("intra", "tower") ...
    static const std::set<std::string> kOcclusion = {"inside", "overlaps", "touches"};
    static const std::set<std::string> kContext = {"minimumDistance", "contextCount"};
    if ((kOcclusion.count(e.text) || kContext.count(e.text)) && e.hasCall) {
      const bool occlusion = kOcclusion.count(e.text) > 0;
      if (occlusion ? e.args.size() > 2 : e.args.size() != 2)
        return fail("'Shape." + e.text + "' takes " + (occlusion ? "at most 2 arguments" : "2 arguments") +
                    ": " + (occlusion ? "Shape." + e.text + "(), " : "") + "Shape." + e.text +
                    "(\"intra\" or \"inter\" or \"all\", \"label\")");
      ConstValue target;
      if (!e.args.empty() && (!evalConst(*e.args[0], target) || target.type != ValueType::Str ||
                              (target.str != "intra" && target.str != "inter" && target.str != "all")))
        return fail("the target of 'Shape." + e.text + "' is the constant \"intra\", \"inter\" or \"all\"");
      if (e.args.size() == 2 && typeOf(*e.args[1], inner, false) != ValueType::Str)
        return fail("the label of 'Shape." + e.text + "' is a string: Shape." + e.text + "(\"intra\", \"tower\")");
      if (report && !e.args.empty()) res_.exprTypes[e.args[0].get()] = ValueType::Str;
      return record(e, occlusion ? ValueType::Bool : ValueType::Num, report);
    }
    return fail("unknown shape query 'Shape." + e.text +
                "' (Shape.depth, Shape.index, Shape.splitIndex, Shape.splitTotal, Shape.compIndex, "
                "Shape.compTotal, Shape.compSel, Shape.visible(\"street\"), Shape.inside overlaps touches(\"intra\", \"label\"), "
                "Shape.minimumDistance contextCount(\"intra\", \"label\"))");
  }
  if (e.object == "Geometry") {  // CGA's geometry.*(): the shape's own geometry
    static const std::set<std::string> kNumbers = {"area", "height", "nVertices", "nFaces", "boundaryLength"};
    if (kNumbers.count(e.text) && !e.hasCall) return record(e, ValueType::Num, report);
    if (e.text == "isConcave" && !e.hasCall) return record(e, ValueType::Bool, report);
    if (e.text == "isPlanar" && e.hasCall && e.args.size() == 1) {
      if (report && typeOf(*e.args[0], inner, false) != ValueType::Num)
        return fail("Geometry.isPlanar takes a tolerance in degrees: Geometry.isPlanar(1)");
      return record(e, ValueType::Bool, report);
    }
    if (e.text == "angle" && e.hasCall && e.args.size() == 1) {  // CGA's geometry.angle(maxSlope)
      ConstValue selector;
      if (!evalConst(*e.args[0], selector) || selector.type != ValueType::Str ||
          (selector.str != "maxSlope" && selector.str != "azimuth" && selector.str != "zenith"))
        return fail("Geometry.angle takes the constant \"maxSlope\", \"azimuth\" or \"zenith\": "
                    "Geometry.angle(\"maxSlope\")");
      if (report) res_.exprTypes[e.args[0].get()] = ValueType::Str;
      return record(e, ValueType::Num, report);
    }
    if ((e.text == "du" || e.text == "dv") && e.hasCall && e.args.size() == 2) {  // CGA's geometry.du(k, uvSpace)
      ConstValue set, space;
      if (!evalConst(*e.args[0], set) || set.type != ValueType::Num || !(set.num >= 0 && set.num <= 9) ||
          set.num != std::floor(set.num))
        return fail("Geometry." + e.text + " reads a uv set, a constant whole number from 0 to 9: Geometry." +
                    e.text + "(0, \"uvSpace\")");
      if (!evalConst(*e.args[1], space) || space.type != ValueType::Str || space.str != "uvSpace")
        return fail("Geometry." + e.text + " measures in \"uvSpace\" (\"unitSpace\" is not supported yet): Geometry." +
                    e.text + "(0, \"uvSpace\")");
      if (report) res_.exprTypes[e.args[1].get()] = ValueType::Str;
      return record(e, ValueType::Num, report);
    }
    return fail("unknown geometry query 'Geometry." + e.text +
                "' (Geometry.area height nVertices nFaces boundaryLength isConcave, Geometry.isPlanar(degrees), "
                "Geometry.angle(\"maxSlope\" or \"azimuth\" or \"zenith\"), Geometry.du dv(0, \"uvSpace\"))");
  }
  if (e.object == "Feature") {
    bool number = false, takesString = false;
    if (!isFeatureMember(e.text, number, takesString) || e.hasCall != takesString ||
        (takesString && e.args.size() != 1))
      return fail("unknown feature query 'Feature." + e.text +
                  "' (Feature.corner edge face horizontal vertical curved arc convex concave boundary "
                  "bottom top side, Feature.label(\"window\"), Feature.index valence length area)");
    if (takesString) {
      ConstValue v;
      if (!evalConst(*e.args[0], v) || v.type != ValueType::Str)
        return fail("Feature.label takes a constant string: Feature.label(\"window\")");
      res_.exprTypes[e.args[0].get()] = ValueType::Str;
    }
    return record(e, number ? ValueType::Num : ValueType::Bool, report);
  }
  if (textureLookup) {
    if (e.args.size() > 1 || (e.args.size() == 1 && (e.args[0]->kind != ExprKind::Ident ||
                                                      e.args[0]->text != "texCoord")))
      return fail("a texture context is sampled at the scope's texture coordinate: write "
                  "context." + e.text + "(texCoord)");
    for (const auto& t : res_.textures)
      if (t == e.text) return record(e, ValueType::Num, report);
    return fail("'context." + e.text + "' names no texture; declare it with `texture " +
                e.text + " = \"file.png\";`");
  }
  for (const auto& f : res_.fields)
    if (f == e.object) {
      bool vec = false;
      if (!isFieldMember(e.text, vec) || e.hasCall)
        return fail("unknown field query '" + e.object + "." + e.text +
                    "' (vector1 vector2 value1 value2 length1 Xangle1 div curl gradient "
                    "mincurv maxcurv meancurv gausscurv ...)");
      // Some members only one source answers (R016 at run time): a check-time error instead.
      if (const char* why = memberNotAnswered(res_.fieldSpecs, e.object, e.text))
        return fail("'" + e.object + "." + e.text + "': " + why);
      return record(e, vec ? ValueType::Vec3 : ValueType::Num, report);
    }
  return fail("'" + e.object + "' is not a field, a texture context, Scope, Shape or Feature");
}

}  // namespace fgsg::frontend::sema_detail
