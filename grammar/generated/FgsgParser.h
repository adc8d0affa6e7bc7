
// Generated from grammar/Fgsg.g4 by ANTLR 4.7.2

#pragma once


#include "antlr4-runtime.h"


namespace fgsg_grammar {


class  FgsgParser : public antlr4::Parser {
public:
  enum {
    CONST = 1, ATTR = 2, SURFACE = 3, FIELD = 4, TEXTURE = 5, TILESET = 6, 
    DERIVE = 7, TURTLE = 8, IGNORE = 9, COLLISION = 10, AXIOM = 11, PRIORITY = 12, 
    TRUE = 13, FALSE = 14, EPSILON = 15, ARROW = 16, ASSIGN = 17, EQ = 18, 
    NEQ = 19, LE = 20, GE = 21, LT = 22, GT = 23, AND = 24, OR = 25, PLUS = 26, 
    MINUS = 27, STAR = 28, SLASH = 29, PERCENT = 30, CARET = 31, BANG = 32, 
    AMP = 33, PIPE = 34, BACKSLASH = 35, DOLLAR = 36, QUOTE = 37, TILDE = 38, 
    QUESTION = 39, COLON = 40, SEMI = 41, COMMA = 42, DOT = 43, LPAREN = 44, 
    RPAREN = 45, LBRACK = 46, RBRACK = 47, LBRACE = 48, RBRACE = 49, RELSIZE = 50, 
    FLOAT = 51, INT = 52, ID = 53, STRING = 54, UNTERMINATED_STRING = 55, 
    LINE_COMMENT = 56, BLOCK_COMMENT = 57, UNTERMINATED_COMMENT = 58, WS = 59, 
    UNKNOWN_CHAR = 60, VERTEX = 61, COLORSTEP = 62
  };

  enum {
    RuleProgram = 0, RuleStatement = 1, RuleValueDecl = 2, RuleSurfaceDecl = 3, 
    RuleFieldDecl = 4, RuleFieldSource = 5, RuleFieldDesignItem = 6, RuleFieldDesignWord = 7, 
    RuleDesignValue = 8, RuleTextureDecl = 9, RuleTilesetDecl = 10, RuleTilesetItem = 11, 
    RuleDeriveDecl = 12, RuleTurtleDecl = 13, RuleTurtleSetting = 14, RuleIgnoreDecl = 15, 
    RuleIgnoredSymbol = 16, RuleCollisionDecl = 17, RuleCollisionWord = 18, 
    RuleAxiomDecl = 19, RulePriorityDecl = 20, RuleGrammarRule = 21, RuleRuleLabel = 22, 
    RuleRuleHead = 23, RuleLeftContext = 24, RuleRightContext = 25, RuleContextModule = 26, 
    RuleModulePattern = 27, RuleTurtleSymbol = 28, RuleParamDecl = 29, RuleRuleBody = 30, 
    RuleBranch = 31, RuleArrow = 32, RuleSuccessor = 33, RuleSequenceItem = 34, 
    RuleItem = 35, RuleCallArgs = 36, RuleBody = 37, RuleBodyPart = 38, 
    RuleExpr = 39, RulePrimary = 40, RuleNumber = 41
  };

  FgsgParser(antlr4::TokenStream *input);
  ~FgsgParser();

  virtual std::string getGrammarFileName() const override;
  virtual const antlr4::atn::ATN& getATN() const override { return _atn; };
  virtual const std::vector<std::string>& getTokenNames() const override { return _tokenNames; }; // deprecated: use vocabulary instead.
  virtual const std::vector<std::string>& getRuleNames() const override;
  virtual antlr4::dfa::Vocabulary& getVocabulary() const override;


  class ProgramContext;
  class StatementContext;
  class ValueDeclContext;
  class SurfaceDeclContext;
  class FieldDeclContext;
  class FieldSourceContext;
  class FieldDesignItemContext;
  class FieldDesignWordContext;
  class DesignValueContext;
  class TextureDeclContext;
  class TilesetDeclContext;
  class TilesetItemContext;
  class DeriveDeclContext;
  class TurtleDeclContext;
  class TurtleSettingContext;
  class IgnoreDeclContext;
  class IgnoredSymbolContext;
  class CollisionDeclContext;
  class CollisionWordContext;
  class AxiomDeclContext;
  class PriorityDeclContext;
  class GrammarRuleContext;
  class RuleLabelContext;
  class RuleHeadContext;
  class LeftContextContext;
  class RightContextContext;
  class ContextModuleContext;
  class ModulePatternContext;
  class TurtleSymbolContext;
  class ParamDeclContext;
  class RuleBodyContext;
  class BranchContext;
  class ArrowContext;
  class SuccessorContext;
  class SequenceItemContext;
  class ItemContext;
  class CallArgsContext;
  class BodyContext;
  class BodyPartContext;
  class ExprContext;
  class PrimaryContext;
  class NumberContext; 

  class  ProgramContext : public antlr4::ParserRuleContext {
  public:
    ProgramContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *EOF();
    std::vector<StatementContext *> statement();
    StatementContext* statement(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  ProgramContext* program();

  class  StatementContext : public antlr4::ParserRuleContext {
  public:
    StatementContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    ValueDeclContext *valueDecl();
    SurfaceDeclContext *surfaceDecl();
    FieldDeclContext *fieldDecl();
    TextureDeclContext *textureDecl();
    TilesetDeclContext *tilesetDecl();
    DeriveDeclContext *deriveDecl();
    TurtleDeclContext *turtleDecl();
    IgnoreDeclContext *ignoreDecl();
    CollisionDeclContext *collisionDecl();
    AxiomDeclContext *axiomDecl();
    PriorityDeclContext *priorityDecl();
    GrammarRuleContext *grammarRule();
    antlr4::tree::TerminalNode *SEMI();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  StatementContext* statement();

  class  ValueDeclContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *kind = nullptr;;
    antlr4::Token *name = nullptr;;
    ValueDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *ASSIGN();
    ExprContext *expr();
    antlr4::tree::TerminalNode *SEMI();
    antlr4::tree::TerminalNode *ID();
    antlr4::tree::TerminalNode *CONST();
    antlr4::tree::TerminalNode *ATTR();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  ValueDeclContext* valueDecl();

  class  SurfaceDeclContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *path = nullptr;;
    antlr4::Token *generator = nullptr;;
    SurfaceDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *SURFACE();
    antlr4::tree::TerminalNode *SEMI();
    antlr4::tree::TerminalNode *STRING();
    antlr4::tree::TerminalNode *ID();
    CallArgsContext *callArgs();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  SurfaceDeclContext* surfaceDecl();

  class  FieldDeclContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *name = nullptr;;
    FieldDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *FIELD();
    antlr4::tree::TerminalNode *ASSIGN();
    FieldSourceContext *fieldSource();
    antlr4::tree::TerminalNode *SEMI();
    antlr4::tree::TerminalNode *ID();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  FieldDeclContext* fieldDecl();

  class  FieldSourceContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *designWord = nullptr;;
    antlr4::Token *function = nullptr;;
    FieldSourceContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *LBRACE();
    antlr4::tree::TerminalNode *RBRACE();
    std::vector<antlr4::tree::TerminalNode *> ID();
    antlr4::tree::TerminalNode* ID(size_t i);
    std::vector<FieldDesignItemContext *> fieldDesignItem();
    FieldDesignItemContext* fieldDesignItem(size_t i);
    CallArgsContext *callArgs();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  FieldSourceContext* fieldSource();

  class  FieldDesignItemContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *kind = nullptr;;
    FieldDesignItemContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *SEMI();
    antlr4::tree::TerminalNode *ID();
    std::vector<FieldDesignWordContext *> fieldDesignWord();
    FieldDesignWordContext* fieldDesignWord(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  FieldDesignItemContext* fieldDesignItem();

  class  FieldDesignWordContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *keyword = nullptr;;
    FieldDesignWordContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *ID();
    DesignValueContext *designValue();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  FieldDesignWordContext* fieldDesignWord();

  class  DesignValueContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *sign = nullptr;;
    DesignValueContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    NumberContext *number();
    antlr4::tree::TerminalNode *STRING();
    antlr4::tree::TerminalNode *TRUE();
    antlr4::tree::TerminalNode *FALSE();
    antlr4::tree::TerminalNode *LPAREN();
    std::vector<ExprContext *> expr();
    ExprContext* expr(size_t i);
    antlr4::tree::TerminalNode *RPAREN();
    antlr4::tree::TerminalNode *MINUS();
    antlr4::tree::TerminalNode *PLUS();
    std::vector<antlr4::tree::TerminalNode *> COMMA();
    antlr4::tree::TerminalNode* COMMA(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  DesignValueContext* designValue();

  class  TextureDeclContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *name = nullptr;;
    antlr4::Token *path = nullptr;;
    TextureDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *TEXTURE();
    antlr4::tree::TerminalNode *ASSIGN();
    antlr4::tree::TerminalNode *SEMI();
    antlr4::tree::TerminalNode *ID();
    antlr4::tree::TerminalNode *STRING();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  TextureDeclContext* textureDecl();

  class  TilesetDeclContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *name = nullptr;;
    TilesetDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *TILESET();
    antlr4::tree::TerminalNode *LBRACE();
    antlr4::tree::TerminalNode *RBRACE();
    antlr4::tree::TerminalNode *SEMI();
    antlr4::tree::TerminalNode *ID();
    std::vector<TilesetItemContext *> tilesetItem();
    TilesetItemContext* tilesetItem(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  TilesetDeclContext* tilesetDecl();

  class  TilesetItemContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *kind = nullptr;;
    antlr4::Token *itemName = nullptr;;
    TilesetItemContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<ExprContext *> expr();
    ExprContext* expr(size_t i);
    antlr4::tree::TerminalNode *SEMI();
    std::vector<antlr4::tree::TerminalNode *> ID();
    antlr4::tree::TerminalNode* ID(size_t i);
    antlr4::tree::TerminalNode *ASSIGN();
    std::vector<antlr4::tree::TerminalNode *> COMMA();
    antlr4::tree::TerminalNode* COMMA(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  TilesetItemContext* tilesetItem();

  class  DeriveDeclContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *order = nullptr;;
    FgsgParser::ExprContext *steps = nullptr;;
    DeriveDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *DERIVE();
    antlr4::tree::TerminalNode *SEMI();
    antlr4::tree::TerminalNode *ID();
    ExprContext *expr();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  DeriveDeclContext* deriveDecl();

  class  TurtleDeclContext : public antlr4::ParserRuleContext {
  public:
    TurtleDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *TURTLE();
    antlr4::tree::TerminalNode *SEMI();
    std::vector<TurtleSettingContext *> turtleSetting();
    TurtleSettingContext* turtleSetting(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  TurtleDeclContext* turtleDecl();

  class  TurtleSettingContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *name = nullptr;;
    FgsgParser::ExprContext *value = nullptr;;
    TurtleSettingContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *ID();
    ExprContext *expr();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  TurtleSettingContext* turtleSetting();

  class  IgnoreDeclContext : public antlr4::ParserRuleContext {
  public:
    IgnoreDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *IGNORE();
    antlr4::tree::TerminalNode *SEMI();
    antlr4::tree::TerminalNode *COLON();
    std::vector<IgnoredSymbolContext *> ignoredSymbol();
    IgnoredSymbolContext* ignoredSymbol(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  IgnoreDeclContext* ignoreDecl();

  class  IgnoredSymbolContext : public antlr4::ParserRuleContext {
  public:
    IgnoredSymbolContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *ID();
    TurtleSymbolContext *turtleSymbol();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  IgnoredSymbolContext* ignoredSymbol();

  class  CollisionDeclContext : public antlr4::ParserRuleContext {
  public:
    CollisionDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *COLLISION();
    antlr4::tree::TerminalNode *SEMI();
    std::vector<CollisionWordContext *> collisionWord();
    CollisionWordContext* collisionWord(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  CollisionDeclContext* collisionDecl();

  class  CollisionWordContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *word = nullptr;;
    antlr4::Token *sign = nullptr;;
    CollisionWordContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *ID();
    NumberContext *number();
    antlr4::tree::TerminalNode *MINUS();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  CollisionWordContext* collisionWord();

  class  AxiomDeclContext : public antlr4::ParserRuleContext {
  public:
    AxiomDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *AXIOM();
    antlr4::tree::TerminalNode *COLON();
    SuccessorContext *successor();
    antlr4::tree::TerminalNode *SEMI();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  AxiomDeclContext* axiomDecl();

  class  PriorityDeclContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *sign = nullptr;;
    antlr4::Token *level = nullptr;;
    PriorityDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *PRIORITY();
    antlr4::tree::TerminalNode *COLON();
    antlr4::tree::TerminalNode *INT();
    antlr4::tree::TerminalNode *MINUS();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  PriorityDeclContext* priorityDecl();

  class  GrammarRuleContext : public antlr4::ParserRuleContext {
  public:
    FgsgParser::RuleLabelContext *label = nullptr;;
    FgsgParser::ExprContext *guard = nullptr;;
    GrammarRuleContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    RuleHeadContext *ruleHead();
    ArrowContext *arrow();
    RuleBodyContext *ruleBody();
    antlr4::tree::TerminalNode *SEMI();
    std::vector<antlr4::tree::TerminalNode *> COLON();
    antlr4::tree::TerminalNode* COLON(size_t i);
    RuleLabelContext *ruleLabel();
    ExprContext *expr();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  GrammarRuleContext* grammarRule();

  class  RuleLabelContext : public antlr4::ParserRuleContext {
  public:
    RuleLabelContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *INT();
    antlr4::tree::TerminalNode *ID();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  RuleLabelContext* ruleLabel();

  class  RuleHeadContext : public antlr4::ParserRuleContext {
  public:
    FgsgParser::ModulePatternContext *predecessor = nullptr;;
    RuleHeadContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    ModulePatternContext *modulePattern();
    LeftContextContext *leftContext();
    antlr4::tree::TerminalNode *LT();
    antlr4::tree::TerminalNode *GT();
    RightContextContext *rightContext();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  RuleHeadContext* ruleHead();

  class  LeftContextContext : public antlr4::ParserRuleContext {
  public:
    LeftContextContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<ModulePatternContext *> modulePattern();
    ModulePatternContext* modulePattern(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  LeftContextContext* leftContext();

  class  RightContextContext : public antlr4::ParserRuleContext {
  public:
    RightContextContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<ContextModuleContext *> contextModule();
    ContextModuleContext* contextModule(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  RightContextContext* rightContext();

  class  ContextModuleContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *open = nullptr;;
    antlr4::Token *close = nullptr;;
    ContextModuleContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    ModulePatternContext *modulePattern();
    antlr4::tree::TerminalNode *LBRACK();
    antlr4::tree::TerminalNode *RBRACK();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  ContextModuleContext* contextModule();

  class  ModulePatternContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *name = nullptr;;
    FgsgParser::TurtleSymbolContext *turtle = nullptr;;
    ModulePatternContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *ID();
    TurtleSymbolContext *turtleSymbol();
    antlr4::tree::TerminalNode *LPAREN();
    antlr4::tree::TerminalNode *RPAREN();
    std::vector<ParamDeclContext *> paramDecl();
    ParamDeclContext* paramDecl(size_t i);
    std::vector<antlr4::tree::TerminalNode *> COMMA();
    antlr4::tree::TerminalNode* COMMA(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  ModulePatternContext* modulePattern();

  class  TurtleSymbolContext : public antlr4::ParserRuleContext {
  public:
    TurtleSymbolContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *PLUS();
    antlr4::tree::TerminalNode *MINUS();
    antlr4::tree::TerminalNode *AMP();
    antlr4::tree::TerminalNode *CARET();
    antlr4::tree::TerminalNode *BACKSLASH();
    antlr4::tree::TerminalNode *SLASH();
    antlr4::tree::TerminalNode *PIPE();
    antlr4::tree::TerminalNode *BANG();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  TurtleSymbolContext* turtleSymbol();

  class  ParamDeclContext : public antlr4::ParserRuleContext {
  public:
    ParamDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *ID();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  ParamDeclContext* paramDecl();

  class  RuleBodyContext : public antlr4::ParserRuleContext {
  public:
    FgsgParser::ExprContext *mullerGuard = nullptr;;
    RuleBodyContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    std::vector<BranchContext *> branch();
    BranchContext* branch(size_t i);
    std::vector<ArrowContext *> arrow();
    ArrowContext* arrow(size_t i);
    ExprContext *expr();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  RuleBodyContext* ruleBody();

  class  BranchContext : public antlr4::ParserRuleContext {
  public:
    FgsgParser::ExprContext *probability = nullptr;;
    BranchContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    SuccessorContext *successor();
    antlr4::tree::TerminalNode *COLON();
    ExprContext *expr();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  BranchContext* branch();

  class  ArrowContext : public antlr4::ParserRuleContext {
  public:
    ArrowContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *ARROW();
    antlr4::tree::TerminalNode *ASSIGN();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  ArrowContext* arrow();

  class  SuccessorContext : public antlr4::ParserRuleContext {
  public:
    SuccessorContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *EPSILON();
    std::vector<SequenceItemContext *> sequenceItem();
    SequenceItemContext* sequenceItem(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  SuccessorContext* successor();

  class  SequenceItemContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *symbol = nullptr;;
    antlr4::Token *polygon = nullptr;;
    SequenceItemContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    ItemContext *item();
    antlr4::tree::TerminalNode *PIPE();
    antlr4::tree::TerminalNode *OR();
    antlr4::tree::TerminalNode *COLORSTEP();
    CallArgsContext *callArgs();
    antlr4::tree::TerminalNode *LBRACE();
    antlr4::tree::TerminalNode *RBRACE();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  SequenceItemContext* sequenceItem();

  class  ItemContext : public antlr4::ParserRuleContext {
  public:
    ItemContext(antlr4::ParserRuleContext *parent, size_t invokingState);
   
    ItemContext() = default;
    void copyFrom(ItemContext *context);
    using antlr4::ParserRuleContext::copyFrom;

    virtual size_t getRuleIndex() const override;

   
  };

  class  CallItemContext : public ItemContext {
  public:
    CallItemContext(ItemContext *ctx);

    antlr4::Token *name = nullptr;
    antlr4::tree::TerminalNode *ID();
    CallArgsContext *callArgs();
    BodyContext *body();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  BracketItemContext : public ItemContext {
  public:
    BracketItemContext(ItemContext *ctx);

    antlr4::tree::TerminalNode *LBRACK();
    antlr4::tree::TerminalNode *RBRACK();
    std::vector<SequenceItemContext *> sequenceItem();
    SequenceItemContext* sequenceItem(size_t i);
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  TurtleItemContext : public ItemContext {
  public:
    TurtleItemContext(ItemContext *ctx);

    antlr4::Token *symbol = nullptr;
    antlr4::tree::TerminalNode *PLUS();
    antlr4::tree::TerminalNode *MINUS();
    antlr4::tree::TerminalNode *AMP();
    antlr4::tree::TerminalNode *AND();
    antlr4::tree::TerminalNode *CARET();
    antlr4::tree::TerminalNode *BACKSLASH();
    antlr4::tree::TerminalNode *SLASH();
    antlr4::tree::TerminalNode *BANG();
    antlr4::tree::TerminalNode *DOLLAR();
    antlr4::tree::TerminalNode *PERCENT();
    antlr4::tree::TerminalNode *QUOTE();
    CallArgsContext *callArgs();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  SurfaceItemContext : public ItemContext {
  public:
    SurfaceItemContext(ItemContext *ctx);

    antlr4::Token *surface = nullptr;
    antlr4::Token *surfaceFile = nullptr;
    antlr4::tree::TerminalNode *TILDE();
    antlr4::tree::TerminalNode *ID();
    antlr4::tree::TerminalNode *STRING();
    CallArgsContext *callArgs();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  PolygonItemContext : public ItemContext {
  public:
    PolygonItemContext(ItemContext *ctx);

    antlr4::Token *polygon = nullptr;
    antlr4::tree::TerminalNode *VERTEX();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  ItemContext* item();

  class  CallArgsContext : public antlr4::ParserRuleContext {
  public:
    CallArgsContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *LPAREN();
    antlr4::tree::TerminalNode *RPAREN();
    std::vector<ExprContext *> expr();
    ExprContext* expr(size_t i);
    std::vector<antlr4::tree::TerminalNode *> COMMA();
    antlr4::tree::TerminalNode* COMMA(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  CallArgsContext* callArgs();

  class  BodyContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *repeat = nullptr;;
    BodyContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *LBRACE();
    std::vector<BodyPartContext *> bodyPart();
    BodyPartContext* bodyPart(size_t i);
    antlr4::tree::TerminalNode *RBRACE();
    std::vector<antlr4::tree::TerminalNode *> PIPE();
    antlr4::tree::TerminalNode* PIPE(size_t i);
    std::vector<antlr4::tree::TerminalNode *> COMMA();
    antlr4::tree::TerminalNode* COMMA(size_t i);
    antlr4::tree::TerminalNode *STAR();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  BodyContext* body();

  class  BodyPartContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *selector = nullptr;;
    FgsgParser::ExprContext *size = nullptr;;
    BodyPartContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *EPSILON();
    antlr4::tree::TerminalNode *COLON();
    antlr4::tree::TerminalNode *ID();
    ExprContext *expr();
    std::vector<ItemContext *> item();
    ItemContext* item(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  BodyPartContext* bodyPart();

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

  class  TernaryExprContext : public ExprContext {
  public:
    TernaryExprContext(ExprContext *ctx);

    std::vector<ExprContext *> expr();
    ExprContext* expr(size_t i);
    antlr4::tree::TerminalNode *QUESTION();
    antlr4::tree::TerminalNode *COLON();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  BinaryExprContext : public ExprContext {
  public:
    BinaryExprContext(ExprContext *ctx);

    antlr4::Token *op = nullptr;
    std::vector<ExprContext *> expr();
    ExprContext* expr(size_t i);
    antlr4::tree::TerminalNode *CARET();
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

  class  MemberPrimaryContext : public PrimaryContext {
  public:
    MemberPrimaryContext(PrimaryContext *ctx);

    antlr4::Token *object = nullptr;
    antlr4::Token *member = nullptr;
    antlr4::Token *sub = nullptr;
    std::vector<antlr4::tree::TerminalNode *> DOT();
    antlr4::tree::TerminalNode* DOT(size_t i);
    std::vector<antlr4::tree::TerminalNode *> ID();
    antlr4::tree::TerminalNode* ID(size_t i);
    CallArgsContext *callArgs();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  IdentPrimaryContext : public PrimaryContext {
  public:
    IdentPrimaryContext(PrimaryContext *ctx);

    antlr4::Token *name = nullptr;
    antlr4::tree::TerminalNode *ID();
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

  class  VectorPrimaryContext : public PrimaryContext {
  public:
    VectorPrimaryContext(PrimaryContext *ctx);

    antlr4::tree::TerminalNode *LPAREN();
    std::vector<ExprContext *> expr();
    ExprContext* expr(size_t i);
    antlr4::tree::TerminalNode *RPAREN();
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

  class  FloatSizePrimaryContext : public PrimaryContext {
  public:
    FloatSizePrimaryContext(PrimaryContext *ctx);

    antlr4::tree::TerminalNode *TILDE();
    PrimaryContext *primary();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  CallPrimaryContext : public PrimaryContext {
  public:
    CallPrimaryContext(PrimaryContext *ctx);

    antlr4::Token *name = nullptr;
    CallArgsContext *callArgs();
    antlr4::tree::TerminalNode *ID();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  RelSizePrimaryContext : public PrimaryContext {
  public:
    RelSizePrimaryContext(PrimaryContext *ctx);

    antlr4::tree::TerminalNode *RELSIZE();
    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
  };

  class  BoolPrimaryContext : public PrimaryContext {
  public:
    BoolPrimaryContext(PrimaryContext *ctx);

    antlr4::Token *value = nullptr;
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
