// The `.cga` dialect's translator: CityEngine CGA parse trees (grammar/Cga.g4) into the
// AST of frontend/ast.h, with CityEngine's meaning. Private to frontend/cga/: one class,
// its parts in one file per concept —
//   cga_to_ast.cpp      declarations, rules, `case` and stochastic choices, the start rule
//   cga_operations.cpp  operations: CityEngine's names and argument forms -> fgsg commands
//   cga_functions.cpp   expressions, built-in functions, user functions (inlined)
//   cga_annotations.cpp @Range, @Enum ... as attr metadata
#pragma once

#include "frontend/ast.h"
#include "frontend/ast_copy.h"
#include "frontend/diagnostics.h"

#include "CgaParser.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace fgsg::frontend::cga {

using P = fgsg_grammar::CgaParser;

SourceRange rangeOf(const antlr4::ParserRuleContext* ctx);
SourceRange rangeOf(const antlr4::Token* token);
ExprPtr makeExpr(ExprKind kind, const SourceRange& at);
ExprPtr number(double v, const SourceRange& at);
ExprPtr binary(const std::string& op, ExprPtr a, ExprPtr b);
ExprPtr unaryNot(ExprPtr a);
// a && b where either may be null (null: true).
ExprPtr conjunction(ExprPtr a, ExprPtr b);
// The text of a string literal token without its quotes, escapes resolved.
std::string stringValue(const std::string& token);

// The symbol a CityEngine rule name becomes: itself, or with a '$' after it where fgsg has
// a command of that name (`Roof`, `Footprint`, `Texture` ...), which would take its place.
// No CGA or fgsg name can hold a '$', and the IR's symbol (what outputs show) drops it
// again: the user's `Roof` (frontend/ast.h: symbolDisplayName).
std::string symbolName(const std::string& name);

// A CityEngine operation this dialect knows the name of (supported or not).
bool isCityEngineOperation(const std::string& name);
// Those names, sorted, each once (an editor's completion).
std::vector<std::string> cityEngineOperations();
// The CityEngine functions this dialect translates, with their argument forms
// (`rand(min, max)`): the ones Translator::call accepts besides the file's own.
std::vector<std::pair<std::string, std::string>> cityEngineFunctions();
// The members of CityEngine's geometry object Translator::call translates (geometry.area() ...).
std::vector<std::string> cityEngineGeometryFunctions();

// A user function (or a const: CityEngine's are functions without parameters).
struct Function {
  std::string name;
  std::vector<std::string> params;
  P::ValueContext* body = nullptr;
  SourceRange range;
};

// What an expression is translated in: the names bound to arguments of an inlined
// function, the rule's parameters, and how `'x` reads (the split's or s()'s axis).
struct Env {
  std::map<std::string, const Expr*> bound;  // function parameter -> argument
  const std::set<std::string>* ruleParams = nullptr;
  // `'x`: -1 not allowed here; 0..2 x times the scope's size along that axis (split, t);
  // 3: fgsg's relative size `xr` (s()); 4: x times the shape's area (splitArea).
  int relativeAxis = -1;
  int relativeIndex = 0;  // t(): the argument's axis
};

class Translator {
 public:
  // `styleFromImporter`: the file is an import read in its importer's style
  // (`Style$`), which it may lack (its own declarations are then the Default style's).
  Translator(Program& program, Diagnostics& diags, const std::string& fileName, std::string startRule,
             bool styleFromImporter = false)
      : program_(program),
        diags_(&diags),
        fileName_(fileName),
        startRuleOverride_(std::move(startRule)),
        styleFromImporter_(styleFromImporter) {}

  void run(P::CgaFileContext* file);

  // ---- expressions (cga_functions.cpp)
  ExprPtr expr(P::ExprContext* ctx, const Env& env);
  ExprPtr primary(P::PrimaryContext* ctx, const Env& env);
  // case / stochastic values become conditional expressions.
  ExprPtr value(P::ValueContext* ctx, const Env& env);
  ExprPtr contextQuery(const std::string& fn, const SourceRange& at, const SourceRange& nameAt,
                       const std::vector<P::ExprContext*>& argCtx, const Env& env);
  ExprPtr call(const std::string& name, const SourceRange& at, const SourceRange& nameAt,
               const std::vector<P::ExprContext*>& args, const Env& env);
  ExprPtr name(const std::string& name, const SourceRange& at, const Env& env);
  ExprPtr initialShapeAttribute(const std::string& member, const SourceRange& at);
  // `texture(wallTexture)`, `i(treeAsset)`: a string attr with a constant default gives that
  // default as the file name (null for anything else).
  ExprPtr pinnedAttrString(const Expr& value, const SourceRange& at);
  void annotatePinnedAttrs();
  // Whether `e` draws random numbers (Rand).
  static bool isRandom(const Expr& e);

  // ---- operations (cga_operations.cpp)
  // Translates ops[from..] into `out` (appending); true when they create shapes. A
  // top-level successor that creates none ends with the shape as a leaf.
  bool operations(const std::vector<P::OperationContext*>& ops, size_t from, Successor& out, const Env& env,
                  bool topLevel);

  // ---- annotations (cga_annotations.cpp)
  std::vector<AttrAnnotation> annotations(const std::vector<P::AnnotationContext*>& list, bool& startRule,
                                          const std::string& declName);

  void error(const std::string& code, const SourceRange& at, const std::string& message) {
    diags_->error(code, at, message);
  }
  void warning(const std::string& code, const SourceRange& at, const std::string& message) {
    diags_->warning(code, at, message);
  }
  // The symbol of `name`'s rule with `arity` parameters: symbolName(name) for its fewest,
  // `Door$/3` for another (symbols must differ; the IR shows it `Door/3`, frontend/ast.h:
  // symbolDisplayName). All overloads' leaves are the written name's (`Door.`): instances
  // are named Door, as in CityEngine. A name without rules: symbolName.
  std::string overloadSymbol(const std::string& name, size_t arity) const;
  // `name`'s parameter counts as a message writes them: "3", "0 or 3", "0, 1 or 3".
  std::string arityList(const std::string& name) const;

  void notSupported(const SourceRange& at, const std::string& what) {
    diags_->error("E801", at, what + " (CityEngine CGA; not supported yet)");
  }

 private:
  struct RuleHead {
    std::string name;
    std::vector<ParamDecl> params;
    SourceRange range;
    std::set<std::string> paramNames;
  };

  // cga_to_ast.cpp
  void collect(P::CgaFileContext* file);
  void declaration(P::AnnotatedContext* ctx);
  void rule(P::RuleDeclContext* ctx);
  void ruleBody(P::RuleBodyContext* body, const RuleHead& head, ExprPtr guard);
  void caseChain(P::CaseBodyContext* body, size_t from, const RuleHead& head, ExprPtr guard);
  Successor successorFor(P::RuleBodyContext* body, const RuleHead& head);
  Rule newRule(const RuleHead& head, ExprPtr guard);
  RuleHead auxHead(const RuleHead& head);
  Successor emitOf(const RuleHead& head, const SourceRange& at);
  void startRule();
  void importDecl(P::ImportDeclContext* ctx);
  void importSetting(P::FunctionDeclContext* ctx);
  void exportFunctions();

  // cga_styles.cpp
  void readStyles(P::CgaFileContext* file);
  // Whether a declaration is translated in the chosen style (not another style's, not
  // redefined by a nearer style).
  bool keeps(P::AnnotatedContext* ctx) const;
  P::ValueContext* styledAttrValue(P::AttrDeclContext* ctx) const;

  // cga_operations.cpp
  struct Sequence;
  void operation(P::OperationContext* op, Sequence& seq, const Env& env);
  void callOperation(P::CallOperationContext* op, Sequence& seq, const Env& env);
  void split(P::CallOperationContext* op, const std::string& axis, Sequence& seq, const Env& env);
  void splitBody(P::SplitBodyContext* body, const std::string& axis, Item& item, const Env& env);
  void comp(P::CallOperationContext* op, Sequence& seq, const Env& env);
  void compEdgesOrVertices(P::CallOperationContext* op, const std::string& kind, Sequence& seq, const Env& env);
  bool offsetComp(const std::vector<P::OperationContext*>& ops, size_t next, Item& offset, const Env& env);
  void insert(P::CallOperationContext* op, Sequence& seq, const Env& env);
  void materialItem(P::CallOperationContext* op, const std::string& property, const Env& env, Sequence& seq);
  void uvOperation(P::CallOperationContext* op, const Env& env, Sequence& seq);
  // cga_shape_operations.cpp: true when the call is one of issue #44's footprint-shaping or
  // scope operations; `item` is then its command (empty after an error).
  bool shapeOperation(P::CallOperationContext* op, const Env& env, std::optional<Item>& item);
  bool envelopePerEdge(P::CallOperationContext* op, const Env& env, std::optional<Item>& item);
  // cga_scatter.cpp: scatter(domain, n, distribution[, mean, stddev]) { operations } as
  // fgsg's Scatter command with the operations as its body (empty after an error).
  std::optional<Item> scatter(P::CallOperationContext* op, const Env& env);
  // warnMissing false: a file not found gives no W801 (insertAlongUV's R003 says it).
  bool assetPath(std::string& path, const SourceRange& at, const char* what, bool warnMissing = true);
  std::string selectorWord(P::ExprContext* e) const;
  Item command(const std::string& fgsgName, const SourceRange& at);

 public:
  // The rule whose successor is being translated: implicit leaves are named after it.
  std::string currentRule_;
  const std::set<std::string>* currentParams_ = nullptr;

 private:
  friend struct SequenceAccess;
  Program& program_;
  Diagnostics* diags_;  // exportFunctions() points it at a quiet list for a while
  std::string fileName_;
  std::string startRuleOverride_;
  std::map<std::string, Function> functions_;
  std::set<std::string> attrs_;
  std::map<std::string, P::AttrDeclContext*> attrDecls_;
  // String attrs whose default this file's texture() or i() takes as its file name, with
  // the first such use (ir::kPinnedAttrAnnotation: setting them is a run-time error).
  std::map<std::string, SourceRange> pinnedAttrs_;
  // rule name -> its rules' parameter counts: CityEngine's `Door` and `Door(w, h, d)` are
  // two rules (overloads), each its own symbol (overloadSymbol).
  std::map<std::string, std::set<size_t>> rules_;
  std::map<std::pair<std::string, size_t>, SourceRange> ruleDecls_;  // each overload's first rule
  std::set<std::string> importAliases_;
  std::vector<std::string> inlining_;  // functions being inlined (recursion check)
  std::string startRule_;              // @StartRule
  std::string declaredStartRule_;      // the first @StartRule, known from collect() on
  struct Style {
    std::string base;  // "Default" when it extends no other
    SourceRange range;
    SourceRange baseRange;
  };
  std::map<std::string, Style> styles_;  // all but Default
  std::string chosenStyle_ = "Default";  // `--start-rule Style$Rule`'s
  bool styleFromImporter_ = false;
  std::vector<std::string> chain_;                          // the chosen style, its base ... Default
  std::map<P::AnnotatedContext*, std::string> owner_;       // declaration -> its style
  std::set<P::AnnotatedContext*> kept_;                     // those translated (keeps)
  std::map<std::string, P::AttrDeclContext*> attrValueFromStyle_;  // Default attr -> nearer value
  SourceRange startRange_;
  int auxCount_ = 0;
  std::set<std::string> warnedAssets_;
};

}  // namespace fgsg::frontend::cga
