// The semantic analyser's one class, shared by the files of frontend/sema: Analyzer holds
// the program, the result being built and the diagnostics, and its member functions live
// in the file named after their concept (sema_declarations.cpp, sema_collision.cpp,
// sema_symbols.cpp, sema_rules.cpp, sema_commands.cpp, sema_expressions.cpp,
// sema_constants.cpp, sema_reachability.cpp); run() in sema.cpp fixes the order of the
// passes. Private to the frontend: only frontend/sema*.cpp include it.
#pragma once

#include "frontend/builtins.h"
#include "frontend/sema.h"

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace fgsg::frontend::sema_detail {

constexpr double kPi = 3.14159265358979323846;

// Where an expression is being checked: inside a rule (its parameters are visible),
// and whether a relative/floating size is allowed at this position; outside rules, the
// names an expression may use besides consts and attrs (a scalar field's x, y, z).
struct Where {
  int rule = -1;
  bool sizeArg = false;
  const std::vector<std::pair<std::string, ValueType>>* bound = nullptr;
  // The same place, for an operand: no sizes.
  Where operand(bool sizes = false) const { return {rule, sizes, bound}; }
};

struct GaSetting;  // a genetic-algorithm setting a tileset may give (sema_tilesets.cpp)

class Analyzer {
 public:
  Analyzer(const Program& p, SemaResult& r, Diagnostics& d) : prog_(p), res_(r), diags_(d) {}

  // The passes in order (sema.cpp); false when errors were reported.
  bool run();

 private:
  // Declarations (sema_declarations.cpp): const/attr values, field and texture names,
  // the surface count, the derivation mode and the turtle settings.
  void collectValues();
  void collectEnvironment();
  bool checkSurfaceExpression(const Expr& e);
  // Tilesets (sema_tilesets.cpp): `tileset NAME { locus ...; section ...; ... }`.
  void collectTilesets();
  bool tileCurve(const TilesetItem& item, TileCurveInfo& out);
  bool gaSettingItem(const TilesetItem& item, const GaSetting& setting, const std::string& tileset,
                     TilesetInfo& out);
  bool facesItem(const TilesetItem& item, const std::string& tileset, TilesetInfo& out);
  bool tilesetDeclared(const std::string& name) const;

  // Collision (sema_collision.cpp): `collision [all] [mesh | centre R | geodesic R];`.
  void collectCollision();
  bool collisionRadius(const CollisionWord& w, double& radius) const;
  void checkCollisionDecl(const CollisionDecl& d);

  // Symbols and parameter types (sema_symbols.cpp).
  SymbolInfo& symbol(const std::string& name, const SourceRange& at);
  void useArity(const std::string& name, size_t arity, const SourceRange& at, bool isRuleHead);
  void collectSymbols();
  void collectIgnored();
  void collectSuccessorSymbols(const Successor& s);
  void collectItemSymbols(const Item& item);
  // A CityEngine operation (`color("#f00")`, `taper(2)`) written in the fgsg dialect, where it
  // would be a shape that does nothing: E800 with arguments, W800 without.
  void checkCityEngineName(const Item& item);
  std::vector<std::pair<std::string, ValueType>> ruleParamList(const Rule& r) const;
  void inferParameterTypes();
  bool inferFromSuccessor(const Successor& s, int rule);

  // Rules: guards, contexts, probabilities, successors and shape items (sema_rules.cpp).
  void checkRules();
  void checkSection(const Rule& r);
  void checkProbabilitySums();
  void checkSuccessor(const Successor& s, const Where& w);
  void checkItem(const Item& item, const Where& w);
  void checkAtModule(const Item& item, const Where& w);
  void checkShapeItem(const Item& item, const Where& w);
  void checkQueryModule(const Item& item);

  // Commands: arity, argument types and constants, { } bodies (sema_commands.cpp).
  void checkCommand(const Item& item, const CommandInfo& cmd, const Where& w);
  void checkBody(const Item& item, const CommandInfo& cmd);
  bool checkSplitSyntax(const Item& item, const CommandInfo& cmd);

  // Expressions and their types; names resolved (sema_expressions.cpp).
  void expect(const Expr& e, const Where& w, ValueType want, const std::string& what);
  ValueType record(const Expr& e, ValueType t, bool report);
  ValueType typeOfLotQuery(const Expr& e, bool report);
  ValueType typeOf(const Expr& e, const Where& w, bool report);
  ValueType typeOfIdent(const Expr& e, const Where& w, bool report);
  ValueType typeOfBinary(const Expr& e, const Where& w, bool report);
  ValueType typeOfCall(const Expr& e, const Where& w, bool report);
  ValueType typeOfMember(const Expr& e, const Where& w, bool report);

  // Constant expressions (sema_constants.cpp).
  const Expr* zeroDivisor(const Expr& e) const;
  bool evalConst(const Expr& e, ConstValue& out) const;
  // An import's attr setting over the importer's attrs (ValueDecl::fromImporter): typed,
  // its default from the attrs' defaults in `out`; false (nothing reported) when it reads
  // more than constants, attrs and math (and, with `random`, random numbers: a CityEngine
  // attr drawn once per start shape).
  bool importerValue(const Expr& e, ConstValue& out, bool random = false);
  void collectComputedAttrs(std::vector<const ValueDecl*> pending);
  static std::string wholeNumberText(double v);
  static std::string formatNumber(double v);

  // The start symbol and reachability (sema_reachability.cpp).
  void checkStart();
  void checkReachability();
  std::string nearName(const std::string& name) const;

  const Program& prog_;
  SemaResult& res_;
  Diagnostics& diags_;
  std::set<std::string> failedValues_;  // consts/attrs whose declaration was an error
};

}  // namespace fgsg::frontend::sema_detail
