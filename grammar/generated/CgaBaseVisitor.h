
// Generated from grammar/Cga.g4 by ANTLR 4.7.2

#pragma once


#include "antlr4-runtime.h"
#include "CgaVisitor.h"


namespace fgsg_grammar {

/**
 * This class provides an empty implementation of CgaVisitor, which can be
 * extended to create a visitor which only needs to handle a subset of the available methods.
 */
class  CgaBaseVisitor : public CgaVisitor {
public:

  virtual antlrcpp::Any visitCgaFile(CgaParser::CgaFileContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitDeclaration(CgaParser::DeclarationContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitVersionDecl(CgaParser::VersionDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitDialectDecl(CgaParser::DialectDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitImportDecl(CgaParser::ImportDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitImportArg(CgaParser::ImportArgContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitStyleDecl(CgaParser::StyleDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitAnnotated(CgaParser::AnnotatedContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitAnnotation(CgaParser::AnnotationContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitAnnotationArg(CgaParser::AnnotationArgContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitAttrDecl(CgaParser::AttrDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitConstDecl(CgaParser::ConstDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitFunctionDecl(CgaParser::FunctionDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitRuleDecl(CgaParser::RuleDeclContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitParams(CgaParser::ParamsContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitCaseValue(CgaParser::CaseValueContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitStochasticValue(CgaParser::StochasticValueContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitPlainValue(CgaParser::PlainValueContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitCaseBody(CgaParser::CaseBodyContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitStochasticBody(CgaParser::StochasticBodyContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitOperationBody(CgaParser::OperationBodyContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitNilOperation(CgaParser::NilOperationContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitCallOperation(CgaParser::CallOperationContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitLeafOperation(CgaParser::LeafOperationContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitShapeOperation(CgaParser::ShapeOperationContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitDotOperation(CgaParser::DotOperationContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitPushPopOperation(CgaParser::PushPopOperationContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitOperationBlock(CgaParser::OperationBlockContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitSplitBody(CgaParser::SplitBodyContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitSizedPart(CgaParser::SizedPartContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitNestedPart(CgaParser::NestedPartContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitUnaryExpr(CgaParser::UnaryExprContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitPrimaryExpr(CgaParser::PrimaryExprContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitBinaryExpr(CgaParser::BinaryExprContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitNumberPrimary(CgaParser::NumberPrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitStringPrimary(CgaParser::StringPrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitBoolPrimary(CgaParser::BoolPrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitCallPrimary(CgaParser::CallPrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitNamePrimary(CgaParser::NamePrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitParenPrimary(CgaParser::ParenPrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitArrayPrimary(CgaParser::ArrayPrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitRelativePrimary(CgaParser::RelativePrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitFloatingPrimary(CgaParser::FloatingPrimaryContext *ctx) override {
    return visitChildren(ctx);
  }

  virtual antlrcpp::Any visitNumber(CgaParser::NumberContext *ctx) override {
    return visitChildren(ctx);
  }


};

}  // namespace fgsg_grammar
