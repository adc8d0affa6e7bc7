// Shape symbols and their parameters: every rule head, context module and shape created
// in a successor becomes a SymbolInfo with a fixed arity (E019, W004); parameter types are
// then inferred from the arguments at the places shapes are created (a fixed point).

#include "frontend/sema_analyzer.h"

#include "frontend/builtins.h"
#include "frontend/cga/cga_parse.h"

#include <cctype>

#include <functional>
#include <set>

namespace fgsg::frontend::sema_detail {

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

// ABOP's #ignore: a name must be a symbol of the grammar, or F, f or a turtle symbol
// (commands, which context matching always steps over); anything else is likely a typo.
// lpfg's #consider (L-Py's consider:) lists the symbols context matching sees: every
// other symbol is ignored. Both in one grammar: a symbol is seen when a #consider lists it
// and no #ignore does.
void Analyzer::collectIgnored() {
  std::set<std::string> ignored, considered;
  bool considerOnly = false;
  for (const auto& d : prog_.ignores) {
    considerOnly = considerOnly || d.consider;
    const char* keyword = d.consider ? "#consider" : "#ignore";
    for (const auto& [name, range] : d.symbols) {
      if (res_.findSymbol(name) >= 0) {
        if (d.consider)
          considered.insert(name);
        else if (ignored.insert(name).second)
          res_.contextIgnored.push_back(name);  // in the order written
        continue;
      }
      const bool turtleSymbol = name.size() == 1 && std::string("+-&^\\/|!$%").find(name[0]) != std::string::npos;
      if (name == "F" || name == "f" || turtleSymbol) {
        if (d.consider)  // lpfg's context would see it; fgsg's never does (a command)
          diags_.warning("W006", range,
                         "'#consider' names '" + name + "', a turtle command without rules: context matching "
                         "steps over commands whatever '#consider' lists");
        continue;
      }
      diags_.warning("W006", range,
                     std::string("'") + keyword + "' names '" + name +
                         "', which is no symbol of this grammar: " +
                         (d.consider ? "no context can see it" : "nothing is ignored for it"));
    }
  }
  if (considerOnly)
    for (const SymbolInfo& s : res_.symbols)
      if (!considered.count(s.name) && !ignored.count(s.name)) res_.contextIgnored.push_back(s.name);
}

void Analyzer::collectSuccessorSymbols(const Successor& s) {
  for (const auto& item : s.items) collectItemSymbols(item);
}

void Analyzer::collectItemSymbols(const Item& item) {
  if (item.kind == ItemKind::Bracket) {
    for (const auto& c : item.children) collectItemSymbols(c);
    return;
  }
  if (isShapeItem(item, res_)) {
    useArity(item.name, item.args.size(), item.range, false);
    checkCityEngineName(item);
  }
  for (const auto& b : item.body) collectSuccessorSymbols(b);
}

void Analyzer::checkCityEngineName(const Item& item) {
  if (item.name.empty() || !std::islower(static_cast<unsigned char>(item.name[0])) ||
      !isCityEngineOperationName(item.name))
    return;
  const int s = res_.findSymbol(item.name);
  if (s >= 0 && !res_.symbols[size_t(s)].rules.empty()) return;  // the grammar's own symbol
  const std::string hint = "; to read the file as CityEngine CGA, name it .cga (docs/cga.md, \"CGA for CityEngine users\")";
  if (!item.args.empty() || item.hasBody)
    diags_.error("E800", item.range,
                 "unknown operation '" + item.name + "': a CityEngine CGA operation, which the fgsg dialect does not have" +
                     hint);
  else
    diags_.warning("W800", item.range,
                   "'" + item.name + "' is a CityEngine CGA operation; here it is a shape without rules, which does nothing" +
                       hint);
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

}  // namespace fgsg::frontend::sema_detail
