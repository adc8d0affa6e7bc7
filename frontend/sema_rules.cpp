// Checking rules: parameters declared twice, guards, contexts outside a parallel
// derivation, probabilities (each and their sums per symbol), and the items of successors
// and axioms: turtle symbols, shape items against their symbol's parameter types, and
// commands (handed to sema_commands.cpp).

#include "frontend/sema_analyzer.h"

#include "frontend/builtins.h"
#include "frontend/query_modules.h"

#include <cmath>
#include <cstring>
#include <set>

namespace fgsg::frontend::sema_detail {

void Analyzer::checkRules() {
  for (size_t i = 0; i < prog_.rules.size(); ++i) {
    const Rule& r = prog_.rules[i];
    Where w{static_cast<int>(i), false};
    std::set<std::string> names;
    for (const auto& [name, type] : res_.ruleParams[i])
      if (!names.insert(name).second)
        diags_.error("E021", r.range, "parameter '" + name + "' is declared twice in this rule");
    if (r.guard) expect(*r.guard, w, ValueType::Bool, "a guard");
    checkSection(r);
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
  // Per section: a symbol's productions compete with each other, its homomorphisms too.
  for (RuleSection section : {RuleSection::Production, RuleSection::Decomposition, RuleSection::Homomorphism}) {
    for (const auto& whole : res_.symbols) {
      SymbolInfo s = whole;
      s.rules.clear();
      for (size_t ri : whole.rules)
        if (prog_.rules[ri].section == section) s.rules.push_back(ri);
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
      if (isShapeItem(item, res_)) {  // rewritten by its rules, drawn after the last step
        checkShapeItem(item, w);
        return;
      }
      if ((item.name == "$" || item.name == "%" || item.name == "{" || item.name == "." || item.name == "}") &&
          !item.args.empty())
        diags_.error("E016", item.range, "turtle symbol '" + item.name + "' takes no argument");
      if (item.hasBody) diags_.error("E018", item.range, "a turtle symbol takes no { } body");
      if (item.name[0] == '@') {  // lpfg's and L-Py's @ modules (frontend/lex.cpp)
        checkAtModule(item, w);
        return;
      }
      if (item.name == "~" && (item.args.size() == 2 || item.args.size() > 3))
        diags_.error("E016", item.range,
                     "a predefined surface '~' takes one size, three sizes (x, y, z) or none (1)");
      else if (item.name != "~" && item.args.size() > 1)
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
  if (isQueryModuleName(item.name)) checkQueryModule(item);
  if (item.name == "SetContour" && res_.mode == "parallel")  // L-Py's, with a PlantGL curve
    diags_.error("E048", item.range,
                 "L-Py's SetContour(curve) is not supported: fgsg's generalized cylinders (@Gs, @Gc, @Ge) "
                 "sweep a circle of `turtle sides` sides (docs/language.md, the turtle)");
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

// lpfg's decomposition and homomorphism rules (L-Py's interpretation rules) run between
// the steps of an L-system and context-free, as L-Py runs its interpretation rules.
void Analyzer::checkSection(const Rule& r) {
  if (r.section == RuleSection::Production) return;
  const std::string what = r.section == RuleSection::Decomposition ? "a decomposition rule" : "a homomorphism rule";
  if (res_.mode != "parallel")
    diags_.error("E048", r.predecessor.range,
                 what + " needs an L-system (`derive parallel N;`): decomposition and homomorphism run "
                        "between and after the steps of a parallel derivation");
  else if (!r.leftContext.empty() || !r.rightContext.empty())
    diags_.error("E048", (r.leftContext.empty() ? r.rightContext : r.leftContext).front().range,
                 what + " has no context in fgsg (L-Py's interpretation rules neither): write the context in a "
                        "production");
}

// A query module ?P ?H ?U ?L (frontend/query_modules.h) is filled between the steps of
// an L-system with two or three of the turtle's coordinates. fgsg fills it from the
// derived string, so a homomorphism, which only the last drawing reads, would give
// values the drawing does not show: E048 rather than a silent difference from lpfg.
// The environmental query ?E is filled with the grammar's first field where the turtle
// stands: it needs one (E066), and takes one argument for a scalar field (its value), two
// or three for the others (their vector's x, y[, z]).
void Analyzer::checkQueryModule(const Item& item) {
  const size_t n = item.args.size();
  if (item.name == "?E" && prog_.fields.empty()) {
    diags_.error("E066", item.range,
                 "the environmental query '?E' reads the grammar's first field where the turtle stands, and "
                 "this grammar declares no field: declare a surface and a field, e.g. `surface plane(10, 10);` "
                 "`field F = design vector { regular at (0, 0, 0) direction (1, 0, 0); };`");
  } else if (item.name == "?E" && prog_.fields.front().function == "scalar") {
    if (n != 1)
      diags_.error("E016", item.range,
                   "'?E' reads the grammar's first field, the scalar field '" + prog_.fields.front().name +
                       "': it takes 1 argument (its value), got " + std::to_string(n));
  } else if (item.name == "?E") {
    if (n < 2 || n > 3)
      diags_.error("E016", item.range,
                   "'?E' reads the grammar's first field, '" + prog_.fields.front().name +
                       "': it takes 2 or 3 arguments (x, y[, z] of the field's vector), got " + std::to_string(n));
  } else if (n < 2 || n > 3) {
    diags_.error("E016", item.range,
                 "the query module '" + item.name + "' takes 2 or 3 arguments (x, y[, z]), got " +
                     std::to_string(n));
  }
  if (res_.mode != "parallel") {
    diags_.error("E048", item.range,
                 "the query module '" + item.name + "' needs an L-system (`derive parallel N;`): it is filled by "
                 "the turtle between the steps of a parallel derivation");
    return;
  }
  for (const Rule& r : prog_.rules)
    if (r.section == RuleSection::Homomorphism) {
      diags_.error("E048", item.range,
                   "the query module '" + item.name + "' in a grammar with a 'homomorphism:' section is not "
                   "supported yet: fgsg fills query modules from the derived string, without the homomorphism");
      return;
    }
}

// lpfg's and L-Py's turtle modules written with '@': those fgsg runs take their
// arguments as numbers; the others are a located E048, never silently dropped.
void Analyzer::checkAtModule(const Item& item, const Where& w) {
  struct AtModule {
    const char* name;
    size_t minArgs, maxArgs;
    const char* usage;
  };
  static const AtModule kSupported[] = {
      {"@Tp", 3, 3, "@Tp(x, y, z): the tropism vector"},
      {"@Ts", 1, 1, "@Ts(e): the elasticity"},
      {"@O", 0, 1, "@O(r): a sphere of radius r (default half the width)"},
      {"@o", 0, 1, "@o(r): a circle of radius r across the heading (default half the width)"},
      {"@M", 3, 3, "@M(x, y, z): move to the point"},
      {"@R", 6, 6, "@R(hx, hy, hz, ux, uy, uz): set the heading and up vectors"},
      {"@Gs", 0, 0, "@Gs: start a generalized cylinder"},
      {"@Gc", 0, 1, "@Gc(n): a control point of the generalized cylinder, n strips from the last"},
      {"@Ge", 0, 1, "@Ge(n): end the generalized cylinder, n strips from the last control point"},
  };
  for (const AtModule& m : kSupported) {
    if (item.name != m.name) continue;
    if (item.args.size() < m.minArgs || item.args.size() > m.maxArgs)
      diags_.error("E016", item.range,
                   "'" + item.name + "' takes " + (m.minArgs == m.maxArgs ? "" : "at most ") +
                       std::to_string(m.maxArgs) + " argument" + (m.maxArgs == 1 ? "" : "s") + ", got " +
                       std::to_string(item.args.size()) + ": " + m.usage);
    for (const auto& a : item.args) expect(*a, w, ValueType::Num, "a turtle argument");
    return;
  }
  // lpfg writes modules together (`@GsF(2)`); fgsg reads a name to its end.
  std::string together;
  for (const AtModule& m : kSupported)
    if (item.name.size() > std::strlen(m.name) && item.name.compare(0, std::strlen(m.name), m.name) == 0)
      together = "; to write '" + std::string(m.name) + "' and then '" + item.name.substr(std::strlen(m.name)) +
                 "', separate them with a space";
  diags_.error("E048", item.range,
               "the turtle module '" + item.name + "' (lpfg, L-Py) is not supported yet; supported: @Tp, @Ts, "
               "@O, @o, @M, @R, @Gs, @Gc and @Ge (docs/language.md, the turtle)" + together);
}

}  // namespace fgsg::frontend::sema_detail
