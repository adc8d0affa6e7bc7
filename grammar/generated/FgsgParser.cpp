
// Generated from grammar/Fgsg.g4 by ANTLR 4.7.2


#include "FgsgVisitor.h"

#include "FgsgParser.h"


using namespace antlrcpp;
using namespace fgsg_grammar;
using namespace antlr4;

FgsgParser::FgsgParser(TokenStream *input) : Parser(input) {
  static Initializer once;
  _interpreter = new atn::ParserATNSimulator(this, _atn, _decisionToDFA, _sharedContextCache);
}

FgsgParser::~FgsgParser() {
  delete _interpreter;
}

std::string FgsgParser::getGrammarFileName() const {
  return "Fgsg.g4";
}

const std::vector<std::string>& FgsgParser::getRuleNames() const {
  return _ruleNames;
}

dfa::Vocabulary& FgsgParser::getVocabulary() const {
  return _vocabulary;
}


//----------------- ProgramContext ------------------------------------------------------------------

FgsgParser::ProgramContext::ProgramContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::ProgramContext::EOF() {
  return getToken(FgsgParser::EOF, 0);
}

std::vector<FgsgParser::StatementContext *> FgsgParser::ProgramContext::statement() {
  return getRuleContexts<FgsgParser::StatementContext>();
}

FgsgParser::StatementContext* FgsgParser::ProgramContext::statement(size_t i) {
  return getRuleContext<FgsgParser::StatementContext>(i);
}


size_t FgsgParser::ProgramContext::getRuleIndex() const {
  return FgsgParser::RuleProgram;
}

antlrcpp::Any FgsgParser::ProgramContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitProgram(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::ProgramContext* FgsgParser::program() {
  ProgramContext *_localctx = _tracker.createInstance<ProgramContext>(_ctx, getState());
  enterRule(_localctx, 0, FgsgParser::RuleProgram);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(91);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while ((((_la & ~ 0x3fULL) == 0) &&
      ((1ULL << _la) & ((1ULL << FgsgParser::IMPORT)
      | (1ULL << FgsgParser::CONST)
      | (1ULL << FgsgParser::ATTR)
      | (1ULL << FgsgParser::SURFACE)
      | (1ULL << FgsgParser::FIELD)
      | (1ULL << FgsgParser::TEXTURE)
      | (1ULL << FgsgParser::TILESET)
      | (1ULL << FgsgParser::DERIVE)
      | (1ULL << FgsgParser::TURTLE)
      | (1ULL << FgsgParser::IGNORE)
      | (1ULL << FgsgParser::COLLISION)
      | (1ULL << FgsgParser::AXIOM)
      | (1ULL << FgsgParser::PRIORITY)
      | (1ULL << FgsgParser::PLUS)
      | (1ULL << FgsgParser::MINUS)
      | (1ULL << FgsgParser::SLASH)
      | (1ULL << FgsgParser::CARET)
      | (1ULL << FgsgParser::BANG)
      | (1ULL << FgsgParser::AMP)
      | (1ULL << FgsgParser::PIPE)
      | (1ULL << FgsgParser::BACKSLASH)
      | (1ULL << FgsgParser::SEMI)
      | (1ULL << FgsgParser::INT)
      | (1ULL << FgsgParser::ID))) != 0)) {
      setState(88);
      statement();
      setState(93);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(94);
    match(FgsgParser::EOF);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- StatementContext ------------------------------------------------------------------

FgsgParser::StatementContext::StatementContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

FgsgParser::ImportDeclContext* FgsgParser::StatementContext::importDecl() {
  return getRuleContext<FgsgParser::ImportDeclContext>(0);
}

FgsgParser::ValueDeclContext* FgsgParser::StatementContext::valueDecl() {
  return getRuleContext<FgsgParser::ValueDeclContext>(0);
}

FgsgParser::SurfaceDeclContext* FgsgParser::StatementContext::surfaceDecl() {
  return getRuleContext<FgsgParser::SurfaceDeclContext>(0);
}

FgsgParser::FieldDeclContext* FgsgParser::StatementContext::fieldDecl() {
  return getRuleContext<FgsgParser::FieldDeclContext>(0);
}

FgsgParser::TextureDeclContext* FgsgParser::StatementContext::textureDecl() {
  return getRuleContext<FgsgParser::TextureDeclContext>(0);
}

FgsgParser::TilesetDeclContext* FgsgParser::StatementContext::tilesetDecl() {
  return getRuleContext<FgsgParser::TilesetDeclContext>(0);
}

FgsgParser::DeriveDeclContext* FgsgParser::StatementContext::deriveDecl() {
  return getRuleContext<FgsgParser::DeriveDeclContext>(0);
}

FgsgParser::TurtleDeclContext* FgsgParser::StatementContext::turtleDecl() {
  return getRuleContext<FgsgParser::TurtleDeclContext>(0);
}

FgsgParser::IgnoreDeclContext* FgsgParser::StatementContext::ignoreDecl() {
  return getRuleContext<FgsgParser::IgnoreDeclContext>(0);
}

FgsgParser::CollisionDeclContext* FgsgParser::StatementContext::collisionDecl() {
  return getRuleContext<FgsgParser::CollisionDeclContext>(0);
}

FgsgParser::AxiomDeclContext* FgsgParser::StatementContext::axiomDecl() {
  return getRuleContext<FgsgParser::AxiomDeclContext>(0);
}

FgsgParser::PriorityDeclContext* FgsgParser::StatementContext::priorityDecl() {
  return getRuleContext<FgsgParser::PriorityDeclContext>(0);
}

FgsgParser::GrammarRuleContext* FgsgParser::StatementContext::grammarRule() {
  return getRuleContext<FgsgParser::GrammarRuleContext>(0);
}

tree::TerminalNode* FgsgParser::StatementContext::SEMI() {
  return getToken(FgsgParser::SEMI, 0);
}


size_t FgsgParser::StatementContext::getRuleIndex() const {
  return FgsgParser::RuleStatement;
}

antlrcpp::Any FgsgParser::StatementContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitStatement(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::StatementContext* FgsgParser::statement() {
  StatementContext *_localctx = _tracker.createInstance<StatementContext>(_ctx, getState());
  enterRule(_localctx, 2, FgsgParser::RuleStatement);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(110);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case FgsgParser::IMPORT: {
        enterOuterAlt(_localctx, 1);
        setState(96);
        importDecl();
        break;
      }

      case FgsgParser::CONST:
      case FgsgParser::ATTR: {
        enterOuterAlt(_localctx, 2);
        setState(97);
        valueDecl();
        break;
      }

      case FgsgParser::SURFACE: {
        enterOuterAlt(_localctx, 3);
        setState(98);
        surfaceDecl();
        break;
      }

      case FgsgParser::FIELD: {
        enterOuterAlt(_localctx, 4);
        setState(99);
        fieldDecl();
        break;
      }

      case FgsgParser::TEXTURE: {
        enterOuterAlt(_localctx, 5);
        setState(100);
        textureDecl();
        break;
      }

      case FgsgParser::TILESET: {
        enterOuterAlt(_localctx, 6);
        setState(101);
        tilesetDecl();
        break;
      }

      case FgsgParser::DERIVE: {
        enterOuterAlt(_localctx, 7);
        setState(102);
        deriveDecl();
        break;
      }

      case FgsgParser::TURTLE: {
        enterOuterAlt(_localctx, 8);
        setState(103);
        turtleDecl();
        break;
      }

      case FgsgParser::IGNORE: {
        enterOuterAlt(_localctx, 9);
        setState(104);
        ignoreDecl();
        break;
      }

      case FgsgParser::COLLISION: {
        enterOuterAlt(_localctx, 10);
        setState(105);
        collisionDecl();
        break;
      }

      case FgsgParser::AXIOM: {
        enterOuterAlt(_localctx, 11);
        setState(106);
        axiomDecl();
        break;
      }

      case FgsgParser::PRIORITY: {
        enterOuterAlt(_localctx, 12);
        setState(107);
        priorityDecl();
        break;
      }

      case FgsgParser::PLUS:
      case FgsgParser::MINUS:
      case FgsgParser::SLASH:
      case FgsgParser::CARET:
      case FgsgParser::BANG:
      case FgsgParser::AMP:
      case FgsgParser::PIPE:
      case FgsgParser::BACKSLASH:
      case FgsgParser::INT:
      case FgsgParser::ID: {
        enterOuterAlt(_localctx, 13);
        setState(108);
        grammarRule();
        break;
      }

      case FgsgParser::SEMI: {
        enterOuterAlt(_localctx, 14);
        setState(109);
        match(FgsgParser::SEMI);
        break;
      }

    default:
      throw NoViableAltException(this);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ValueDeclContext ------------------------------------------------------------------

FgsgParser::ValueDeclContext::ValueDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::ValueDeclContext::ASSIGN() {
  return getToken(FgsgParser::ASSIGN, 0);
}

FgsgParser::ExprContext* FgsgParser::ValueDeclContext::expr() {
  return getRuleContext<FgsgParser::ExprContext>(0);
}

tree::TerminalNode* FgsgParser::ValueDeclContext::SEMI() {
  return getToken(FgsgParser::SEMI, 0);
}

tree::TerminalNode* FgsgParser::ValueDeclContext::ID() {
  return getToken(FgsgParser::ID, 0);
}

tree::TerminalNode* FgsgParser::ValueDeclContext::CONST() {
  return getToken(FgsgParser::CONST, 0);
}

tree::TerminalNode* FgsgParser::ValueDeclContext::ATTR() {
  return getToken(FgsgParser::ATTR, 0);
}


size_t FgsgParser::ValueDeclContext::getRuleIndex() const {
  return FgsgParser::RuleValueDecl;
}

antlrcpp::Any FgsgParser::ValueDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitValueDecl(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::ValueDeclContext* FgsgParser::valueDecl() {
  ValueDeclContext *_localctx = _tracker.createInstance<ValueDeclContext>(_ctx, getState());
  enterRule(_localctx, 4, FgsgParser::RuleValueDecl);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(112);
    dynamic_cast<ValueDeclContext *>(_localctx)->kind = _input->LT(1);
    _la = _input->LA(1);
    if (!(_la == FgsgParser::CONST

    || _la == FgsgParser::ATTR)) {
      dynamic_cast<ValueDeclContext *>(_localctx)->kind = _errHandler->recoverInline(this);
    }
    else {
      _errHandler->reportMatch(this);
      consume();
    }
    setState(113);
    dynamic_cast<ValueDeclContext *>(_localctx)->name = match(FgsgParser::ID);
    setState(114);
    match(FgsgParser::ASSIGN);
    setState(115);
    expr(0);
    setState(116);
    match(FgsgParser::SEMI);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ImportDeclContext ------------------------------------------------------------------

FgsgParser::ImportDeclContext::ImportDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::ImportDeclContext::IMPORT() {
  return getToken(FgsgParser::IMPORT, 0);
}

tree::TerminalNode* FgsgParser::ImportDeclContext::SEMI() {
  return getToken(FgsgParser::SEMI, 0);
}

tree::TerminalNode* FgsgParser::ImportDeclContext::STRING() {
  return getToken(FgsgParser::STRING, 0);
}

tree::TerminalNode* FgsgParser::ImportDeclContext::LPAREN() {
  return getToken(FgsgParser::LPAREN, 0);
}

std::vector<FgsgParser::ImportSettingContext *> FgsgParser::ImportDeclContext::importSetting() {
  return getRuleContexts<FgsgParser::ImportSettingContext>();
}

FgsgParser::ImportSettingContext* FgsgParser::ImportDeclContext::importSetting(size_t i) {
  return getRuleContext<FgsgParser::ImportSettingContext>(i);
}

tree::TerminalNode* FgsgParser::ImportDeclContext::RPAREN() {
  return getToken(FgsgParser::RPAREN, 0);
}

std::vector<tree::TerminalNode *> FgsgParser::ImportDeclContext::ID() {
  return getTokens(FgsgParser::ID);
}

tree::TerminalNode* FgsgParser::ImportDeclContext::ID(size_t i) {
  return getToken(FgsgParser::ID, i);
}

std::vector<tree::TerminalNode *> FgsgParser::ImportDeclContext::COMMA() {
  return getTokens(FgsgParser::COMMA);
}

tree::TerminalNode* FgsgParser::ImportDeclContext::COMMA(size_t i) {
  return getToken(FgsgParser::COMMA, i);
}


size_t FgsgParser::ImportDeclContext::getRuleIndex() const {
  return FgsgParser::RuleImportDecl;
}

antlrcpp::Any FgsgParser::ImportDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitImportDecl(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::ImportDeclContext* FgsgParser::importDecl() {
  ImportDeclContext *_localctx = _tracker.createInstance<ImportDeclContext>(_ctx, getState());
  enterRule(_localctx, 6, FgsgParser::RuleImportDecl);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(118);
    match(FgsgParser::IMPORT);
    setState(119);
    dynamic_cast<ImportDeclContext *>(_localctx)->path = match(FgsgParser::STRING);
    setState(122);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == FgsgParser::ID) {
      setState(120);
      dynamic_cast<ImportDeclContext *>(_localctx)->asWord = match(FgsgParser::ID);
      setState(121);
      dynamic_cast<ImportDeclContext *>(_localctx)->alias = match(FgsgParser::ID);
    }
    setState(135);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == FgsgParser::LPAREN) {
      setState(124);
      match(FgsgParser::LPAREN);
      setState(125);
      importSetting();
      setState(130);
      _errHandler->sync(this);
      _la = _input->LA(1);
      while (_la == FgsgParser::COMMA) {
        setState(126);
        match(FgsgParser::COMMA);
        setState(127);
        importSetting();
        setState(132);
        _errHandler->sync(this);
        _la = _input->LA(1);
      }
      setState(133);
      match(FgsgParser::RPAREN);
    }
    setState(137);
    match(FgsgParser::SEMI);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ImportSettingContext ------------------------------------------------------------------

FgsgParser::ImportSettingContext::ImportSettingContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::ImportSettingContext::ASSIGN() {
  return getToken(FgsgParser::ASSIGN, 0);
}

FgsgParser::ExprContext* FgsgParser::ImportSettingContext::expr() {
  return getRuleContext<FgsgParser::ExprContext>(0);
}

tree::TerminalNode* FgsgParser::ImportSettingContext::ID() {
  return getToken(FgsgParser::ID, 0);
}


size_t FgsgParser::ImportSettingContext::getRuleIndex() const {
  return FgsgParser::RuleImportSetting;
}

antlrcpp::Any FgsgParser::ImportSettingContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitImportSetting(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::ImportSettingContext* FgsgParser::importSetting() {
  ImportSettingContext *_localctx = _tracker.createInstance<ImportSettingContext>(_ctx, getState());
  enterRule(_localctx, 8, FgsgParser::RuleImportSetting);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(139);
    dynamic_cast<ImportSettingContext *>(_localctx)->name = match(FgsgParser::ID);
    setState(140);
    match(FgsgParser::ASSIGN);
    setState(141);
    expr(0);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- SurfaceDeclContext ------------------------------------------------------------------

FgsgParser::SurfaceDeclContext::SurfaceDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::SurfaceDeclContext::SURFACE() {
  return getToken(FgsgParser::SURFACE, 0);
}

tree::TerminalNode* FgsgParser::SurfaceDeclContext::SEMI() {
  return getToken(FgsgParser::SEMI, 0);
}

tree::TerminalNode* FgsgParser::SurfaceDeclContext::STRING() {
  return getToken(FgsgParser::STRING, 0);
}

tree::TerminalNode* FgsgParser::SurfaceDeclContext::ID() {
  return getToken(FgsgParser::ID, 0);
}

FgsgParser::CallArgsContext* FgsgParser::SurfaceDeclContext::callArgs() {
  return getRuleContext<FgsgParser::CallArgsContext>(0);
}


size_t FgsgParser::SurfaceDeclContext::getRuleIndex() const {
  return FgsgParser::RuleSurfaceDecl;
}

antlrcpp::Any FgsgParser::SurfaceDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitSurfaceDecl(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::SurfaceDeclContext* FgsgParser::surfaceDecl() {
  SurfaceDeclContext *_localctx = _tracker.createInstance<SurfaceDeclContext>(_ctx, getState());
  enterRule(_localctx, 10, FgsgParser::RuleSurfaceDecl);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(143);
    match(FgsgParser::SURFACE);
    setState(149);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case FgsgParser::STRING: {
        setState(144);
        dynamic_cast<SurfaceDeclContext *>(_localctx)->path = match(FgsgParser::STRING);
        break;
      }

      case FgsgParser::ID: {
        setState(145);
        dynamic_cast<SurfaceDeclContext *>(_localctx)->generator = match(FgsgParser::ID);
        setState(147);
        _errHandler->sync(this);

        _la = _input->LA(1);
        if (_la == FgsgParser::LPAREN) {
          setState(146);
          callArgs();
        }
        break;
      }

    default:
      throw NoViableAltException(this);
    }
    setState(151);
    match(FgsgParser::SEMI);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- FieldDeclContext ------------------------------------------------------------------

FgsgParser::FieldDeclContext::FieldDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::FieldDeclContext::FIELD() {
  return getToken(FgsgParser::FIELD, 0);
}

tree::TerminalNode* FgsgParser::FieldDeclContext::ASSIGN() {
  return getToken(FgsgParser::ASSIGN, 0);
}

FgsgParser::FieldSourceContext* FgsgParser::FieldDeclContext::fieldSource() {
  return getRuleContext<FgsgParser::FieldSourceContext>(0);
}

tree::TerminalNode* FgsgParser::FieldDeclContext::SEMI() {
  return getToken(FgsgParser::SEMI, 0);
}

tree::TerminalNode* FgsgParser::FieldDeclContext::ID() {
  return getToken(FgsgParser::ID, 0);
}


size_t FgsgParser::FieldDeclContext::getRuleIndex() const {
  return FgsgParser::RuleFieldDecl;
}

antlrcpp::Any FgsgParser::FieldDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitFieldDecl(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::FieldDeclContext* FgsgParser::fieldDecl() {
  FieldDeclContext *_localctx = _tracker.createInstance<FieldDeclContext>(_ctx, getState());
  enterRule(_localctx, 12, FgsgParser::RuleFieldDecl);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(153);
    match(FgsgParser::FIELD);
    setState(154);
    dynamic_cast<FieldDeclContext *>(_localctx)->name = match(FgsgParser::ID);
    setState(155);
    match(FgsgParser::ASSIGN);
    setState(156);
    fieldSource();
    setState(157);
    match(FgsgParser::SEMI);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- FieldSourceContext ------------------------------------------------------------------

FgsgParser::FieldSourceContext::FieldSourceContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::FieldSourceContext::LBRACE() {
  return getToken(FgsgParser::LBRACE, 0);
}

tree::TerminalNode* FgsgParser::FieldSourceContext::RBRACE() {
  return getToken(FgsgParser::RBRACE, 0);
}

std::vector<tree::TerminalNode *> FgsgParser::FieldSourceContext::ID() {
  return getTokens(FgsgParser::ID);
}

tree::TerminalNode* FgsgParser::FieldSourceContext::ID(size_t i) {
  return getToken(FgsgParser::ID, i);
}

std::vector<FgsgParser::FieldDesignItemContext *> FgsgParser::FieldSourceContext::fieldDesignItem() {
  return getRuleContexts<FgsgParser::FieldDesignItemContext>();
}

FgsgParser::FieldDesignItemContext* FgsgParser::FieldSourceContext::fieldDesignItem(size_t i) {
  return getRuleContext<FgsgParser::FieldDesignItemContext>(i);
}

FgsgParser::CallArgsContext* FgsgParser::FieldSourceContext::callArgs() {
  return getRuleContext<FgsgParser::CallArgsContext>(0);
}


size_t FgsgParser::FieldSourceContext::getRuleIndex() const {
  return FgsgParser::RuleFieldSource;
}

antlrcpp::Any FgsgParser::FieldSourceContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitFieldSource(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::FieldSourceContext* FgsgParser::fieldSource() {
  FieldSourceContext *_localctx = _tracker.createInstance<FieldSourceContext>(_ctx, getState());
  enterRule(_localctx, 14, FgsgParser::RuleFieldSource);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(173);
    _errHandler->sync(this);
    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 9, _ctx)) {
    case 1: {
      enterOuterAlt(_localctx, 1);
      setState(159);
      dynamic_cast<FieldSourceContext *>(_localctx)->designWord = match(FgsgParser::ID);
      setState(160);
      dynamic_cast<FieldSourceContext *>(_localctx)->function = match(FgsgParser::ID);
      setState(161);
      match(FgsgParser::LBRACE);
      setState(165);
      _errHandler->sync(this);
      _la = _input->LA(1);
      while (_la == FgsgParser::ID) {
        setState(162);
        fieldDesignItem();
        setState(167);
        _errHandler->sync(this);
        _la = _input->LA(1);
      }
      setState(168);
      match(FgsgParser::RBRACE);
      break;
    }

    case 2: {
      enterOuterAlt(_localctx, 2);
      setState(169);
      dynamic_cast<FieldSourceContext *>(_localctx)->function = match(FgsgParser::ID);
      setState(171);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == FgsgParser::LPAREN) {
        setState(170);
        callArgs();
      }
      break;
    }

    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- FieldDesignItemContext ------------------------------------------------------------------

FgsgParser::FieldDesignItemContext::FieldDesignItemContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::FieldDesignItemContext::SEMI() {
  return getToken(FgsgParser::SEMI, 0);
}

tree::TerminalNode* FgsgParser::FieldDesignItemContext::ID() {
  return getToken(FgsgParser::ID, 0);
}

std::vector<FgsgParser::FieldDesignWordContext *> FgsgParser::FieldDesignItemContext::fieldDesignWord() {
  return getRuleContexts<FgsgParser::FieldDesignWordContext>();
}

FgsgParser::FieldDesignWordContext* FgsgParser::FieldDesignItemContext::fieldDesignWord(size_t i) {
  return getRuleContext<FgsgParser::FieldDesignWordContext>(i);
}


size_t FgsgParser::FieldDesignItemContext::getRuleIndex() const {
  return FgsgParser::RuleFieldDesignItem;
}

antlrcpp::Any FgsgParser::FieldDesignItemContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitFieldDesignItem(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::FieldDesignItemContext* FgsgParser::fieldDesignItem() {
  FieldDesignItemContext *_localctx = _tracker.createInstance<FieldDesignItemContext>(_ctx, getState());
  enterRule(_localctx, 16, FgsgParser::RuleFieldDesignItem);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(175);
    dynamic_cast<FieldDesignItemContext *>(_localctx)->kind = match(FgsgParser::ID);
    setState(179);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while ((((_la & ~ 0x3fULL) == 0) &&
      ((1ULL << _la) & ((1ULL << FgsgParser::TRUE)
      | (1ULL << FgsgParser::FALSE)
      | (1ULL << FgsgParser::PLUS)
      | (1ULL << FgsgParser::MINUS)
      | (1ULL << FgsgParser::LPAREN)
      | (1ULL << FgsgParser::FLOAT)
      | (1ULL << FgsgParser::INT)
      | (1ULL << FgsgParser::ID)
      | (1ULL << FgsgParser::STRING))) != 0)) {
      setState(176);
      fieldDesignWord();
      setState(181);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(182);
    match(FgsgParser::SEMI);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- FieldDesignWordContext ------------------------------------------------------------------

FgsgParser::FieldDesignWordContext::FieldDesignWordContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::FieldDesignWordContext::ID() {
  return getToken(FgsgParser::ID, 0);
}

FgsgParser::DesignValueContext* FgsgParser::FieldDesignWordContext::designValue() {
  return getRuleContext<FgsgParser::DesignValueContext>(0);
}


size_t FgsgParser::FieldDesignWordContext::getRuleIndex() const {
  return FgsgParser::RuleFieldDesignWord;
}

antlrcpp::Any FgsgParser::FieldDesignWordContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitFieldDesignWord(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::FieldDesignWordContext* FgsgParser::fieldDesignWord() {
  FieldDesignWordContext *_localctx = _tracker.createInstance<FieldDesignWordContext>(_ctx, getState());
  enterRule(_localctx, 18, FgsgParser::RuleFieldDesignWord);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(189);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case FgsgParser::ID: {
        enterOuterAlt(_localctx, 1);
        setState(184);
        dynamic_cast<FieldDesignWordContext *>(_localctx)->keyword = match(FgsgParser::ID);
        setState(186);
        _errHandler->sync(this);

        switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 11, _ctx)) {
        case 1: {
          setState(185);
          designValue();
          break;
        }

        }
        break;
      }

      case FgsgParser::TRUE:
      case FgsgParser::FALSE:
      case FgsgParser::PLUS:
      case FgsgParser::MINUS:
      case FgsgParser::LPAREN:
      case FgsgParser::FLOAT:
      case FgsgParser::INT:
      case FgsgParser::STRING: {
        enterOuterAlt(_localctx, 2);
        setState(188);
        designValue();
        break;
      }

    default:
      throw NoViableAltException(this);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- DesignValueContext ------------------------------------------------------------------

FgsgParser::DesignValueContext::DesignValueContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

FgsgParser::NumberContext* FgsgParser::DesignValueContext::number() {
  return getRuleContext<FgsgParser::NumberContext>(0);
}

tree::TerminalNode* FgsgParser::DesignValueContext::STRING() {
  return getToken(FgsgParser::STRING, 0);
}

tree::TerminalNode* FgsgParser::DesignValueContext::TRUE() {
  return getToken(FgsgParser::TRUE, 0);
}

tree::TerminalNode* FgsgParser::DesignValueContext::FALSE() {
  return getToken(FgsgParser::FALSE, 0);
}

tree::TerminalNode* FgsgParser::DesignValueContext::LPAREN() {
  return getToken(FgsgParser::LPAREN, 0);
}

std::vector<FgsgParser::ExprContext *> FgsgParser::DesignValueContext::expr() {
  return getRuleContexts<FgsgParser::ExprContext>();
}

FgsgParser::ExprContext* FgsgParser::DesignValueContext::expr(size_t i) {
  return getRuleContext<FgsgParser::ExprContext>(i);
}

tree::TerminalNode* FgsgParser::DesignValueContext::RPAREN() {
  return getToken(FgsgParser::RPAREN, 0);
}

tree::TerminalNode* FgsgParser::DesignValueContext::MINUS() {
  return getToken(FgsgParser::MINUS, 0);
}

tree::TerminalNode* FgsgParser::DesignValueContext::PLUS() {
  return getToken(FgsgParser::PLUS, 0);
}

std::vector<tree::TerminalNode *> FgsgParser::DesignValueContext::COMMA() {
  return getTokens(FgsgParser::COMMA);
}

tree::TerminalNode* FgsgParser::DesignValueContext::COMMA(size_t i) {
  return getToken(FgsgParser::COMMA, i);
}


size_t FgsgParser::DesignValueContext::getRuleIndex() const {
  return FgsgParser::RuleDesignValue;
}

antlrcpp::Any FgsgParser::DesignValueContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitDesignValue(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::DesignValueContext* FgsgParser::designValue() {
  DesignValueContext *_localctx = _tracker.createInstance<DesignValueContext>(_ctx, getState());
  enterRule(_localctx, 20, FgsgParser::RuleDesignValue);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(192);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == FgsgParser::PLUS

    || _la == FgsgParser::MINUS) {
      setState(191);
      dynamic_cast<DesignValueContext *>(_localctx)->sign = _input->LT(1);
      _la = _input->LA(1);
      if (!(_la == FgsgParser::PLUS

      || _la == FgsgParser::MINUS)) {
        dynamic_cast<DesignValueContext *>(_localctx)->sign = _errHandler->recoverInline(this);
      }
      else {
        _errHandler->reportMatch(this);
        consume();
      }
    }
    setState(209);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case FgsgParser::FLOAT:
      case FgsgParser::INT: {
        setState(194);
        number();
        break;
      }

      case FgsgParser::STRING: {
        setState(195);
        match(FgsgParser::STRING);
        break;
      }

      case FgsgParser::TRUE: {
        setState(196);
        match(FgsgParser::TRUE);
        break;
      }

      case FgsgParser::FALSE: {
        setState(197);
        match(FgsgParser::FALSE);
        break;
      }

      case FgsgParser::LPAREN: {
        setState(198);
        match(FgsgParser::LPAREN);
        setState(199);
        expr(0);
        setState(204);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == FgsgParser::COMMA) {
          setState(200);
          match(FgsgParser::COMMA);
          setState(201);
          expr(0);
          setState(206);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
        setState(207);
        match(FgsgParser::RPAREN);
        break;
      }

    default:
      throw NoViableAltException(this);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- TextureDeclContext ------------------------------------------------------------------

FgsgParser::TextureDeclContext::TextureDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::TextureDeclContext::TEXTURE() {
  return getToken(FgsgParser::TEXTURE, 0);
}

tree::TerminalNode* FgsgParser::TextureDeclContext::ASSIGN() {
  return getToken(FgsgParser::ASSIGN, 0);
}

tree::TerminalNode* FgsgParser::TextureDeclContext::SEMI() {
  return getToken(FgsgParser::SEMI, 0);
}

tree::TerminalNode* FgsgParser::TextureDeclContext::ID() {
  return getToken(FgsgParser::ID, 0);
}

tree::TerminalNode* FgsgParser::TextureDeclContext::STRING() {
  return getToken(FgsgParser::STRING, 0);
}


size_t FgsgParser::TextureDeclContext::getRuleIndex() const {
  return FgsgParser::RuleTextureDecl;
}

antlrcpp::Any FgsgParser::TextureDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitTextureDecl(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::TextureDeclContext* FgsgParser::textureDecl() {
  TextureDeclContext *_localctx = _tracker.createInstance<TextureDeclContext>(_ctx, getState());
  enterRule(_localctx, 22, FgsgParser::RuleTextureDecl);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(211);
    match(FgsgParser::TEXTURE);
    setState(212);
    dynamic_cast<TextureDeclContext *>(_localctx)->name = match(FgsgParser::ID);
    setState(213);
    match(FgsgParser::ASSIGN);
    setState(214);
    dynamic_cast<TextureDeclContext *>(_localctx)->path = match(FgsgParser::STRING);
    setState(215);
    match(FgsgParser::SEMI);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- TilesetDeclContext ------------------------------------------------------------------

FgsgParser::TilesetDeclContext::TilesetDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::TilesetDeclContext::TILESET() {
  return getToken(FgsgParser::TILESET, 0);
}

tree::TerminalNode* FgsgParser::TilesetDeclContext::LBRACE() {
  return getToken(FgsgParser::LBRACE, 0);
}

tree::TerminalNode* FgsgParser::TilesetDeclContext::RBRACE() {
  return getToken(FgsgParser::RBRACE, 0);
}

tree::TerminalNode* FgsgParser::TilesetDeclContext::SEMI() {
  return getToken(FgsgParser::SEMI, 0);
}

tree::TerminalNode* FgsgParser::TilesetDeclContext::ID() {
  return getToken(FgsgParser::ID, 0);
}

std::vector<FgsgParser::TilesetItemContext *> FgsgParser::TilesetDeclContext::tilesetItem() {
  return getRuleContexts<FgsgParser::TilesetItemContext>();
}

FgsgParser::TilesetItemContext* FgsgParser::TilesetDeclContext::tilesetItem(size_t i) {
  return getRuleContext<FgsgParser::TilesetItemContext>(i);
}


size_t FgsgParser::TilesetDeclContext::getRuleIndex() const {
  return FgsgParser::RuleTilesetDecl;
}

antlrcpp::Any FgsgParser::TilesetDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitTilesetDecl(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::TilesetDeclContext* FgsgParser::tilesetDecl() {
  TilesetDeclContext *_localctx = _tracker.createInstance<TilesetDeclContext>(_ctx, getState());
  enterRule(_localctx, 24, FgsgParser::RuleTilesetDecl);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(217);
    match(FgsgParser::TILESET);
    setState(218);
    dynamic_cast<TilesetDeclContext *>(_localctx)->name = match(FgsgParser::ID);
    setState(219);
    match(FgsgParser::LBRACE);
    setState(223);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while (_la == FgsgParser::ID) {
      setState(220);
      tilesetItem();
      setState(225);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(226);
    match(FgsgParser::RBRACE);
    setState(227);
    match(FgsgParser::SEMI);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- TilesetItemContext ------------------------------------------------------------------

FgsgParser::TilesetItemContext::TilesetItemContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<FgsgParser::ExprContext *> FgsgParser::TilesetItemContext::expr() {
  return getRuleContexts<FgsgParser::ExprContext>();
}

FgsgParser::ExprContext* FgsgParser::TilesetItemContext::expr(size_t i) {
  return getRuleContext<FgsgParser::ExprContext>(i);
}

tree::TerminalNode* FgsgParser::TilesetItemContext::SEMI() {
  return getToken(FgsgParser::SEMI, 0);
}

std::vector<tree::TerminalNode *> FgsgParser::TilesetItemContext::ID() {
  return getTokens(FgsgParser::ID);
}

tree::TerminalNode* FgsgParser::TilesetItemContext::ID(size_t i) {
  return getToken(FgsgParser::ID, i);
}

tree::TerminalNode* FgsgParser::TilesetItemContext::ASSIGN() {
  return getToken(FgsgParser::ASSIGN, 0);
}

std::vector<tree::TerminalNode *> FgsgParser::TilesetItemContext::COMMA() {
  return getTokens(FgsgParser::COMMA);
}

tree::TerminalNode* FgsgParser::TilesetItemContext::COMMA(size_t i) {
  return getToken(FgsgParser::COMMA, i);
}


size_t FgsgParser::TilesetItemContext::getRuleIndex() const {
  return FgsgParser::RuleTilesetItem;
}

antlrcpp::Any FgsgParser::TilesetItemContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitTilesetItem(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::TilesetItemContext* FgsgParser::tilesetItem() {
  TilesetItemContext *_localctx = _tracker.createInstance<TilesetItemContext>(_ctx, getState());
  enterRule(_localctx, 26, FgsgParser::RuleTilesetItem);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(229);
    dynamic_cast<TilesetItemContext *>(_localctx)->kind = match(FgsgParser::ID);
    setState(232);
    _errHandler->sync(this);

    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 17, _ctx)) {
    case 1: {
      setState(230);
      dynamic_cast<TilesetItemContext *>(_localctx)->itemName = match(FgsgParser::ID);
      setState(231);
      match(FgsgParser::ASSIGN);
      break;
    }

    }
    setState(234);
    expr(0);
    setState(239);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while (_la == FgsgParser::COMMA) {
      setState(235);
      match(FgsgParser::COMMA);
      setState(236);
      expr(0);
      setState(241);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(242);
    match(FgsgParser::SEMI);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- DeriveDeclContext ------------------------------------------------------------------

FgsgParser::DeriveDeclContext::DeriveDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::DeriveDeclContext::DERIVE() {
  return getToken(FgsgParser::DERIVE, 0);
}

tree::TerminalNode* FgsgParser::DeriveDeclContext::SEMI() {
  return getToken(FgsgParser::SEMI, 0);
}

tree::TerminalNode* FgsgParser::DeriveDeclContext::ID() {
  return getToken(FgsgParser::ID, 0);
}

FgsgParser::ExprContext* FgsgParser::DeriveDeclContext::expr() {
  return getRuleContext<FgsgParser::ExprContext>(0);
}


size_t FgsgParser::DeriveDeclContext::getRuleIndex() const {
  return FgsgParser::RuleDeriveDecl;
}

antlrcpp::Any FgsgParser::DeriveDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitDeriveDecl(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::DeriveDeclContext* FgsgParser::deriveDecl() {
  DeriveDeclContext *_localctx = _tracker.createInstance<DeriveDeclContext>(_ctx, getState());
  enterRule(_localctx, 28, FgsgParser::RuleDeriveDecl);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(244);
    match(FgsgParser::DERIVE);
    setState(245);
    dynamic_cast<DeriveDeclContext *>(_localctx)->order = match(FgsgParser::ID);
    setState(247);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if ((((_la & ~ 0x3fULL) == 0) &&
      ((1ULL << _la) & ((1ULL << FgsgParser::TRUE)
      | (1ULL << FgsgParser::FALSE)
      | (1ULL << FgsgParser::PLUS)
      | (1ULL << FgsgParser::MINUS)
      | (1ULL << FgsgParser::BANG)
      | (1ULL << FgsgParser::TILDE)
      | (1ULL << FgsgParser::LPAREN)
      | (1ULL << FgsgParser::RELSIZE)
      | (1ULL << FgsgParser::FLOAT)
      | (1ULL << FgsgParser::INT)
      | (1ULL << FgsgParser::ID)
      | (1ULL << FgsgParser::STRING))) != 0)) {
      setState(246);
      dynamic_cast<DeriveDeclContext *>(_localctx)->steps = expr(0);
    }
    setState(249);
    match(FgsgParser::SEMI);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- TurtleDeclContext ------------------------------------------------------------------

FgsgParser::TurtleDeclContext::TurtleDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::TurtleDeclContext::TURTLE() {
  return getToken(FgsgParser::TURTLE, 0);
}

tree::TerminalNode* FgsgParser::TurtleDeclContext::SEMI() {
  return getToken(FgsgParser::SEMI, 0);
}

std::vector<FgsgParser::TurtleSettingContext *> FgsgParser::TurtleDeclContext::turtleSetting() {
  return getRuleContexts<FgsgParser::TurtleSettingContext>();
}

FgsgParser::TurtleSettingContext* FgsgParser::TurtleDeclContext::turtleSetting(size_t i) {
  return getRuleContext<FgsgParser::TurtleSettingContext>(i);
}


size_t FgsgParser::TurtleDeclContext::getRuleIndex() const {
  return FgsgParser::RuleTurtleDecl;
}

antlrcpp::Any FgsgParser::TurtleDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitTurtleDecl(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::TurtleDeclContext* FgsgParser::turtleDecl() {
  TurtleDeclContext *_localctx = _tracker.createInstance<TurtleDeclContext>(_ctx, getState());
  enterRule(_localctx, 30, FgsgParser::RuleTurtleDecl);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(251);
    match(FgsgParser::TURTLE);
    setState(255);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while (_la == FgsgParser::ID) {
      setState(252);
      turtleSetting();
      setState(257);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(258);
    match(FgsgParser::SEMI);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- TurtleSettingContext ------------------------------------------------------------------

FgsgParser::TurtleSettingContext::TurtleSettingContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::TurtleSettingContext::ID() {
  return getToken(FgsgParser::ID, 0);
}

FgsgParser::ExprContext* FgsgParser::TurtleSettingContext::expr() {
  return getRuleContext<FgsgParser::ExprContext>(0);
}


size_t FgsgParser::TurtleSettingContext::getRuleIndex() const {
  return FgsgParser::RuleTurtleSetting;
}

antlrcpp::Any FgsgParser::TurtleSettingContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitTurtleSetting(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::TurtleSettingContext* FgsgParser::turtleSetting() {
  TurtleSettingContext *_localctx = _tracker.createInstance<TurtleSettingContext>(_ctx, getState());
  enterRule(_localctx, 32, FgsgParser::RuleTurtleSetting);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(260);
    dynamic_cast<TurtleSettingContext *>(_localctx)->name = match(FgsgParser::ID);
    setState(261);
    dynamic_cast<TurtleSettingContext *>(_localctx)->value = expr(0);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- IgnoreDeclContext ------------------------------------------------------------------

FgsgParser::IgnoreDeclContext::IgnoreDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::IgnoreDeclContext::IGNORE() {
  return getToken(FgsgParser::IGNORE, 0);
}

tree::TerminalNode* FgsgParser::IgnoreDeclContext::SEMI() {
  return getToken(FgsgParser::SEMI, 0);
}

tree::TerminalNode* FgsgParser::IgnoreDeclContext::COLON() {
  return getToken(FgsgParser::COLON, 0);
}

std::vector<FgsgParser::IgnoredSymbolContext *> FgsgParser::IgnoreDeclContext::ignoredSymbol() {
  return getRuleContexts<FgsgParser::IgnoredSymbolContext>();
}

FgsgParser::IgnoredSymbolContext* FgsgParser::IgnoreDeclContext::ignoredSymbol(size_t i) {
  return getRuleContext<FgsgParser::IgnoredSymbolContext>(i);
}


size_t FgsgParser::IgnoreDeclContext::getRuleIndex() const {
  return FgsgParser::RuleIgnoreDecl;
}

antlrcpp::Any FgsgParser::IgnoreDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitIgnoreDecl(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::IgnoreDeclContext* FgsgParser::ignoreDecl() {
  IgnoreDeclContext *_localctx = _tracker.createInstance<IgnoreDeclContext>(_ctx, getState());
  enterRule(_localctx, 34, FgsgParser::RuleIgnoreDecl);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(263);
    match(FgsgParser::IGNORE);
    setState(265);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == FgsgParser::COLON) {
      setState(264);
      match(FgsgParser::COLON);
    }
    setState(268); 
    _errHandler->sync(this);
    _la = _input->LA(1);
    do {
      setState(267);
      ignoredSymbol();
      setState(270); 
      _errHandler->sync(this);
      _la = _input->LA(1);
    } while ((((_la & ~ 0x3fULL) == 0) &&
      ((1ULL << _la) & ((1ULL << FgsgParser::PLUS)
      | (1ULL << FgsgParser::MINUS)
      | (1ULL << FgsgParser::SLASH)
      | (1ULL << FgsgParser::CARET)
      | (1ULL << FgsgParser::BANG)
      | (1ULL << FgsgParser::AMP)
      | (1ULL << FgsgParser::PIPE)
      | (1ULL << FgsgParser::BACKSLASH)
      | (1ULL << FgsgParser::ID))) != 0));
    setState(272);
    match(FgsgParser::SEMI);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- IgnoredSymbolContext ------------------------------------------------------------------

FgsgParser::IgnoredSymbolContext::IgnoredSymbolContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::IgnoredSymbolContext::ID() {
  return getToken(FgsgParser::ID, 0);
}

FgsgParser::TurtleSymbolContext* FgsgParser::IgnoredSymbolContext::turtleSymbol() {
  return getRuleContext<FgsgParser::TurtleSymbolContext>(0);
}


size_t FgsgParser::IgnoredSymbolContext::getRuleIndex() const {
  return FgsgParser::RuleIgnoredSymbol;
}

antlrcpp::Any FgsgParser::IgnoredSymbolContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitIgnoredSymbol(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::IgnoredSymbolContext* FgsgParser::ignoredSymbol() {
  IgnoredSymbolContext *_localctx = _tracker.createInstance<IgnoredSymbolContext>(_ctx, getState());
  enterRule(_localctx, 36, FgsgParser::RuleIgnoredSymbol);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(276);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case FgsgParser::ID: {
        enterOuterAlt(_localctx, 1);
        setState(274);
        match(FgsgParser::ID);
        break;
      }

      case FgsgParser::PLUS:
      case FgsgParser::MINUS:
      case FgsgParser::SLASH:
      case FgsgParser::CARET:
      case FgsgParser::BANG:
      case FgsgParser::AMP:
      case FgsgParser::PIPE:
      case FgsgParser::BACKSLASH: {
        enterOuterAlt(_localctx, 2);
        setState(275);
        turtleSymbol();
        break;
      }

    default:
      throw NoViableAltException(this);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- CollisionDeclContext ------------------------------------------------------------------

FgsgParser::CollisionDeclContext::CollisionDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::CollisionDeclContext::COLLISION() {
  return getToken(FgsgParser::COLLISION, 0);
}

tree::TerminalNode* FgsgParser::CollisionDeclContext::SEMI() {
  return getToken(FgsgParser::SEMI, 0);
}

std::vector<FgsgParser::CollisionWordContext *> FgsgParser::CollisionDeclContext::collisionWord() {
  return getRuleContexts<FgsgParser::CollisionWordContext>();
}

FgsgParser::CollisionWordContext* FgsgParser::CollisionDeclContext::collisionWord(size_t i) {
  return getRuleContext<FgsgParser::CollisionWordContext>(i);
}


size_t FgsgParser::CollisionDeclContext::getRuleIndex() const {
  return FgsgParser::RuleCollisionDecl;
}

antlrcpp::Any FgsgParser::CollisionDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitCollisionDecl(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::CollisionDeclContext* FgsgParser::collisionDecl() {
  CollisionDeclContext *_localctx = _tracker.createInstance<CollisionDeclContext>(_ctx, getState());
  enterRule(_localctx, 38, FgsgParser::RuleCollisionDecl);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(278);
    match(FgsgParser::COLLISION);
    setState(282);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while ((((_la & ~ 0x3fULL) == 0) &&
      ((1ULL << _la) & ((1ULL << FgsgParser::MINUS)
      | (1ULL << FgsgParser::FLOAT)
      | (1ULL << FgsgParser::INT)
      | (1ULL << FgsgParser::ID))) != 0)) {
      setState(279);
      collisionWord();
      setState(284);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(285);
    match(FgsgParser::SEMI);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- CollisionWordContext ------------------------------------------------------------------

FgsgParser::CollisionWordContext::CollisionWordContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::CollisionWordContext::ID() {
  return getToken(FgsgParser::ID, 0);
}

FgsgParser::NumberContext* FgsgParser::CollisionWordContext::number() {
  return getRuleContext<FgsgParser::NumberContext>(0);
}

tree::TerminalNode* FgsgParser::CollisionWordContext::MINUS() {
  return getToken(FgsgParser::MINUS, 0);
}


size_t FgsgParser::CollisionWordContext::getRuleIndex() const {
  return FgsgParser::RuleCollisionWord;
}

antlrcpp::Any FgsgParser::CollisionWordContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitCollisionWord(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::CollisionWordContext* FgsgParser::collisionWord() {
  CollisionWordContext *_localctx = _tracker.createInstance<CollisionWordContext>(_ctx, getState());
  enterRule(_localctx, 40, FgsgParser::RuleCollisionWord);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(292);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case FgsgParser::ID: {
        enterOuterAlt(_localctx, 1);
        setState(287);
        dynamic_cast<CollisionWordContext *>(_localctx)->word = match(FgsgParser::ID);
        break;
      }

      case FgsgParser::MINUS:
      case FgsgParser::FLOAT:
      case FgsgParser::INT: {
        enterOuterAlt(_localctx, 2);
        setState(289);
        _errHandler->sync(this);

        _la = _input->LA(1);
        if (_la == FgsgParser::MINUS) {
          setState(288);
          dynamic_cast<CollisionWordContext *>(_localctx)->sign = match(FgsgParser::MINUS);
        }
        setState(291);
        number();
        break;
      }

    default:
      throw NoViableAltException(this);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- AxiomDeclContext ------------------------------------------------------------------

FgsgParser::AxiomDeclContext::AxiomDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::AxiomDeclContext::AXIOM() {
  return getToken(FgsgParser::AXIOM, 0);
}

tree::TerminalNode* FgsgParser::AxiomDeclContext::COLON() {
  return getToken(FgsgParser::COLON, 0);
}

FgsgParser::SuccessorContext* FgsgParser::AxiomDeclContext::successor() {
  return getRuleContext<FgsgParser::SuccessorContext>(0);
}

tree::TerminalNode* FgsgParser::AxiomDeclContext::SEMI() {
  return getToken(FgsgParser::SEMI, 0);
}


size_t FgsgParser::AxiomDeclContext::getRuleIndex() const {
  return FgsgParser::RuleAxiomDecl;
}

antlrcpp::Any FgsgParser::AxiomDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitAxiomDecl(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::AxiomDeclContext* FgsgParser::axiomDecl() {
  AxiomDeclContext *_localctx = _tracker.createInstance<AxiomDeclContext>(_ctx, getState());
  enterRule(_localctx, 42, FgsgParser::RuleAxiomDecl);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(294);
    match(FgsgParser::AXIOM);
    setState(295);
    match(FgsgParser::COLON);
    setState(296);
    successor();
    setState(297);
    match(FgsgParser::SEMI);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- PriorityDeclContext ------------------------------------------------------------------

FgsgParser::PriorityDeclContext::PriorityDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::PriorityDeclContext::PRIORITY() {
  return getToken(FgsgParser::PRIORITY, 0);
}

tree::TerminalNode* FgsgParser::PriorityDeclContext::COLON() {
  return getToken(FgsgParser::COLON, 0);
}

tree::TerminalNode* FgsgParser::PriorityDeclContext::INT() {
  return getToken(FgsgParser::INT, 0);
}

tree::TerminalNode* FgsgParser::PriorityDeclContext::MINUS() {
  return getToken(FgsgParser::MINUS, 0);
}


size_t FgsgParser::PriorityDeclContext::getRuleIndex() const {
  return FgsgParser::RulePriorityDecl;
}

antlrcpp::Any FgsgParser::PriorityDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitPriorityDecl(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::PriorityDeclContext* FgsgParser::priorityDecl() {
  PriorityDeclContext *_localctx = _tracker.createInstance<PriorityDeclContext>(_ctx, getState());
  enterRule(_localctx, 44, FgsgParser::RulePriorityDecl);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(299);
    match(FgsgParser::PRIORITY);
    setState(301);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == FgsgParser::MINUS) {
      setState(300);
      dynamic_cast<PriorityDeclContext *>(_localctx)->sign = match(FgsgParser::MINUS);
    }
    setState(303);
    dynamic_cast<PriorityDeclContext *>(_localctx)->level = match(FgsgParser::INT);
    setState(304);
    match(FgsgParser::COLON);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- GrammarRuleContext ------------------------------------------------------------------

FgsgParser::GrammarRuleContext::GrammarRuleContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

FgsgParser::RuleHeadContext* FgsgParser::GrammarRuleContext::ruleHead() {
  return getRuleContext<FgsgParser::RuleHeadContext>(0);
}

FgsgParser::ArrowContext* FgsgParser::GrammarRuleContext::arrow() {
  return getRuleContext<FgsgParser::ArrowContext>(0);
}

FgsgParser::RuleBodyContext* FgsgParser::GrammarRuleContext::ruleBody() {
  return getRuleContext<FgsgParser::RuleBodyContext>(0);
}

tree::TerminalNode* FgsgParser::GrammarRuleContext::SEMI() {
  return getToken(FgsgParser::SEMI, 0);
}

std::vector<tree::TerminalNode *> FgsgParser::GrammarRuleContext::COLON() {
  return getTokens(FgsgParser::COLON);
}

tree::TerminalNode* FgsgParser::GrammarRuleContext::COLON(size_t i) {
  return getToken(FgsgParser::COLON, i);
}

FgsgParser::RuleLabelContext* FgsgParser::GrammarRuleContext::ruleLabel() {
  return getRuleContext<FgsgParser::RuleLabelContext>(0);
}

FgsgParser::ExprContext* FgsgParser::GrammarRuleContext::expr() {
  return getRuleContext<FgsgParser::ExprContext>(0);
}


size_t FgsgParser::GrammarRuleContext::getRuleIndex() const {
  return FgsgParser::RuleGrammarRule;
}

antlrcpp::Any FgsgParser::GrammarRuleContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitGrammarRule(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::GrammarRuleContext* FgsgParser::grammarRule() {
  GrammarRuleContext *_localctx = _tracker.createInstance<GrammarRuleContext>(_ctx, getState());
  enterRule(_localctx, 46, FgsgParser::RuleGrammarRule);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(309);
    _errHandler->sync(this);

    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 28, _ctx)) {
    case 1: {
      setState(306);
      dynamic_cast<GrammarRuleContext *>(_localctx)->label = ruleLabel();
      setState(307);
      match(FgsgParser::COLON);
      break;
    }

    }
    setState(311);
    ruleHead();
    setState(314);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == FgsgParser::COLON) {
      setState(312);
      match(FgsgParser::COLON);
      setState(313);
      dynamic_cast<GrammarRuleContext *>(_localctx)->guard = expr(0);
    }
    setState(316);
    arrow();
    setState(317);
    ruleBody();
    setState(318);
    match(FgsgParser::SEMI);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- RuleLabelContext ------------------------------------------------------------------

FgsgParser::RuleLabelContext::RuleLabelContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::RuleLabelContext::INT() {
  return getToken(FgsgParser::INT, 0);
}

tree::TerminalNode* FgsgParser::RuleLabelContext::ID() {
  return getToken(FgsgParser::ID, 0);
}


size_t FgsgParser::RuleLabelContext::getRuleIndex() const {
  return FgsgParser::RuleRuleLabel;
}

antlrcpp::Any FgsgParser::RuleLabelContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitRuleLabel(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::RuleLabelContext* FgsgParser::ruleLabel() {
  RuleLabelContext *_localctx = _tracker.createInstance<RuleLabelContext>(_ctx, getState());
  enterRule(_localctx, 48, FgsgParser::RuleRuleLabel);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(320);
    _la = _input->LA(1);
    if (!(_la == FgsgParser::INT

    || _la == FgsgParser::ID)) {
    _errHandler->recoverInline(this);
    }
    else {
      _errHandler->reportMatch(this);
      consume();
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- RuleHeadContext ------------------------------------------------------------------

FgsgParser::RuleHeadContext::RuleHeadContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

FgsgParser::ModulePatternContext* FgsgParser::RuleHeadContext::modulePattern() {
  return getRuleContext<FgsgParser::ModulePatternContext>(0);
}

FgsgParser::LeftContextContext* FgsgParser::RuleHeadContext::leftContext() {
  return getRuleContext<FgsgParser::LeftContextContext>(0);
}

tree::TerminalNode* FgsgParser::RuleHeadContext::LT() {
  return getToken(FgsgParser::LT, 0);
}

tree::TerminalNode* FgsgParser::RuleHeadContext::GT() {
  return getToken(FgsgParser::GT, 0);
}

FgsgParser::RightContextContext* FgsgParser::RuleHeadContext::rightContext() {
  return getRuleContext<FgsgParser::RightContextContext>(0);
}


size_t FgsgParser::RuleHeadContext::getRuleIndex() const {
  return FgsgParser::RuleRuleHead;
}

antlrcpp::Any FgsgParser::RuleHeadContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitRuleHead(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::RuleHeadContext* FgsgParser::ruleHead() {
  RuleHeadContext *_localctx = _tracker.createInstance<RuleHeadContext>(_ctx, getState());
  enterRule(_localctx, 50, FgsgParser::RuleRuleHead);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(325);
    _errHandler->sync(this);

    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 30, _ctx)) {
    case 1: {
      setState(322);
      leftContext();
      setState(323);
      match(FgsgParser::LT);
      break;
    }

    }
    setState(327);
    dynamic_cast<RuleHeadContext *>(_localctx)->predecessor = modulePattern();
    setState(330);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == FgsgParser::GT) {
      setState(328);
      match(FgsgParser::GT);
      setState(329);
      rightContext();
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- LeftContextContext ------------------------------------------------------------------

FgsgParser::LeftContextContext::LeftContextContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<FgsgParser::ModulePatternContext *> FgsgParser::LeftContextContext::modulePattern() {
  return getRuleContexts<FgsgParser::ModulePatternContext>();
}

FgsgParser::ModulePatternContext* FgsgParser::LeftContextContext::modulePattern(size_t i) {
  return getRuleContext<FgsgParser::ModulePatternContext>(i);
}


size_t FgsgParser::LeftContextContext::getRuleIndex() const {
  return FgsgParser::RuleLeftContext;
}

antlrcpp::Any FgsgParser::LeftContextContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitLeftContext(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::LeftContextContext* FgsgParser::leftContext() {
  LeftContextContext *_localctx = _tracker.createInstance<LeftContextContext>(_ctx, getState());
  enterRule(_localctx, 52, FgsgParser::RuleLeftContext);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(333); 
    _errHandler->sync(this);
    _la = _input->LA(1);
    do {
      setState(332);
      modulePattern();
      setState(335); 
      _errHandler->sync(this);
      _la = _input->LA(1);
    } while ((((_la & ~ 0x3fULL) == 0) &&
      ((1ULL << _la) & ((1ULL << FgsgParser::PLUS)
      | (1ULL << FgsgParser::MINUS)
      | (1ULL << FgsgParser::SLASH)
      | (1ULL << FgsgParser::CARET)
      | (1ULL << FgsgParser::BANG)
      | (1ULL << FgsgParser::AMP)
      | (1ULL << FgsgParser::PIPE)
      | (1ULL << FgsgParser::BACKSLASH)
      | (1ULL << FgsgParser::ID))) != 0));
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- RightContextContext ------------------------------------------------------------------

FgsgParser::RightContextContext::RightContextContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<FgsgParser::ContextModuleContext *> FgsgParser::RightContextContext::contextModule() {
  return getRuleContexts<FgsgParser::ContextModuleContext>();
}

FgsgParser::ContextModuleContext* FgsgParser::RightContextContext::contextModule(size_t i) {
  return getRuleContext<FgsgParser::ContextModuleContext>(i);
}


size_t FgsgParser::RightContextContext::getRuleIndex() const {
  return FgsgParser::RuleRightContext;
}

antlrcpp::Any FgsgParser::RightContextContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitRightContext(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::RightContextContext* FgsgParser::rightContext() {
  RightContextContext *_localctx = _tracker.createInstance<RightContextContext>(_ctx, getState());
  enterRule(_localctx, 54, FgsgParser::RuleRightContext);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(338); 
    _errHandler->sync(this);
    _la = _input->LA(1);
    do {
      setState(337);
      contextModule();
      setState(340); 
      _errHandler->sync(this);
      _la = _input->LA(1);
    } while ((((_la & ~ 0x3fULL) == 0) &&
      ((1ULL << _la) & ((1ULL << FgsgParser::PLUS)
      | (1ULL << FgsgParser::MINUS)
      | (1ULL << FgsgParser::SLASH)
      | (1ULL << FgsgParser::CARET)
      | (1ULL << FgsgParser::BANG)
      | (1ULL << FgsgParser::AMP)
      | (1ULL << FgsgParser::PIPE)
      | (1ULL << FgsgParser::BACKSLASH)
      | (1ULL << FgsgParser::LBRACK)
      | (1ULL << FgsgParser::RBRACK)
      | (1ULL << FgsgParser::ID))) != 0));
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ContextModuleContext ------------------------------------------------------------------

FgsgParser::ContextModuleContext::ContextModuleContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

FgsgParser::ModulePatternContext* FgsgParser::ContextModuleContext::modulePattern() {
  return getRuleContext<FgsgParser::ModulePatternContext>(0);
}

tree::TerminalNode* FgsgParser::ContextModuleContext::LBRACK() {
  return getToken(FgsgParser::LBRACK, 0);
}

tree::TerminalNode* FgsgParser::ContextModuleContext::RBRACK() {
  return getToken(FgsgParser::RBRACK, 0);
}


size_t FgsgParser::ContextModuleContext::getRuleIndex() const {
  return FgsgParser::RuleContextModule;
}

antlrcpp::Any FgsgParser::ContextModuleContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitContextModule(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::ContextModuleContext* FgsgParser::contextModule() {
  ContextModuleContext *_localctx = _tracker.createInstance<ContextModuleContext>(_ctx, getState());
  enterRule(_localctx, 56, FgsgParser::RuleContextModule);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(345);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case FgsgParser::PLUS:
      case FgsgParser::MINUS:
      case FgsgParser::SLASH:
      case FgsgParser::CARET:
      case FgsgParser::BANG:
      case FgsgParser::AMP:
      case FgsgParser::PIPE:
      case FgsgParser::BACKSLASH:
      case FgsgParser::ID: {
        enterOuterAlt(_localctx, 1);
        setState(342);
        modulePattern();
        break;
      }

      case FgsgParser::LBRACK: {
        enterOuterAlt(_localctx, 2);
        setState(343);
        dynamic_cast<ContextModuleContext *>(_localctx)->open = match(FgsgParser::LBRACK);
        break;
      }

      case FgsgParser::RBRACK: {
        enterOuterAlt(_localctx, 3);
        setState(344);
        dynamic_cast<ContextModuleContext *>(_localctx)->close = match(FgsgParser::RBRACK);
        break;
      }

    default:
      throw NoViableAltException(this);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ModulePatternContext ------------------------------------------------------------------

FgsgParser::ModulePatternContext::ModulePatternContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::ModulePatternContext::ID() {
  return getToken(FgsgParser::ID, 0);
}

FgsgParser::TurtleSymbolContext* FgsgParser::ModulePatternContext::turtleSymbol() {
  return getRuleContext<FgsgParser::TurtleSymbolContext>(0);
}

tree::TerminalNode* FgsgParser::ModulePatternContext::LPAREN() {
  return getToken(FgsgParser::LPAREN, 0);
}

tree::TerminalNode* FgsgParser::ModulePatternContext::RPAREN() {
  return getToken(FgsgParser::RPAREN, 0);
}

std::vector<FgsgParser::ParamDeclContext *> FgsgParser::ModulePatternContext::paramDecl() {
  return getRuleContexts<FgsgParser::ParamDeclContext>();
}

FgsgParser::ParamDeclContext* FgsgParser::ModulePatternContext::paramDecl(size_t i) {
  return getRuleContext<FgsgParser::ParamDeclContext>(i);
}

std::vector<tree::TerminalNode *> FgsgParser::ModulePatternContext::COMMA() {
  return getTokens(FgsgParser::COMMA);
}

tree::TerminalNode* FgsgParser::ModulePatternContext::COMMA(size_t i) {
  return getToken(FgsgParser::COMMA, i);
}


size_t FgsgParser::ModulePatternContext::getRuleIndex() const {
  return FgsgParser::RuleModulePattern;
}

antlrcpp::Any FgsgParser::ModulePatternContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitModulePattern(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::ModulePatternContext* FgsgParser::modulePattern() {
  ModulePatternContext *_localctx = _tracker.createInstance<ModulePatternContext>(_ctx, getState());
  enterRule(_localctx, 58, FgsgParser::RuleModulePattern);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(349);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case FgsgParser::ID: {
        setState(347);
        dynamic_cast<ModulePatternContext *>(_localctx)->name = match(FgsgParser::ID);
        break;
      }

      case FgsgParser::PLUS:
      case FgsgParser::MINUS:
      case FgsgParser::SLASH:
      case FgsgParser::CARET:
      case FgsgParser::BANG:
      case FgsgParser::AMP:
      case FgsgParser::PIPE:
      case FgsgParser::BACKSLASH: {
        setState(348);
        dynamic_cast<ModulePatternContext *>(_localctx)->turtle = turtleSymbol();
        break;
      }

    default:
      throw NoViableAltException(this);
    }
    setState(363);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == FgsgParser::LPAREN) {
      setState(351);
      match(FgsgParser::LPAREN);
      setState(360);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == FgsgParser::ID) {
        setState(352);
        paramDecl();
        setState(357);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == FgsgParser::COMMA) {
          setState(353);
          match(FgsgParser::COMMA);
          setState(354);
          paramDecl();
          setState(359);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(362);
      match(FgsgParser::RPAREN);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- TurtleSymbolContext ------------------------------------------------------------------

FgsgParser::TurtleSymbolContext::TurtleSymbolContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::TurtleSymbolContext::PLUS() {
  return getToken(FgsgParser::PLUS, 0);
}

tree::TerminalNode* FgsgParser::TurtleSymbolContext::MINUS() {
  return getToken(FgsgParser::MINUS, 0);
}

tree::TerminalNode* FgsgParser::TurtleSymbolContext::AMP() {
  return getToken(FgsgParser::AMP, 0);
}

tree::TerminalNode* FgsgParser::TurtleSymbolContext::CARET() {
  return getToken(FgsgParser::CARET, 0);
}

tree::TerminalNode* FgsgParser::TurtleSymbolContext::BACKSLASH() {
  return getToken(FgsgParser::BACKSLASH, 0);
}

tree::TerminalNode* FgsgParser::TurtleSymbolContext::SLASH() {
  return getToken(FgsgParser::SLASH, 0);
}

tree::TerminalNode* FgsgParser::TurtleSymbolContext::PIPE() {
  return getToken(FgsgParser::PIPE, 0);
}

tree::TerminalNode* FgsgParser::TurtleSymbolContext::BANG() {
  return getToken(FgsgParser::BANG, 0);
}


size_t FgsgParser::TurtleSymbolContext::getRuleIndex() const {
  return FgsgParser::RuleTurtleSymbol;
}

antlrcpp::Any FgsgParser::TurtleSymbolContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitTurtleSymbol(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::TurtleSymbolContext* FgsgParser::turtleSymbol() {
  TurtleSymbolContext *_localctx = _tracker.createInstance<TurtleSymbolContext>(_ctx, getState());
  enterRule(_localctx, 60, FgsgParser::RuleTurtleSymbol);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(365);
    _la = _input->LA(1);
    if (!((((_la & ~ 0x3fULL) == 0) &&
      ((1ULL << _la) & ((1ULL << FgsgParser::PLUS)
      | (1ULL << FgsgParser::MINUS)
      | (1ULL << FgsgParser::SLASH)
      | (1ULL << FgsgParser::CARET)
      | (1ULL << FgsgParser::BANG)
      | (1ULL << FgsgParser::AMP)
      | (1ULL << FgsgParser::PIPE)
      | (1ULL << FgsgParser::BACKSLASH))) != 0))) {
    _errHandler->recoverInline(this);
    }
    else {
      _errHandler->reportMatch(this);
      consume();
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ParamDeclContext ------------------------------------------------------------------

FgsgParser::ParamDeclContext::ParamDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::ParamDeclContext::ID() {
  return getToken(FgsgParser::ID, 0);
}


size_t FgsgParser::ParamDeclContext::getRuleIndex() const {
  return FgsgParser::RuleParamDecl;
}

antlrcpp::Any FgsgParser::ParamDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitParamDecl(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::ParamDeclContext* FgsgParser::paramDecl() {
  ParamDeclContext *_localctx = _tracker.createInstance<ParamDeclContext>(_ctx, getState());
  enterRule(_localctx, 62, FgsgParser::RuleParamDecl);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(367);
    match(FgsgParser::ID);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- RuleBodyContext ------------------------------------------------------------------

FgsgParser::RuleBodyContext::RuleBodyContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<FgsgParser::BranchContext *> FgsgParser::RuleBodyContext::branch() {
  return getRuleContexts<FgsgParser::BranchContext>();
}

FgsgParser::BranchContext* FgsgParser::RuleBodyContext::branch(size_t i) {
  return getRuleContext<FgsgParser::BranchContext>(i);
}

std::vector<FgsgParser::ArrowContext *> FgsgParser::RuleBodyContext::arrow() {
  return getRuleContexts<FgsgParser::ArrowContext>();
}

FgsgParser::ArrowContext* FgsgParser::RuleBodyContext::arrow(size_t i) {
  return getRuleContext<FgsgParser::ArrowContext>(i);
}

FgsgParser::ExprContext* FgsgParser::RuleBodyContext::expr() {
  return getRuleContext<FgsgParser::ExprContext>(0);
}


size_t FgsgParser::RuleBodyContext::getRuleIndex() const {
  return FgsgParser::RuleRuleBody;
}

antlrcpp::Any FgsgParser::RuleBodyContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitRuleBody(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::RuleBodyContext* FgsgParser::ruleBody() {
  RuleBodyContext *_localctx = _tracker.createInstance<RuleBodyContext>(_ctx, getState());
  enterRule(_localctx, 64, FgsgParser::RuleRuleBody);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(389);
    _errHandler->sync(this);
    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 41, _ctx)) {
    case 1: {
      enterOuterAlt(_localctx, 1);
      setState(369);
      branch();
      setState(375);
      _errHandler->sync(this);
      _la = _input->LA(1);
      while (_la == FgsgParser::ARROW

      || _la == FgsgParser::ASSIGN) {
        setState(370);
        arrow();
        setState(371);
        branch();
        setState(377);
        _errHandler->sync(this);
        _la = _input->LA(1);
      }
      break;
    }

    case 2: {
      enterOuterAlt(_localctx, 2);
      setState(378);
      dynamic_cast<RuleBodyContext *>(_localctx)->mullerGuard = expr(0);
      setState(379);
      arrow();
      setState(380);
      branch();
      setState(386);
      _errHandler->sync(this);
      _la = _input->LA(1);
      while (_la == FgsgParser::ARROW

      || _la == FgsgParser::ASSIGN) {
        setState(381);
        arrow();
        setState(382);
        branch();
        setState(388);
        _errHandler->sync(this);
        _la = _input->LA(1);
      }
      break;
    }

    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- BranchContext ------------------------------------------------------------------

FgsgParser::BranchContext::BranchContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

FgsgParser::SuccessorContext* FgsgParser::BranchContext::successor() {
  return getRuleContext<FgsgParser::SuccessorContext>(0);
}

tree::TerminalNode* FgsgParser::BranchContext::COLON() {
  return getToken(FgsgParser::COLON, 0);
}

FgsgParser::ExprContext* FgsgParser::BranchContext::expr() {
  return getRuleContext<FgsgParser::ExprContext>(0);
}


size_t FgsgParser::BranchContext::getRuleIndex() const {
  return FgsgParser::RuleBranch;
}

antlrcpp::Any FgsgParser::BranchContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitBranch(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::BranchContext* FgsgParser::branch() {
  BranchContext *_localctx = _tracker.createInstance<BranchContext>(_ctx, getState());
  enterRule(_localctx, 66, FgsgParser::RuleBranch);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(391);
    successor();
    setState(394);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == FgsgParser::COLON) {
      setState(392);
      match(FgsgParser::COLON);
      setState(393);
      dynamic_cast<BranchContext *>(_localctx)->probability = expr(0);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ArrowContext ------------------------------------------------------------------

FgsgParser::ArrowContext::ArrowContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::ArrowContext::ARROW() {
  return getToken(FgsgParser::ARROW, 0);
}

tree::TerminalNode* FgsgParser::ArrowContext::ASSIGN() {
  return getToken(FgsgParser::ASSIGN, 0);
}


size_t FgsgParser::ArrowContext::getRuleIndex() const {
  return FgsgParser::RuleArrow;
}

antlrcpp::Any FgsgParser::ArrowContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitArrow(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::ArrowContext* FgsgParser::arrow() {
  ArrowContext *_localctx = _tracker.createInstance<ArrowContext>(_ctx, getState());
  enterRule(_localctx, 68, FgsgParser::RuleArrow);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(396);
    _la = _input->LA(1);
    if (!(_la == FgsgParser::ARROW

    || _la == FgsgParser::ASSIGN)) {
    _errHandler->recoverInline(this);
    }
    else {
      _errHandler->reportMatch(this);
      consume();
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- SuccessorContext ------------------------------------------------------------------

FgsgParser::SuccessorContext::SuccessorContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::SuccessorContext::EPSILON() {
  return getToken(FgsgParser::EPSILON, 0);
}

std::vector<FgsgParser::SequenceItemContext *> FgsgParser::SuccessorContext::sequenceItem() {
  return getRuleContexts<FgsgParser::SequenceItemContext>();
}

FgsgParser::SequenceItemContext* FgsgParser::SuccessorContext::sequenceItem(size_t i) {
  return getRuleContext<FgsgParser::SequenceItemContext>(i);
}


size_t FgsgParser::SuccessorContext::getRuleIndex() const {
  return FgsgParser::RuleSuccessor;
}

antlrcpp::Any FgsgParser::SuccessorContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitSuccessor(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::SuccessorContext* FgsgParser::successor() {
  SuccessorContext *_localctx = _tracker.createInstance<SuccessorContext>(_ctx, getState());
  enterRule(_localctx, 70, FgsgParser::RuleSuccessor);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(404);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case FgsgParser::EPSILON: {
        enterOuterAlt(_localctx, 1);
        setState(398);
        match(FgsgParser::EPSILON);
        break;
      }

      case FgsgParser::AND:
      case FgsgParser::OR:
      case FgsgParser::PLUS:
      case FgsgParser::MINUS:
      case FgsgParser::SLASH:
      case FgsgParser::PERCENT:
      case FgsgParser::CARET:
      case FgsgParser::BANG:
      case FgsgParser::AMP:
      case FgsgParser::PIPE:
      case FgsgParser::BACKSLASH:
      case FgsgParser::DOLLAR:
      case FgsgParser::QUOTE:
      case FgsgParser::TILDE:
      case FgsgParser::LBRACK:
      case FgsgParser::LBRACE:
      case FgsgParser::RBRACE:
      case FgsgParser::ID:
      case FgsgParser::VERTEX:
      case FgsgParser::COLORSTEP: {
        enterOuterAlt(_localctx, 2);
        setState(400); 
        _errHandler->sync(this);
        _la = _input->LA(1);
        do {
          setState(399);
          sequenceItem();
          setState(402); 
          _errHandler->sync(this);
          _la = _input->LA(1);
        } while ((((_la & ~ 0x3fULL) == 0) &&
          ((1ULL << _la) & ((1ULL << FgsgParser::AND)
          | (1ULL << FgsgParser::OR)
          | (1ULL << FgsgParser::PLUS)
          | (1ULL << FgsgParser::MINUS)
          | (1ULL << FgsgParser::SLASH)
          | (1ULL << FgsgParser::PERCENT)
          | (1ULL << FgsgParser::CARET)
          | (1ULL << FgsgParser::BANG)
          | (1ULL << FgsgParser::AMP)
          | (1ULL << FgsgParser::PIPE)
          | (1ULL << FgsgParser::BACKSLASH)
          | (1ULL << FgsgParser::DOLLAR)
          | (1ULL << FgsgParser::QUOTE)
          | (1ULL << FgsgParser::TILDE)
          | (1ULL << FgsgParser::LBRACK)
          | (1ULL << FgsgParser::LBRACE)
          | (1ULL << FgsgParser::RBRACE)
          | (1ULL << FgsgParser::ID)
          | (1ULL << FgsgParser::VERTEX)
          | (1ULL << FgsgParser::COLORSTEP))) != 0));
        break;
      }

    default:
      throw NoViableAltException(this);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- SequenceItemContext ------------------------------------------------------------------

FgsgParser::SequenceItemContext::SequenceItemContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

FgsgParser::ItemContext* FgsgParser::SequenceItemContext::item() {
  return getRuleContext<FgsgParser::ItemContext>(0);
}

tree::TerminalNode* FgsgParser::SequenceItemContext::PIPE() {
  return getToken(FgsgParser::PIPE, 0);
}

tree::TerminalNode* FgsgParser::SequenceItemContext::OR() {
  return getToken(FgsgParser::OR, 0);
}

tree::TerminalNode* FgsgParser::SequenceItemContext::COLORSTEP() {
  return getToken(FgsgParser::COLORSTEP, 0);
}

FgsgParser::CallArgsContext* FgsgParser::SequenceItemContext::callArgs() {
  return getRuleContext<FgsgParser::CallArgsContext>(0);
}

tree::TerminalNode* FgsgParser::SequenceItemContext::LBRACE() {
  return getToken(FgsgParser::LBRACE, 0);
}

tree::TerminalNode* FgsgParser::SequenceItemContext::RBRACE() {
  return getToken(FgsgParser::RBRACE, 0);
}


size_t FgsgParser::SequenceItemContext::getRuleIndex() const {
  return FgsgParser::RuleSequenceItem;
}

antlrcpp::Any FgsgParser::SequenceItemContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitSequenceItem(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::SequenceItemContext* FgsgParser::sequenceItem() {
  SequenceItemContext *_localctx = _tracker.createInstance<SequenceItemContext>(_ctx, getState());
  enterRule(_localctx, 72, FgsgParser::RuleSequenceItem);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(412);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case FgsgParser::AND:
      case FgsgParser::PLUS:
      case FgsgParser::MINUS:
      case FgsgParser::SLASH:
      case FgsgParser::PERCENT:
      case FgsgParser::CARET:
      case FgsgParser::BANG:
      case FgsgParser::AMP:
      case FgsgParser::BACKSLASH:
      case FgsgParser::DOLLAR:
      case FgsgParser::QUOTE:
      case FgsgParser::TILDE:
      case FgsgParser::LBRACK:
      case FgsgParser::ID:
      case FgsgParser::VERTEX: {
        enterOuterAlt(_localctx, 1);
        setState(406);
        item();
        break;
      }

      case FgsgParser::OR:
      case FgsgParser::PIPE:
      case FgsgParser::COLORSTEP: {
        enterOuterAlt(_localctx, 2);
        setState(407);
        dynamic_cast<SequenceItemContext *>(_localctx)->symbol = _input->LT(1);
        _la = _input->LA(1);
        if (!((((_la & ~ 0x3fULL) == 0) &&
          ((1ULL << _la) & ((1ULL << FgsgParser::OR)
          | (1ULL << FgsgParser::PIPE)
          | (1ULL << FgsgParser::COLORSTEP))) != 0))) {
          dynamic_cast<SequenceItemContext *>(_localctx)->symbol = _errHandler->recoverInline(this);
        }
        else {
          _errHandler->reportMatch(this);
          consume();
        }
        setState(409);
        _errHandler->sync(this);

        _la = _input->LA(1);
        if (_la == FgsgParser::LPAREN) {
          setState(408);
          callArgs();
        }
        break;
      }

      case FgsgParser::LBRACE:
      case FgsgParser::RBRACE: {
        enterOuterAlt(_localctx, 3);
        setState(411);
        dynamic_cast<SequenceItemContext *>(_localctx)->polygon = _input->LT(1);
        _la = _input->LA(1);
        if (!(_la == FgsgParser::LBRACE

        || _la == FgsgParser::RBRACE)) {
          dynamic_cast<SequenceItemContext *>(_localctx)->polygon = _errHandler->recoverInline(this);
        }
        else {
          _errHandler->reportMatch(this);
          consume();
        }
        break;
      }

    default:
      throw NoViableAltException(this);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ItemContext ------------------------------------------------------------------

FgsgParser::ItemContext::ItemContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}


size_t FgsgParser::ItemContext::getRuleIndex() const {
  return FgsgParser::RuleItem;
}

void FgsgParser::ItemContext::copyFrom(ItemContext *ctx) {
  ParserRuleContext::copyFrom(ctx);
}

//----------------- CallItemContext ------------------------------------------------------------------

tree::TerminalNode* FgsgParser::CallItemContext::ID() {
  return getToken(FgsgParser::ID, 0);
}

FgsgParser::CallArgsContext* FgsgParser::CallItemContext::callArgs() {
  return getRuleContext<FgsgParser::CallArgsContext>(0);
}

FgsgParser::BodyContext* FgsgParser::CallItemContext::body() {
  return getRuleContext<FgsgParser::BodyContext>(0);
}

FgsgParser::CallItemContext::CallItemContext(ItemContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::CallItemContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitCallItem(this);
  else
    return visitor->visitChildren(this);
}
//----------------- BracketItemContext ------------------------------------------------------------------

tree::TerminalNode* FgsgParser::BracketItemContext::LBRACK() {
  return getToken(FgsgParser::LBRACK, 0);
}

tree::TerminalNode* FgsgParser::BracketItemContext::RBRACK() {
  return getToken(FgsgParser::RBRACK, 0);
}

std::vector<FgsgParser::SequenceItemContext *> FgsgParser::BracketItemContext::sequenceItem() {
  return getRuleContexts<FgsgParser::SequenceItemContext>();
}

FgsgParser::SequenceItemContext* FgsgParser::BracketItemContext::sequenceItem(size_t i) {
  return getRuleContext<FgsgParser::SequenceItemContext>(i);
}

FgsgParser::BracketItemContext::BracketItemContext(ItemContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::BracketItemContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitBracketItem(this);
  else
    return visitor->visitChildren(this);
}
//----------------- TurtleItemContext ------------------------------------------------------------------

tree::TerminalNode* FgsgParser::TurtleItemContext::PLUS() {
  return getToken(FgsgParser::PLUS, 0);
}

tree::TerminalNode* FgsgParser::TurtleItemContext::MINUS() {
  return getToken(FgsgParser::MINUS, 0);
}

tree::TerminalNode* FgsgParser::TurtleItemContext::AMP() {
  return getToken(FgsgParser::AMP, 0);
}

tree::TerminalNode* FgsgParser::TurtleItemContext::AND() {
  return getToken(FgsgParser::AND, 0);
}

tree::TerminalNode* FgsgParser::TurtleItemContext::CARET() {
  return getToken(FgsgParser::CARET, 0);
}

tree::TerminalNode* FgsgParser::TurtleItemContext::BACKSLASH() {
  return getToken(FgsgParser::BACKSLASH, 0);
}

tree::TerminalNode* FgsgParser::TurtleItemContext::SLASH() {
  return getToken(FgsgParser::SLASH, 0);
}

tree::TerminalNode* FgsgParser::TurtleItemContext::BANG() {
  return getToken(FgsgParser::BANG, 0);
}

tree::TerminalNode* FgsgParser::TurtleItemContext::DOLLAR() {
  return getToken(FgsgParser::DOLLAR, 0);
}

tree::TerminalNode* FgsgParser::TurtleItemContext::PERCENT() {
  return getToken(FgsgParser::PERCENT, 0);
}

tree::TerminalNode* FgsgParser::TurtleItemContext::QUOTE() {
  return getToken(FgsgParser::QUOTE, 0);
}

FgsgParser::CallArgsContext* FgsgParser::TurtleItemContext::callArgs() {
  return getRuleContext<FgsgParser::CallArgsContext>(0);
}

FgsgParser::TurtleItemContext::TurtleItemContext(ItemContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::TurtleItemContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitTurtleItem(this);
  else
    return visitor->visitChildren(this);
}
//----------------- SurfaceItemContext ------------------------------------------------------------------

tree::TerminalNode* FgsgParser::SurfaceItemContext::TILDE() {
  return getToken(FgsgParser::TILDE, 0);
}

tree::TerminalNode* FgsgParser::SurfaceItemContext::ID() {
  return getToken(FgsgParser::ID, 0);
}

tree::TerminalNode* FgsgParser::SurfaceItemContext::STRING() {
  return getToken(FgsgParser::STRING, 0);
}

FgsgParser::CallArgsContext* FgsgParser::SurfaceItemContext::callArgs() {
  return getRuleContext<FgsgParser::CallArgsContext>(0);
}

FgsgParser::SurfaceItemContext::SurfaceItemContext(ItemContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::SurfaceItemContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitSurfaceItem(this);
  else
    return visitor->visitChildren(this);
}
//----------------- PolygonItemContext ------------------------------------------------------------------

tree::TerminalNode* FgsgParser::PolygonItemContext::VERTEX() {
  return getToken(FgsgParser::VERTEX, 0);
}

FgsgParser::PolygonItemContext::PolygonItemContext(ItemContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::PolygonItemContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitPolygonItem(this);
  else
    return visitor->visitChildren(this);
}
FgsgParser::ItemContext* FgsgParser::item() {
  ItemContext *_localctx = _tracker.createInstance<ItemContext>(_ctx, getState());
  enterRule(_localctx, 74, FgsgParser::RuleItem);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(442);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case FgsgParser::ID: {
        _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<FgsgParser::CallItemContext>(_localctx));
        enterOuterAlt(_localctx, 1);
        setState(414);
        dynamic_cast<CallItemContext *>(_localctx)->name = match(FgsgParser::ID);
        setState(416);
        _errHandler->sync(this);

        _la = _input->LA(1);
        if (_la == FgsgParser::LPAREN) {
          setState(415);
          callArgs();
        }
        setState(419);
        _errHandler->sync(this);

        switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 48, _ctx)) {
        case 1: {
          setState(418);
          body();
          break;
        }

        }
        break;
      }

      case FgsgParser::AND:
      case FgsgParser::PLUS:
      case FgsgParser::MINUS:
      case FgsgParser::SLASH:
      case FgsgParser::PERCENT:
      case FgsgParser::CARET:
      case FgsgParser::BANG:
      case FgsgParser::AMP:
      case FgsgParser::BACKSLASH:
      case FgsgParser::DOLLAR:
      case FgsgParser::QUOTE: {
        _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<FgsgParser::TurtleItemContext>(_localctx));
        enterOuterAlt(_localctx, 2);
        setState(421);
        dynamic_cast<TurtleItemContext *>(_localctx)->symbol = _input->LT(1);
        _la = _input->LA(1);
        if (!((((_la & ~ 0x3fULL) == 0) &&
          ((1ULL << _la) & ((1ULL << FgsgParser::AND)
          | (1ULL << FgsgParser::PLUS)
          | (1ULL << FgsgParser::MINUS)
          | (1ULL << FgsgParser::SLASH)
          | (1ULL << FgsgParser::PERCENT)
          | (1ULL << FgsgParser::CARET)
          | (1ULL << FgsgParser::BANG)
          | (1ULL << FgsgParser::AMP)
          | (1ULL << FgsgParser::BACKSLASH)
          | (1ULL << FgsgParser::DOLLAR)
          | (1ULL << FgsgParser::QUOTE))) != 0))) {
          dynamic_cast<TurtleItemContext *>(_localctx)->symbol = _errHandler->recoverInline(this);
        }
        else {
          _errHandler->reportMatch(this);
          consume();
        }
        setState(423);
        _errHandler->sync(this);

        _la = _input->LA(1);
        if (_la == FgsgParser::LPAREN) {
          setState(422);
          callArgs();
        }
        break;
      }

      case FgsgParser::LBRACK: {
        _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<FgsgParser::BracketItemContext>(_localctx));
        enterOuterAlt(_localctx, 3);
        setState(425);
        match(FgsgParser::LBRACK);
        setState(429);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while ((((_la & ~ 0x3fULL) == 0) &&
          ((1ULL << _la) & ((1ULL << FgsgParser::AND)
          | (1ULL << FgsgParser::OR)
          | (1ULL << FgsgParser::PLUS)
          | (1ULL << FgsgParser::MINUS)
          | (1ULL << FgsgParser::SLASH)
          | (1ULL << FgsgParser::PERCENT)
          | (1ULL << FgsgParser::CARET)
          | (1ULL << FgsgParser::BANG)
          | (1ULL << FgsgParser::AMP)
          | (1ULL << FgsgParser::PIPE)
          | (1ULL << FgsgParser::BACKSLASH)
          | (1ULL << FgsgParser::DOLLAR)
          | (1ULL << FgsgParser::QUOTE)
          | (1ULL << FgsgParser::TILDE)
          | (1ULL << FgsgParser::LBRACK)
          | (1ULL << FgsgParser::LBRACE)
          | (1ULL << FgsgParser::RBRACE)
          | (1ULL << FgsgParser::ID)
          | (1ULL << FgsgParser::VERTEX)
          | (1ULL << FgsgParser::COLORSTEP))) != 0)) {
          setState(426);
          sequenceItem();
          setState(431);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
        setState(432);
        match(FgsgParser::RBRACK);
        break;
      }

      case FgsgParser::VERTEX: {
        _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<FgsgParser::PolygonItemContext>(_localctx));
        enterOuterAlt(_localctx, 4);
        setState(433);
        dynamic_cast<PolygonItemContext *>(_localctx)->polygon = match(FgsgParser::VERTEX);
        break;
      }

      case FgsgParser::TILDE: {
        _localctx = dynamic_cast<ItemContext *>(_tracker.createInstance<FgsgParser::SurfaceItemContext>(_localctx));
        enterOuterAlt(_localctx, 5);
        setState(434);
        match(FgsgParser::TILDE);
        setState(437);
        _errHandler->sync(this);
        switch (_input->LA(1)) {
          case FgsgParser::ID: {
            setState(435);
            dynamic_cast<SurfaceItemContext *>(_localctx)->surface = match(FgsgParser::ID);
            break;
          }

          case FgsgParser::STRING: {
            setState(436);
            dynamic_cast<SurfaceItemContext *>(_localctx)->surfaceFile = match(FgsgParser::STRING);
            break;
          }

        default:
          throw NoViableAltException(this);
        }
        setState(440);
        _errHandler->sync(this);

        _la = _input->LA(1);
        if (_la == FgsgParser::LPAREN) {
          setState(439);
          callArgs();
        }
        break;
      }

    default:
      throw NoViableAltException(this);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- CallArgsContext ------------------------------------------------------------------

FgsgParser::CallArgsContext::CallArgsContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::CallArgsContext::LPAREN() {
  return getToken(FgsgParser::LPAREN, 0);
}

tree::TerminalNode* FgsgParser::CallArgsContext::RPAREN() {
  return getToken(FgsgParser::RPAREN, 0);
}

std::vector<FgsgParser::ExprContext *> FgsgParser::CallArgsContext::expr() {
  return getRuleContexts<FgsgParser::ExprContext>();
}

FgsgParser::ExprContext* FgsgParser::CallArgsContext::expr(size_t i) {
  return getRuleContext<FgsgParser::ExprContext>(i);
}

std::vector<tree::TerminalNode *> FgsgParser::CallArgsContext::COMMA() {
  return getTokens(FgsgParser::COMMA);
}

tree::TerminalNode* FgsgParser::CallArgsContext::COMMA(size_t i) {
  return getToken(FgsgParser::COMMA, i);
}


size_t FgsgParser::CallArgsContext::getRuleIndex() const {
  return FgsgParser::RuleCallArgs;
}

antlrcpp::Any FgsgParser::CallArgsContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitCallArgs(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::CallArgsContext* FgsgParser::callArgs() {
  CallArgsContext *_localctx = _tracker.createInstance<CallArgsContext>(_ctx, getState());
  enterRule(_localctx, 76, FgsgParser::RuleCallArgs);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(444);
    match(FgsgParser::LPAREN);
    setState(453);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if ((((_la & ~ 0x3fULL) == 0) &&
      ((1ULL << _la) & ((1ULL << FgsgParser::TRUE)
      | (1ULL << FgsgParser::FALSE)
      | (1ULL << FgsgParser::PLUS)
      | (1ULL << FgsgParser::MINUS)
      | (1ULL << FgsgParser::BANG)
      | (1ULL << FgsgParser::TILDE)
      | (1ULL << FgsgParser::LPAREN)
      | (1ULL << FgsgParser::RELSIZE)
      | (1ULL << FgsgParser::FLOAT)
      | (1ULL << FgsgParser::INT)
      | (1ULL << FgsgParser::ID)
      | (1ULL << FgsgParser::STRING))) != 0)) {
      setState(445);
      expr(0);
      setState(450);
      _errHandler->sync(this);
      _la = _input->LA(1);
      while (_la == FgsgParser::COMMA) {
        setState(446);
        match(FgsgParser::COMMA);
        setState(447);
        expr(0);
        setState(452);
        _errHandler->sync(this);
        _la = _input->LA(1);
      }
    }
    setState(455);
    match(FgsgParser::RPAREN);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- BodyContext ------------------------------------------------------------------

FgsgParser::BodyContext::BodyContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::BodyContext::LBRACE() {
  return getToken(FgsgParser::LBRACE, 0);
}

std::vector<FgsgParser::BodyPartContext *> FgsgParser::BodyContext::bodyPart() {
  return getRuleContexts<FgsgParser::BodyPartContext>();
}

FgsgParser::BodyPartContext* FgsgParser::BodyContext::bodyPart(size_t i) {
  return getRuleContext<FgsgParser::BodyPartContext>(i);
}

tree::TerminalNode* FgsgParser::BodyContext::RBRACE() {
  return getToken(FgsgParser::RBRACE, 0);
}

std::vector<tree::TerminalNode *> FgsgParser::BodyContext::PIPE() {
  return getTokens(FgsgParser::PIPE);
}

tree::TerminalNode* FgsgParser::BodyContext::PIPE(size_t i) {
  return getToken(FgsgParser::PIPE, i);
}

std::vector<tree::TerminalNode *> FgsgParser::BodyContext::COMMA() {
  return getTokens(FgsgParser::COMMA);
}

tree::TerminalNode* FgsgParser::BodyContext::COMMA(size_t i) {
  return getToken(FgsgParser::COMMA, i);
}

tree::TerminalNode* FgsgParser::BodyContext::STAR() {
  return getToken(FgsgParser::STAR, 0);
}


size_t FgsgParser::BodyContext::getRuleIndex() const {
  return FgsgParser::RuleBody;
}

antlrcpp::Any FgsgParser::BodyContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitBody(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::BodyContext* FgsgParser::body() {
  BodyContext *_localctx = _tracker.createInstance<BodyContext>(_ctx, getState());
  enterRule(_localctx, 78, FgsgParser::RuleBody);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(457);
    match(FgsgParser::LBRACE);
    setState(458);
    bodyPart();
    setState(463);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while (_la == FgsgParser::PIPE

    || _la == FgsgParser::COMMA) {
      setState(459);
      _la = _input->LA(1);
      if (!(_la == FgsgParser::PIPE

      || _la == FgsgParser::COMMA)) {
      _errHandler->recoverInline(this);
      }
      else {
        _errHandler->reportMatch(this);
        consume();
      }
      setState(460);
      bodyPart();
      setState(465);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(466);
    match(FgsgParser::RBRACE);
    setState(468);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == FgsgParser::STAR) {
      setState(467);
      dynamic_cast<BodyContext *>(_localctx)->repeat = match(FgsgParser::STAR);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- BodyPartContext ------------------------------------------------------------------

FgsgParser::BodyPartContext::BodyPartContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::BodyPartContext::EPSILON() {
  return getToken(FgsgParser::EPSILON, 0);
}

tree::TerminalNode* FgsgParser::BodyPartContext::COLON() {
  return getToken(FgsgParser::COLON, 0);
}

tree::TerminalNode* FgsgParser::BodyPartContext::ID() {
  return getToken(FgsgParser::ID, 0);
}

FgsgParser::ExprContext* FgsgParser::BodyPartContext::expr() {
  return getRuleContext<FgsgParser::ExprContext>(0);
}

std::vector<FgsgParser::ItemContext *> FgsgParser::BodyPartContext::item() {
  return getRuleContexts<FgsgParser::ItemContext>();
}

FgsgParser::ItemContext* FgsgParser::BodyPartContext::item(size_t i) {
  return getRuleContext<FgsgParser::ItemContext>(i);
}

tree::TerminalNode* FgsgParser::BodyPartContext::ASSIGN() {
  return getToken(FgsgParser::ASSIGN, 0);
}


size_t FgsgParser::BodyPartContext::getRuleIndex() const {
  return FgsgParser::RuleBodyPart;
}

antlrcpp::Any FgsgParser::BodyPartContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitBodyPart(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::BodyPartContext* FgsgParser::bodyPart() {
  BodyPartContext *_localctx = _tracker.createInstance<BodyPartContext>(_ctx, getState());
  enterRule(_localctx, 80, FgsgParser::RuleBodyPart);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(478);
    _errHandler->sync(this);

    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 59, _ctx)) {
    case 1: {
      setState(470);
      dynamic_cast<BodyPartContext *>(_localctx)->selector = match(FgsgParser::ID);
      setState(472);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == FgsgParser::ASSIGN) {
        setState(471);
        dynamic_cast<BodyPartContext *>(_localctx)->merged = match(FgsgParser::ASSIGN);
      }
      setState(474);
      match(FgsgParser::COLON);
      break;
    }

    case 2: {
      setState(475);
      dynamic_cast<BodyPartContext *>(_localctx)->size = expr(0);
      setState(476);
      match(FgsgParser::COLON);
      break;
    }

    }
    setState(486);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case FgsgParser::EPSILON: {
        setState(480);
        match(FgsgParser::EPSILON);
        break;
      }

      case FgsgParser::AND:
      case FgsgParser::PLUS:
      case FgsgParser::MINUS:
      case FgsgParser::SLASH:
      case FgsgParser::PERCENT:
      case FgsgParser::CARET:
      case FgsgParser::BANG:
      case FgsgParser::AMP:
      case FgsgParser::BACKSLASH:
      case FgsgParser::DOLLAR:
      case FgsgParser::QUOTE:
      case FgsgParser::TILDE:
      case FgsgParser::LBRACK:
      case FgsgParser::ID:
      case FgsgParser::VERTEX: {
        setState(482); 
        _errHandler->sync(this);
        _la = _input->LA(1);
        do {
          setState(481);
          item();
          setState(484); 
          _errHandler->sync(this);
          _la = _input->LA(1);
        } while ((((_la & ~ 0x3fULL) == 0) &&
          ((1ULL << _la) & ((1ULL << FgsgParser::AND)
          | (1ULL << FgsgParser::PLUS)
          | (1ULL << FgsgParser::MINUS)
          | (1ULL << FgsgParser::SLASH)
          | (1ULL << FgsgParser::PERCENT)
          | (1ULL << FgsgParser::CARET)
          | (1ULL << FgsgParser::BANG)
          | (1ULL << FgsgParser::AMP)
          | (1ULL << FgsgParser::BACKSLASH)
          | (1ULL << FgsgParser::DOLLAR)
          | (1ULL << FgsgParser::QUOTE)
          | (1ULL << FgsgParser::TILDE)
          | (1ULL << FgsgParser::LBRACK)
          | (1ULL << FgsgParser::ID)
          | (1ULL << FgsgParser::VERTEX))) != 0));
        break;
      }

    default:
      throw NoViableAltException(this);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ExprContext ------------------------------------------------------------------

FgsgParser::ExprContext::ExprContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}


size_t FgsgParser::ExprContext::getRuleIndex() const {
  return FgsgParser::RuleExpr;
}

void FgsgParser::ExprContext::copyFrom(ExprContext *ctx) {
  ParserRuleContext::copyFrom(ctx);
}

//----------------- UnaryExprContext ------------------------------------------------------------------

FgsgParser::ExprContext* FgsgParser::UnaryExprContext::expr() {
  return getRuleContext<FgsgParser::ExprContext>(0);
}

tree::TerminalNode* FgsgParser::UnaryExprContext::MINUS() {
  return getToken(FgsgParser::MINUS, 0);
}

tree::TerminalNode* FgsgParser::UnaryExprContext::BANG() {
  return getToken(FgsgParser::BANG, 0);
}

tree::TerminalNode* FgsgParser::UnaryExprContext::PLUS() {
  return getToken(FgsgParser::PLUS, 0);
}

FgsgParser::UnaryExprContext::UnaryExprContext(ExprContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::UnaryExprContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitUnaryExpr(this);
  else
    return visitor->visitChildren(this);
}
//----------------- PrimaryExprContext ------------------------------------------------------------------

FgsgParser::PrimaryContext* FgsgParser::PrimaryExprContext::primary() {
  return getRuleContext<FgsgParser::PrimaryContext>(0);
}

FgsgParser::PrimaryExprContext::PrimaryExprContext(ExprContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::PrimaryExprContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitPrimaryExpr(this);
  else
    return visitor->visitChildren(this);
}
//----------------- TernaryExprContext ------------------------------------------------------------------

std::vector<FgsgParser::ExprContext *> FgsgParser::TernaryExprContext::expr() {
  return getRuleContexts<FgsgParser::ExprContext>();
}

FgsgParser::ExprContext* FgsgParser::TernaryExprContext::expr(size_t i) {
  return getRuleContext<FgsgParser::ExprContext>(i);
}

tree::TerminalNode* FgsgParser::TernaryExprContext::QUESTION() {
  return getToken(FgsgParser::QUESTION, 0);
}

tree::TerminalNode* FgsgParser::TernaryExprContext::COLON() {
  return getToken(FgsgParser::COLON, 0);
}

FgsgParser::TernaryExprContext::TernaryExprContext(ExprContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::TernaryExprContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitTernaryExpr(this);
  else
    return visitor->visitChildren(this);
}
//----------------- BinaryExprContext ------------------------------------------------------------------

std::vector<FgsgParser::ExprContext *> FgsgParser::BinaryExprContext::expr() {
  return getRuleContexts<FgsgParser::ExprContext>();
}

FgsgParser::ExprContext* FgsgParser::BinaryExprContext::expr(size_t i) {
  return getRuleContext<FgsgParser::ExprContext>(i);
}

tree::TerminalNode* FgsgParser::BinaryExprContext::CARET() {
  return getToken(FgsgParser::CARET, 0);
}

tree::TerminalNode* FgsgParser::BinaryExprContext::STAR() {
  return getToken(FgsgParser::STAR, 0);
}

tree::TerminalNode* FgsgParser::BinaryExprContext::SLASH() {
  return getToken(FgsgParser::SLASH, 0);
}

tree::TerminalNode* FgsgParser::BinaryExprContext::PERCENT() {
  return getToken(FgsgParser::PERCENT, 0);
}

tree::TerminalNode* FgsgParser::BinaryExprContext::PLUS() {
  return getToken(FgsgParser::PLUS, 0);
}

tree::TerminalNode* FgsgParser::BinaryExprContext::MINUS() {
  return getToken(FgsgParser::MINUS, 0);
}

tree::TerminalNode* FgsgParser::BinaryExprContext::LT() {
  return getToken(FgsgParser::LT, 0);
}

tree::TerminalNode* FgsgParser::BinaryExprContext::LE() {
  return getToken(FgsgParser::LE, 0);
}

tree::TerminalNode* FgsgParser::BinaryExprContext::GT() {
  return getToken(FgsgParser::GT, 0);
}

tree::TerminalNode* FgsgParser::BinaryExprContext::GE() {
  return getToken(FgsgParser::GE, 0);
}

tree::TerminalNode* FgsgParser::BinaryExprContext::EQ() {
  return getToken(FgsgParser::EQ, 0);
}

tree::TerminalNode* FgsgParser::BinaryExprContext::NEQ() {
  return getToken(FgsgParser::NEQ, 0);
}

tree::TerminalNode* FgsgParser::BinaryExprContext::AND() {
  return getToken(FgsgParser::AND, 0);
}

tree::TerminalNode* FgsgParser::BinaryExprContext::OR() {
  return getToken(FgsgParser::OR, 0);
}

FgsgParser::BinaryExprContext::BinaryExprContext(ExprContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::BinaryExprContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitBinaryExpr(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::ExprContext* FgsgParser::expr() {
   return expr(0);
}

FgsgParser::ExprContext* FgsgParser::expr(int precedence) {
  ParserRuleContext *parentContext = _ctx;
  size_t parentState = getState();
  FgsgParser::ExprContext *_localctx = _tracker.createInstance<ExprContext>(_ctx, parentState);
  FgsgParser::ExprContext *previousContext = _localctx;
  (void)previousContext; // Silence compiler, in case the context is not used by generated code.
  size_t startState = 82;
  enterRecursionRule(_localctx, 82, FgsgParser::RuleExpr, precedence);

    size_t _la = 0;

  auto onExit = finally([=] {
    unrollRecursionContexts(parentContext);
  });
  try {
    size_t alt;
    enterOuterAlt(_localctx, 1);
    setState(492);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case FgsgParser::TRUE:
      case FgsgParser::FALSE:
      case FgsgParser::TILDE:
      case FgsgParser::LPAREN:
      case FgsgParser::RELSIZE:
      case FgsgParser::FLOAT:
      case FgsgParser::INT:
      case FgsgParser::ID:
      case FgsgParser::STRING: {
        _localctx = _tracker.createInstance<PrimaryExprContext>(_localctx);
        _ctx = _localctx;
        previousContext = _localctx;

        setState(489);
        primary();
        break;
      }

      case FgsgParser::PLUS:
      case FgsgParser::MINUS:
      case FgsgParser::BANG: {
        _localctx = _tracker.createInstance<UnaryExprContext>(_localctx);
        _ctx = _localctx;
        previousContext = _localctx;
        setState(490);
        dynamic_cast<UnaryExprContext *>(_localctx)->op = _input->LT(1);
        _la = _input->LA(1);
        if (!((((_la & ~ 0x3fULL) == 0) &&
          ((1ULL << _la) & ((1ULL << FgsgParser::PLUS)
          | (1ULL << FgsgParser::MINUS)
          | (1ULL << FgsgParser::BANG))) != 0))) {
          dynamic_cast<UnaryExprContext *>(_localctx)->op = _errHandler->recoverInline(this);
        }
        else {
          _errHandler->reportMatch(this);
          consume();
        }
        setState(491);
        expr(8);
        break;
      }

    default:
      throw NoViableAltException(this);
    }
    _ctx->stop = _input->LT(-1);
    setState(523);
    _errHandler->sync(this);
    alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 64, _ctx);
    while (alt != 2 && alt != atn::ATN::INVALID_ALT_NUMBER) {
      if (alt == 1) {
        if (!_parseListeners.empty())
          triggerExitRuleEvent();
        previousContext = _localctx;
        setState(521);
        _errHandler->sync(this);
        switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 63, _ctx)) {
        case 1: {
          auto newContext = _tracker.createInstance<BinaryExprContext>(_tracker.createInstance<ExprContext>(parentContext, parentState));
          _localctx = newContext;
          pushNewRecursionContext(newContext, startState, RuleExpr);
          setState(494);

          if (!(precpred(_ctx, 9))) throw FailedPredicateException(this, "precpred(_ctx, 9)");
          setState(495);
          dynamic_cast<BinaryExprContext *>(_localctx)->op = match(FgsgParser::CARET);
          setState(496);
          expr(9);
          break;
        }

        case 2: {
          auto newContext = _tracker.createInstance<BinaryExprContext>(_tracker.createInstance<ExprContext>(parentContext, parentState));
          _localctx = newContext;
          pushNewRecursionContext(newContext, startState, RuleExpr);
          setState(497);

          if (!(precpred(_ctx, 7))) throw FailedPredicateException(this, "precpred(_ctx, 7)");
          setState(498);
          dynamic_cast<BinaryExprContext *>(_localctx)->op = _input->LT(1);
          _la = _input->LA(1);
          if (!((((_la & ~ 0x3fULL) == 0) &&
            ((1ULL << _la) & ((1ULL << FgsgParser::STAR)
            | (1ULL << FgsgParser::SLASH)
            | (1ULL << FgsgParser::PERCENT))) != 0))) {
            dynamic_cast<BinaryExprContext *>(_localctx)->op = _errHandler->recoverInline(this);
          }
          else {
            _errHandler->reportMatch(this);
            consume();
          }
          setState(499);
          expr(8);
          break;
        }

        case 3: {
          auto newContext = _tracker.createInstance<BinaryExprContext>(_tracker.createInstance<ExprContext>(parentContext, parentState));
          _localctx = newContext;
          pushNewRecursionContext(newContext, startState, RuleExpr);
          setState(500);

          if (!(precpred(_ctx, 6))) throw FailedPredicateException(this, "precpred(_ctx, 6)");
          setState(501);
          dynamic_cast<BinaryExprContext *>(_localctx)->op = _input->LT(1);
          _la = _input->LA(1);
          if (!(_la == FgsgParser::PLUS

          || _la == FgsgParser::MINUS)) {
            dynamic_cast<BinaryExprContext *>(_localctx)->op = _errHandler->recoverInline(this);
          }
          else {
            _errHandler->reportMatch(this);
            consume();
          }
          setState(502);
          expr(7);
          break;
        }

        case 4: {
          auto newContext = _tracker.createInstance<BinaryExprContext>(_tracker.createInstance<ExprContext>(parentContext, parentState));
          _localctx = newContext;
          pushNewRecursionContext(newContext, startState, RuleExpr);
          setState(503);

          if (!(precpred(_ctx, 5))) throw FailedPredicateException(this, "precpred(_ctx, 5)");
          setState(504);
          dynamic_cast<BinaryExprContext *>(_localctx)->op = _input->LT(1);
          _la = _input->LA(1);
          if (!((((_la & ~ 0x3fULL) == 0) &&
            ((1ULL << _la) & ((1ULL << FgsgParser::LE)
            | (1ULL << FgsgParser::GE)
            | (1ULL << FgsgParser::LT)
            | (1ULL << FgsgParser::GT))) != 0))) {
            dynamic_cast<BinaryExprContext *>(_localctx)->op = _errHandler->recoverInline(this);
          }
          else {
            _errHandler->reportMatch(this);
            consume();
          }
          setState(505);
          expr(6);
          break;
        }

        case 5: {
          auto newContext = _tracker.createInstance<BinaryExprContext>(_tracker.createInstance<ExprContext>(parentContext, parentState));
          _localctx = newContext;
          pushNewRecursionContext(newContext, startState, RuleExpr);
          setState(506);

          if (!(precpred(_ctx, 4))) throw FailedPredicateException(this, "precpred(_ctx, 4)");
          setState(507);
          dynamic_cast<BinaryExprContext *>(_localctx)->op = _input->LT(1);
          _la = _input->LA(1);
          if (!(_la == FgsgParser::EQ

          || _la == FgsgParser::NEQ)) {
            dynamic_cast<BinaryExprContext *>(_localctx)->op = _errHandler->recoverInline(this);
          }
          else {
            _errHandler->reportMatch(this);
            consume();
          }
          setState(508);
          expr(5);
          break;
        }

        case 6: {
          auto newContext = _tracker.createInstance<BinaryExprContext>(_tracker.createInstance<ExprContext>(parentContext, parentState));
          _localctx = newContext;
          pushNewRecursionContext(newContext, startState, RuleExpr);
          setState(509);

          if (!(precpred(_ctx, 3))) throw FailedPredicateException(this, "precpred(_ctx, 3)");
          setState(510);
          dynamic_cast<BinaryExprContext *>(_localctx)->op = match(FgsgParser::AND);
          setState(511);
          expr(4);
          break;
        }

        case 7: {
          auto newContext = _tracker.createInstance<BinaryExprContext>(_tracker.createInstance<ExprContext>(parentContext, parentState));
          _localctx = newContext;
          pushNewRecursionContext(newContext, startState, RuleExpr);
          setState(512);

          if (!(precpred(_ctx, 2))) throw FailedPredicateException(this, "precpred(_ctx, 2)");
          setState(513);
          dynamic_cast<BinaryExprContext *>(_localctx)->op = match(FgsgParser::OR);
          setState(514);
          expr(3);
          break;
        }

        case 8: {
          auto newContext = _tracker.createInstance<TernaryExprContext>(_tracker.createInstance<ExprContext>(parentContext, parentState));
          _localctx = newContext;
          pushNewRecursionContext(newContext, startState, RuleExpr);
          setState(515);

          if (!(precpred(_ctx, 1))) throw FailedPredicateException(this, "precpred(_ctx, 1)");
          setState(516);
          match(FgsgParser::QUESTION);
          setState(517);
          expr(0);
          setState(518);
          match(FgsgParser::COLON);
          setState(519);
          expr(1);
          break;
        }

        } 
      }
      setState(525);
      _errHandler->sync(this);
      alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 64, _ctx);
    }
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }
  return _localctx;
}

//----------------- PrimaryContext ------------------------------------------------------------------

FgsgParser::PrimaryContext::PrimaryContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}


size_t FgsgParser::PrimaryContext::getRuleIndex() const {
  return FgsgParser::RulePrimary;
}

void FgsgParser::PrimaryContext::copyFrom(PrimaryContext *ctx) {
  ParserRuleContext::copyFrom(ctx);
}

//----------------- MemberPrimaryContext ------------------------------------------------------------------

std::vector<tree::TerminalNode *> FgsgParser::MemberPrimaryContext::DOT() {
  return getTokens(FgsgParser::DOT);
}

tree::TerminalNode* FgsgParser::MemberPrimaryContext::DOT(size_t i) {
  return getToken(FgsgParser::DOT, i);
}

std::vector<tree::TerminalNode *> FgsgParser::MemberPrimaryContext::ID() {
  return getTokens(FgsgParser::ID);
}

tree::TerminalNode* FgsgParser::MemberPrimaryContext::ID(size_t i) {
  return getToken(FgsgParser::ID, i);
}

FgsgParser::CallArgsContext* FgsgParser::MemberPrimaryContext::callArgs() {
  return getRuleContext<FgsgParser::CallArgsContext>(0);
}

FgsgParser::MemberPrimaryContext::MemberPrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::MemberPrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitMemberPrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- IdentPrimaryContext ------------------------------------------------------------------

tree::TerminalNode* FgsgParser::IdentPrimaryContext::ID() {
  return getToken(FgsgParser::ID, 0);
}

FgsgParser::IdentPrimaryContext::IdentPrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::IdentPrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitIdentPrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- ParenPrimaryContext ------------------------------------------------------------------

tree::TerminalNode* FgsgParser::ParenPrimaryContext::LPAREN() {
  return getToken(FgsgParser::LPAREN, 0);
}

FgsgParser::ExprContext* FgsgParser::ParenPrimaryContext::expr() {
  return getRuleContext<FgsgParser::ExprContext>(0);
}

tree::TerminalNode* FgsgParser::ParenPrimaryContext::RPAREN() {
  return getToken(FgsgParser::RPAREN, 0);
}

FgsgParser::ParenPrimaryContext::ParenPrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::ParenPrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitParenPrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- VectorPrimaryContext ------------------------------------------------------------------

tree::TerminalNode* FgsgParser::VectorPrimaryContext::LPAREN() {
  return getToken(FgsgParser::LPAREN, 0);
}

std::vector<FgsgParser::ExprContext *> FgsgParser::VectorPrimaryContext::expr() {
  return getRuleContexts<FgsgParser::ExprContext>();
}

FgsgParser::ExprContext* FgsgParser::VectorPrimaryContext::expr(size_t i) {
  return getRuleContext<FgsgParser::ExprContext>(i);
}

tree::TerminalNode* FgsgParser::VectorPrimaryContext::RPAREN() {
  return getToken(FgsgParser::RPAREN, 0);
}

std::vector<tree::TerminalNode *> FgsgParser::VectorPrimaryContext::COMMA() {
  return getTokens(FgsgParser::COMMA);
}

tree::TerminalNode* FgsgParser::VectorPrimaryContext::COMMA(size_t i) {
  return getToken(FgsgParser::COMMA, i);
}

FgsgParser::VectorPrimaryContext::VectorPrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::VectorPrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitVectorPrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- StringPrimaryContext ------------------------------------------------------------------

tree::TerminalNode* FgsgParser::StringPrimaryContext::STRING() {
  return getToken(FgsgParser::STRING, 0);
}

FgsgParser::StringPrimaryContext::StringPrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::StringPrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitStringPrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- FloatSizePrimaryContext ------------------------------------------------------------------

tree::TerminalNode* FgsgParser::FloatSizePrimaryContext::TILDE() {
  return getToken(FgsgParser::TILDE, 0);
}

FgsgParser::PrimaryContext* FgsgParser::FloatSizePrimaryContext::primary() {
  return getRuleContext<FgsgParser::PrimaryContext>(0);
}

FgsgParser::FloatSizePrimaryContext::FloatSizePrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::FloatSizePrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitFloatSizePrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- CallPrimaryContext ------------------------------------------------------------------

FgsgParser::CallArgsContext* FgsgParser::CallPrimaryContext::callArgs() {
  return getRuleContext<FgsgParser::CallArgsContext>(0);
}

tree::TerminalNode* FgsgParser::CallPrimaryContext::ID() {
  return getToken(FgsgParser::ID, 0);
}

FgsgParser::CallPrimaryContext::CallPrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::CallPrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitCallPrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- RelSizePrimaryContext ------------------------------------------------------------------

tree::TerminalNode* FgsgParser::RelSizePrimaryContext::RELSIZE() {
  return getToken(FgsgParser::RELSIZE, 0);
}

FgsgParser::RelSizePrimaryContext::RelSizePrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::RelSizePrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitRelSizePrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- BoolPrimaryContext ------------------------------------------------------------------

tree::TerminalNode* FgsgParser::BoolPrimaryContext::TRUE() {
  return getToken(FgsgParser::TRUE, 0);
}

tree::TerminalNode* FgsgParser::BoolPrimaryContext::FALSE() {
  return getToken(FgsgParser::FALSE, 0);
}

FgsgParser::BoolPrimaryContext::BoolPrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::BoolPrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitBoolPrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- NumberPrimaryContext ------------------------------------------------------------------

FgsgParser::NumberContext* FgsgParser::NumberPrimaryContext::number() {
  return getRuleContext<FgsgParser::NumberContext>(0);
}

FgsgParser::NumberPrimaryContext::NumberPrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any FgsgParser::NumberPrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitNumberPrimary(this);
  else
    return visitor->visitChildren(this);
}
FgsgParser::PrimaryContext* FgsgParser::primary() {
  PrimaryContext *_localctx = _tracker.createInstance<PrimaryContext>(_ctx, getState());
  enterRule(_localctx, 84, FgsgParser::RulePrimary);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(559);
    _errHandler->sync(this);
    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 68, _ctx)) {
    case 1: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<FgsgParser::NumberPrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 1);
      setState(526);
      number();
      break;
    }

    case 2: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<FgsgParser::RelSizePrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 2);
      setState(527);
      match(FgsgParser::RELSIZE);
      break;
    }

    case 3: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<FgsgParser::StringPrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 3);
      setState(528);
      match(FgsgParser::STRING);
      break;
    }

    case 4: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<FgsgParser::BoolPrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 4);
      setState(529);
      dynamic_cast<BoolPrimaryContext *>(_localctx)->value = _input->LT(1);
      _la = _input->LA(1);
      if (!(_la == FgsgParser::TRUE

      || _la == FgsgParser::FALSE)) {
        dynamic_cast<BoolPrimaryContext *>(_localctx)->value = _errHandler->recoverInline(this);
      }
      else {
        _errHandler->reportMatch(this);
        consume();
      }
      break;
    }

    case 5: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<FgsgParser::MemberPrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 5);
      setState(530);
      dynamic_cast<MemberPrimaryContext *>(_localctx)->object = match(FgsgParser::ID);
      setState(531);
      match(FgsgParser::DOT);
      setState(532);
      dynamic_cast<MemberPrimaryContext *>(_localctx)->member = match(FgsgParser::ID);
      setState(535);
      _errHandler->sync(this);

      switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 65, _ctx)) {
      case 1: {
        setState(533);
        match(FgsgParser::DOT);
        setState(534);
        dynamic_cast<MemberPrimaryContext *>(_localctx)->sub = match(FgsgParser::ID);
        break;
      }

      }
      setState(538);
      _errHandler->sync(this);

      switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 66, _ctx)) {
      case 1: {
        setState(537);
        callArgs();
        break;
      }

      }
      break;
    }

    case 6: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<FgsgParser::CallPrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 6);
      setState(540);
      dynamic_cast<CallPrimaryContext *>(_localctx)->name = match(FgsgParser::ID);
      setState(541);
      callArgs();
      break;
    }

    case 7: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<FgsgParser::IdentPrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 7);
      setState(542);
      dynamic_cast<IdentPrimaryContext *>(_localctx)->name = match(FgsgParser::ID);
      break;
    }

    case 8: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<FgsgParser::ParenPrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 8);
      setState(543);
      match(FgsgParser::LPAREN);
      setState(544);
      expr(0);
      setState(545);
      match(FgsgParser::RPAREN);
      break;
    }

    case 9: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<FgsgParser::VectorPrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 9);
      setState(547);
      match(FgsgParser::LPAREN);
      setState(548);
      expr(0);
      setState(551); 
      _errHandler->sync(this);
      _la = _input->LA(1);
      do {
        setState(549);
        match(FgsgParser::COMMA);
        setState(550);
        expr(0);
        setState(553); 
        _errHandler->sync(this);
        _la = _input->LA(1);
      } while (_la == FgsgParser::COMMA);
      setState(555);
      match(FgsgParser::RPAREN);
      break;
    }

    case 10: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<FgsgParser::FloatSizePrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 10);
      setState(557);
      match(FgsgParser::TILDE);
      setState(558);
      primary();
      break;
    }

    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- NumberContext ------------------------------------------------------------------

FgsgParser::NumberContext::NumberContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* FgsgParser::NumberContext::INT() {
  return getToken(FgsgParser::INT, 0);
}

tree::TerminalNode* FgsgParser::NumberContext::FLOAT() {
  return getToken(FgsgParser::FLOAT, 0);
}


size_t FgsgParser::NumberContext::getRuleIndex() const {
  return FgsgParser::RuleNumber;
}

antlrcpp::Any FgsgParser::NumberContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<FgsgVisitor*>(visitor))
    return parserVisitor->visitNumber(this);
  else
    return visitor->visitChildren(this);
}

FgsgParser::NumberContext* FgsgParser::number() {
  NumberContext *_localctx = _tracker.createInstance<NumberContext>(_ctx, getState());
  enterRule(_localctx, 86, FgsgParser::RuleNumber);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(561);
    _la = _input->LA(1);
    if (!(_la == FgsgParser::FLOAT

    || _la == FgsgParser::INT)) {
    _errHandler->recoverInline(this);
    }
    else {
      _errHandler->reportMatch(this);
      consume();
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

bool FgsgParser::sempred(RuleContext *context, size_t ruleIndex, size_t predicateIndex) {
  switch (ruleIndex) {
    case 41: return exprSempred(dynamic_cast<ExprContext *>(context), predicateIndex);

  default:
    break;
  }
  return true;
}

bool FgsgParser::exprSempred(ExprContext *_localctx, size_t predicateIndex) {
  switch (predicateIndex) {
    case 0: return precpred(_ctx, 9);
    case 1: return precpred(_ctx, 7);
    case 2: return precpred(_ctx, 6);
    case 3: return precpred(_ctx, 5);
    case 4: return precpred(_ctx, 4);
    case 5: return precpred(_ctx, 3);
    case 6: return precpred(_ctx, 2);
    case 7: return precpred(_ctx, 1);

  default:
    break;
  }
  return true;
}

// Static vars and initialization.
std::vector<dfa::DFA> FgsgParser::_decisionToDFA;
atn::PredictionContextCache FgsgParser::_sharedContextCache;

// We own the ATN which in turn owns the ATN states.
atn::ATN FgsgParser::_atn;
std::vector<uint16_t> FgsgParser::_serializedATN;

std::vector<std::string> FgsgParser::_ruleNames = {
  "program", "statement", "valueDecl", "importDecl", "importSetting", "surfaceDecl", 
  "fieldDecl", "fieldSource", "fieldDesignItem", "fieldDesignWord", "designValue", 
  "textureDecl", "tilesetDecl", "tilesetItem", "deriveDecl", "turtleDecl", 
  "turtleSetting", "ignoreDecl", "ignoredSymbol", "collisionDecl", "collisionWord", 
  "axiomDecl", "priorityDecl", "grammarRule", "ruleLabel", "ruleHead", "leftContext", 
  "rightContext", "contextModule", "modulePattern", "turtleSymbol", "paramDecl", 
  "ruleBody", "branch", "arrow", "successor", "sequenceItem", "item", "callArgs", 
  "body", "bodyPart", "expr", "primary", "number"
};

std::vector<std::string> FgsgParser::_literalNames = {
  "", "'import'", "'const'", "'attr'", "'surface'", "'field'", "'texture'", 
  "'tileset'", "'derive'", "'turtle'", "'#ignore'", "'collision'", "'axiom'", 
  "", "'true'", "'false'", "", "", "'='", "'=='", "'!='", "'<='", "'>='", 
  "'<'", "'>'", "'&&'", "'||'", "'+'", "'-'", "'*'", "'/'", "'%'", "'^'", 
  "'!'", "'&'", "'|'", "'\\'", "'$'", "'''", "'~'", "'?'", "':'", "';'", 
  "','", "'.'", "'('", "')'", "'['", "']'", "'{'", "'}'"
};

std::vector<std::string> FgsgParser::_symbolicNames = {
  "", "IMPORT", "CONST", "ATTR", "SURFACE", "FIELD", "TEXTURE", "TILESET", 
  "DERIVE", "TURTLE", "IGNORE", "COLLISION", "AXIOM", "PRIORITY", "TRUE", 
  "FALSE", "EPSILON", "ARROW", "ASSIGN", "EQ", "NEQ", "LE", "GE", "LT", 
  "GT", "AND", "OR", "PLUS", "MINUS", "STAR", "SLASH", "PERCENT", "CARET", 
  "BANG", "AMP", "PIPE", "BACKSLASH", "DOLLAR", "QUOTE", "TILDE", "QUESTION", 
  "COLON", "SEMI", "COMMA", "DOT", "LPAREN", "RPAREN", "LBRACK", "RBRACK", 
  "LBRACE", "RBRACE", "RELSIZE", "FLOAT", "INT", "ID", "STRING", "UNTERMINATED_STRING", 
  "LINE_COMMENT", "BLOCK_COMMENT", "UNTERMINATED_COMMENT", "WS", "UNKNOWN_CHAR", 
  "VERTEX", "COLORSTEP"
};

dfa::Vocabulary FgsgParser::_vocabulary(_literalNames, _symbolicNames);

std::vector<std::string> FgsgParser::_tokenNames;

FgsgParser::Initializer::Initializer() {
	for (size_t i = 0; i < _symbolicNames.size(); ++i) {
		std::string name = _vocabulary.getLiteralName(i);
		if (name.empty()) {
			name = _vocabulary.getSymbolicName(i);
		}

		if (name.empty()) {
			_tokenNames.push_back("<INVALID>");
		} else {
      _tokenNames.push_back(name);
    }
	}

  _serializedATN = {
    0x3, 0x608b, 0xa72a, 0x8133, 0xb9ed, 0x417c, 0x3be7, 0x7786, 0x5964, 0x3, 
    0x41, 0x236, 0x4, 0x2, 0x9, 0x2, 0x4, 0x3, 0x9, 0x3, 0x4, 0x4, 0x9, 0x4, 
    0x4, 0x5, 0x9, 0x5, 0x4, 0x6, 0x9, 0x6, 0x4, 0x7, 0x9, 0x7, 0x4, 0x8, 
    0x9, 0x8, 0x4, 0x9, 0x9, 0x9, 0x4, 0xa, 0x9, 0xa, 0x4, 0xb, 0x9, 0xb, 
    0x4, 0xc, 0x9, 0xc, 0x4, 0xd, 0x9, 0xd, 0x4, 0xe, 0x9, 0xe, 0x4, 0xf, 
    0x9, 0xf, 0x4, 0x10, 0x9, 0x10, 0x4, 0x11, 0x9, 0x11, 0x4, 0x12, 0x9, 
    0x12, 0x4, 0x13, 0x9, 0x13, 0x4, 0x14, 0x9, 0x14, 0x4, 0x15, 0x9, 0x15, 
    0x4, 0x16, 0x9, 0x16, 0x4, 0x17, 0x9, 0x17, 0x4, 0x18, 0x9, 0x18, 0x4, 
    0x19, 0x9, 0x19, 0x4, 0x1a, 0x9, 0x1a, 0x4, 0x1b, 0x9, 0x1b, 0x4, 0x1c, 
    0x9, 0x1c, 0x4, 0x1d, 0x9, 0x1d, 0x4, 0x1e, 0x9, 0x1e, 0x4, 0x1f, 0x9, 
    0x1f, 0x4, 0x20, 0x9, 0x20, 0x4, 0x21, 0x9, 0x21, 0x4, 0x22, 0x9, 0x22, 
    0x4, 0x23, 0x9, 0x23, 0x4, 0x24, 0x9, 0x24, 0x4, 0x25, 0x9, 0x25, 0x4, 
    0x26, 0x9, 0x26, 0x4, 0x27, 0x9, 0x27, 0x4, 0x28, 0x9, 0x28, 0x4, 0x29, 
    0x9, 0x29, 0x4, 0x2a, 0x9, 0x2a, 0x4, 0x2b, 0x9, 0x2b, 0x4, 0x2c, 0x9, 
    0x2c, 0x4, 0x2d, 0x9, 0x2d, 0x3, 0x2, 0x7, 0x2, 0x5c, 0xa, 0x2, 0xc, 0x2, 
    0xe, 0x2, 0x5f, 0xb, 0x2, 0x3, 0x2, 0x3, 0x2, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x5, 0x3, 0x71, 0xa, 0x3, 
    0x3, 0x4, 0x3, 0x4, 0x3, 0x4, 0x3, 0x4, 0x3, 0x4, 0x3, 0x4, 0x3, 0x5, 
    0x3, 0x5, 0x3, 0x5, 0x3, 0x5, 0x5, 0x5, 0x7d, 0xa, 0x5, 0x3, 0x5, 0x3, 
    0x5, 0x3, 0x5, 0x3, 0x5, 0x7, 0x5, 0x83, 0xa, 0x5, 0xc, 0x5, 0xe, 0x5, 
    0x86, 0xb, 0x5, 0x3, 0x5, 0x3, 0x5, 0x5, 0x5, 0x8a, 0xa, 0x5, 0x3, 0x5, 
    0x3, 0x5, 0x3, 0x6, 0x3, 0x6, 0x3, 0x6, 0x3, 0x6, 0x3, 0x7, 0x3, 0x7, 
    0x3, 0x7, 0x3, 0x7, 0x5, 0x7, 0x96, 0xa, 0x7, 0x5, 0x7, 0x98, 0xa, 0x7, 
    0x3, 0x7, 0x3, 0x7, 0x3, 0x8, 0x3, 0x8, 0x3, 0x8, 0x3, 0x8, 0x3, 0x8, 
    0x3, 0x8, 0x3, 0x9, 0x3, 0x9, 0x3, 0x9, 0x3, 0x9, 0x7, 0x9, 0xa6, 0xa, 
    0x9, 0xc, 0x9, 0xe, 0x9, 0xa9, 0xb, 0x9, 0x3, 0x9, 0x3, 0x9, 0x3, 0x9, 
    0x5, 0x9, 0xae, 0xa, 0x9, 0x5, 0x9, 0xb0, 0xa, 0x9, 0x3, 0xa, 0x3, 0xa, 
    0x7, 0xa, 0xb4, 0xa, 0xa, 0xc, 0xa, 0xe, 0xa, 0xb7, 0xb, 0xa, 0x3, 0xa, 
    0x3, 0xa, 0x3, 0xb, 0x3, 0xb, 0x5, 0xb, 0xbd, 0xa, 0xb, 0x3, 0xb, 0x5, 
    0xb, 0xc0, 0xa, 0xb, 0x3, 0xc, 0x5, 0xc, 0xc3, 0xa, 0xc, 0x3, 0xc, 0x3, 
    0xc, 0x3, 0xc, 0x3, 0xc, 0x3, 0xc, 0x3, 0xc, 0x3, 0xc, 0x3, 0xc, 0x7, 
    0xc, 0xcd, 0xa, 0xc, 0xc, 0xc, 0xe, 0xc, 0xd0, 0xb, 0xc, 0x3, 0xc, 0x3, 
    0xc, 0x5, 0xc, 0xd4, 0xa, 0xc, 0x3, 0xd, 0x3, 0xd, 0x3, 0xd, 0x3, 0xd, 
    0x3, 0xd, 0x3, 0xd, 0x3, 0xe, 0x3, 0xe, 0x3, 0xe, 0x3, 0xe, 0x7, 0xe, 
    0xe0, 0xa, 0xe, 0xc, 0xe, 0xe, 0xe, 0xe3, 0xb, 0xe, 0x3, 0xe, 0x3, 0xe, 
    0x3, 0xe, 0x3, 0xf, 0x3, 0xf, 0x3, 0xf, 0x5, 0xf, 0xeb, 0xa, 0xf, 0x3, 
    0xf, 0x3, 0xf, 0x3, 0xf, 0x7, 0xf, 0xf0, 0xa, 0xf, 0xc, 0xf, 0xe, 0xf, 
    0xf3, 0xb, 0xf, 0x3, 0xf, 0x3, 0xf, 0x3, 0x10, 0x3, 0x10, 0x3, 0x10, 0x5, 
    0x10, 0xfa, 0xa, 0x10, 0x3, 0x10, 0x3, 0x10, 0x3, 0x11, 0x3, 0x11, 0x7, 
    0x11, 0x100, 0xa, 0x11, 0xc, 0x11, 0xe, 0x11, 0x103, 0xb, 0x11, 0x3, 
    0x11, 0x3, 0x11, 0x3, 0x12, 0x3, 0x12, 0x3, 0x12, 0x3, 0x13, 0x3, 0x13, 
    0x5, 0x13, 0x10c, 0xa, 0x13, 0x3, 0x13, 0x6, 0x13, 0x10f, 0xa, 0x13, 0xd, 
    0x13, 0xe, 0x13, 0x110, 0x3, 0x13, 0x3, 0x13, 0x3, 0x14, 0x3, 0x14, 0x5, 
    0x14, 0x117, 0xa, 0x14, 0x3, 0x15, 0x3, 0x15, 0x7, 0x15, 0x11b, 0xa, 
    0x15, 0xc, 0x15, 0xe, 0x15, 0x11e, 0xb, 0x15, 0x3, 0x15, 0x3, 0x15, 0x3, 
    0x16, 0x3, 0x16, 0x5, 0x16, 0x124, 0xa, 0x16, 0x3, 0x16, 0x5, 0x16, 
    0x127, 0xa, 0x16, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 
    0x3, 0x18, 0x3, 0x18, 0x5, 0x18, 0x130, 0xa, 0x18, 0x3, 0x18, 0x3, 0x18, 
    0x3, 0x18, 0x3, 0x19, 0x3, 0x19, 0x3, 0x19, 0x5, 0x19, 0x138, 0xa, 0x19, 
    0x3, 0x19, 0x3, 0x19, 0x3, 0x19, 0x5, 0x19, 0x13d, 0xa, 0x19, 0x3, 0x19, 
    0x3, 0x19, 0x3, 0x19, 0x3, 0x19, 0x3, 0x1a, 0x3, 0x1a, 0x3, 0x1b, 0x3, 
    0x1b, 0x3, 0x1b, 0x5, 0x1b, 0x148, 0xa, 0x1b, 0x3, 0x1b, 0x3, 0x1b, 0x3, 
    0x1b, 0x5, 0x1b, 0x14d, 0xa, 0x1b, 0x3, 0x1c, 0x6, 0x1c, 0x150, 0xa, 
    0x1c, 0xd, 0x1c, 0xe, 0x1c, 0x151, 0x3, 0x1d, 0x6, 0x1d, 0x155, 0xa, 
    0x1d, 0xd, 0x1d, 0xe, 0x1d, 0x156, 0x3, 0x1e, 0x3, 0x1e, 0x3, 0x1e, 0x5, 
    0x1e, 0x15c, 0xa, 0x1e, 0x3, 0x1f, 0x3, 0x1f, 0x5, 0x1f, 0x160, 0xa, 
    0x1f, 0x3, 0x1f, 0x3, 0x1f, 0x3, 0x1f, 0x3, 0x1f, 0x7, 0x1f, 0x166, 0xa, 
    0x1f, 0xc, 0x1f, 0xe, 0x1f, 0x169, 0xb, 0x1f, 0x5, 0x1f, 0x16b, 0xa, 
    0x1f, 0x3, 0x1f, 0x5, 0x1f, 0x16e, 0xa, 0x1f, 0x3, 0x20, 0x3, 0x20, 0x3, 
    0x21, 0x3, 0x21, 0x3, 0x22, 0x3, 0x22, 0x3, 0x22, 0x3, 0x22, 0x7, 0x22, 
    0x178, 0xa, 0x22, 0xc, 0x22, 0xe, 0x22, 0x17b, 0xb, 0x22, 0x3, 0x22, 0x3, 
    0x22, 0x3, 0x22, 0x3, 0x22, 0x3, 0x22, 0x3, 0x22, 0x7, 0x22, 0x183, 0xa, 
    0x22, 0xc, 0x22, 0xe, 0x22, 0x186, 0xb, 0x22, 0x5, 0x22, 0x188, 0xa, 
    0x22, 0x3, 0x23, 0x3, 0x23, 0x3, 0x23, 0x5, 0x23, 0x18d, 0xa, 0x23, 0x3, 
    0x24, 0x3, 0x24, 0x3, 0x25, 0x3, 0x25, 0x6, 0x25, 0x193, 0xa, 0x25, 0xd, 
    0x25, 0xe, 0x25, 0x194, 0x5, 0x25, 0x197, 0xa, 0x25, 0x3, 0x26, 0x3, 
    0x26, 0x3, 0x26, 0x5, 0x26, 0x19c, 0xa, 0x26, 0x3, 0x26, 0x5, 0x26, 
    0x19f, 0xa, 0x26, 0x3, 0x27, 0x3, 0x27, 0x5, 0x27, 0x1a3, 0xa, 0x27, 0x3, 
    0x27, 0x5, 0x27, 0x1a6, 0xa, 0x27, 0x3, 0x27, 0x3, 0x27, 0x5, 0x27, 
    0x1aa, 0xa, 0x27, 0x3, 0x27, 0x3, 0x27, 0x7, 0x27, 0x1ae, 0xa, 0x27, 0xc, 
    0x27, 0xe, 0x27, 0x1b1, 0xb, 0x27, 0x3, 0x27, 0x3, 0x27, 0x3, 0x27, 0x3, 
    0x27, 0x3, 0x27, 0x5, 0x27, 0x1b8, 0xa, 0x27, 0x3, 0x27, 0x5, 0x27, 
    0x1bb, 0xa, 0x27, 0x5, 0x27, 0x1bd, 0xa, 0x27, 0x3, 0x28, 0x3, 0x28, 0x3, 
    0x28, 0x3, 0x28, 0x7, 0x28, 0x1c3, 0xa, 0x28, 0xc, 0x28, 0xe, 0x28, 
    0x1c6, 0xb, 0x28, 0x5, 0x28, 0x1c8, 0xa, 0x28, 0x3, 0x28, 0x3, 0x28, 0x3, 
    0x29, 0x3, 0x29, 0x3, 0x29, 0x3, 0x29, 0x7, 0x29, 0x1d0, 0xa, 0x29, 0xc, 
    0x29, 0xe, 0x29, 0x1d3, 0xb, 0x29, 0x3, 0x29, 0x3, 0x29, 0x5, 0x29, 
    0x1d7, 0xa, 0x29, 0x3, 0x2a, 0x3, 0x2a, 0x5, 0x2a, 0x1db, 0xa, 0x2a, 0x3, 
    0x2a, 0x3, 0x2a, 0x3, 0x2a, 0x3, 0x2a, 0x5, 0x2a, 0x1e1, 0xa, 0x2a, 0x3, 
    0x2a, 0x3, 0x2a, 0x6, 0x2a, 0x1e5, 0xa, 0x2a, 0xd, 0x2a, 0xe, 0x2a, 
    0x1e6, 0x5, 0x2a, 0x1e9, 0xa, 0x2a, 0x3, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x3, 
    0x2b, 0x5, 0x2b, 0x1ef, 0xa, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x3, 
    0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 
    0x3, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x3, 
    0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 
    0x3, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x3, 0x2b, 0x7, 0x2b, 0x20c, 0xa, 0x2b, 
    0xc, 0x2b, 0xe, 0x2b, 0x20f, 0xb, 0x2b, 0x3, 0x2c, 0x3, 0x2c, 0x3, 0x2c, 
    0x3, 0x2c, 0x3, 0x2c, 0x3, 0x2c, 0x3, 0x2c, 0x3, 0x2c, 0x3, 0x2c, 0x5, 
    0x2c, 0x21a, 0xa, 0x2c, 0x3, 0x2c, 0x5, 0x2c, 0x21d, 0xa, 0x2c, 0x3, 
    0x2c, 0x3, 0x2c, 0x3, 0x2c, 0x3, 0x2c, 0x3, 0x2c, 0x3, 0x2c, 0x3, 0x2c, 
    0x3, 0x2c, 0x3, 0x2c, 0x3, 0x2c, 0x3, 0x2c, 0x6, 0x2c, 0x22a, 0xa, 0x2c, 
    0xd, 0x2c, 0xe, 0x2c, 0x22b, 0x3, 0x2c, 0x3, 0x2c, 0x3, 0x2c, 0x3, 0x2c, 
    0x5, 0x2c, 0x232, 0xa, 0x2c, 0x3, 0x2d, 0x3, 0x2d, 0x3, 0x2d, 0x2, 0x3, 
    0x54, 0x2e, 0x2, 0x4, 0x6, 0x8, 0xa, 0xc, 0xe, 0x10, 0x12, 0x14, 0x16, 
    0x18, 0x1a, 0x1c, 0x1e, 0x20, 0x22, 0x24, 0x26, 0x28, 0x2a, 0x2c, 0x2e, 
    0x30, 0x32, 0x34, 0x36, 0x38, 0x3a, 0x3c, 0x3e, 0x40, 0x42, 0x44, 0x46, 
    0x48, 0x4a, 0x4c, 0x4e, 0x50, 0x52, 0x54, 0x56, 0x58, 0x2, 0x11, 0x3, 
    0x2, 0x4, 0x5, 0x3, 0x2, 0x1d, 0x1e, 0x3, 0x2, 0x37, 0x38, 0x5, 0x2, 
    0x22, 0x26, 0x20, 0x20, 0x1d, 0x1e, 0x3, 0x2, 0x13, 0x14, 0x5, 0x2, 0x41, 
    0x41, 0x25, 0x25, 0x1c, 0x1c, 0x3, 0x2, 0x33, 0x34, 0x6, 0x2, 0x26, 0x28, 
    0x20, 0x24, 0x1d, 0x1e, 0x1b, 0x1b, 0x4, 0x2, 0x2d, 0x2d, 0x25, 0x25, 
    0x4, 0x2, 0x23, 0x23, 0x1d, 0x1e, 0x3, 0x2, 0x1f, 0x21, 0x3, 0x2, 0x17, 
    0x1a, 0x3, 0x2, 0x15, 0x16, 0x3, 0x2, 0x10, 0x11, 0x3, 0x2, 0x36, 0x37, 
    0x2, 0x271, 0x2, 0x5d, 0x3, 0x2, 0x2, 0x2, 0x4, 0x70, 0x3, 0x2, 0x2, 0x2, 
    0x6, 0x72, 0x3, 0x2, 0x2, 0x2, 0x8, 0x78, 0x3, 0x2, 0x2, 0x2, 0xa, 0x8d, 
    0x3, 0x2, 0x2, 0x2, 0xc, 0x91, 0x3, 0x2, 0x2, 0x2, 0xe, 0x9b, 0x3, 0x2, 
    0x2, 0x2, 0x10, 0xaf, 0x3, 0x2, 0x2, 0x2, 0x12, 0xb1, 0x3, 0x2, 0x2, 0x2, 
    0x14, 0xbf, 0x3, 0x2, 0x2, 0x2, 0x16, 0xc2, 0x3, 0x2, 0x2, 0x2, 0x18, 
    0xd5, 0x3, 0x2, 0x2, 0x2, 0x1a, 0xdb, 0x3, 0x2, 0x2, 0x2, 0x1c, 0xe7, 
    0x3, 0x2, 0x2, 0x2, 0x1e, 0xf6, 0x3, 0x2, 0x2, 0x2, 0x20, 0xfd, 0x3, 0x2, 
    0x2, 0x2, 0x22, 0x106, 0x3, 0x2, 0x2, 0x2, 0x24, 0x109, 0x3, 0x2, 0x2, 
    0x2, 0x26, 0x116, 0x3, 0x2, 0x2, 0x2, 0x28, 0x118, 0x3, 0x2, 0x2, 0x2, 
    0x2a, 0x126, 0x3, 0x2, 0x2, 0x2, 0x2c, 0x128, 0x3, 0x2, 0x2, 0x2, 0x2e, 
    0x12d, 0x3, 0x2, 0x2, 0x2, 0x30, 0x137, 0x3, 0x2, 0x2, 0x2, 0x32, 0x142, 
    0x3, 0x2, 0x2, 0x2, 0x34, 0x147, 0x3, 0x2, 0x2, 0x2, 0x36, 0x14f, 0x3, 
    0x2, 0x2, 0x2, 0x38, 0x154, 0x3, 0x2, 0x2, 0x2, 0x3a, 0x15b, 0x3, 0x2, 
    0x2, 0x2, 0x3c, 0x15f, 0x3, 0x2, 0x2, 0x2, 0x3e, 0x16f, 0x3, 0x2, 0x2, 
    0x2, 0x40, 0x171, 0x3, 0x2, 0x2, 0x2, 0x42, 0x187, 0x3, 0x2, 0x2, 0x2, 
    0x44, 0x189, 0x3, 0x2, 0x2, 0x2, 0x46, 0x18e, 0x3, 0x2, 0x2, 0x2, 0x48, 
    0x196, 0x3, 0x2, 0x2, 0x2, 0x4a, 0x19e, 0x3, 0x2, 0x2, 0x2, 0x4c, 0x1bc, 
    0x3, 0x2, 0x2, 0x2, 0x4e, 0x1be, 0x3, 0x2, 0x2, 0x2, 0x50, 0x1cb, 0x3, 
    0x2, 0x2, 0x2, 0x52, 0x1e0, 0x3, 0x2, 0x2, 0x2, 0x54, 0x1ee, 0x3, 0x2, 
    0x2, 0x2, 0x56, 0x231, 0x3, 0x2, 0x2, 0x2, 0x58, 0x233, 0x3, 0x2, 0x2, 
    0x2, 0x5a, 0x5c, 0x5, 0x4, 0x3, 0x2, 0x5b, 0x5a, 0x3, 0x2, 0x2, 0x2, 
    0x5c, 0x5f, 0x3, 0x2, 0x2, 0x2, 0x5d, 0x5b, 0x3, 0x2, 0x2, 0x2, 0x5d, 
    0x5e, 0x3, 0x2, 0x2, 0x2, 0x5e, 0x60, 0x3, 0x2, 0x2, 0x2, 0x5f, 0x5d, 
    0x3, 0x2, 0x2, 0x2, 0x60, 0x61, 0x7, 0x2, 0x2, 0x3, 0x61, 0x3, 0x3, 0x2, 
    0x2, 0x2, 0x62, 0x71, 0x5, 0x8, 0x5, 0x2, 0x63, 0x71, 0x5, 0x6, 0x4, 0x2, 
    0x64, 0x71, 0x5, 0xc, 0x7, 0x2, 0x65, 0x71, 0x5, 0xe, 0x8, 0x2, 0x66, 
    0x71, 0x5, 0x18, 0xd, 0x2, 0x67, 0x71, 0x5, 0x1a, 0xe, 0x2, 0x68, 0x71, 
    0x5, 0x1e, 0x10, 0x2, 0x69, 0x71, 0x5, 0x20, 0x11, 0x2, 0x6a, 0x71, 0x5, 
    0x24, 0x13, 0x2, 0x6b, 0x71, 0x5, 0x28, 0x15, 0x2, 0x6c, 0x71, 0x5, 0x2c, 
    0x17, 0x2, 0x6d, 0x71, 0x5, 0x2e, 0x18, 0x2, 0x6e, 0x71, 0x5, 0x30, 0x19, 
    0x2, 0x6f, 0x71, 0x7, 0x2c, 0x2, 0x2, 0x70, 0x62, 0x3, 0x2, 0x2, 0x2, 
    0x70, 0x63, 0x3, 0x2, 0x2, 0x2, 0x70, 0x64, 0x3, 0x2, 0x2, 0x2, 0x70, 
    0x65, 0x3, 0x2, 0x2, 0x2, 0x70, 0x66, 0x3, 0x2, 0x2, 0x2, 0x70, 0x67, 
    0x3, 0x2, 0x2, 0x2, 0x70, 0x68, 0x3, 0x2, 0x2, 0x2, 0x70, 0x69, 0x3, 0x2, 
    0x2, 0x2, 0x70, 0x6a, 0x3, 0x2, 0x2, 0x2, 0x70, 0x6b, 0x3, 0x2, 0x2, 0x2, 
    0x70, 0x6c, 0x3, 0x2, 0x2, 0x2, 0x70, 0x6d, 0x3, 0x2, 0x2, 0x2, 0x70, 
    0x6e, 0x3, 0x2, 0x2, 0x2, 0x70, 0x6f, 0x3, 0x2, 0x2, 0x2, 0x71, 0x5, 0x3, 
    0x2, 0x2, 0x2, 0x72, 0x73, 0x9, 0x2, 0x2, 0x2, 0x73, 0x74, 0x7, 0x38, 
    0x2, 0x2, 0x74, 0x75, 0x7, 0x14, 0x2, 0x2, 0x75, 0x76, 0x5, 0x54, 0x2b, 
    0x2, 0x76, 0x77, 0x7, 0x2c, 0x2, 0x2, 0x77, 0x7, 0x3, 0x2, 0x2, 0x2, 
    0x78, 0x79, 0x7, 0x3, 0x2, 0x2, 0x79, 0x7c, 0x7, 0x39, 0x2, 0x2, 0x7a, 
    0x7b, 0x7, 0x38, 0x2, 0x2, 0x7b, 0x7d, 0x7, 0x38, 0x2, 0x2, 0x7c, 0x7a, 
    0x3, 0x2, 0x2, 0x2, 0x7c, 0x7d, 0x3, 0x2, 0x2, 0x2, 0x7d, 0x89, 0x3, 0x2, 
    0x2, 0x2, 0x7e, 0x7f, 0x7, 0x2f, 0x2, 0x2, 0x7f, 0x84, 0x5, 0xa, 0x6, 
    0x2, 0x80, 0x81, 0x7, 0x2d, 0x2, 0x2, 0x81, 0x83, 0x5, 0xa, 0x6, 0x2, 
    0x82, 0x80, 0x3, 0x2, 0x2, 0x2, 0x83, 0x86, 0x3, 0x2, 0x2, 0x2, 0x84, 
    0x82, 0x3, 0x2, 0x2, 0x2, 0x84, 0x85, 0x3, 0x2, 0x2, 0x2, 0x85, 0x87, 
    0x3, 0x2, 0x2, 0x2, 0x86, 0x84, 0x3, 0x2, 0x2, 0x2, 0x87, 0x88, 0x7, 
    0x30, 0x2, 0x2, 0x88, 0x8a, 0x3, 0x2, 0x2, 0x2, 0x89, 0x7e, 0x3, 0x2, 
    0x2, 0x2, 0x89, 0x8a, 0x3, 0x2, 0x2, 0x2, 0x8a, 0x8b, 0x3, 0x2, 0x2, 0x2, 
    0x8b, 0x8c, 0x7, 0x2c, 0x2, 0x2, 0x8c, 0x9, 0x3, 0x2, 0x2, 0x2, 0x8d, 
    0x8e, 0x7, 0x38, 0x2, 0x2, 0x8e, 0x8f, 0x7, 0x14, 0x2, 0x2, 0x8f, 0x90, 
    0x5, 0x54, 0x2b, 0x2, 0x90, 0xb, 0x3, 0x2, 0x2, 0x2, 0x91, 0x97, 0x7, 
    0x6, 0x2, 0x2, 0x92, 0x98, 0x7, 0x39, 0x2, 0x2, 0x93, 0x95, 0x7, 0x38, 
    0x2, 0x2, 0x94, 0x96, 0x5, 0x4e, 0x28, 0x2, 0x95, 0x94, 0x3, 0x2, 0x2, 
    0x2, 0x95, 0x96, 0x3, 0x2, 0x2, 0x2, 0x96, 0x98, 0x3, 0x2, 0x2, 0x2, 
    0x97, 0x92, 0x3, 0x2, 0x2, 0x2, 0x97, 0x93, 0x3, 0x2, 0x2, 0x2, 0x98, 
    0x99, 0x3, 0x2, 0x2, 0x2, 0x99, 0x9a, 0x7, 0x2c, 0x2, 0x2, 0x9a, 0xd, 
    0x3, 0x2, 0x2, 0x2, 0x9b, 0x9c, 0x7, 0x7, 0x2, 0x2, 0x9c, 0x9d, 0x7, 
    0x38, 0x2, 0x2, 0x9d, 0x9e, 0x7, 0x14, 0x2, 0x2, 0x9e, 0x9f, 0x5, 0x10, 
    0x9, 0x2, 0x9f, 0xa0, 0x7, 0x2c, 0x2, 0x2, 0xa0, 0xf, 0x3, 0x2, 0x2, 0x2, 
    0xa1, 0xa2, 0x7, 0x38, 0x2, 0x2, 0xa2, 0xa3, 0x7, 0x38, 0x2, 0x2, 0xa3, 
    0xa7, 0x7, 0x33, 0x2, 0x2, 0xa4, 0xa6, 0x5, 0x12, 0xa, 0x2, 0xa5, 0xa4, 
    0x3, 0x2, 0x2, 0x2, 0xa6, 0xa9, 0x3, 0x2, 0x2, 0x2, 0xa7, 0xa5, 0x3, 0x2, 
    0x2, 0x2, 0xa7, 0xa8, 0x3, 0x2, 0x2, 0x2, 0xa8, 0xaa, 0x3, 0x2, 0x2, 0x2, 
    0xa9, 0xa7, 0x3, 0x2, 0x2, 0x2, 0xaa, 0xb0, 0x7, 0x34, 0x2, 0x2, 0xab, 
    0xad, 0x7, 0x38, 0x2, 0x2, 0xac, 0xae, 0x5, 0x4e, 0x28, 0x2, 0xad, 0xac, 
    0x3, 0x2, 0x2, 0x2, 0xad, 0xae, 0x3, 0x2, 0x2, 0x2, 0xae, 0xb0, 0x3, 0x2, 
    0x2, 0x2, 0xaf, 0xa1, 0x3, 0x2, 0x2, 0x2, 0xaf, 0xab, 0x3, 0x2, 0x2, 0x2, 
    0xb0, 0x11, 0x3, 0x2, 0x2, 0x2, 0xb1, 0xb5, 0x7, 0x38, 0x2, 0x2, 0xb2, 
    0xb4, 0x5, 0x14, 0xb, 0x2, 0xb3, 0xb2, 0x3, 0x2, 0x2, 0x2, 0xb4, 0xb7, 
    0x3, 0x2, 0x2, 0x2, 0xb5, 0xb3, 0x3, 0x2, 0x2, 0x2, 0xb5, 0xb6, 0x3, 0x2, 
    0x2, 0x2, 0xb6, 0xb8, 0x3, 0x2, 0x2, 0x2, 0xb7, 0xb5, 0x3, 0x2, 0x2, 0x2, 
    0xb8, 0xb9, 0x7, 0x2c, 0x2, 0x2, 0xb9, 0x13, 0x3, 0x2, 0x2, 0x2, 0xba, 
    0xbc, 0x7, 0x38, 0x2, 0x2, 0xbb, 0xbd, 0x5, 0x16, 0xc, 0x2, 0xbc, 0xbb, 
    0x3, 0x2, 0x2, 0x2, 0xbc, 0xbd, 0x3, 0x2, 0x2, 0x2, 0xbd, 0xc0, 0x3, 0x2, 
    0x2, 0x2, 0xbe, 0xc0, 0x5, 0x16, 0xc, 0x2, 0xbf, 0xba, 0x3, 0x2, 0x2, 
    0x2, 0xbf, 0xbe, 0x3, 0x2, 0x2, 0x2, 0xc0, 0x15, 0x3, 0x2, 0x2, 0x2, 
    0xc1, 0xc3, 0x9, 0x3, 0x2, 0x2, 0xc2, 0xc1, 0x3, 0x2, 0x2, 0x2, 0xc2, 
    0xc3, 0x3, 0x2, 0x2, 0x2, 0xc3, 0xd3, 0x3, 0x2, 0x2, 0x2, 0xc4, 0xd4, 
    0x5, 0x58, 0x2d, 0x2, 0xc5, 0xd4, 0x7, 0x39, 0x2, 0x2, 0xc6, 0xd4, 0x7, 
    0x10, 0x2, 0x2, 0xc7, 0xd4, 0x7, 0x11, 0x2, 0x2, 0xc8, 0xc9, 0x7, 0x2f, 
    0x2, 0x2, 0xc9, 0xce, 0x5, 0x54, 0x2b, 0x2, 0xca, 0xcb, 0x7, 0x2d, 0x2, 
    0x2, 0xcb, 0xcd, 0x5, 0x54, 0x2b, 0x2, 0xcc, 0xca, 0x3, 0x2, 0x2, 0x2, 
    0xcd, 0xd0, 0x3, 0x2, 0x2, 0x2, 0xce, 0xcc, 0x3, 0x2, 0x2, 0x2, 0xce, 
    0xcf, 0x3, 0x2, 0x2, 0x2, 0xcf, 0xd1, 0x3, 0x2, 0x2, 0x2, 0xd0, 0xce, 
    0x3, 0x2, 0x2, 0x2, 0xd1, 0xd2, 0x7, 0x30, 0x2, 0x2, 0xd2, 0xd4, 0x3, 
    0x2, 0x2, 0x2, 0xd3, 0xc4, 0x3, 0x2, 0x2, 0x2, 0xd3, 0xc5, 0x3, 0x2, 0x2, 
    0x2, 0xd3, 0xc6, 0x3, 0x2, 0x2, 0x2, 0xd3, 0xc7, 0x3, 0x2, 0x2, 0x2, 
    0xd3, 0xc8, 0x3, 0x2, 0x2, 0x2, 0xd4, 0x17, 0x3, 0x2, 0x2, 0x2, 0xd5, 
    0xd6, 0x7, 0x8, 0x2, 0x2, 0xd6, 0xd7, 0x7, 0x38, 0x2, 0x2, 0xd7, 0xd8, 
    0x7, 0x14, 0x2, 0x2, 0xd8, 0xd9, 0x7, 0x39, 0x2, 0x2, 0xd9, 0xda, 0x7, 
    0x2c, 0x2, 0x2, 0xda, 0x19, 0x3, 0x2, 0x2, 0x2, 0xdb, 0xdc, 0x7, 0x9, 
    0x2, 0x2, 0xdc, 0xdd, 0x7, 0x38, 0x2, 0x2, 0xdd, 0xe1, 0x7, 0x33, 0x2, 
    0x2, 0xde, 0xe0, 0x5, 0x1c, 0xf, 0x2, 0xdf, 0xde, 0x3, 0x2, 0x2, 0x2, 
    0xe0, 0xe3, 0x3, 0x2, 0x2, 0x2, 0xe1, 0xdf, 0x3, 0x2, 0x2, 0x2, 0xe1, 
    0xe2, 0x3, 0x2, 0x2, 0x2, 0xe2, 0xe4, 0x3, 0x2, 0x2, 0x2, 0xe3, 0xe1, 
    0x3, 0x2, 0x2, 0x2, 0xe4, 0xe5, 0x7, 0x34, 0x2, 0x2, 0xe5, 0xe6, 0x7, 
    0x2c, 0x2, 0x2, 0xe6, 0x1b, 0x3, 0x2, 0x2, 0x2, 0xe7, 0xea, 0x7, 0x38, 
    0x2, 0x2, 0xe8, 0xe9, 0x7, 0x38, 0x2, 0x2, 0xe9, 0xeb, 0x7, 0x14, 0x2, 
    0x2, 0xea, 0xe8, 0x3, 0x2, 0x2, 0x2, 0xea, 0xeb, 0x3, 0x2, 0x2, 0x2, 
    0xeb, 0xec, 0x3, 0x2, 0x2, 0x2, 0xec, 0xf1, 0x5, 0x54, 0x2b, 0x2, 0xed, 
    0xee, 0x7, 0x2d, 0x2, 0x2, 0xee, 0xf0, 0x5, 0x54, 0x2b, 0x2, 0xef, 0xed, 
    0x3, 0x2, 0x2, 0x2, 0xf0, 0xf3, 0x3, 0x2, 0x2, 0x2, 0xf1, 0xef, 0x3, 0x2, 
    0x2, 0x2, 0xf1, 0xf2, 0x3, 0x2, 0x2, 0x2, 0xf2, 0xf4, 0x3, 0x2, 0x2, 0x2, 
    0xf3, 0xf1, 0x3, 0x2, 0x2, 0x2, 0xf4, 0xf5, 0x7, 0x2c, 0x2, 0x2, 0xf5, 
    0x1d, 0x3, 0x2, 0x2, 0x2, 0xf6, 0xf7, 0x7, 0xa, 0x2, 0x2, 0xf7, 0xf9, 
    0x7, 0x38, 0x2, 0x2, 0xf8, 0xfa, 0x5, 0x54, 0x2b, 0x2, 0xf9, 0xf8, 0x3, 
    0x2, 0x2, 0x2, 0xf9, 0xfa, 0x3, 0x2, 0x2, 0x2, 0xfa, 0xfb, 0x3, 0x2, 0x2, 
    0x2, 0xfb, 0xfc, 0x7, 0x2c, 0x2, 0x2, 0xfc, 0x1f, 0x3, 0x2, 0x2, 0x2, 
    0xfd, 0x101, 0x7, 0xb, 0x2, 0x2, 0xfe, 0x100, 0x5, 0x22, 0x12, 0x2, 0xff, 
    0xfe, 0x3, 0x2, 0x2, 0x2, 0x100, 0x103, 0x3, 0x2, 0x2, 0x2, 0x101, 0xff, 
    0x3, 0x2, 0x2, 0x2, 0x101, 0x102, 0x3, 0x2, 0x2, 0x2, 0x102, 0x104, 0x3, 
    0x2, 0x2, 0x2, 0x103, 0x101, 0x3, 0x2, 0x2, 0x2, 0x104, 0x105, 0x7, 0x2c, 
    0x2, 0x2, 0x105, 0x21, 0x3, 0x2, 0x2, 0x2, 0x106, 0x107, 0x7, 0x38, 0x2, 
    0x2, 0x107, 0x108, 0x5, 0x54, 0x2b, 0x2, 0x108, 0x23, 0x3, 0x2, 0x2, 0x2, 
    0x109, 0x10b, 0x7, 0xc, 0x2, 0x2, 0x10a, 0x10c, 0x7, 0x2b, 0x2, 0x2, 
    0x10b, 0x10a, 0x3, 0x2, 0x2, 0x2, 0x10b, 0x10c, 0x3, 0x2, 0x2, 0x2, 
    0x10c, 0x10e, 0x3, 0x2, 0x2, 0x2, 0x10d, 0x10f, 0x5, 0x26, 0x14, 0x2, 
    0x10e, 0x10d, 0x3, 0x2, 0x2, 0x2, 0x10f, 0x110, 0x3, 0x2, 0x2, 0x2, 
    0x110, 0x10e, 0x3, 0x2, 0x2, 0x2, 0x110, 0x111, 0x3, 0x2, 0x2, 0x2, 
    0x111, 0x112, 0x3, 0x2, 0x2, 0x2, 0x112, 0x113, 0x7, 0x2c, 0x2, 0x2, 
    0x113, 0x25, 0x3, 0x2, 0x2, 0x2, 0x114, 0x117, 0x7, 0x38, 0x2, 0x2, 
    0x115, 0x117, 0x5, 0x3e, 0x20, 0x2, 0x116, 0x114, 0x3, 0x2, 0x2, 0x2, 
    0x116, 0x115, 0x3, 0x2, 0x2, 0x2, 0x117, 0x27, 0x3, 0x2, 0x2, 0x2, 0x118, 
    0x11c, 0x7, 0xd, 0x2, 0x2, 0x119, 0x11b, 0x5, 0x2a, 0x16, 0x2, 0x11a, 
    0x119, 0x3, 0x2, 0x2, 0x2, 0x11b, 0x11e, 0x3, 0x2, 0x2, 0x2, 0x11c, 
    0x11a, 0x3, 0x2, 0x2, 0x2, 0x11c, 0x11d, 0x3, 0x2, 0x2, 0x2, 0x11d, 
    0x11f, 0x3, 0x2, 0x2, 0x2, 0x11e, 0x11c, 0x3, 0x2, 0x2, 0x2, 0x11f, 
    0x120, 0x7, 0x2c, 0x2, 0x2, 0x120, 0x29, 0x3, 0x2, 0x2, 0x2, 0x121, 
    0x127, 0x7, 0x38, 0x2, 0x2, 0x122, 0x124, 0x7, 0x1e, 0x2, 0x2, 0x123, 
    0x122, 0x3, 0x2, 0x2, 0x2, 0x123, 0x124, 0x3, 0x2, 0x2, 0x2, 0x124, 
    0x125, 0x3, 0x2, 0x2, 0x2, 0x125, 0x127, 0x5, 0x58, 0x2d, 0x2, 0x126, 
    0x121, 0x3, 0x2, 0x2, 0x2, 0x126, 0x123, 0x3, 0x2, 0x2, 0x2, 0x127, 0x2b, 
    0x3, 0x2, 0x2, 0x2, 0x128, 0x129, 0x7, 0xe, 0x2, 0x2, 0x129, 0x12a, 0x7, 
    0x2b, 0x2, 0x2, 0x12a, 0x12b, 0x5, 0x48, 0x25, 0x2, 0x12b, 0x12c, 0x7, 
    0x2c, 0x2, 0x2, 0x12c, 0x2d, 0x3, 0x2, 0x2, 0x2, 0x12d, 0x12f, 0x7, 0xf, 
    0x2, 0x2, 0x12e, 0x130, 0x7, 0x1e, 0x2, 0x2, 0x12f, 0x12e, 0x3, 0x2, 0x2, 
    0x2, 0x12f, 0x130, 0x3, 0x2, 0x2, 0x2, 0x130, 0x131, 0x3, 0x2, 0x2, 0x2, 
    0x131, 0x132, 0x7, 0x37, 0x2, 0x2, 0x132, 0x133, 0x7, 0x2b, 0x2, 0x2, 
    0x133, 0x2f, 0x3, 0x2, 0x2, 0x2, 0x134, 0x135, 0x5, 0x32, 0x1a, 0x2, 
    0x135, 0x136, 0x7, 0x2b, 0x2, 0x2, 0x136, 0x138, 0x3, 0x2, 0x2, 0x2, 
    0x137, 0x134, 0x3, 0x2, 0x2, 0x2, 0x137, 0x138, 0x3, 0x2, 0x2, 0x2, 
    0x138, 0x139, 0x3, 0x2, 0x2, 0x2, 0x139, 0x13c, 0x5, 0x34, 0x1b, 0x2, 
    0x13a, 0x13b, 0x7, 0x2b, 0x2, 0x2, 0x13b, 0x13d, 0x5, 0x54, 0x2b, 0x2, 
    0x13c, 0x13a, 0x3, 0x2, 0x2, 0x2, 0x13c, 0x13d, 0x3, 0x2, 0x2, 0x2, 
    0x13d, 0x13e, 0x3, 0x2, 0x2, 0x2, 0x13e, 0x13f, 0x5, 0x46, 0x24, 0x2, 
    0x13f, 0x140, 0x5, 0x42, 0x22, 0x2, 0x140, 0x141, 0x7, 0x2c, 0x2, 0x2, 
    0x141, 0x31, 0x3, 0x2, 0x2, 0x2, 0x142, 0x143, 0x9, 0x4, 0x2, 0x2, 0x143, 
    0x33, 0x3, 0x2, 0x2, 0x2, 0x144, 0x145, 0x5, 0x36, 0x1c, 0x2, 0x145, 
    0x146, 0x7, 0x19, 0x2, 0x2, 0x146, 0x148, 0x3, 0x2, 0x2, 0x2, 0x147, 
    0x144, 0x3, 0x2, 0x2, 0x2, 0x147, 0x148, 0x3, 0x2, 0x2, 0x2, 0x148, 
    0x149, 0x3, 0x2, 0x2, 0x2, 0x149, 0x14c, 0x5, 0x3c, 0x1f, 0x2, 0x14a, 
    0x14b, 0x7, 0x1a, 0x2, 0x2, 0x14b, 0x14d, 0x5, 0x38, 0x1d, 0x2, 0x14c, 
    0x14a, 0x3, 0x2, 0x2, 0x2, 0x14c, 0x14d, 0x3, 0x2, 0x2, 0x2, 0x14d, 0x35, 
    0x3, 0x2, 0x2, 0x2, 0x14e, 0x150, 0x5, 0x3c, 0x1f, 0x2, 0x14f, 0x14e, 
    0x3, 0x2, 0x2, 0x2, 0x150, 0x151, 0x3, 0x2, 0x2, 0x2, 0x151, 0x14f, 0x3, 
    0x2, 0x2, 0x2, 0x151, 0x152, 0x3, 0x2, 0x2, 0x2, 0x152, 0x37, 0x3, 0x2, 
    0x2, 0x2, 0x153, 0x155, 0x5, 0x3a, 0x1e, 0x2, 0x154, 0x153, 0x3, 0x2, 
    0x2, 0x2, 0x155, 0x156, 0x3, 0x2, 0x2, 0x2, 0x156, 0x154, 0x3, 0x2, 0x2, 
    0x2, 0x156, 0x157, 0x3, 0x2, 0x2, 0x2, 0x157, 0x39, 0x3, 0x2, 0x2, 0x2, 
    0x158, 0x15c, 0x5, 0x3c, 0x1f, 0x2, 0x159, 0x15c, 0x7, 0x31, 0x2, 0x2, 
    0x15a, 0x15c, 0x7, 0x32, 0x2, 0x2, 0x15b, 0x158, 0x3, 0x2, 0x2, 0x2, 
    0x15b, 0x159, 0x3, 0x2, 0x2, 0x2, 0x15b, 0x15a, 0x3, 0x2, 0x2, 0x2, 
    0x15c, 0x3b, 0x3, 0x2, 0x2, 0x2, 0x15d, 0x160, 0x7, 0x38, 0x2, 0x2, 
    0x15e, 0x160, 0x5, 0x3e, 0x20, 0x2, 0x15f, 0x15d, 0x3, 0x2, 0x2, 0x2, 
    0x15f, 0x15e, 0x3, 0x2, 0x2, 0x2, 0x160, 0x16d, 0x3, 0x2, 0x2, 0x2, 
    0x161, 0x16a, 0x7, 0x2f, 0x2, 0x2, 0x162, 0x167, 0x5, 0x40, 0x21, 0x2, 
    0x163, 0x164, 0x7, 0x2d, 0x2, 0x2, 0x164, 0x166, 0x5, 0x40, 0x21, 0x2, 
    0x165, 0x163, 0x3, 0x2, 0x2, 0x2, 0x166, 0x169, 0x3, 0x2, 0x2, 0x2, 
    0x167, 0x165, 0x3, 0x2, 0x2, 0x2, 0x167, 0x168, 0x3, 0x2, 0x2, 0x2, 
    0x168, 0x16b, 0x3, 0x2, 0x2, 0x2, 0x169, 0x167, 0x3, 0x2, 0x2, 0x2, 
    0x16a, 0x162, 0x3, 0x2, 0x2, 0x2, 0x16a, 0x16b, 0x3, 0x2, 0x2, 0x2, 
    0x16b, 0x16c, 0x3, 0x2, 0x2, 0x2, 0x16c, 0x16e, 0x7, 0x30, 0x2, 0x2, 
    0x16d, 0x161, 0x3, 0x2, 0x2, 0x2, 0x16d, 0x16e, 0x3, 0x2, 0x2, 0x2, 
    0x16e, 0x3d, 0x3, 0x2, 0x2, 0x2, 0x16f, 0x170, 0x9, 0x5, 0x2, 0x2, 0x170, 
    0x3f, 0x3, 0x2, 0x2, 0x2, 0x171, 0x172, 0x7, 0x38, 0x2, 0x2, 0x172, 0x41, 
    0x3, 0x2, 0x2, 0x2, 0x173, 0x179, 0x5, 0x44, 0x23, 0x2, 0x174, 0x175, 
    0x5, 0x46, 0x24, 0x2, 0x175, 0x176, 0x5, 0x44, 0x23, 0x2, 0x176, 0x178, 
    0x3, 0x2, 0x2, 0x2, 0x177, 0x174, 0x3, 0x2, 0x2, 0x2, 0x178, 0x17b, 0x3, 
    0x2, 0x2, 0x2, 0x179, 0x177, 0x3, 0x2, 0x2, 0x2, 0x179, 0x17a, 0x3, 0x2, 
    0x2, 0x2, 0x17a, 0x188, 0x3, 0x2, 0x2, 0x2, 0x17b, 0x179, 0x3, 0x2, 0x2, 
    0x2, 0x17c, 0x17d, 0x5, 0x54, 0x2b, 0x2, 0x17d, 0x17e, 0x5, 0x46, 0x24, 
    0x2, 0x17e, 0x184, 0x5, 0x44, 0x23, 0x2, 0x17f, 0x180, 0x5, 0x46, 0x24, 
    0x2, 0x180, 0x181, 0x5, 0x44, 0x23, 0x2, 0x181, 0x183, 0x3, 0x2, 0x2, 
    0x2, 0x182, 0x17f, 0x3, 0x2, 0x2, 0x2, 0x183, 0x186, 0x3, 0x2, 0x2, 0x2, 
    0x184, 0x182, 0x3, 0x2, 0x2, 0x2, 0x184, 0x185, 0x3, 0x2, 0x2, 0x2, 
    0x185, 0x188, 0x3, 0x2, 0x2, 0x2, 0x186, 0x184, 0x3, 0x2, 0x2, 0x2, 
    0x187, 0x173, 0x3, 0x2, 0x2, 0x2, 0x187, 0x17c, 0x3, 0x2, 0x2, 0x2, 
    0x188, 0x43, 0x3, 0x2, 0x2, 0x2, 0x189, 0x18c, 0x5, 0x48, 0x25, 0x2, 
    0x18a, 0x18b, 0x7, 0x2b, 0x2, 0x2, 0x18b, 0x18d, 0x5, 0x54, 0x2b, 0x2, 
    0x18c, 0x18a, 0x3, 0x2, 0x2, 0x2, 0x18c, 0x18d, 0x3, 0x2, 0x2, 0x2, 
    0x18d, 0x45, 0x3, 0x2, 0x2, 0x2, 0x18e, 0x18f, 0x9, 0x6, 0x2, 0x2, 0x18f, 
    0x47, 0x3, 0x2, 0x2, 0x2, 0x190, 0x197, 0x7, 0x12, 0x2, 0x2, 0x191, 
    0x193, 0x5, 0x4a, 0x26, 0x2, 0x192, 0x191, 0x3, 0x2, 0x2, 0x2, 0x193, 
    0x194, 0x3, 0x2, 0x2, 0x2, 0x194, 0x192, 0x3, 0x2, 0x2, 0x2, 0x194, 
    0x195, 0x3, 0x2, 0x2, 0x2, 0x195, 0x197, 0x3, 0x2, 0x2, 0x2, 0x196, 
    0x190, 0x3, 0x2, 0x2, 0x2, 0x196, 0x192, 0x3, 0x2, 0x2, 0x2, 0x197, 0x49, 
    0x3, 0x2, 0x2, 0x2, 0x198, 0x19f, 0x5, 0x4c, 0x27, 0x2, 0x199, 0x19b, 
    0x9, 0x7, 0x2, 0x2, 0x19a, 0x19c, 0x5, 0x4e, 0x28, 0x2, 0x19b, 0x19a, 
    0x3, 0x2, 0x2, 0x2, 0x19b, 0x19c, 0x3, 0x2, 0x2, 0x2, 0x19c, 0x19f, 0x3, 
    0x2, 0x2, 0x2, 0x19d, 0x19f, 0x9, 0x8, 0x2, 0x2, 0x19e, 0x198, 0x3, 0x2, 
    0x2, 0x2, 0x19e, 0x199, 0x3, 0x2, 0x2, 0x2, 0x19e, 0x19d, 0x3, 0x2, 0x2, 
    0x2, 0x19f, 0x4b, 0x3, 0x2, 0x2, 0x2, 0x1a0, 0x1a2, 0x7, 0x38, 0x2, 0x2, 
    0x1a1, 0x1a3, 0x5, 0x4e, 0x28, 0x2, 0x1a2, 0x1a1, 0x3, 0x2, 0x2, 0x2, 
    0x1a2, 0x1a3, 0x3, 0x2, 0x2, 0x2, 0x1a3, 0x1a5, 0x3, 0x2, 0x2, 0x2, 
    0x1a4, 0x1a6, 0x5, 0x50, 0x29, 0x2, 0x1a5, 0x1a4, 0x3, 0x2, 0x2, 0x2, 
    0x1a5, 0x1a6, 0x3, 0x2, 0x2, 0x2, 0x1a6, 0x1bd, 0x3, 0x2, 0x2, 0x2, 
    0x1a7, 0x1a9, 0x9, 0x9, 0x2, 0x2, 0x1a8, 0x1aa, 0x5, 0x4e, 0x28, 0x2, 
    0x1a9, 0x1a8, 0x3, 0x2, 0x2, 0x2, 0x1a9, 0x1aa, 0x3, 0x2, 0x2, 0x2, 
    0x1aa, 0x1bd, 0x3, 0x2, 0x2, 0x2, 0x1ab, 0x1af, 0x7, 0x31, 0x2, 0x2, 
    0x1ac, 0x1ae, 0x5, 0x4a, 0x26, 0x2, 0x1ad, 0x1ac, 0x3, 0x2, 0x2, 0x2, 
    0x1ae, 0x1b1, 0x3, 0x2, 0x2, 0x2, 0x1af, 0x1ad, 0x3, 0x2, 0x2, 0x2, 
    0x1af, 0x1b0, 0x3, 0x2, 0x2, 0x2, 0x1b0, 0x1b2, 0x3, 0x2, 0x2, 0x2, 
    0x1b1, 0x1af, 0x3, 0x2, 0x2, 0x2, 0x1b2, 0x1bd, 0x7, 0x32, 0x2, 0x2, 
    0x1b3, 0x1bd, 0x7, 0x40, 0x2, 0x2, 0x1b4, 0x1b7, 0x7, 0x29, 0x2, 0x2, 
    0x1b5, 0x1b8, 0x7, 0x38, 0x2, 0x2, 0x1b6, 0x1b8, 0x7, 0x39, 0x2, 0x2, 
    0x1b7, 0x1b5, 0x3, 0x2, 0x2, 0x2, 0x1b7, 0x1b6, 0x3, 0x2, 0x2, 0x2, 
    0x1b8, 0x1ba, 0x3, 0x2, 0x2, 0x2, 0x1b9, 0x1bb, 0x5, 0x4e, 0x28, 0x2, 
    0x1ba, 0x1b9, 0x3, 0x2, 0x2, 0x2, 0x1ba, 0x1bb, 0x3, 0x2, 0x2, 0x2, 
    0x1bb, 0x1bd, 0x3, 0x2, 0x2, 0x2, 0x1bc, 0x1a0, 0x3, 0x2, 0x2, 0x2, 
    0x1bc, 0x1a7, 0x3, 0x2, 0x2, 0x2, 0x1bc, 0x1ab, 0x3, 0x2, 0x2, 0x2, 
    0x1bc, 0x1b3, 0x3, 0x2, 0x2, 0x2, 0x1bc, 0x1b4, 0x3, 0x2, 0x2, 0x2, 
    0x1bd, 0x4d, 0x3, 0x2, 0x2, 0x2, 0x1be, 0x1c7, 0x7, 0x2f, 0x2, 0x2, 
    0x1bf, 0x1c4, 0x5, 0x54, 0x2b, 0x2, 0x1c0, 0x1c1, 0x7, 0x2d, 0x2, 0x2, 
    0x1c1, 0x1c3, 0x5, 0x54, 0x2b, 0x2, 0x1c2, 0x1c0, 0x3, 0x2, 0x2, 0x2, 
    0x1c3, 0x1c6, 0x3, 0x2, 0x2, 0x2, 0x1c4, 0x1c2, 0x3, 0x2, 0x2, 0x2, 
    0x1c4, 0x1c5, 0x3, 0x2, 0x2, 0x2, 0x1c5, 0x1c8, 0x3, 0x2, 0x2, 0x2, 
    0x1c6, 0x1c4, 0x3, 0x2, 0x2, 0x2, 0x1c7, 0x1bf, 0x3, 0x2, 0x2, 0x2, 
    0x1c7, 0x1c8, 0x3, 0x2, 0x2, 0x2, 0x1c8, 0x1c9, 0x3, 0x2, 0x2, 0x2, 
    0x1c9, 0x1ca, 0x7, 0x30, 0x2, 0x2, 0x1ca, 0x4f, 0x3, 0x2, 0x2, 0x2, 
    0x1cb, 0x1cc, 0x7, 0x33, 0x2, 0x2, 0x1cc, 0x1d1, 0x5, 0x52, 0x2a, 0x2, 
    0x1cd, 0x1ce, 0x9, 0xa, 0x2, 0x2, 0x1ce, 0x1d0, 0x5, 0x52, 0x2a, 0x2, 
    0x1cf, 0x1cd, 0x3, 0x2, 0x2, 0x2, 0x1d0, 0x1d3, 0x3, 0x2, 0x2, 0x2, 
    0x1d1, 0x1cf, 0x3, 0x2, 0x2, 0x2, 0x1d1, 0x1d2, 0x3, 0x2, 0x2, 0x2, 
    0x1d2, 0x1d4, 0x3, 0x2, 0x2, 0x2, 0x1d3, 0x1d1, 0x3, 0x2, 0x2, 0x2, 
    0x1d4, 0x1d6, 0x7, 0x34, 0x2, 0x2, 0x1d5, 0x1d7, 0x7, 0x1f, 0x2, 0x2, 
    0x1d6, 0x1d5, 0x3, 0x2, 0x2, 0x2, 0x1d6, 0x1d7, 0x3, 0x2, 0x2, 0x2, 
    0x1d7, 0x51, 0x3, 0x2, 0x2, 0x2, 0x1d8, 0x1da, 0x7, 0x38, 0x2, 0x2, 
    0x1d9, 0x1db, 0x7, 0x14, 0x2, 0x2, 0x1da, 0x1d9, 0x3, 0x2, 0x2, 0x2, 
    0x1da, 0x1db, 0x3, 0x2, 0x2, 0x2, 0x1db, 0x1dc, 0x3, 0x2, 0x2, 0x2, 
    0x1dc, 0x1e1, 0x7, 0x2b, 0x2, 0x2, 0x1dd, 0x1de, 0x5, 0x54, 0x2b, 0x2, 
    0x1de, 0x1df, 0x7, 0x2b, 0x2, 0x2, 0x1df, 0x1e1, 0x3, 0x2, 0x2, 0x2, 
    0x1e0, 0x1d8, 0x3, 0x2, 0x2, 0x2, 0x1e0, 0x1dd, 0x3, 0x2, 0x2, 0x2, 
    0x1e0, 0x1e1, 0x3, 0x2, 0x2, 0x2, 0x1e1, 0x1e8, 0x3, 0x2, 0x2, 0x2, 
    0x1e2, 0x1e9, 0x7, 0x12, 0x2, 0x2, 0x1e3, 0x1e5, 0x5, 0x4c, 0x27, 0x2, 
    0x1e4, 0x1e3, 0x3, 0x2, 0x2, 0x2, 0x1e5, 0x1e6, 0x3, 0x2, 0x2, 0x2, 
    0x1e6, 0x1e4, 0x3, 0x2, 0x2, 0x2, 0x1e6, 0x1e7, 0x3, 0x2, 0x2, 0x2, 
    0x1e7, 0x1e9, 0x3, 0x2, 0x2, 0x2, 0x1e8, 0x1e2, 0x3, 0x2, 0x2, 0x2, 
    0x1e8, 0x1e4, 0x3, 0x2, 0x2, 0x2, 0x1e9, 0x53, 0x3, 0x2, 0x2, 0x2, 0x1ea, 
    0x1eb, 0x8, 0x2b, 0x1, 0x2, 0x1eb, 0x1ef, 0x5, 0x56, 0x2c, 0x2, 0x1ec, 
    0x1ed, 0x9, 0xb, 0x2, 0x2, 0x1ed, 0x1ef, 0x5, 0x54, 0x2b, 0xa, 0x1ee, 
    0x1ea, 0x3, 0x2, 0x2, 0x2, 0x1ee, 0x1ec, 0x3, 0x2, 0x2, 0x2, 0x1ef, 
    0x20d, 0x3, 0x2, 0x2, 0x2, 0x1f0, 0x1f1, 0xc, 0xb, 0x2, 0x2, 0x1f1, 
    0x1f2, 0x7, 0x22, 0x2, 0x2, 0x1f2, 0x20c, 0x5, 0x54, 0x2b, 0xb, 0x1f3, 
    0x1f4, 0xc, 0x9, 0x2, 0x2, 0x1f4, 0x1f5, 0x9, 0xc, 0x2, 0x2, 0x1f5, 
    0x20c, 0x5, 0x54, 0x2b, 0xa, 0x1f6, 0x1f7, 0xc, 0x8, 0x2, 0x2, 0x1f7, 
    0x1f8, 0x9, 0x3, 0x2, 0x2, 0x1f8, 0x20c, 0x5, 0x54, 0x2b, 0x9, 0x1f9, 
    0x1fa, 0xc, 0x7, 0x2, 0x2, 0x1fa, 0x1fb, 0x9, 0xd, 0x2, 0x2, 0x1fb, 
    0x20c, 0x5, 0x54, 0x2b, 0x8, 0x1fc, 0x1fd, 0xc, 0x6, 0x2, 0x2, 0x1fd, 
    0x1fe, 0x9, 0xe, 0x2, 0x2, 0x1fe, 0x20c, 0x5, 0x54, 0x2b, 0x7, 0x1ff, 
    0x200, 0xc, 0x5, 0x2, 0x2, 0x200, 0x201, 0x7, 0x1b, 0x2, 0x2, 0x201, 
    0x20c, 0x5, 0x54, 0x2b, 0x6, 0x202, 0x203, 0xc, 0x4, 0x2, 0x2, 0x203, 
    0x204, 0x7, 0x1c, 0x2, 0x2, 0x204, 0x20c, 0x5, 0x54, 0x2b, 0x5, 0x205, 
    0x206, 0xc, 0x3, 0x2, 0x2, 0x206, 0x207, 0x7, 0x2a, 0x2, 0x2, 0x207, 
    0x208, 0x5, 0x54, 0x2b, 0x2, 0x208, 0x209, 0x7, 0x2b, 0x2, 0x2, 0x209, 
    0x20a, 0x5, 0x54, 0x2b, 0x3, 0x20a, 0x20c, 0x3, 0x2, 0x2, 0x2, 0x20b, 
    0x1f0, 0x3, 0x2, 0x2, 0x2, 0x20b, 0x1f3, 0x3, 0x2, 0x2, 0x2, 0x20b, 
    0x1f6, 0x3, 0x2, 0x2, 0x2, 0x20b, 0x1f9, 0x3, 0x2, 0x2, 0x2, 0x20b, 
    0x1fc, 0x3, 0x2, 0x2, 0x2, 0x20b, 0x1ff, 0x3, 0x2, 0x2, 0x2, 0x20b, 
    0x202, 0x3, 0x2, 0x2, 0x2, 0x20b, 0x205, 0x3, 0x2, 0x2, 0x2, 0x20c, 
    0x20f, 0x3, 0x2, 0x2, 0x2, 0x20d, 0x20b, 0x3, 0x2, 0x2, 0x2, 0x20d, 
    0x20e, 0x3, 0x2, 0x2, 0x2, 0x20e, 0x55, 0x3, 0x2, 0x2, 0x2, 0x20f, 0x20d, 
    0x3, 0x2, 0x2, 0x2, 0x210, 0x232, 0x5, 0x58, 0x2d, 0x2, 0x211, 0x232, 
    0x7, 0x35, 0x2, 0x2, 0x212, 0x232, 0x7, 0x39, 0x2, 0x2, 0x213, 0x232, 
    0x9, 0xf, 0x2, 0x2, 0x214, 0x215, 0x7, 0x38, 0x2, 0x2, 0x215, 0x216, 0x7, 
    0x2e, 0x2, 0x2, 0x216, 0x219, 0x7, 0x38, 0x2, 0x2, 0x217, 0x218, 0x7, 
    0x2e, 0x2, 0x2, 0x218, 0x21a, 0x7, 0x38, 0x2, 0x2, 0x219, 0x217, 0x3, 
    0x2, 0x2, 0x2, 0x219, 0x21a, 0x3, 0x2, 0x2, 0x2, 0x21a, 0x21c, 0x3, 0x2, 
    0x2, 0x2, 0x21b, 0x21d, 0x5, 0x4e, 0x28, 0x2, 0x21c, 0x21b, 0x3, 0x2, 
    0x2, 0x2, 0x21c, 0x21d, 0x3, 0x2, 0x2, 0x2, 0x21d, 0x232, 0x3, 0x2, 0x2, 
    0x2, 0x21e, 0x21f, 0x7, 0x38, 0x2, 0x2, 0x21f, 0x232, 0x5, 0x4e, 0x28, 
    0x2, 0x220, 0x232, 0x7, 0x38, 0x2, 0x2, 0x221, 0x222, 0x7, 0x2f, 0x2, 
    0x2, 0x222, 0x223, 0x5, 0x54, 0x2b, 0x2, 0x223, 0x224, 0x7, 0x30, 0x2, 
    0x2, 0x224, 0x232, 0x3, 0x2, 0x2, 0x2, 0x225, 0x226, 0x7, 0x2f, 0x2, 0x2, 
    0x226, 0x229, 0x5, 0x54, 0x2b, 0x2, 0x227, 0x228, 0x7, 0x2d, 0x2, 0x2, 
    0x228, 0x22a, 0x5, 0x54, 0x2b, 0x2, 0x229, 0x227, 0x3, 0x2, 0x2, 0x2, 
    0x22a, 0x22b, 0x3, 0x2, 0x2, 0x2, 0x22b, 0x229, 0x3, 0x2, 0x2, 0x2, 
    0x22b, 0x22c, 0x3, 0x2, 0x2, 0x2, 0x22c, 0x22d, 0x3, 0x2, 0x2, 0x2, 
    0x22d, 0x22e, 0x7, 0x30, 0x2, 0x2, 0x22e, 0x232, 0x3, 0x2, 0x2, 0x2, 
    0x22f, 0x230, 0x7, 0x29, 0x2, 0x2, 0x230, 0x232, 0x5, 0x56, 0x2c, 0x2, 
    0x231, 0x210, 0x3, 0x2, 0x2, 0x2, 0x231, 0x211, 0x3, 0x2, 0x2, 0x2, 
    0x231, 0x212, 0x3, 0x2, 0x2, 0x2, 0x231, 0x213, 0x3, 0x2, 0x2, 0x2, 
    0x231, 0x214, 0x3, 0x2, 0x2, 0x2, 0x231, 0x21e, 0x3, 0x2, 0x2, 0x2, 
    0x231, 0x220, 0x3, 0x2, 0x2, 0x2, 0x231, 0x221, 0x3, 0x2, 0x2, 0x2, 
    0x231, 0x225, 0x3, 0x2, 0x2, 0x2, 0x231, 0x22f, 0x3, 0x2, 0x2, 0x2, 
    0x232, 0x57, 0x3, 0x2, 0x2, 0x2, 0x233, 0x234, 0x9, 0x10, 0x2, 0x2, 
    0x234, 0x59, 0x3, 0x2, 0x2, 0x2, 0x47, 0x5d, 0x70, 0x7c, 0x84, 0x89, 
    0x95, 0x97, 0xa7, 0xad, 0xaf, 0xb5, 0xbc, 0xbf, 0xc2, 0xce, 0xd3, 0xe1, 
    0xea, 0xf1, 0xf9, 0x101, 0x10b, 0x110, 0x116, 0x11c, 0x123, 0x126, 0x12f, 
    0x137, 0x13c, 0x147, 0x14c, 0x151, 0x156, 0x15b, 0x15f, 0x167, 0x16a, 
    0x16d, 0x179, 0x184, 0x187, 0x18c, 0x194, 0x196, 0x19b, 0x19e, 0x1a2, 
    0x1a5, 0x1a9, 0x1af, 0x1b7, 0x1ba, 0x1bc, 0x1c4, 0x1c7, 0x1d1, 0x1d6, 
    0x1da, 0x1e0, 0x1e6, 0x1e8, 0x1ee, 0x20b, 0x20d, 0x219, 0x21c, 0x22b, 
    0x231, 
  };

  atn::ATNDeserializer deserializer;
  _atn = deserializer.deserialize(_serializedATN);

  size_t count = _atn.getNumberOfDecisions();
  _decisionToDFA.reserve(count);
  for (size_t i = 0; i < count; i++) { 
    _decisionToDFA.emplace_back(_atn.getDecisionState(i), i);
  }
}

// FgsgParser::Initializer runs in the constructor, on first use (scripts/regen-grammar.sh).
