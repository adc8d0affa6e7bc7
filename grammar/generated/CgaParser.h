
// Generated from grammar/Cga.g4 by ANTLR 4.7.2

#pragma once


#include "antlr4-runtime.h"


namespace fgsg_grammar {


class  CgaParser : public antlr4::Parser {
public:
  enum {
    VERSION = 1, DIALECT = 2, IMPORT = 3, STYLE = 4, EXTENDS = 5, ATTR = 6, 
    CONST = 7, CASE = 8, ELSE = 9, NIL = 10, TRUE = 11, FALSE = 12, ARROW = 13, 
    AT = 14, EQ = 15, NEQ = 16, LE = 17, GE = 18, LT = 19, GT = 20, AND = 21, 
    OR = 22, ASSIGN = 23, PLUS = 24, MINUS = 25, STAR = 26, SLASH = 27, 
    PERCENT = 28, BANG = 29, PIPE = 30, QUOTE = 31, TILDE = 32, COLON = 33, 
    SEMI = 34, COMMA = 35, DOT = 36, LPAREN = 37, RPAREN = 38, LBRACK = 39, 
    RBRACK = 40, LBRACE = 41, RBRACE = 42, PERCENT_LIT = 43, FLOAT = 44, 
    INT = 45, QID = 46, LEAF = 47, ID = 48, STRING = 49, UNTERMINATED_STRING = 50, 
    LINE_COMMENT = 51, HASH_COMMENT = 52, BLOCK_COMMENT = 53, UNTERMINATED_COMMENT = 54, 
    WS = 55, UNKNOWN_CHAR = 56
  };

  enum {
    RuleCgaFile = 0, RuleDeclaration = 1, RuleVersionDecl = 2, RuleDialectDecl = 3, 
    RuleImportDecl = 4, RuleImportArg = 5, RuleStyleDecl = 6, RuleAnnotated = 7, 
    RuleAnnotation = 8, RuleAnnotationArg = 9, RuleAttrDecl = 10, RuleConstDecl = 11, 
    RuleFunctionDecl = 12, RuleRuleDecl = 13, RuleParams = 14, RuleValue = 15, 
    RuleRuleBody = 16, RuleOperation = 17, RuleOperationBlock = 18, RuleSplitBody = 19, 
    RuleSplitPart = 20, RuleExpr = 21, RulePrimary = 22, RuleNumber = 23
  };

  CgaParser(antlr4::TokenStream *input);
  ~CgaParser();

  virtual std::string getGrammarFileName() const override;
  virtual const antlr4::atn::ATN& getATN() const override { return _atn; };
  virtual const std::vector<std::string>& getTokenNames() const override { return _tokenNames; }; // deprecated: use vocabulary instead.
  virtual const std::vector<std::string>& getRuleNames() const override;
  virtual antlr4::dfa::Vocabulary& getVocabulary() const override;


  class CgaFileContext;
  class DeclarationContext;
  class VersionDeclContext;
  class DialectDeclContext;
  class ImportDeclContext;
  class ImportArgContext;
  class StyleDeclContext;
  class AnnotatedContext;
  class AnnotationContext;
  class AnnotationArgContext;
  class AttrDeclContext;
  class ConstDeclContext;
  class FunctionDeclContext;
  class RuleDeclContext;
  class ParamsContext;
  class ValueContext;
  class RuleBodyContext;
  class OperationContext;
  class OperationBlockContext;
  class SplitBodyContext;
  class SplitPartContext;
  class ExprContext;
  class PrimaryContext;
  class NumberContext; 

  class  CgaFileContext : public antlr4::ParserRuleContext {
  public:
    CgaFileContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *EOF();
    std::vector<DeclarationContext *> declaration();
    DeclarationContext* declaration(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  CgaFileContext* cgaFile();

  class  DeclarationContext : public antlr4::ParserRuleContext {
  public:
    DeclarationContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    VersionDeclContext *versionDecl();
    DialectDeclContext *dialectDecl();
    ImportDeclContext *importDecl();
    StyleDeclContext *styleDecl();
    AnnotatedContext *annotated();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  DeclarationContext* declaration();

  class  VersionDeclContext : public antlr4::ParserRuleContext {
  public:
    VersionDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *VERSION();
    antlr4::tree::TerminalNode *STRING();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  VersionDeclContext* versionDecl();

  class  DialectDeclContext : public antlr4::ParserRuleContext {
  public:
    DialectDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *DIALECT();
    antlr4::tree::TerminalNode *ID();
    antlr4::tree::TerminalNode *SEMI();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  DialectDeclContext* dialectDecl();

  class  ImportDeclContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *alias = nullptr;;
    antlr4::Token *idToken = nullptr;;
    std::vector<antlr4::Token *> styles;;
    antlr4::Token *path = nullptr;;
    ImportDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *IMPORT();
    antlr4::tree::TerminalNode *STRING();
    antlr4::tree::TerminalNode *COLON();
    std::vector<antlr4::tree::TerminalNode *> LPAREN();
    antlr4::tree::TerminalNode* LPAREN(size_t i);
    std::vector<antlr4::tree::TerminalNode *> RPAREN();
    antlr4::tree::TerminalNode* RPAREN(size_t i);
    std::vector<antlr4::tree::TerminalNode *> ID();
    antlr4::tree::TerminalNode* ID(size_t i);
    std::vector<ImportArgContext *> importArg();
    ImportArgContext* importArg(size_t i);
    std::vector<antlr4::tree::TerminalNode *> COMMA();
    antlr4::tree::TerminalNode* COMMA(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  ImportDeclContext* importDecl();

  class  ImportArgContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *key = nullptr;;
    ImportArgContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    ExprContext *expr();
    antlr4::tree::TerminalNode *ASSIGN();
    antlr4::tree::TerminalNode *ID();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  ImportArgContext* importArg();

  class  StyleDeclContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *name = nullptr;;
    antlr4::Token *base = nullptr;;
    StyleDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *STYLE();
    std::vector<antlr4::tree::TerminalNode *> ID();
    antlr4::tree::TerminalNode* ID(size_t i);
    antlr4::tree::TerminalNode *EXTENDS();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  StyleDeclContext* styleDecl();

  class  AnnotatedContext : public antlr4::ParserRuleContext {
  public:
    AnnotatedContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    AttrDeclContext *attrDecl();
    ConstDeclContext *constDecl();
    FunctionDeclContext *functionDecl();
    RuleDeclContext *ruleDecl();
    std::vector<AnnotationContext *> annotation();
    AnnotationContext* annotation(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  AnnotatedContext* annotated();

  class  AnnotationContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *name = nullptr;;
    AnnotationContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *AT();
    antlr4::tree::TerminalNode *ID();
    antlr4::tree::TerminalNode *LPAREN();
    antlr4::tree::TerminalNode *RPAREN();
    std::vector<AnnotationArgContext *> annotationArg();
    AnnotationArgContext* annotationArg(size_t i);
    std::vector<antlr4::tree::TerminalNode *> COMMA();
    antlr4::tree::TerminalNode* COMMA(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  AnnotationContext* annotation();

  class  AnnotationArgContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *key = nullptr;;
    AnnotationArgContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    ExprContext *expr();
    antlr4::tree::TerminalNode *ASSIGN();
    antlr4::tree::TerminalNode *ID();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  AnnotationArgContext* annotationArg();

  class  AttrDeclContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *name = nullptr;;
    AttrDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *ATTR();
    antlr4::tree::TerminalNode *ASSIGN();
    ValueContext *value();
    antlr4::tree::TerminalNode *ID();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  AttrDeclContext* attrDecl();

  class  ConstDeclContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *name = nullptr;;
    ConstDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *CONST();
    antlr4::tree::TerminalNode *ASSIGN();
    ValueContext *value();
    antlr4::tree::TerminalNode *ID();
    antlr4::tree::TerminalNode *LPAREN();
    antlr4::tree::TerminalNode *RPAREN();
    ParamsContext *params();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  ConstDeclContext* constDecl();

  class  FunctionDeclContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *name = nullptr;;
    FunctionDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *ASSIGN();
    ValueContext *value();
    antlr4::tree::TerminalNode *ID();
    antlr4::tree::TerminalNode *QID();
    antlr4::tree::TerminalNode *LPAREN();
    antlr4::tree::TerminalNode *RPAREN();
    ParamsContext *params();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  FunctionDeclContext* functionDecl();

  class  RuleDeclContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *name = nullptr;;
    RuleDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *ARROW();
    RuleBodyContext *ruleBody();
    antlr4::tree::TerminalNode *ID();
    antlr4::tree::TerminalNode *LPAREN();
    antlr4::tree::TerminalNode *RPAREN();
    ParamsContext *params();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  RuleDeclContext* ruleDecl();

  class  ParamsContext : public antlr4::ParserRuleContext {
  public:
    ParamsContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<antlr4::tree::TerminalNode *> ID();
    antlr4::tree::TerminalNode* ID(size_t i);
    std::vector<antlr4::tree::TerminalNode *> COMMA();
    antlr4::tree::TerminalNode* COMMA(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  ParamsContext* params();

  class  ValueContext : public antlr4::ParserRuleContext {
  public:
    ValueContext(antlr4::ParserRuleContext *parent, size_t invokingState);
   
    ValueContext() = default;
    void copyFrom(ValueContext *context);
    using antlr4::ParserRuleContext::copyFrom;

    virtual size_t getRuleIndex() const override;

   
  };

  class  StochasticValueContext : public ValueContext {
  public:
    StochasticValueContext(ValueContext *ctx);

    std::vector<antlr4::tree::TerminalNode *> PERCENT_LIT();
    antlr4::tree::TerminalNode* PERCENT_LIT(size_t i);
    std::vector<antlr4::tree::TerminalNode *> COLON();
    antlr4::tree::TerminalNode* COLON(size_t i);
    std::vector<ValueContext *> value();
    ValueContext* value(size_t i);
    antlr4::tree::TerminalNode *ELSE();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  PlainValueContext : public ValueContext {
  public:
    PlainValueContext(ValueContext *ctx);

    ExprContext *expr();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  CaseValueContext : public ValueContext {
  public:
    CaseValueContext(ValueContext *ctx);

    antlr4::tree::TerminalNode *ELSE();
    std::vector<antlr4::tree::TerminalNode *> COLON();
    antlr4::tree::TerminalNode* COLON(size_t i);
    std::vector<ValueContext *> value();
    ValueContext* value(size_t i);
    std::vector<antlr4::tree::TerminalNode *> CASE();
    antlr4::tree::TerminalNode* CASE(size_t i);
    std::vector<ExprContext *> expr();
    ExprContext* expr(size_t i);
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  ValueContext* value();

  class  RuleBodyContext : public antlr4::ParserRuleContext {
  public:
    RuleBodyContext(antlr4::ParserRuleContext *parent, size_t invokingState);
   
    RuleBodyContext() = default;
    void copyFrom(RuleBodyContext *context);
    using antlr4::ParserRuleContext::copyFrom;

    virtual size_t getRuleIndex() const override;

   
  };

  class  OperationBodyContext : public RuleBodyContext {
  public:
    OperationBodyContext(RuleBodyContext *ctx);

    std::vector<OperationContext *> operation();
    OperationContext* operation(size_t i);
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  StochasticBodyContext : public RuleBodyContext {
  public:
    StochasticBodyContext(RuleBodyContext *ctx);

    std::vector<antlr4::tree::TerminalNode *> PERCENT_LIT();
    antlr4::tree::TerminalNode* PERCENT_LIT(size_t i);
    std::vector<antlr4::tree::TerminalNode *> COLON();
    antlr4::tree::TerminalNode* COLON(size_t i);
    std::vector<RuleBodyContext *> ruleBody();
    RuleBodyContext* ruleBody(size_t i);
    antlr4::tree::TerminalNode *ELSE();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  CaseBodyContext : public RuleBodyContext {
  public:
    CaseBodyContext(RuleBodyContext *ctx);

    antlr4::tree::TerminalNode *ELSE();
    std::vector<antlr4::tree::TerminalNode *> COLON();
    antlr4::tree::TerminalNode* COLON(size_t i);
    std::vector<RuleBodyContext *> ruleBody();
    RuleBodyContext* ruleBody(size_t i);
    std::vector<antlr4::tree::TerminalNode *> CASE();
    antlr4::tree::TerminalNode* CASE(size_t i);
    std::vector<ExprContext *> expr();
    ExprContext* expr(size_t i);
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  RuleBodyContext* ruleBody();

  class  OperationContext : public antlr4::ParserRuleContext {
  public:
    OperationContext(antlr4::ParserRuleContext *parent, size_t invokingState);
   
    OperationContext() = default;
    void copyFrom(OperationContext *context);
    using antlr4::ParserRuleContext::copyFrom;

    virtual size_t getRuleIndex() const override;

   
  };

  class  PushPopOperationContext : public OperationContext {
  public:
    PushPopOperationContext(OperationContext *ctx);

    antlr4::tree::TerminalNode *LBRACK();
    antlr4::tree::TerminalNode *RBRACK();
    std::vector<OperationContext *> operation();
    OperationContext* operation(size_t i);
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  CallOperationContext : public OperationContext {
  public:
    CallOperationContext(OperationContext *ctx);

    antlr4::Token *name = nullptr;
    antlr4::tree::TerminalNode *LPAREN();
    antlr4::tree::TerminalNode *RPAREN();
    antlr4::tree::TerminalNode *ID();
    antlr4::tree::TerminalNode *QID();
    std::vector<ExprContext *> expr();
    ExprContext* expr(size_t i);
    SplitBodyContext *splitBody();
    OperationBlockContext *operationBlock();
    std::vector<antlr4::tree::TerminalNode *> COMMA();
    antlr4::tree::TerminalNode* COMMA(size_t i);
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  ShapeOperationContext : public OperationContext {
  public:
    ShapeOperationContext(OperationContext *ctx);

    antlr4::Token *name = nullptr;
    antlr4::tree::TerminalNode *ID();
    antlr4::tree::TerminalNode *QID();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  DotOperationContext : public OperationContext {
  public:
    DotOperationContext(OperationContext *ctx);

    antlr4::tree::TerminalNode *DOT();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  NilOperationContext : public OperationContext {
  public:
    NilOperationContext(OperationContext *ctx);

    antlr4::tree::TerminalNode *NIL();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  LeafOperationContext : public OperationContext {
  public:
    LeafOperationContext(OperationContext *ctx);

    antlr4::Token *leaf = nullptr;
    antlr4::tree::TerminalNode *LEAF();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  OperationContext* operation();

  class  OperationBlockContext : public antlr4::ParserRuleContext {
  public:
    OperationBlockContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *LBRACE();
    antlr4::tree::TerminalNode *RBRACE();
    std::vector<OperationContext *> operation();
    OperationContext* operation(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  OperationBlockContext* operationBlock();

  class  SplitBodyContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *repeat = nullptr;;
    SplitBodyContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *LBRACE();
    std::vector<SplitPartContext *> splitPart();
    SplitPartContext* splitPart(size_t i);
    antlr4::tree::TerminalNode *RBRACE();
    std::vector<antlr4::tree::TerminalNode *> PIPE();
    antlr4::tree::TerminalNode* PIPE(size_t i);
    antlr4::tree::TerminalNode *STAR();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  SplitBodyContext* splitBody();

  class  SplitPartContext : public antlr4::ParserRuleContext {
  public:
    SplitPartContext(antlr4::ParserRuleContext *parent, size_t invokingState);
   
    SplitPartContext() = default;
    void copyFrom(SplitPartContext *context);
    using antlr4::ParserRuleContext::copyFrom;

    virtual size_t getRuleIndex() const override;

   
  };

  class  NestedPartContext : public SplitPartContext {
  public:
    NestedPartContext(SplitPartContext *ctx);

    SplitBodyContext *splitBody();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  SizedPartContext : public SplitPartContext {
  public:
    SizedPartContext(SplitPartContext *ctx);

    CgaParser::ExprContext *key = nullptr;
    antlr4::Token *sep = nullptr;
    ExprContext *expr();
    antlr4::tree::TerminalNode *COLON();
    antlr4::tree::TerminalNode *ASSIGN();
    std::vector<OperationContext *> operation();
    OperationContext* operation(size_t i);
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  SplitPartContext* splitPart();

  class  ExprContext : public antlr4::ParserRuleContext {
  public:
    ExprContext(antlr4::ParserRuleContext *parent, size_t invokingState);
   
    ExprContext() = default;
    void copyFrom(ExprContext *context);
    using antlr4::ParserRuleContext::copyFrom;

    virtual size_t getRuleIndex() const override;

   
  };

  class  UnaryExprContext : public ExprContext {
  public:
    UnaryExprContext(ExprContext *ctx);

    antlr4::Token *op = nullptr;
    ExprContext *expr();
    antlr4::tree::TerminalNode *MINUS();
    antlr4::tree::TerminalNode *BANG();
    antlr4::tree::TerminalNode *PLUS();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  PrimaryExprContext : public ExprContext {
  public:
    PrimaryExprContext(ExprContext *ctx);

    PrimaryContext *primary();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  BinaryExprContext : public ExprContext {
  public:
    BinaryExprContext(ExprContext *ctx);

    antlr4::Token *op = nullptr;
    std::vector<ExprContext *> expr();
    ExprContext* expr(size_t i);
    antlr4::tree::TerminalNode *STAR();
    antlr4::tree::TerminalNode *SLASH();
    antlr4::tree::TerminalNode *PERCENT();
    antlr4::tree::TerminalNode *PLUS();
    antlr4::tree::TerminalNode *MINUS();
    antlr4::tree::TerminalNode *LT();
    antlr4::tree::TerminalNode *LE();
    antlr4::tree::TerminalNode *GT();
    antlr4::tree::TerminalNode *GE();
    antlr4::tree::TerminalNode *EQ();
    antlr4::tree::TerminalNode *NEQ();
    antlr4::tree::TerminalNode *AND();
    antlr4::tree::TerminalNode *OR();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  ExprContext* expr();
  ExprContext* expr(int precedence);
  class  PrimaryContext : public antlr4::ParserRuleContext {
  public:
    PrimaryContext(antlr4::ParserRuleContext *parent, size_t invokingState);
   
    PrimaryContext() = default;
    void copyFrom(PrimaryContext *context);
    using antlr4::ParserRuleContext::copyFrom;

    virtual size_t getRuleIndex() const override;

   
  };

  class  RelativePrimaryContext : public PrimaryContext {
  public:
    RelativePrimaryContext(PrimaryContext *ctx);

    antlr4::tree::TerminalNode *QUOTE();
    PrimaryContext *primary();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  ParenPrimaryContext : public PrimaryContext {
  public:
    ParenPrimaryContext(PrimaryContext *ctx);

    antlr4::tree::TerminalNode *LPAREN();
    ExprContext *expr();
    antlr4::tree::TerminalNode *RPAREN();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  ArrayPrimaryContext : public PrimaryContext {
  public:
    ArrayPrimaryContext(PrimaryContext *ctx);

    antlr4::tree::TerminalNode *LBRACK();
    antlr4::tree::TerminalNode *RBRACK();
    std::vector<ExprContext *> expr();
    ExprContext* expr(size_t i);
    std::vector<antlr4::tree::TerminalNode *> COMMA();
    antlr4::tree::TerminalNode* COMMA(size_t i);
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  StringPrimaryContext : public PrimaryContext {
  public:
    StringPrimaryContext(PrimaryContext *ctx);

    antlr4::tree::TerminalNode *STRING();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  CallPrimaryContext : public PrimaryContext {
  public:
    CallPrimaryContext(PrimaryContext *ctx);

    antlr4::Token *name = nullptr;
    antlr4::tree::TerminalNode *LPAREN();
    antlr4::tree::TerminalNode *RPAREN();
    antlr4::tree::TerminalNode *ID();
    antlr4::tree::TerminalNode *QID();
    std::vector<ExprContext *> expr();
    ExprContext* expr(size_t i);
    std::vector<antlr4::tree::TerminalNode *> COMMA();
    antlr4::tree::TerminalNode* COMMA(size_t i);
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  BoolPrimaryContext : public PrimaryContext {
  public:
    BoolPrimaryContext(PrimaryContext *ctx);

    antlr4::Token *flag = nullptr;
    antlr4::tree::TerminalNode *TRUE();
    antlr4::tree::TerminalNode *FALSE();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  NumberPrimaryContext : public PrimaryContext {
  public:
    NumberPrimaryContext(PrimaryContext *ctx);

    NumberContext *number();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  NamePrimaryContext : public PrimaryContext {
  public:
    NamePrimaryContext(PrimaryContext *ctx);

    antlr4::Token *name = nullptr;
    antlr4::tree::TerminalNode *ID();
    antlr4::tree::TerminalNode *QID();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  FloatingPrimaryContext : public PrimaryContext {
  public:
    FloatingPrimaryContext(PrimaryContext *ctx);

    antlr4::tree::TerminalNode *TILDE();
    PrimaryContext *primary();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  PrimaryContext* primary();

  class  NumberContext : public antlr4::ParserRuleContext {
  public:
    NumberContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *INT();
    antlr4::tree::TerminalNode *FLOAT();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  NumberContext* number();


  virtual bool sempred(antlr4::RuleContext *_localctx, size_t ruleIndex, size_t predicateIndex) override;
  bool exprSempred(ExprContext *_localctx, size_t predicateIndex);

private:
  static std::vector<antlr4::dfa::DFA> _decisionToDFA;
  static antlr4::atn::PredictionContextCache _sharedContextCache;
  static std::vector<std::string> _ruleNames;
  static std::vector<std::string> _tokenNames;

  static std::vector<std::string> _literalNames;
  static std::vector<std::string> _symbolicNames;
  static antlr4::dfa::Vocabulary _vocabulary;
  static antlr4::atn::ATN _atn;
  static std::vector<uint16_t> _serializedATN;


  struct Initializer {
    Initializer();
  };
  static Initializer _init;
};

}  // namespace fgsg_grammar
