// Semantic analysis of the declarations that give a grammar its values and settings:
// `const` and `attr` (evaluated once, here, so that rules see constants), the names of
// `field` and `texture` declarations (for queries), the surface count, `derive` and
// `turtle`. The surface and field bodies themselves are sema_environment.cpp's.

#include "frontend/color_literal.h"
#include "frontend/sema_analyzer.h"
#include "frontend/sema_environment.h"

#include <cmath>
#include <functional>
#include <set>
#include <string>

namespace fgsg::frontend::sema_detail {

namespace {

constexpr int kMaxDeriveCount = 2147483647;  // INT32_MAX: ir::Module::steps and depthBound are ints

}  // namespace

void Analyzer::collectValues() {
  std::set<std::string> seen;
  // A CityEngine attr computed from other attrs (`attr groundFloorH = floorH + 1`, in any
  // order): set aside until the attrs it reads are known, then it follows them at run time.
  std::vector<const ValueDecl*> computedAttrs;
  for (const auto& v : prog_.values) {
    if (!seen.insert(v.name).second) {
      diags_.error("E022", v.range, "'" + v.name + "' is declared twice");
      continue;
    }
    ConstValue value;
    if (v.isAttr && v.fromImporter && !evalConst(*v.value, value) && importerValue(*v.value, value)) {
      res_.attrs.push_back({v.name, value, v.range, v.annotations, v.value.get()});
      continue;
    }
    // An importer's value may read the importer's computed attrs (`lib.tile = tile * 2`,
    // `attr tile = height / 4`): it waits for them with the computed attrs.
    if (prog_.cityEngineLots && v.isAttr && !evalConst(*v.value, value) && !zeroDivisor(*v.value)) {
      computedAttrs.push_back(&v);
      continue;
    }
    if (!evalConst(*v.value, value)) {
      // Its uses are not reported again as unknown names (E010): this is the one error.
      failedValues_.insert(v.name);
      if (const Expr* zero = zeroDivisor(*v.value)) {
        diags_.error("E027", zero->range, "division by zero");
        continue;
      }
      diags_.error("E023", v.value->range,
                   v.fromImporter ? "the importer's value of attr '" + v.name +
                                        "' may use numbers, strings, constants, this file's attrs and math "
                                        "functions"
                                  : std::string(v.isAttr ? "the default of attr '" : "const '") + v.name +
                                        "' must be a constant expression (numbers, strings, earlier "
                                        "constants and math functions)");
      continue;
    }
    if (v.isAttr)
      res_.attrs.push_back({v.name, value, v.range, v.annotations});
    else
      res_.constants[v.name] = value;
  }
  collectComputedAttrs(computedAttrs);
}

void Analyzer::collectComputedAttrs(std::vector<const ValueDecl*> pending) {
  // Each pass takes those whose attrs are now known, so an attr comes after those it reads
  // (attributeSlots computes them in that order; a random draw is made once per start
  // shape there); what is left reads a query, an unknown name or itself through others.
  for (bool progress = true; progress && !pending.empty();) {
    progress = false;
    for (auto it = pending.begin(); it != pending.end();) {
      ConstValue value;
      if (!importerValue(*(*it)->value, value, true)) {
        ++it;
        continue;
      }
      res_.attrs.push_back({(*it)->name, value, (*it)->range, (*it)->annotations, (*it)->value.get()});
      it = pending.erase(it);
      progress = true;
    }
  }
  for (const ValueDecl* v : pending) {
    failedValues_.insert(v->name);
    diags_.error("E023", v->value->range,
                 (v->fromImporter ? "the importer's value of attr '" : "the default of attr '") + v->name +
                     "' may use numbers, strings, consts, functions, other attrs, random numbers "
                     "and math functions; not shape queries or a cycle of attrs (CityEngine CGA; "
                     "not supported yet)");
  }
}

bool Analyzer::importerValue(const Expr& e, ConstValue& out, bool random) {
  // Only what is known before any shape exists: no queries, parameters or random numbers.
  std::function<bool(const Expr&)> plain = [&](const Expr& x) {
    if (x.kind == ExprKind::Member || x.kind == ExprKind::RelSize || x.kind == ExprKind::FloatSize) return false;
    if (x.kind == ExprKind::Call && (x.text == "Rand" || x.text == "rand") && !random) return false;
    if (x.kind == ExprKind::Ident && !res_.constants.count(x.text) && x.text != "pi" && x.text != "PI") {
      bool attr = false;
      for (const AttrInfo& a : res_.attrs) attr |= a.name == x.text;
      if (!attr) return false;
    }
    for (const auto& a : x.args)
      if (!plain(*a)) return false;
    return true;
  };
  if (!plain(e)) return false;
  const ValueType type = typeOf(e, Where{}, true);
  if (type == ValueType::Unknown) return false;
  // The default: the expression over the attrs' defaults (as constants for a moment).
  const std::map<std::string, ConstValue> constants = res_.constants;
  for (const AttrInfo& a : res_.attrs) res_.constants.emplace(a.name, a.value);
  const bool folded = evalConst(e, out);
  res_.constants = constants;
  if (!folded || out.type != type) {  // a string `+`: joined when the attrs are known
    out = {};
    out.type = type;
  }
  return true;
}

// A scalar field's expression is computed once per vertex, before any shape exists: it
// reads the vertex's position, consts, attrs and math, not the queries of a shape.
bool Analyzer::checkSurfaceExpression(const Expr& e) {
  bool ok = true;
  std::function<void(const Expr&)> noQueries = [&](const Expr& x) {
    if (x.kind == ExprKind::Member) {
      diags_.error("E035", x.range,
                   "a scalar field's expression is computed at each vertex of the surface before "
                   "any shape exists: it may use x, y, z, numbers, consts, attrs and math "
                   "functions, not the query '" + x.object + "." + x.text + "'");
      ok = false;
      return;
    }
    for (const auto& a : x.args) noQueries(*a);
  };
  noQueries(e);
  if (!ok) return false;
  const int errors = diags_.errorCount();
  expect(e, Where{-1, false, &surfacePointNames()}, ValueType::Num, "a scalar field's expression");
  return diags_.errorCount() == errors && res_.exprTypes[&e] == ValueType::Num;
}

void Analyzer::collectEnvironment() {
  std::set<std::string> names;
  for (const auto& f : prog_.fields) {
    if (!names.insert(f.name).second)
      diags_.error("E022", f.range, "field '" + f.name + "' is declared twice");
    res_.fields.push_back(f.name);
  }
  for (const auto& t : prog_.textures) {
    if (!names.insert(t.name).second)
      diags_.error("E022", t.range, "texture '" + t.name + "' is declared twice");
    res_.textures.push_back(t.name);
  }
  if (prog_.surfaces.size() > 1)
    diags_.error("E029", prog_.surfaces[1].range, "only one surface may be declared");
  checkSurfaceAndFields(
      prog_, res_, diags_, [this](const Expr& e, ConstValue& v) { return evalConst(e, v); },
      [this](const Expr& e) { return checkSurfaceExpression(e); });
  // The last `derive` wins. Its number is the step count of a parallel derivation and
  // the depth bound of a sequential one (both: how many levels are rewritten).
  for (const auto& d : prog_.derives) {
    const bool parallel = d.mode == "parallel";
    if (!parallel && d.mode != "breadthfirst" && d.mode != "depthfirst") {
      diags_.error("E029", d.range,
                   "unknown derivation mode '" + d.mode +
                       "' (expected parallel N, or breadthfirst or depthfirst with an optional depth bound N)");
      continue;
    }
    ConstValue count;
    // An attr as N: its default now, a --set value when the grammar runs.
    const AttrInfo* attr = nullptr;
    if (d.steps && d.steps->kind == ExprKind::Ident && !d.steps->hasCall)
      for (const auto& a : res_.attrs)
        if (a.name == d.steps->text) attr = &a;
    if (attr) count = attr->value;
    else if (d.steps && !evalConst(*d.steps, count)) {
      if (const Expr* zero = zeroDivisor(*d.steps)) {
        diags_.error("E027", zero->range, "division by zero");
        continue;
      }
    }
    // The count is an int in the IR: larger values are refused, not wrapped.
    if ((parallel || d.steps) &&
        (!d.steps || (!attr && !evalConst(*d.steps, count)) || count.type != ValueType::Num || !(count.num >= 0) ||
         count.num > kMaxDeriveCount || count.num != std::floor(count.num))) {
      diags_.error("E029", d.steps ? d.steps->range : d.range,
                   (parallel ? "`derive parallel N;` needs a whole number of steps N from 0 to "
                             : "`derive " + d.mode + " N;` bounds the depth: N must be a whole number from 0 to ") +
                       std::to_string(kMaxDeriveCount) + " (a constant or an attr)" +
                       (d.steps && (attr || evalConst(*d.steps, count)) && count.type == ValueType::Num
                            ? ", got " + wholeNumberText(count.num) + (attr ? " (the default of attr '" + attr->name + "')" : "")
                            : std::string()));
      continue;
    }
    if (parallel) res_.steps = static_cast<int>(count.num);
    res_.depthBound = !parallel && d.steps ? static_cast<int>(count.num) : -1;
    res_.countAttr = attr ? attr->name : std::string();
    res_.mode = d.mode;
  }
  for (const auto& t : prog_.turtles) {
    for (const auto& [key, expr] : t.settings) {
      ConstValue v;
      if (expr && !evalConst(*expr, v))
        if (const Expr* zero = zeroDivisor(*expr)) {
          diags_.error("E027", zero->range, "division by zero");
          continue;
        }
      if (key == "colors") {  // `turtle colors "#5b3a1e #2f6b2f";`: the palette of '
        std::vector<std::array<float, 3>> colors;
        if (!expr || !evalConst(*expr, v) || v.type != ValueType::Str || !parseHexColors(v.str, colors)) {
          diags_.error("E029", t.range,
                       "turtle setting 'colors' needs a string of colours \"#rrggbb #rrggbb ...\" (at least one)");
          continue;
        }
        res_.turtleColors = std::move(colors);
        continue;
      }
      if (key == "segments") {
        if (!expr || !evalConst(*expr, v) || v.type != ValueType::Str ||
            (v.str != "cylinders" && v.str != "tubes" && v.str != "ribbons" && v.str != "lines")) {
          diags_.error("E029", t.range,
                       "turtle setting 'segments' needs \"cylinders\", \"tubes\", \"ribbons\" or \"lines\"");
          continue;
        }
        res_.turtleSegments = v.str;
        continue;
      }
      if (!expr || !evalConst(*expr, v) || v.type != ValueType::Num) {
        diags_.error("E029", t.range, "turtle setting '" + key + "' needs a constant number");
        continue;
      }
      if (key == "sides") {
        if (!(v.num >= 3 && v.num <= 64 && v.num == std::floor(v.num))) {
          diags_.error("E029", t.range, "turtle setting 'sides' needs a whole number from 3 to 64");
          continue;
        }
        res_.turtleSides = static_cast<int>(v.num);
      } else if (key == "angle")
        res_.turtleAngle = v.num;
      else if (key == "step")
        res_.turtleStep = v.num;
      else if (key == "width")
        res_.turtleWidth = v.num;
      else
        diags_.error("E029", t.range,
                     "unknown turtle setting '" + key + "' (expected angle, step, width, segments, sides or colors)");
    }
  }
}

}  // namespace fgsg::frontend::sema_detail
