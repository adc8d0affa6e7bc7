// Builds the AST (frontend/ast.h) from ANTLR parse-tree contexts, one typed function per
// grammar rule. Private to the front end: parse.cpp feeds it one statement at a time.
#pragma once

#include "frontend/ast.h"
#include "frontend/diagnostics.h"

#include "FgsgParser.h"

namespace fgsg::frontend {

class AstBuilder {
 public:
  AstBuilder(Program& program, Diagnostics& diags) : program_(program), diags_(diags) {}

  void addStatement(fgsg_grammar::FgsgParser::StatementContext* ctx);
  // The lpfg / L-Py section (`decomposition:` ...) the next statement's rule belongs to.
  void setSection(RuleSection section) { section_ = section; }
  // The `priority N:` in force for the next rule (part of what its AST depends on).
  int priority() const { return priority_; }

 private:
  using P = fgsg_grammar::FgsgParser;

  // declarations
  ImportDecl buildImportDecl(P::ImportDeclContext* ctx);
  ValueDecl buildValueDecl(P::ValueDeclContext* ctx);
  SurfaceDecl buildSurfaceDecl(P::SurfaceDeclContext* ctx);
  FieldDecl buildFieldDecl(P::FieldDeclContext* ctx);
  FieldDesignItem buildFieldDesignItem(P::FieldDesignItemContext* ctx);
  ExprPtr buildDesignValue(P::DesignValueContext* ctx);
  TextureDecl buildTextureDecl(P::TextureDeclContext* ctx);
  TilesetDecl buildTilesetDecl(P::TilesetDeclContext* ctx);
  DeriveDecl buildDeriveDecl(P::DeriveDeclContext* ctx);
  TurtleDecl buildTurtleDecl(P::TurtleDeclContext* ctx);
  bool appendNameThenPolygon(P::CallItemContext* ctx, std::vector<Item>& out);
  IgnoreDecl buildIgnoreDecl(P::IgnoreDeclContext* ctx);
  CollisionDecl buildCollisionDecl(P::CollisionDeclContext* ctx);
  AxiomDecl buildAxiomDecl(P::AxiomDeclContext* ctx);
  void applyPriorityDecl(P::PriorityDeclContext* ctx);

  // rules
  Rule buildRule(P::GrammarRuleContext* ctx);
  ModulePattern buildModulePattern(P::ModulePatternContext* ctx);
  ModulePattern buildContextModule(P::ContextModuleContext* ctx);
  Branch buildBranch(P::BranchContext* ctx);

  // successors
  Successor buildSuccessor(P::SuccessorContext* ctx);
  Successor buildBodyPart(P::BodyPartContext* ctx);
  void sizesFromParts(Item& item);
  void edgeIndexesFromParts(Item& item);
  void cornersAsPairs(Item& item);
  void appendSequenceItem(P::SequenceItemContext* ctx, std::vector<Item>& out);
  void appendItem(P::ItemContext* ctx, std::vector<Item>& out);
  Item buildCallItem(P::CallItemContext* ctx);
  void appendTurtleSymbols(antlr4::ParserRuleContext* ctx, antlr4::Token* symbol,
                           P::CallArgsContext* args, std::vector<Item>& out);
  Item buildBracketItem(P::BracketItemContext* ctx);
  Item buildSurfaceItem(P::SurfaceItemContext* ctx);
  std::vector<ExprPtr> buildCallArgs(P::CallArgsContext* ctx);

  // expressions
  ExprPtr buildExpr(P::ExprContext* ctx);
  ExprPtr buildUnary(P::UnaryExprContext* ctx);
  ExprPtr buildBinary(P::BinaryExprContext* ctx);
  ExprPtr buildTernary(P::TernaryExprContext* ctx);
  ExprPtr buildPrimary(P::PrimaryContext* ctx);
  ExprPtr buildNumber(P::NumberContext* ctx);
  // The value of a number literal (`2.5`, `1e3`, `0.5r`); one beyond the largest double
  // is E002 at `at` (not a silent 0 or infinity).
  double literalNumber(const std::string& text, const SourceRange& at);
  ExprPtr buildMember(P::MemberPrimaryContext* ctx);
  ExprPtr buildVector(P::VectorPrimaryContext* ctx);

  class DepthGuard;

  Program& program_;
  Diagnostics& diags_;
  int priority_ = 0;             // from the last `priority N:`
  RuleSection section_ = RuleSection::Production;
  int exprDepth_ = 0;            // guards the recursion against absurdly deep expressions
  bool depthReported_ = false;   // one "too deep" error per statement
};

}  // namespace fgsg::frontend
