
// Generated from grammar/Cga.g4 by ANTLR 4.7.2

#pragma once


#include "antlr4-runtime.h"
#include "CgaParser.h"


namespace fgsg_grammar {

/**
 * This class defines an abstract visitor for a parse tree
 * produced by CgaParser.
 */
class  CgaVisitor : public antlr4::tree::AbstractParseTreeVisitor {
public:

  /**
   * Visit parse trees produced by CgaParser.
   */
    virtual antlrcpp::Any visitCgaFile(CgaParser::CgaFileContext *context) = 0;

    virtual antlrcpp::Any visitDeclaration(CgaParser::DeclarationContext *context) = 0;

    virtual antlrcpp::Any visitVersionDecl(CgaParser::VersionDeclContext *context) = 0;

    virtual antlrcpp::Any visitDialectDecl(CgaParser::DialectDeclContext *context) = 0;

    virtual antlrcpp::Any visitImportDecl(CgaParser::ImportDeclContext *context) = 0;

    virtual antlrcpp::Any visitImportArg(CgaParser::ImportArgContext *context) = 0;

    virtual antlrcpp::Any visitStyleDecl(CgaParser::StyleDeclContext *context) = 0;

    virtual antlrcpp::Any visitAnnotated(CgaParser::AnnotatedContext *context) = 0;

    virtual antlrcpp::Any visitAnnotation(CgaParser::AnnotationContext *context) = 0;

    virtual antlrcpp::Any visitAnnotationArg(CgaParser::AnnotationArgContext *context) = 0;

    virtual antlrcpp::Any visitAttrDecl(CgaParser::AttrDeclContext *context) = 0;

    virtual antlrcpp::Any visitConstDecl(CgaParser::ConstDeclContext *context) = 0;

    virtual antlrcpp::Any visitFunctionDecl(CgaParser::FunctionDeclContext *context) = 0;

    virtual antlrcpp::Any visitRuleDecl(CgaParser::RuleDeclContext *context) = 0;

    virtual antlrcpp::Any visitParams(CgaParser::ParamsContext *context) = 0;

    virtual antlrcpp::Any visitCaseValue(CgaParser::CaseValueContext *context) = 0;

    virtual antlrcpp::Any visitStochasticValue(CgaParser::StochasticValueContext *context) = 0;

    virtual antlrcpp::Any visitPlainValue(CgaParser::PlainValueContext *context) = 0;

    virtual antlrcpp::Any visitCaseBody(CgaParser::CaseBodyContext *context) = 0;

    virtual antlrcpp::Any visitStochasticBody(CgaParser::StochasticBodyContext *context) = 0;

    virtual antlrcpp::Any visitOperationBody(CgaParser::OperationBodyContext *context) = 0;

    virtual antlrcpp::Any visitNilOperation(CgaParser::NilOperationContext *context) = 0;

    virtual antlrcpp::Any visitCallOperation(CgaParser::CallOperationContext *context) = 0;

    virtual antlrcpp::Any visitLeafOperation(CgaParser::LeafOperationContext *context) = 0;

    virtual antlrcpp::Any visitShapeOperation(CgaParser::ShapeOperationContext *context) = 0;

    virtual antlrcpp::Any visitDotOperation(CgaParser::DotOperationContext *context) = 0;

    virtual antlrcpp::Any visitPushPopOperation(CgaParser::PushPopOperationContext *context) = 0;

    virtual antlrcpp::Any visitOperationBlock(CgaParser::OperationBlockContext *context) = 0;

    virtual antlrcpp::Any visitSplitBody(CgaParser::SplitBodyContext *context) = 0;

    virtual antlrcpp::Any visitSizedPart(CgaParser::SizedPartContext *context) = 0;

    virtual antlrcpp::Any visitNestedPart(CgaParser::NestedPartContext *context) = 0;

    virtual antlrcpp::Any visitUnaryExpr(CgaParser::UnaryExprContext *context) = 0;

    virtual antlrcpp::Any visitPrimaryExpr(CgaParser::PrimaryExprContext *context) = 0;

    virtual antlrcpp::Any visitBinaryExpr(CgaParser::BinaryExprContext *context) = 0;

    virtual antlrcpp::Any visitNumberPrimary(CgaParser::NumberPrimaryContext *context) = 0;

    virtual antlrcpp::Any visitStringPrimary(CgaParser::StringPrimaryContext *context) = 0;

    virtual antlrcpp::Any visitBoolPrimary(CgaParser::BoolPrimaryContext *context) = 0;

    virtual antlrcpp::Any visitCallPrimary(CgaParser::CallPrimaryContext *context) = 0;

    virtual antlrcpp::Any visitNamePrimary(CgaParser::NamePrimaryContext *context) = 0;

    virtual antlrcpp::Any visitParenPrimary(CgaParser::ParenPrimaryContext *context) = 0;

    virtual antlrcpp::Any visitArrayPrimary(CgaParser::ArrayPrimaryContext *context) = 0;

    virtual antlrcpp::Any visitRelativePrimary(CgaParser::RelativePrimaryContext *context) = 0;

    virtual antlrcpp::Any visitFloatingPrimary(CgaParser::FloatingPrimaryContext *context) = 0;

    virtual antlrcpp::Any visitNumber(CgaParser::NumberContext *context) = 0;


};

}  // namespace fgsg_grammar
