
// Generated from grammar/Fgsg.g4 by ANTLR 4.7.2

#pragma once


#include "antlr4-runtime.h"
#include "FgsgVisitor.h"


namespace fgsg_grammar {

/**
 * This class provides an empty implementation of FgsgVisitor, which can be
 * extended to create a visitor which only needs to handle a subset of the available methods.
 */
class  FgsgBaseVisitor : public FgsgVisitor {
public:

  virtual antlrcpp::Any visitProgram(FgsgParser::ProgramContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitStatement(FgsgParser::StatementContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitValueDecl(FgsgParser::ValueDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitImportDecl(FgsgParser::ImportDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitImportSetting(FgsgParser::ImportSettingContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitSurfaceDecl(FgsgParser::SurfaceDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitFieldDecl(FgsgParser::FieldDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitFieldSource(FgsgParser::FieldSourceContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitFieldDesignItem(FgsgParser::FieldDesignItemContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitFieldDesignWord(FgsgParser::FieldDesignWordContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitDesignValue(FgsgParser::DesignValueContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitTextureDecl(FgsgParser::TextureDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitTilesetDecl(FgsgParser::TilesetDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitTilesetItem(FgsgParser::TilesetItemContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitDeriveDecl(FgsgParser::DeriveDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitTurtleDecl(FgsgParser::TurtleDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitTurtleSetting(FgsgParser::TurtleSettingContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitIgnoreDecl(FgsgParser::IgnoreDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitIgnoredSymbol(FgsgParser::IgnoredSymbolContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitCollisionDecl(FgsgParser::CollisionDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitCollisionWord(FgsgParser::CollisionWordContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitAxiomDecl(FgsgParser::AxiomDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitPriorityDecl(FgsgParser::PriorityDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitGrammarRule(FgsgParser::GrammarRuleContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitRuleLabel(FgsgParser::RuleLabelContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitRuleHead(FgsgParser::RuleHeadContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitLeftContext(FgsgParser::LeftContextContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitRightContext(FgsgParser::RightContextContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitContextModule(FgsgParser::ContextModuleContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitModulePattern(FgsgParser::ModulePatternContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitTurtleSymbol(FgsgParser::TurtleSymbolContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitParamDecl(FgsgParser::ParamDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitRuleBody(FgsgParser::RuleBodyContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitBranch(FgsgParser::BranchContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitArrow(FgsgParser::ArrowContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitSuccessor(FgsgParser::SuccessorContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitSequenceItem(FgsgParser::SequenceItemContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitCallItem(FgsgParser::CallItemContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitTurtleItem(FgsgParser::TurtleItemContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitBracketItem(FgsgParser::BracketItemContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitPolygonItem(FgsgParser::PolygonItemContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitSurfaceItem(FgsgParser::SurfaceItemContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitCallArgs(FgsgParser::CallArgsContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitBody(FgsgParser::BodyContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitBodyPart(FgsgParser::BodyPartContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitUnaryExpr(FgsgParser::UnaryExprContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitPrimaryExpr(FgsgParser::PrimaryExprContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitTernaryExpr(FgsgParser::TernaryExprContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitBinaryExpr(FgsgParser::BinaryExprContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitNumberPrimary(FgsgParser::NumberPrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitRelSizePrimary(FgsgParser::RelSizePrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitStringPrimary(FgsgParser::StringPrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitBoolPrimary(FgsgParser::BoolPrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitMemberPrimary(FgsgParser::MemberPrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitCallPrimary(FgsgParser::CallPrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitIdentPrimary(FgsgParser::IdentPrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitParenPrimary(FgsgParser::ParenPrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitVectorPrimary(FgsgParser::VectorPrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitFloatSizePrimary(FgsgParser::FloatSizePrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitNumber(FgsgParser::NumberContext *ctx) override {
    return visitChildren(ctx);
  }


};

}  // namespace fgsg_grammar
