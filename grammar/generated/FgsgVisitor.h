
// Generated from grammar/Fgsg.g4 by ANTLR 4.7.2

#pragma once


#include "antlr4-runtime.h"
#include "FgsgParser.h"


namespace fgsg_grammar {

/**
 * This class defines an abstract visitor for a parse tree
 * produced by FgsgParser.
 */
class  FgsgVisitor : public antlr4::tree::AbstractParseTreeVisitor {
public:

  /**
   * Visit parse trees produced by FgsgParser.
   */
    virtual antlrcpp::Any visitProgram(FgsgParser::ProgramContext *context) = 0;

    virtual antlrcpp::Any visitStatement(FgsgParser::StatementContext *context) = 0;

    virtual antlrcpp::Any visitValueDecl(FgsgParser::ValueDeclContext *context) = 0;

    virtual antlrcpp::Any visitImportDecl(FgsgParser::ImportDeclContext *context) = 0;

    virtual antlrcpp::Any visitImportSetting(FgsgParser::ImportSettingContext *context) = 0;

    virtual antlrcpp::Any visitSurfaceDecl(FgsgParser::SurfaceDeclContext *context) = 0;

    virtual antlrcpp::Any visitFieldDecl(FgsgParser::FieldDeclContext *context) = 0;

    virtual antlrcpp::Any visitFieldSource(FgsgParser::FieldSourceContext *context) = 0;

    virtual antlrcpp::Any visitFieldDesignItem(FgsgParser::FieldDesignItemContext *context) = 0;

    virtual antlrcpp::Any visitFieldDesignWord(FgsgParser::FieldDesignWordContext *context) = 0;

    virtual antlrcpp::Any visitDesignValue(FgsgParser::DesignValueContext *context) = 0;

    virtual antlrcpp::Any visitTextureDecl(FgsgParser::TextureDeclContext *context) = 0;

    virtual antlrcpp::Any visitTilesetDecl(FgsgParser::TilesetDeclContext *context) = 0;

    virtual antlrcpp::Any visitTilesetItem(FgsgParser::TilesetItemContext *context) = 0;

    virtual antlrcpp::Any visitDeriveDecl(FgsgParser::DeriveDeclContext *context) = 0;

    virtual antlrcpp::Any visitTurtleDecl(FgsgParser::TurtleDeclContext *context) = 0;

    virtual antlrcpp::Any visitTurtleSetting(FgsgParser::TurtleSettingContext *context) = 0;

    virtual antlrcpp::Any visitIgnoreDecl(FgsgParser::IgnoreDeclContext *context) = 0;

    virtual antlrcpp::Any visitIgnoredSymbol(FgsgParser::IgnoredSymbolContext *context) = 0;

    virtual antlrcpp::Any visitCollisionDecl(FgsgParser::CollisionDeclContext *context) = 0;

    virtual antlrcpp::Any visitCollisionWord(FgsgParser::CollisionWordContext *context) = 0;

    virtual antlrcpp::Any visitAxiomDecl(FgsgParser::AxiomDeclContext *context) = 0;

    virtual antlrcpp::Any visitPriorityDecl(FgsgParser::PriorityDeclContext *context) = 0;

    virtual antlrcpp::Any visitGrammarRule(FgsgParser::GrammarRuleContext *context) = 0;

    virtual antlrcpp::Any visitRuleLabel(FgsgParser::RuleLabelContext *context) = 0;

    virtual antlrcpp::Any visitRuleHead(FgsgParser::RuleHeadContext *context) = 0;

    virtual antlrcpp::Any visitLeftContext(FgsgParser::LeftContextContext *context) = 0;

    virtual antlrcpp::Any visitRightContext(FgsgParser::RightContextContext *context) = 0;

    virtual antlrcpp::Any visitContextModule(FgsgParser::ContextModuleContext *context) = 0;

    virtual antlrcpp::Any visitModulePattern(FgsgParser::ModulePatternContext *context) = 0;

    virtual antlrcpp::Any visitTurtleSymbol(FgsgParser::TurtleSymbolContext *context) = 0;

    virtual antlrcpp::Any visitParamDecl(FgsgParser::ParamDeclContext *context) = 0;

    virtual antlrcpp::Any visitRuleBody(FgsgParser::RuleBodyContext *context) = 0;

    virtual antlrcpp::Any visitBranch(FgsgParser::BranchContext *context) = 0;

    virtual antlrcpp::Any visitArrow(FgsgParser::ArrowContext *context) = 0;

    virtual antlrcpp::Any visitSuccessor(FgsgParser::SuccessorContext *context) = 0;

    virtual antlrcpp::Any visitSequenceItem(FgsgParser::SequenceItemContext *context) = 0;

    virtual antlrcpp::Any visitCallItem(FgsgParser::CallItemContext *context) = 0;

    virtual antlrcpp::Any visitTurtleItem(FgsgParser::TurtleItemContext *context) = 0;

    virtual antlrcpp::Any visitBracketItem(FgsgParser::BracketItemContext *context) = 0;

    virtual antlrcpp::Any visitPolygonItem(FgsgParser::PolygonItemContext *context) = 0;

    virtual antlrcpp::Any visitSurfaceItem(FgsgParser::SurfaceItemContext *context) = 0;

    virtual antlrcpp::Any visitCallArgs(FgsgParser::CallArgsContext *context) = 0;

    virtual antlrcpp::Any visitBody(FgsgParser::BodyContext *context) = 0;

    virtual antlrcpp::Any visitBodyPart(FgsgParser::BodyPartContext *context) = 0;

    virtual antlrcpp::Any visitUnaryExpr(FgsgParser::UnaryExprContext *context) = 0;

    virtual antlrcpp::Any visitPrimaryExpr(FgsgParser::PrimaryExprContext *context) = 0;

    virtual antlrcpp::Any visitTernaryExpr(FgsgParser::TernaryExprContext *context) = 0;

    virtual antlrcpp::Any visitBinaryExpr(FgsgParser::BinaryExprContext *context) = 0;

    virtual antlrcpp::Any visitNumberPrimary(FgsgParser::NumberPrimaryContext *context) = 0;

    virtual antlrcpp::Any visitRelSizePrimary(FgsgParser::RelSizePrimaryContext *context) = 0;

    virtual antlrcpp::Any visitStringPrimary(FgsgParser::StringPrimaryContext *context) = 0;

    virtual antlrcpp::Any visitBoolPrimary(FgsgParser::BoolPrimaryContext *context) = 0;

    virtual antlrcpp::Any visitMemberPrimary(FgsgParser::MemberPrimaryContext *context) = 0;

    virtual antlrcpp::Any visitCallPrimary(FgsgParser::CallPrimaryContext *context) = 0;

    virtual antlrcpp::Any visitIdentPrimary(FgsgParser::IdentPrimaryContext *context) = 0;

    virtual antlrcpp::Any visitParenPrimary(FgsgParser::ParenPrimaryContext *context) = 0;

    virtual antlrcpp::Any visitVectorPrimary(FgsgParser::VectorPrimaryContext *context) = 0;

    virtual antlrcpp::Any visitFloatSizePrimary(FgsgParser::FloatSizePrimaryContext *context) = 0;

    virtual antlrcpp::Any visitNumber(FgsgParser::NumberContext *context) = 0;


};

}  // namespace fgsg_grammar
