// Semantic analysis (frontend/sema.h): the passes of Analyzer (frontend/sema_analyzer.h)
// and their order; the surface and field declarations are sema_environment.cpp's.
#include "frontend/sema.h"

#include "frontend/builtins.h"
#include "frontend/sema_analyzer.h"
#include "frontend/sema_environment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace fgsg::frontend {

const char* valueTypeName(ValueType t) {
  switch (t) {
    case ValueType::Unknown: return "unknown";
    case ValueType::Num: return "number";
    case ValueType::Bool: return "boolean";
    case ValueType::Str: return "string";
    case ValueType::Vec3: return "vector";
  }
  return "?";
}

bool isShapeItem(const Item& item, const SemaResult& sema) {
  if (item.kind != ItemKind::Call) return false;
  if (!findCommand(item.name)) return true;
  int s = sema.findSymbol(item.name);
  return s >= 0 && !sema.symbols[s].rules.empty();
}

namespace sema_detail {

// Each pass reads what the earlier ones left in res_: constants before anything that
// evaluates expressions, symbols and their arity before parameter types, parameter types
// before the rules are checked, the start symbol before reachability.
bool Analyzer::run() {
  collectValues();
  collectEnvironment();
  collectCollision();
  collectSymbols();
  inferParameterTypes();
  checkRules();
  checkStart();
  checkReachability();
  return !diags_.hasErrors();
}


namespace {

constexpr int kMaxParallelSteps = 2147483647;  // INT32_MAX: ir::Module::steps is an int

}  // namespace

void Analyzer::collectValues() {
  std::set<std::string> seen;
  for (const auto& v : prog_.values) {
    if (!seen.insert(v.name).second) {
      diags_.error("E022", v.range, "'" + v.name + "' is declared twice");
      continue;
    }
    ConstValue value;
    if (!evalConst(*v.value, value)) {
      // Its uses are not reported again as unknown names (E010): this is the one error.
      failedValues_.insert(v.name);
      if (const Expr* zero = zeroDivisor(*v.value)) {
        diags_.error("E027", zero->range, "division by zero");
        continue;
      }
      diags_.error("E023", v.value->range,
                   std::string(v.isAttr ? "the default of attr '" : "const '") + v.name +
                       "' must be a constant expression (numbers, strings, earlier "
                       "constants and math functions)");
      continue;
    }
    if (v.isAttr)
      res_.attrs.push_back({v.name, value, v.range});
    else
      res_.constants[v.name] = value;
  }
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
  checkSurfaceAndFields(prog_, res_, diags_,
                        [this](const Expr& e, ConstValue& v) { return evalConst(e, v); });
  for (const auto& d : prog_.derives) {
    if (d.mode == "parallel") {
      ConstValue steps;
      if (d.steps && !evalConst(*d.steps, steps)) {
        if (const Expr* zero = zeroDivisor(*d.steps)) {
          diags_.error("E027", zero->range, "division by zero");
          continue;
        }
      }
      // The step count is an int in the IR: larger values are refused, not wrapped.
      if (!d.steps || !evalConst(*d.steps, steps) || steps.type != ValueType::Num ||
          !(steps.num >= 0) || steps.num > kMaxParallelSteps || steps.num != std::floor(steps.num)) {
        diags_.error("E029", d.steps ? d.steps->range : d.range,
                     "`derive parallel N;` needs a constant whole number of steps N from 0 to " +
                         std::to_string(kMaxParallelSteps) +
                         (d.steps && evalConst(*d.steps, steps) && steps.type == ValueType::Num
                              ? ", got " + wholeNumberText(steps.num)
                              : std::string()));
        continue;
      }
      res_.steps = static_cast<int>(steps.num);
    } else if (d.mode != "breadthfirst" && d.mode != "depthfirst") {
      diags_.error("E029", d.range,
                   "unknown derivation mode '" + d.mode +
                       "' (expected parallel N, breadthfirst or depthfirst)");
      continue;
    }
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
      if (!expr || !evalConst(*expr, v) || v.type != ValueType::Num) {
        diags_.error("E029", t.range, "turtle setting '" + key + "' needs a constant number");
        continue;
      }
      if (key == "angle")
        res_.turtleAngle = v.num;
      else if (key == "step")
        res_.turtleStep = v.num;
      else if (key == "width")
        res_.turtleWidth = v.num;
      else
        diags_.error("E029", t.range,
                     "unknown turtle setting '" + key + "' (expected angle, step or width)");
    }
  }
}

namespace {

const char* collisionMetricOf(const std::string& word) {
  if (word == "mesh") return "mesh";
  if (word == "centre" || word == "center") return "centre";
  if (word == "geodesic") return "geodesic";
  return nullptr;
}

}  // namespace

// `collision [all] [mesh | centre R | center R | geodesic R];`, words in any order.
// The radius R is a number or the name of a number const.
void Analyzer::collectCollision() {
  for (size_t i = 0; i < prog_.collisions.size(); ++i) {
    const CollisionDecl& d = prog_.collisions[i];
    if (i == 0) {
      checkCollisionDecl(d);
      continue;
    }
    SourceRange keyword = d.range;
    keyword.end = {keyword.begin.line, keyword.begin.col + 8};  // "collision"
    diags_.error("E032", keyword,
                 "only one `collision` declaration is allowed (the first is on line " +
                     std::to_string(prog_.collisions[0].range.begin.line) +
                     "); write all its settings in one: `collision all centre 0.3;`");
  }
}

// A radius written after `centre` / `geodesic`: a number or a number const.
bool Analyzer::collisionRadius(const CollisionWord& w, double& radius) const {
  if (w.isNumber()) return radius = w.number, true;
  if (w.word == "all" || collisionMetricOf(w.word)) return false;
  auto c = res_.constants.find(w.word);
  if (c == res_.constants.end() || c->second.type != ValueType::Num) return false;
  radius = c->second.num;
  return true;
}

void Analyzer::checkCollisionDecl(const CollisionDecl& d) {
  res_.collisionDeclared = true;
  res_.collisionRange = d.range;
  if (d.words.empty()) {
    diags_.error("E030", d.range,
                 "`collision` needs a setting: all, mesh, centre R or geodesic R (R a positive "
                 "radius), e.g. `collision all centre 0.3;`");
    return;
  }
  const CollisionWord* metric = nullptr;  // the first metric written
  bool all = false;
  for (size_t k = 0; k < d.words.size(); ++k) {
    const CollisionWord& w = d.words[k];
    if (w.isNumber()) {
      const CollisionWord* before = k > 0 ? &d.words[k - 1] : nullptr;
      diags_.error("E031", w.range,
                   std::string("a number in `collision` is the radius after 'centre' or "
                               "'geodesic'") +
                       (before && (before->word == "all" || before->word == "mesh")
                            ? ", and '" + before->word + "' takes none"
                            : std::string()) +
                       ": `collision centre 0.3;`");
      continue;
    }
    if (w.word == "all") {
      if (all) diags_.error("E032", w.range, "'all' is written twice in this `collision` declaration");
      all = true;
      continue;
    }
    const char* kind = collisionMetricOf(w.word);
    if (!kind) {
      diags_.error("E030", w.range,
                   "unknown collision setting '" + w.word +
                       "' (expected all, mesh, centre R, center R or geodesic R)");
      continue;
    }
    if (metric)
      diags_.error("E032", w.range,
                   "two collision metrics, '" + metric->word + "' and '" + w.word +
                       "': choose one (mesh, centre R or geodesic R)");
    double radius = 0.0;
    if (std::string(kind) != "mesh") {
      if (k + 1 >= d.words.size() || !collisionRadius(d.words[k + 1], radius)) {
        diags_.error("E031", w.range,
                     "'" + w.word + "' needs a radius: `collision " + w.word + " 0.3;`");
        continue;
      }
      const CollisionWord& r = d.words[++k];
      if (!(radius > 0) || !std::isfinite(radius)) {
        diags_.error("E031", r.range,
                     "the radius of '" + w.word + "' must be a positive number, got " +
                         formatNumber(radius));
        continue;
      }
    }
    if (metric) continue;
    metric = &w;
    res_.collisionMetric = kind;
    res_.collisionRadius = radius;
  }
  res_.collisionAll = all;
}

SymbolInfo& Analyzer::symbol(const std::string& name, const SourceRange& at) {
  auto it = res_.symbolIndex.find(name);
  if (it != res_.symbolIndex.end()) return res_.symbols[it->second];
  res_.symbolIndex[name] = res_.symbols.size();
  SymbolInfo s;
  s.name = name;
  s.firstUse = at;
  res_.symbols.push_back(s);
  return res_.symbols.back();
}

// Records the arity of a symbol; the first sighting fixes it, later ones must agree.
void Analyzer::useArity(const std::string& name, size_t arity, const SourceRange& at, bool isRuleHead) {
  SymbolInfo& s = symbol(name, at);
  if (!s.arityKnown) {
    s.arityKnown = true;
    s.params.assign(arity, ValueType::Unknown);
    return;
  }
  if (s.params.size() != arity)
    diags_.error("E019", at,
                 "'" + name + "' " + (isRuleHead ? "is declared" : "is used") + " with " +
                     std::to_string(arity) + " parameter" + (arity == 1 ? "" : "s") +
                     " but elsewhere with " + std::to_string(s.params.size()));
}

void Analyzer::collectSymbols() {
  // Rule heads first, so that their arity wins in messages about uses.
  for (size_t i = 0; i < prog_.rules.size(); ++i) {
    const Rule& r = prog_.rules[i];
    useArity(r.predecessor.name, r.predecessor.params.size(), r.predecessor.range, true);
    symbol(r.predecessor.name, r.predecessor.range).rules.push_back(i);
    const bool turtleSymbol = r.predecessor.name == "F" || r.predecessor.name == "f";
    if (findCommand(r.predecessor.name) && !turtleSymbol)
      diags_.warning("W004", r.predecessor.range,
                     "rules for '" + r.predecessor.name +
                         "' make it a shape symbol everywhere in this grammar; the built-in "
                         "command of that name is not available here");
    for (const auto* ctx : {&r.leftContext, &r.rightContext})
      for (const auto& m : *ctx)
        if (m.name != "[" && m.name != "]") useArity(m.name, m.params.size(), m.range, true);
  }
  for (const auto& r : prog_.rules)
    for (const auto& b : r.branches) collectSuccessorSymbols(b.successor);
  for (const auto& a : prog_.axioms) collectSuccessorSymbols(a.successor);
}

void Analyzer::collectSuccessorSymbols(const Successor& s) {
  for (const auto& item : s.items) collectItemSymbols(item);
}

void Analyzer::collectItemSymbols(const Item& item) {
  if (item.kind == ItemKind::Bracket) {
    for (const auto& c : item.children) collectItemSymbols(c);
    return;
  }
  if (isShapeItem(item, res_)) useArity(item.name, item.args.size(), item.range, false);
  for (const auto& b : item.body) collectSuccessorSymbols(b);
}

std::vector<std::pair<std::string, ValueType>> Analyzer::ruleParamList(const Rule& r) const {
  std::vector<std::pair<std::string, ValueType>> out;
  auto add = [&](const ModulePattern& m) {
    int s = res_.findSymbol(m.name);
    for (size_t k = 0; k < m.params.size(); ++k) {
      ValueType t = ValueType::Unknown;
      if (s >= 0 && k < res_.symbols[s].params.size()) t = res_.symbols[s].params[k];
      out.push_back({m.params[k].name, t});
    }
  };
  add(r.predecessor);
  for (const auto& m : r.leftContext)
    if (m.name != "[" && m.name != "]") add(m);
  for (const auto& m : r.rightContext)
    if (m.name != "[" && m.name != "]") add(m);
  return out;
}

// Types flow from the arguments of every place a shape is created into the symbol's
// parameters, until nothing changes; parameters no call site constrains are numbers.
void Analyzer::inferParameterTypes() {
  res_.ruleParams.resize(prog_.rules.size());
  for (int round = 0; round < 64; ++round) {
    bool changed = false;
    for (size_t i = 0; i < prog_.rules.size(); ++i) {
      res_.ruleParams[i] = ruleParamList(prog_.rules[i]);
      for (const auto& b : prog_.rules[i].branches)
        changed |= inferFromSuccessor(b.successor, static_cast<int>(i));
    }
    for (const auto& a : prog_.axioms) changed |= inferFromSuccessor(a.successor, -1);
    if (!changed) break;
  }
  for (auto& s : res_.symbols)
    for (auto& t : s.params)
      if (t == ValueType::Unknown) t = ValueType::Num;
  for (size_t i = 0; i < prog_.rules.size(); ++i) res_.ruleParams[i] = ruleParamList(prog_.rules[i]);
}

bool Analyzer::inferFromSuccessor(const Successor& s, int rule) {
  bool changed = false;
  std::function<void(const Item&)> visit = [&](const Item& item) {
    if (item.kind == ItemKind::Bracket) {
      for (const auto& c : item.children) visit(c);
      return;
    }
    if (isShapeItem(item, res_)) {
      int idx = res_.findSymbol(item.name);
      if (idx >= 0) {
        auto& params = res_.symbols[idx].params;
        for (size_t k = 0; k < item.args.size() && k < params.size(); ++k) {
          if (params[k] != ValueType::Unknown) continue;
          ValueType t = typeOf(*item.args[k], Where{rule, false}, false);
          if (t != ValueType::Unknown) {
            params[k] = t;
            changed = true;
          }
        }
      }
    }
    for (const auto& b : item.body)
      for (const auto& c : b.items) visit(c);
  };
  for (const auto& item : s.items) visit(item);
  return changed;
}

void Analyzer::checkRules() {
  for (size_t i = 0; i < prog_.rules.size(); ++i) {
    const Rule& r = prog_.rules[i];
    Where w{static_cast<int>(i), false};
    std::set<std::string> names;
    for (const auto& [name, type] : res_.ruleParams[i])
      if (!names.insert(name).second)
        diags_.error("E021", r.range, "parameter '" + name + "' is declared twice in this rule");
    if (r.guard) expect(*r.guard, w, ValueType::Bool, "a guard");
    if (!r.leftContext.empty() || !r.rightContext.empty()) {
      if (res_.mode != "parallel")
        diags_.warning("W005", r.predecessor.range,
                       "context < > only matters in a parallel derivation (`derive parallel "
                       "N;`); in a sequential derivation this rule never applies");
    }
    for (const auto& b : r.branches) {
      if (b.probability) {
        expect(*b.probability, w, ValueType::Num, "a probability");
        ConstValue v;
        if (evalConst(*b.probability, v) && v.type == ValueType::Num && v.num < 0)
          diags_.error("E015", b.probability->range, "a probability must not be negative");
      }
      checkSuccessor(b.successor, w);
    }
  }
  for (const auto& a : prog_.axioms) checkSuccessor(a.successor, Where{});
  checkProbabilitySums();
}

// Weights are normalised among the rules whose guards hold; a sum other than 1 over
// unguarded constant weights is legal but worth a word, a zero sum is a mistake.
void Analyzer::checkProbabilitySums() {
  for (const auto& s : res_.symbols) {
    double sum = 0;
    bool allConst = true, anyExplicit = false;
    for (size_t ri : s.rules) {
      const Rule& r = prog_.rules[ri];
      if (r.guard) allConst = false;
      for (const auto& b : r.branches) {
        if (!b.probability) {
          sum += 1;
          continue;
        }
        anyExplicit = true;
        ConstValue v;
        if (evalConst(*b.probability, v) && v.type == ValueType::Num)
          sum += v.num;
        else
          allConst = false;
      }
    }
    if (!allConst || !anyExplicit || s.rules.empty()) continue;
    const Rule& first = prog_.rules[s.rules.front()];
    if (sum <= 0)
      diags_.error("E015", first.range,
                   "the probabilities of the rules for '" + s.name + "' add up to " +
                       formatNumber(sum) + "; at least one must be positive");
    else if (std::abs(sum - 1.0) > 1e-9)
      diags_.warning("W003", first.range,
                     "the probabilities of the rules for '" + s.name + "' add up to " +
                         formatNumber(sum) + "; they are normalised to 1");
  }
}

void Analyzer::checkSuccessor(const Successor& s, const Where& w) {
  for (const auto& item : s.items) checkItem(item, w);
}

void Analyzer::checkItem(const Item& item, const Where& w) {
  switch (item.kind) {
    case ItemKind::Bracket:
      for (const auto& c : item.children) checkItem(c, w);
      return;
    case ItemKind::Turtle:
      if (item.name == "$" || item.name == "%")
        diags_.error("E016", item.range,
                     "turtle symbol '" + item.name + "' (" +
                         (item.name == "$" ? "roll to horizontal" : "cut branch") +
                         ") is not supported yet; use + - & ^ \\ / | ! instead");
      if (item.hasBody) diags_.error("E018", item.range, "a turtle symbol takes no { } body");
      if (item.args.size() > 1)
        diags_.error("E016", item.range,
                     "turtle symbol '" + item.name + "' takes at most one argument");
      for (const auto& a : item.args) expect(*a, w, ValueType::Num, "a turtle argument");
      return;
    case ItemKind::Call: break;
  }
  if (isShapeItem(item, res_)) {
    checkShapeItem(item, w);
    return;
  }
  checkCommand(item, *findCommand(item.name), w);
}

void Analyzer::checkShapeItem(const Item& item, const Where& w) {
  int idx = res_.findSymbol(item.name);
  if (item.hasBody)
    diags_.error("E018", item.range,
                 "'" + item.name + "' is a shape symbol, not a command: it takes no { } body");
  if (idx < 0) return;
  const auto& params = res_.symbols[idx].params;
  for (size_t k = 0; k < item.args.size(); ++k) {
    ValueType t = typeOf(*item.args[k], w, true);
    if (k < params.size() && t != ValueType::Unknown && t != params[k])
      diags_.error("E020", item.args[k]->range,
                   "argument " + std::to_string(k + 1) + " of '" + item.name + "' is a " +
                       valueTypeName(t) + " here but a " + valueTypeName(params[k]) +
                       " elsewhere");
  }
}

namespace {

int axisMask(const std::string& axes) {
  int mask = 0;
  for (char c : axes) {
    int bit = (c == 'X' || c == 'x') ? 1 : (c == 'Y' || c == 'y') ? 2 : (c == 'Z' || c == 'z') ? 4 : -1;
    if (bit < 0 || (mask & bit)) return -1;
    mask |= bit;
  }
  return mask;
}

}  // namespace

void Analyzer::checkCommand(const Item& item, const CommandInfo& cmd, const Where& w) {
  const int n = static_cast<int>(item.args.size());
  if (n < cmd.minArgs || (cmd.maxArgs >= 0 && n > cmd.maxArgs)) {
    diags_.error("E016", item.range,
                 "'" + item.name + "' takes " +
                     (cmd.minArgs == cmd.maxArgs ? std::to_string(cmd.minArgs)
                      : cmd.maxArgs < 0 ? "at least " + std::to_string(cmd.minArgs)
                                        : std::to_string(cmd.minArgs) + " to " +
                                              std::to_string(cmd.maxArgs)) +
                     " argument" + (cmd.maxArgs == 1 ? "" : "s") + ", got " +
                     std::to_string(n) + ": " + cmd.signature);
    return;
  }
  checkBody(item, cmd);
  auto stringArg = [&](size_t k, const char* what) -> std::string {
    ConstValue v;
    if (!evalConst(*item.args[k], v) || v.type != ValueType::Str) {
      diags_.error("E017", item.args[k]->range,
                   std::string("the ") + what + " of '" + item.name + "' must be a constant string: " +
                       cmd.signature);
      return {};
    }
    res_.exprTypes[item.args[k].get()] = ValueType::Str;
    return v.str;
  };
  auto numArgs = [&](size_t from, bool sizes) {
    for (size_t k = from; k < item.args.size(); ++k)
      expect(*item.args[k], Where{w.rule, sizes}, ValueType::Num, "this argument");
  };
  switch (cmd.id) {
    case CommandId::Scale: numArgs(0, true); break;
    case CommandId::Instance:
    case CommandId::InstanceCollide: stringArg(0, "asset"); break;
    case CommandId::InstanceMerge:
      stringArg(0, "asset");
      numArgs(1, false);
      break;
    case CommandId::Subdiv: {
      std::string axis = stringArg(0, "axis");
      int mask = axisMask(axis);
      if (!axis.empty() && (mask != 1 && mask != 2 && mask != 4))
        diags_.error("E028", item.args[0]->range,
                     "Subdiv splits along one axis: \"X\", \"Y\" or \"Z\", not \"" + axis + "\"");
      numArgs(1, true);
      break;
    }
    case CommandId::Repeat: {
      std::string axes = stringArg(0, "axes");
      int mask = axisMask(axes);
      if (!axes.empty() && mask <= 0)
        diags_.error("E028", item.args[0]->range,
                     "Repeat axes must be letters X, Y, Z each at most once, not \"" + axes + "\"");
      else if (!axes.empty() && static_cast<int>(axes.size()) != n - 1)
        diags_.error("E016", item.range,
                     "Repeat(\"" + axes + "\", ...) needs one size per axis: " +
                         std::to_string(axes.size()) + " expected, got " + std::to_string(n - 1));
      numArgs(1, false);
      break;
    }
    case CommandId::Comp: {
      static const std::set<std::string> kSelectors = {
          "faces", "sidefaces", "top", "bottom", "front", "back", "left", "right",
          "edges", "sideedges", "topedges", "bottomedges"};
      std::string sel = stringArg(0, "selector");
      if (!sel.empty() && !kSelectors.count(sel))
        diags_.error("E028", item.args[0]->range,
                     "unknown component selector \"" + sel +
                         "\" (faces, sidefaces, top, bottom, front, back, left, right, edges, "
                         "sideedges, topedges, bottomedges)");
      break;
    }
    case CommandId::Roof: {
      std::string kind = stringArg(0, "roof kind");
      if (!kind.empty() && kind != "hipped" && kind != "gable" && kind != "pyramid")
        diags_.error("E028", item.args[0]->range,
                     "unknown roof kind \"" + kind + "\" (hipped, gable or pyramid)");
      numArgs(1, false);
      break;
    }
    case CommandId::Marching:
      expect(*item.args[0], w, ValueType::Num, "the marching length");
      expect(*item.args[1], w, ValueType::Num, "the marching angle");
      expect(*item.args[2], w, ValueType::Bool, "the marching condition");
      break;
    case CommandId::Synthesize:
      stringArg(0, "example file");
      numArgs(1, false);
      break;
    case CommandId::Line:
      if (n > 0) expect(*item.args[0], w, ValueType::Num, "the width of 'Line'");
      if (n > 1) expect(*item.args[1], w, ValueType::Bool, "the merge flag of 'Line'");
      break;
    case CommandId::LineSeg:
      if (n > 0) expect(*item.args[0], w, ValueType::Num, "the length of 'LineSeg'");
      break;
    case CommandId::Evolve:
    case CommandId::Cells:
      for (const auto& a : item.args) typeOf(*a, w, true);
      break;
    default: numArgs(0, false); break;
  }
  for (const auto& b : item.body) checkSuccessor(b, w);
}

void Analyzer::checkBody(const Item& item, const CommandInfo& cmd) {
  const size_t parts = item.body.size();
  switch (cmd.body) {
    case BodyRule::None:
      if (item.hasBody)
        diags_.error("E018", item.range, "'" + item.name + "' takes no { } body: " + cmd.signature);
      break;
    case BodyRule::PerSize:
      if (!item.hasBody)
        diags_.error("E018", item.range, "'" + item.name + "' needs a { } body: " + cmd.signature);
      else if (parts != item.args.size() - 1)
        diags_.error("E018", item.range,
                     "'" + item.name + "' has " + std::to_string(item.args.size() - 1) +
                         " size" + (item.args.size() == 2 ? "" : "s") + " but " +
                         std::to_string(parts) + " body part" + (parts == 1 ? "" : "s") +
                         "; write one part per size, separated by '|'");
      break;
    case BodyRule::One:
      if (!item.hasBody || parts != 1)
        diags_.error("E018", item.range,
                     "'" + item.name + "' needs exactly one { } body part: " + cmd.signature);
      break;
    case BodyRule::AtLeastOne:
      if (!item.hasBody || parts == 0)
        diags_.error("E018", item.range, "'" + item.name + "' needs a { } body: " + cmd.signature);
      break;
    case BodyRule::Optional: break;
  }
}

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
        ValueType t = typeOf(*a, Where{w.rule, false}, report);
        if (report && t != ValueType::Num && t != ValueType::Unknown)
          diags_.error("E013", a->range, "a vector's components must be numbers");
      }
      if (e.args.size() != 3 && report)
        diags_.error("E013", e.range, "a vector literal has exactly three components");
      return record(e, ValueType::Vec3, report);
    }
    case ExprKind::Ident: return typeOfIdent(e, w, report);
    case ExprKind::Unary: {
      ValueType t = typeOf(*e.args[0], Where{w.rule, false}, report);
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
      Where inner{w.rule, false};
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
  if (w.rule >= 0) {
    const auto& params = res_.ruleParams[w.rule];
    for (size_t k = 0; k < params.size(); ++k)
      if (params[k].first == e.text) {
        if (report) res_.names[&e] = NameRef{NameRef::Param, k, {}};
        return record(e, params[k].second, report);
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
                                  : " (not a const or an attr)"));
  return ValueType::Unknown;
}

ValueType Analyzer::typeOfBinary(const Expr& e, const Where& w, bool report) {
  Where inner{w.rule, false};
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
  Where inner{w.rule, false};
  std::vector<ValueType> args;
  for (const auto& a : e.args) args.push_back(typeOf(*a, inner, report));
  if (!f) {
    if (report)
      diags_.error("E011", e.range,
                   "unknown function '" + e.text +
                       "' (math: sin cos tan asin acos atan atan2 sqrt abs min max floor ceil "
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

ValueType Analyzer::typeOfMember(const Expr& e, const Where& w, bool report) {
  Where inner{w.rule, false};
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
    if ((e.text == "depth" || e.text == "index") && !e.hasCall)
      return record(e, ValueType::Num, report);
    if (e.text == "visible" && e.hasCall && e.args.size() == 1)
      return record(e, ValueType::Bool, report);
    return fail("unknown shape query 'Shape." + e.text +
                "' (Shape.depth, Shape.index, Shape.visible(\"street\"))");
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
      return record(e, vec ? ValueType::Vec3 : ValueType::Num, report);
    }
  return fail("'" + e.object + "' is not a field, a texture context, Scope or Shape");
}

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

void Analyzer::checkStart() {
  if (prog_.axioms.size() > 1)
    diags_.error("E024", prog_.axioms[1].range, "only one axiom may be declared");
  if (!prog_.axioms.empty()) return;
  for (const char* name : {"Axiom", "axiom", "start", "Start", "Lot", "footprint"}) {
    int s = res_.findSymbol(name);
    if (s >= 0 && !res_.symbols[s].rules.empty()) {
      if (!res_.symbols[s].params.empty()) {
        diags_.error("E024", res_.symbols[s].firstUse,
                     std::string("the start symbol '") + name +
                         "' must not take parameters; declare `axiom: " + name + "(...);`");
        return;
      }
      res_.startSymbol = name;
      return;
    }
  }
  if (prog_.rules.empty()) {
    diags_.error("E024", SourceRange{{1, 1}, {1, 1}}, "the grammar has no rules and no axiom");
    return;
  }
  const Rule& first = prog_.rules.front();
  if (!first.predecessor.params.empty()) {
    diags_.error("E024", first.predecessor.range,
                 "no start: declare `axiom: ...;` or write a rule for Axiom or start (the first "
                 "rule's predecessor takes parameters, so it cannot start the derivation)");
    return;
  }
  res_.startSymbol = first.predecessor.name;
}

void Analyzer::checkReachability() {
  std::vector<size_t> work;
  auto mark = [&](const std::string& name) {
    int s = res_.findSymbol(name);
    if (s >= 0 && !res_.symbols[s].reachable) {
      res_.symbols[s].reachable = true;
      work.push_back(static_cast<size_t>(s));
    }
  };
  bool synthesizes = false;  // pieces of a synthesized model may be any symbol
  std::function<void(const Item&)> visit = [&](const Item& item) {
    if (item.kind == ItemKind::Bracket)
      for (const auto& c : item.children) visit(c);
    if (item.kind == ItemKind::Call && item.name == "Synthesize" && !isShapeItem(item, res_))
      synthesizes = true;
    if (item.kind == ItemKind::Call && isShapeItem(item, res_)) mark(item.name);
    for (const auto& b : item.body)
      for (const auto& c : b.items) visit(c);
  };
  if (!res_.startSymbol.empty()) mark(res_.startSymbol);
  for (const auto& a : prog_.axioms)
    for (const auto& item : a.successor.items) visit(item);
  while (!work.empty()) {
    size_t s = work.back();
    work.pop_back();
    for (size_t ri : res_.symbols[s].rules)
      for (const auto& b : prog_.rules[ri].branches)
        for (const auto& item : b.successor.items) visit(item);
  }
  for (const auto& s : res_.symbols) {
    if (!s.reachable && !s.rules.empty() && !(synthesizes && s.params.empty()))
      diags_.warning("W002", prog_.rules[s.rules.front()].predecessor.range,
                     "the rules for '" + s.name + "' can never apply: no derivation from the "
                     "start creates a '" + s.name + "'");
    else if (s.reachable && s.rules.empty() && !findCommand(s.name))
      diags_.warning("W001", s.firstUse,
                     "'" + s.name + "' has no rule: it stays a terminal shape and places no "
                     "geometry");
  }
}

}  // namespace sema_detail

bool analyze(const Program& program, SemaResult& out, Diagnostics& diags) {
  return sema_detail::Analyzer(program, out, diags).run();
}

}  // namespace fgsg::frontend
