// Where the derivation starts and what it can reach: the axiom or the start symbol
// (E024), then the warnings about rules that can never apply (W002) and shapes that have
// no rule (W001; not in a CGA grammar, where such a leaf outputs its own geometry).

#include "frontend/sema_analyzer.h"
#include "frontend/query_modules.h"

#include "frontend/builtins.h"
#include "frontend/did_you_mean.h"

#include <algorithm>
#include <cctype>
#include <functional>
#include <vector>

namespace fgsg::frontend::sema_detail {

namespace {

// ABOP's strings of one-letter and digit modules written together (Fig. 1.31's F1F1F1):
// two or more letter-and-digits groups.
bool looksLikeGluedDigitModules(const std::string& name) {
  size_t groups = 0, i = 0;
  while (i < name.size()) {
    if (!std::isalpha(static_cast<unsigned char>(name[i++]))) return false;
    const size_t digits = i;
    while (i < name.size() && std::isdigit(static_cast<unsigned char>(name[i]))) ++i;
    if (i == digits) return false;
    ++groups;
  }
  return groups >= 2;
}

}  // namespace

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

// The operation a rule-less shape used with arguments was meant to be ("Extrud(2)":
// Extrude); "" when none is near. Without arguments it may well be a shape of its own, and
// a name of one or two letters is one edit from too many (B(3) is no slip for T).
static std::string nearOperation(const SymbolInfo& s) {
  if (s.params.empty() || s.name.size() < 3) return "";
  std::vector<std::string> names;
  for (const CommandInfo& c : allCommands()) names.push_back(c.name);
  return closestName(s.name, names);
}

// The name of a symbol with rules one edit away from `name`, if any.
std::string Analyzer::nearName(const std::string& name) const {
  auto lower = [](std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
  };
  // One edit (a letter changed, added or dropped, or two neighbours swapped), or only a
  // change of case.
  for (const auto& other : res_.symbols)
    if (!other.rules.empty() && other.name != name &&
        (editDistance(name, other.name) == 1 || lower(name) == lower(other.name)))
      return other.name;
  return "";
}

void Analyzer::checkReachability() {
  // Flood fill over successors: from `items` and the symbol `start` (-1: none), brackets
  // and bodies opened, each shape symbol met expanded into its rules' successors once;
  // `seen` marks the symbols reached, `onItem` sees every item on the way.
  auto reach = [&](const std::vector<const Item*>& items, int start, std::vector<bool>& seen,
                   const std::function<void(const Item&)>& onItem) {
    std::vector<size_t> work;
    auto mark = [&](int s) {
      if (s >= 0 && !seen[size_t(s)]) seen[size_t(s)] = true, work.push_back(size_t(s));
    };
    std::function<void(const Item&)> visit = [&](const Item& item) {
      onItem(item);
      if (item.kind == ItemKind::Bracket)
        for (const auto& c : item.children) visit(c);
      if (isShapeItem(item, res_)) mark(res_.findSymbol(item.name));
      for (const auto& b : item.body)
        for (const auto& c : b.items) visit(c);
    };
    mark(start);
    for (const Item* item : items) visit(*item);
    while (!work.empty()) {
      const size_t s = work.back();
      work.pop_back();
      for (size_t ri : res_.symbols[s].rules)
        for (const auto& b : prog_.rules[ri].branches)
          for (const auto& item : b.successor.items) visit(item);
    }
  };
  bool synthesizes = false;  // pieces of a synthesized model (or Evolve's cells) may be any symbol
  bool cga = false;          // a CGA grammar: its leaves output their own geometry (no W001)
  std::vector<const Item*> baseParts;  // Cells{ Base | Feature }: what Base creates
  std::vector<const Item*> axiomItems;
  for (const auto& a : prog_.axioms)
    for (const auto& item : a.successor.items) axiomItems.push_back(&item);
  std::vector<bool> reachable(res_.symbols.size(), false);
  reach(axiomItems, res_.startSymbol.empty() ? -1 : res_.findSymbol(res_.startSymbol), reachable,
        [&](const Item& item) {
          if (item.kind != ItemKind::Call || isShapeItem(item, res_)) return;
          if (item.name == "Synthesize" || item.name == "Evolve") synthesizes = true;
          for (const char* name : {"Subdiv", "SplitArea", "Repeat", "Comp", "Extrude", "Roof", "Footprint", "Offset"})
            if (item.name == name) cga = true;
          if (const CommandInfo* c = findCommand(item.name); c && c->id == CommandId::ShapeOperation) cga = true;
          if (item.name == "Cells" && item.body.size() == 2)
            for (const auto& c : item.body[0].items) baseParts.push_back(&c);
        });
  for (size_t si = 0; si < res_.symbols.size(); ++si) res_.symbols[si].reachable = reachable[si];
  // What a start rule of another run reaches (a .cga file's @StartRule when --start-rule
  // names another rule) is used code: no W002 for it.
  std::vector<bool> startable(res_.symbols.size(), false);
  for (const std::string& name : prog_.otherStartRules) reach({}, res_.findSymbol(name), startable, [](const Item&) {});
  // A terminal shape a Cells base part creates is a piece of its base mesh, not a
  // forgotten rule: the symbols reachable from the base parts get no W001.
  std::vector<bool> basePiece(res_.symbols.size(), false);
  reach(baseParts, -1, basePiece, [](const Item&) {});
  for (size_t si = 0; si < res_.symbols.size(); ++si) {
    const auto& s = res_.symbols[si];
    if (!s.reachable && !startable[si] && !s.rules.empty() && !(synthesizes && s.params.empty()) &&
        !prog_.rules[s.rules.front()].imported)  // a module's rules this grammar does not use
      diags_.warning("W002", prog_.rules[s.rules.front()].predecessor.range,
                     "the rules for '" + s.name + "' can never apply: no derivation from the "
                     "start creates a '" + s.name + "'");
    else if (s.reachable && s.rules.empty() && !findCommand(s.name) && !basePiece[si] &&
             !isQueryModuleName(s.name)) {  // a query module holds values; it draws nothing by design
      const std::string op = nearOperation(s);
      std::string opHint = op.empty() ? "" : "; did you mean the operation '" + op + "'?";
      if (op.empty() && res_.mode == "parallel" && looksLikeGluedDigitModules(s.name))
        opHint = "; ABOP writes modules without spaces and with digit names (F1F1F1): fgsg reads '" + s.name +
                 "' as one name; separate the modules with spaces and name digit modules with letters";
      if (op.empty() && res_.mode == "parallel" && s.name == "_")
        opHint = "; L-Py's and lpfg's width symbol '_' is not a turtle command in fgsg: set the width with !(w)";
      if (!(cga && res_.mode != "parallel"))
        diags_.warning("W001", s.firstUse,
                       "'" + s.name + "' has no rule: it stays a terminal shape and places no "
                       "geometry" + opHint);
      else if (!op.empty())
        diags_.warning("W001", s.firstUse, "'" + s.name + "' has no rule: it is a leaf and outputs its own geometry" + opHint);
      else if (const std::string near = s.name.back() == '.' ? "" : nearName(s.name); !near.empty())
        // A CGA leaf is meant to have no rule, unless its name is a slip for one that has.
        // 'X.' is the translator's leaf of rule X (`X.` written, or a rule of operations
        // only, as `Wall --> color("#f00")`): never a slip.
        diags_.warning("W001", s.firstUse,
                       "'" + s.name + "' has no rule: it is a leaf and outputs its own geometry; did you mean '" +
                           near + "'?");
    }
  }
}

}  // namespace fgsg::frontend::sema_detail
