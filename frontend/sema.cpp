// Semantic analysis (frontend/sema.h): the order of the passes, and the two public helpers.
// The passes are member functions of Analyzer (frontend/sema_analyzer.h), each in the file
// named after its concept; the surface and field declarations are sema_environment.cpp's.
#include "frontend/sema.h"

#include "frontend/builtins.h"
#include "frontend/sema_analyzer.h"

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
  if (item.kind == ItemKind::Turtle) {  // a turtle symbol with rules (`+ -> -`)
    const int s = sema.findSymbol(item.name);
    return s >= 0 && !sema.symbols[s].rules.empty();
  }
  if (item.kind != ItemKind::Call) return false;
  if (!findCommand(item.name)) return true;
  int s = sema.findSymbol(item.name);
  return s >= 0 && !sema.symbols[s].rules.empty();
}

const std::vector<std::pair<std::string, ValueType>>& surfacePointNames() {
  static const std::vector<std::pair<std::string, ValueType>> kNames = {
      {"x", ValueType::Num}, {"y", ValueType::Num}, {"z", ValueType::Num}};
  return kNames;
}

namespace sema_detail {

// Each pass reads what the earlier ones left in res_: constants before anything that
// evaluates expressions, symbols and their arity before parameter types, parameter types
// before the rules are checked, the start symbol before reachability.
bool Analyzer::run() {
  collectValues();           // sema_declarations.cpp
  collectEnvironment();      // sema_declarations.cpp, sema_environment.cpp
  collectTilesets();         // sema_tilesets.cpp
  collectCollision();        // sema_collision.cpp
  collectSymbols();          // sema_symbols.cpp
  collectIgnored();          // sema_symbols.cpp
  inferParameterTypes();     // sema_symbols.cpp
  checkRules();              // sema_rules.cpp, sema_commands.cpp, sema_expressions.cpp
  checkStart();              // sema_reachability.cpp
  checkReachability();       // sema_reachability.cpp
  return !diags_.hasErrors();
}

}  // namespace sema_detail

bool analyze(const Program& program, SemaResult& out, Diagnostics& diags) {
  return sema_detail::Analyzer(program, out, diags).run();
}

}  // namespace fgsg::frontend
