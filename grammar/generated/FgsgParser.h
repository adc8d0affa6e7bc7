
// Generated from grammar/Fgsg.g4 by ANTLR 4.7.2

#pragma once


#include "antlr4-runtime.h"


namespace fgsg_grammar {


class  FgsgParser : public antlr4::Parser {
public:
  enum {
    IMPORT = 1, CONST = 2, ATTR = 3, SURFACE = 4, FIELD = 5, TEXTURE = 6, 
    TILESET = 7, DERIVE = 8, TURTLE = 9, IGNORE = 10, COLLISION = 11, AXIOM = 12, 
    PRIORITY = 13, TRUE = 14, FALSE = 15, EPSILON = 16, ARROW = 17, ASSIGN = 18, 
    EQ = 19, NEQ = 20, LE = 21, GE = 22, LT = 23, GT = 24, AND = 25, OR = 26, 
    PLUS = 27, MINUS = 28, STAR = 29, SLASH = 30, PERCENT = 31, CARET = 32, 
    BANG = 33, AMP = 34, PIPE = 35, BACKSLASH = 36, DOLLAR = 37, QUOTE = 38, 
    TILDE = 39, QUESTION = 40, COLON = 41, SEMI = 42, COMMA = 43, DOT = 44, 
    LPAREN = 45, RPAREN = 46, LBRACK = 47, RBRACK = 48, LBRACE = 49, RBRACE = 50, 
    RELSIZE = 51, FLOAT = 52, INT = 53, ID = 54, STRING = 55, UNTERMINATED_STRING = 56, 
    LINE_COMMENT = 57, BLOCK_COMMENT = 58, UNTERMINATED_COMMENT = 59, WS = 60, 
    UNKNOWN_CHAR = 61, VERTEX = 62, COLORSTEP = 63
  };

  enum {
    RuleProgram = 0, RuleStatement = 1, RuleValueDecl = 2, RuleImportDecl = 3, 
    RuleImportSetting = 4, RuleSurfaceDecl = 5, RuleFieldDecl = 6, RuleFieldSource = 7, 
    RuleFieldDesignItem = 8, RuleFieldDesignWord = 9, RuleDesignValue = 10, 
    RuleTextureDecl = 11, RuleTilesetDecl = 12, RuleTilesetItem = 13, RuleDeriveDecl = 14, 
    RuleTurtleDecl = 15, RuleTurtleSetting = 16, RuleIgnoreDecl = 17, RuleIgnoredSymbol = 18, 
    RuleCollisionDecl = 19, RuleCollisionWord = 20, RuleAxiomDecl = 21, 
    RulePriorityDecl = 22, RuleGrammarRule = 23, RuleRuleLabel = 24, RuleRuleHead = 25, 
    RuleLeftContext = 26, RuleRightContext = 27, RuleContextModule = 28, 
    RuleModulePattern = 29, RuleTurtleSymbol = 30, RuleParamDecl = 31, RuleRuleBody = 32, 
    RuleBranch = 33, RuleArrow = 34, RuleSuccessor = 35, RuleSequenceItem = 36, 
    RuleItem = 37, RuleCallArgs = 38, RuleBody = 39, RuleBodyPart = 40, 
    RuleExpr = 41, RulePrimary = 42, RuleNumber = 43
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
  class ImportDeclContext;
  class ImportSettingContext;
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
    ImportDeclContext *importDecl();
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

  class  ImportDeclContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *path = nullptr;;
    antlr4::Token *asWord = nullptr;;
    antlr4::Token *alias = nullptr;;
    ImportDeclContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *IMPORT();
    antlr4::tree::TerminalNode *SEMI();
    antlr4::tree::TerminalNode *STRING();
    antlr4::tree::TerminalNode *LPAREN();
    std::vector<ImportSettingContext *> importSetting();
    ImportSettingContext* importSetting(size_t i);
    antlr4::tree::TerminalNode *RPAREN();
    std::vector<antlr4::tree::TerminalNode *> ID();
    antlr4::tree::TerminalNode* ID(size_t i);
    std::vector<antlr4::tree::TerminalNode *> COMMA();
    antlr4::tree::TerminalNode* COMMA(size_t i);

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  ImportDeclContext* importDecl();

  class  ImportSettingContext : public antlr4::ParserRuleContext {
  public:
    antlr4::Token *name = nullptr;;
    ImportSettingContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *ASSIGN();
    ExprContext *expr();
    antlr4::tree::TerminalNode *ID();

    virtual antlrcpp::Any accept(antlr4::tree::ParseTreeVisitor *visitor) override;
   
  };

  ImportSettingContext* importSetting();

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
    antlr4::Token *merged = nullptr;;
    FgsgParser::ExprContext *size = nullptr;;
    BodyPartContext(antlr4::ParserRuleContext *parent, size_t invokingState);
    virtual size_t getRuleIndex() const override;
    antlr4::tree::TerminalNode *EPSILON();
    antlr4::tree::TerminalNode *COLON();
    antlr4::tree::TerminalNode *ID();
    ExprContext *expr();
    std::vector<ItemContext *> item();
    ItemContext* item(size_t i);
    antlr4::tree::TerminalNode *ASSIGN();

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
