
// Generated from grammar/Cga.g4 by ANTLR 4.7.2


#include "CgaVisitor.h"

#include "CgaParser.h"


using namespace antlrcpp;
using namespace fgsg_grammar;
using namespace antlr4;

CgaParser::CgaParser(TokenStream *input) : Parser(input) {
  static Initializer once;
  _interpreter = new atn::ParserATNSimulator(this, _atn, _decisionToDFA, _sharedContextCache);
}

CgaParser::~CgaParser() {
  delete _interpreter;
}

std::string CgaParser::getGrammarFileName() const {
  return "Cga.g4";
}

const std::vector<std::string>& CgaParser::getRuleNames() const {
  return _ruleNames;
}

dfa::Vocabulary& CgaParser::getVocabulary() const {
  return _vocabulary;
}


//----------------- CgaFileContext ------------------------------------------------------------------

CgaParser::CgaFileContext::CgaFileContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* CgaParser::CgaFileContext::EOF() {
  return getToken(CgaParser::EOF, 0);
}

std::vector<CgaParser::DeclarationContext *> CgaParser::CgaFileContext::declaration() {
  return getRuleContexts<CgaParser::DeclarationContext>();
}

CgaParser::DeclarationContext* CgaParser::CgaFileContext::declaration(size_t i) {
  return getRuleContext<CgaParser::DeclarationContext>(i);
}


size_t CgaParser::CgaFileContext::getRuleIndex() const {
  return CgaParser::RuleCgaFile;
}

antlrcpp::Any CgaParser::CgaFileContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitCgaFile(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::CgaFileContext* CgaParser::cgaFile() {
  CgaFileContext *_localctx = _tracker.createInstance<CgaFileContext>(_ctx, getState());
  enterRule(_localctx, 0, CgaParser::RuleCgaFile);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(51);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while ((((_la & ~ 0x3fULL) == 0) &&
      ((1ULL << _la) & ((1ULL << CgaParser::VERSION)
      | (1ULL << CgaParser::DIALECT)
      | (1ULL << CgaParser::IMPORT)
      | (1ULL << CgaParser::STYLE)
      | (1ULL << CgaParser::ATTR)
      | (1ULL << CgaParser::CONST)
      | (1ULL << CgaParser::AT)
      | (1ULL << CgaParser::QID)
      | (1ULL << CgaParser::ID))) != 0)) {
      setState(48);
      declaration();
      setState(53);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(54);
    match(CgaParser::EOF);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- DeclarationContext ------------------------------------------------------------------

CgaParser::DeclarationContext::DeclarationContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

CgaParser::VersionDeclContext* CgaParser::DeclarationContext::versionDecl() {
  return getRuleContext<CgaParser::VersionDeclContext>(0);
}

CgaParser::DialectDeclContext* CgaParser::DeclarationContext::dialectDecl() {
  return getRuleContext<CgaParser::DialectDeclContext>(0);
}

CgaParser::ImportDeclContext* CgaParser::DeclarationContext::importDecl() {
  return getRuleContext<CgaParser::ImportDeclContext>(0);
}

CgaParser::StyleDeclContext* CgaParser::DeclarationContext::styleDecl() {
  return getRuleContext<CgaParser::StyleDeclContext>(0);
}

CgaParser::AnnotatedContext* CgaParser::DeclarationContext::annotated() {
  return getRuleContext<CgaParser::AnnotatedContext>(0);
}


size_t CgaParser::DeclarationContext::getRuleIndex() const {
  return CgaParser::RuleDeclaration;
}

antlrcpp::Any CgaParser::DeclarationContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitDeclaration(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::DeclarationContext* CgaParser::declaration() {
  DeclarationContext *_localctx = _tracker.createInstance<DeclarationContext>(_ctx, getState());
  enterRule(_localctx, 2, CgaParser::RuleDeclaration);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(61);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case CgaParser::VERSION: {
        enterOuterAlt(_localctx, 1);
        setState(56);
        versionDecl();
        break;
      }

      case CgaParser::DIALECT: {
        enterOuterAlt(_localctx, 2);
        setState(57);
        dialectDecl();
        break;
      }

      case CgaParser::IMPORT: {
        enterOuterAlt(_localctx, 3);
        setState(58);
        importDecl();
        break;
      }

      case CgaParser::STYLE: {
        enterOuterAlt(_localctx, 4);
        setState(59);
        styleDecl();
        break;
      }

      case CgaParser::ATTR:
      case CgaParser::CONST:
      case CgaParser::AT:
      case CgaParser::QID:
      case CgaParser::ID: {
        enterOuterAlt(_localctx, 5);
        setState(60);
        annotated();
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

//----------------- VersionDeclContext ------------------------------------------------------------------

CgaParser::VersionDeclContext::VersionDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* CgaParser::VersionDeclContext::VERSION() {
  return getToken(CgaParser::VERSION, 0);
}

tree::TerminalNode* CgaParser::VersionDeclContext::STRING() {
  return getToken(CgaParser::STRING, 0);
}


size_t CgaParser::VersionDeclContext::getRuleIndex() const {
  return CgaParser::RuleVersionDecl;
}

antlrcpp::Any CgaParser::VersionDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitVersionDecl(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::VersionDeclContext* CgaParser::versionDecl() {
  VersionDeclContext *_localctx = _tracker.createInstance<VersionDeclContext>(_ctx, getState());
  enterRule(_localctx, 4, CgaParser::RuleVersionDecl);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(63);
    match(CgaParser::VERSION);
    setState(64);
    match(CgaParser::STRING);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- DialectDeclContext ------------------------------------------------------------------

CgaParser::DialectDeclContext::DialectDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* CgaParser::DialectDeclContext::DIALECT() {
  return getToken(CgaParser::DIALECT, 0);
}

tree::TerminalNode* CgaParser::DialectDeclContext::ID() {
  return getToken(CgaParser::ID, 0);
}

tree::TerminalNode* CgaParser::DialectDeclContext::SEMI() {
  return getToken(CgaParser::SEMI, 0);
}


size_t CgaParser::DialectDeclContext::getRuleIndex() const {
  return CgaParser::RuleDialectDecl;
}

antlrcpp::Any CgaParser::DialectDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitDialectDecl(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::DialectDeclContext* CgaParser::dialectDecl() {
  DialectDeclContext *_localctx = _tracker.createInstance<DialectDeclContext>(_ctx, getState());
  enterRule(_localctx, 6, CgaParser::RuleDialectDecl);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(66);
    match(CgaParser::DIALECT);
    setState(67);
    match(CgaParser::ID);
    setState(69);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == CgaParser::SEMI) {
      setState(68);
      match(CgaParser::SEMI);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ImportDeclContext ------------------------------------------------------------------

CgaParser::ImportDeclContext::ImportDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* CgaParser::ImportDeclContext::IMPORT() {
  return getToken(CgaParser::IMPORT, 0);
}

tree::TerminalNode* CgaParser::ImportDeclContext::STRING() {
  return getToken(CgaParser::STRING, 0);
}

tree::TerminalNode* CgaParser::ImportDeclContext::COLON() {
  return getToken(CgaParser::COLON, 0);
}

std::vector<tree::TerminalNode *> CgaParser::ImportDeclContext::LPAREN() {
  return getTokens(CgaParser::LPAREN);
}

tree::TerminalNode* CgaParser::ImportDeclContext::LPAREN(size_t i) {
  return getToken(CgaParser::LPAREN, i);
}

std::vector<tree::TerminalNode *> CgaParser::ImportDeclContext::RPAREN() {
  return getTokens(CgaParser::RPAREN);
}

tree::TerminalNode* CgaParser::ImportDeclContext::RPAREN(size_t i) {
  return getToken(CgaParser::RPAREN, i);
}

std::vector<tree::TerminalNode *> CgaParser::ImportDeclContext::ID() {
  return getTokens(CgaParser::ID);
}

tree::TerminalNode* CgaParser::ImportDeclContext::ID(size_t i) {
  return getToken(CgaParser::ID, i);
}

std::vector<CgaParser::ImportArgContext *> CgaParser::ImportDeclContext::importArg() {
  return getRuleContexts<CgaParser::ImportArgContext>();
}

CgaParser::ImportArgContext* CgaParser::ImportDeclContext::importArg(size_t i) {
  return getRuleContext<CgaParser::ImportArgContext>(i);
}

std::vector<tree::TerminalNode *> CgaParser::ImportDeclContext::COMMA() {
  return getTokens(CgaParser::COMMA);
}

tree::TerminalNode* CgaParser::ImportDeclContext::COMMA(size_t i) {
  return getToken(CgaParser::COMMA, i);
}


size_t CgaParser::ImportDeclContext::getRuleIndex() const {
  return CgaParser::RuleImportDecl;
}

antlrcpp::Any CgaParser::ImportDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitImportDecl(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::ImportDeclContext* CgaParser::importDecl() {
  ImportDeclContext *_localctx = _tracker.createInstance<ImportDeclContext>(_ctx, getState());
  enterRule(_localctx, 8, CgaParser::RuleImportDecl);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(71);
    match(CgaParser::IMPORT);
    setState(86);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == CgaParser::ID) {
      setState(72);
      dynamic_cast<ImportDeclContext *>(_localctx)->alias = match(CgaParser::ID);
      setState(83);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == CgaParser::LPAREN) {
        setState(73);
        match(CgaParser::LPAREN);
        setState(74);
        dynamic_cast<ImportDeclContext *>(_localctx)->idToken = match(CgaParser::ID);
        dynamic_cast<ImportDeclContext *>(_localctx)->styles.push_back(dynamic_cast<ImportDeclContext *>(_localctx)->idToken);
        setState(79);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == CgaParser::COMMA) {
          setState(75);
          match(CgaParser::COMMA);
          setState(76);
          dynamic_cast<ImportDeclContext *>(_localctx)->idToken = match(CgaParser::ID);
          dynamic_cast<ImportDeclContext *>(_localctx)->styles.push_back(dynamic_cast<ImportDeclContext *>(_localctx)->idToken);
          setState(81);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
        setState(82);
        match(CgaParser::RPAREN);
      }
      setState(85);
      match(CgaParser::COLON);
    }
    setState(88);
    dynamic_cast<ImportDeclContext *>(_localctx)->path = match(CgaParser::STRING);
    setState(101);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == CgaParser::LPAREN) {
      setState(89);
      match(CgaParser::LPAREN);
      setState(98);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if ((((_la & ~ 0x3fULL) == 0) &&
        ((1ULL << _la) & ((1ULL << CgaParser::TRUE)
        | (1ULL << CgaParser::FALSE)
        | (1ULL << CgaParser::PLUS)
        | (1ULL << CgaParser::MINUS)
        | (1ULL << CgaParser::BANG)
        | (1ULL << CgaParser::QUOTE)
        | (1ULL << CgaParser::TILDE)
        | (1ULL << CgaParser::LPAREN)
        | (1ULL << CgaParser::LBRACK)
        | (1ULL << CgaParser::FLOAT)
        | (1ULL << CgaParser::INT)
        | (1ULL << CgaParser::QID)
        | (1ULL << CgaParser::ID)
        | (1ULL << CgaParser::STRING))) != 0)) {
        setState(90);
        importArg();
        setState(95);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == CgaParser::COMMA) {
          setState(91);
          match(CgaParser::COMMA);
          setState(92);
          importArg();
          setState(97);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(100);
      match(CgaParser::RPAREN);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ImportArgContext ------------------------------------------------------------------

CgaParser::ImportArgContext::ImportArgContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

CgaParser::ExprContext* CgaParser::ImportArgContext::expr() {
  return getRuleContext<CgaParser::ExprContext>(0);
}

tree::TerminalNode* CgaParser::ImportArgContext::ASSIGN() {
  return getToken(CgaParser::ASSIGN, 0);
}

tree::TerminalNode* CgaParser::ImportArgContext::ID() {
  return getToken(CgaParser::ID, 0);
}


size_t CgaParser::ImportArgContext::getRuleIndex() const {
  return CgaParser::RuleImportArg;
}

antlrcpp::Any CgaParser::ImportArgContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitImportArg(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::ImportArgContext* CgaParser::importArg() {
  ImportArgContext *_localctx = _tracker.createInstance<ImportArgContext>(_ctx, getState());
  enterRule(_localctx, 10, CgaParser::RuleImportArg);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(105);
    _errHandler->sync(this);

    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 9, _ctx)) {
    case 1: {
      setState(103);
      dynamic_cast<ImportArgContext *>(_localctx)->key = match(CgaParser::ID);
      setState(104);
      match(CgaParser::ASSIGN);
      break;
    }

    }
    setState(107);
    expr(0);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- StyleDeclContext ------------------------------------------------------------------

CgaParser::StyleDeclContext::StyleDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* CgaParser::StyleDeclContext::STYLE() {
  return getToken(CgaParser::STYLE, 0);
}

std::vector<tree::TerminalNode *> CgaParser::StyleDeclContext::ID() {
  return getTokens(CgaParser::ID);
}

tree::TerminalNode* CgaParser::StyleDeclContext::ID(size_t i) {
  return getToken(CgaParser::ID, i);
}

tree::TerminalNode* CgaParser::StyleDeclContext::EXTENDS() {
  return getToken(CgaParser::EXTENDS, 0);
}


size_t CgaParser::StyleDeclContext::getRuleIndex() const {
  return CgaParser::RuleStyleDecl;
}

antlrcpp::Any CgaParser::StyleDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitStyleDecl(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::StyleDeclContext* CgaParser::styleDecl() {
  StyleDeclContext *_localctx = _tracker.createInstance<StyleDeclContext>(_ctx, getState());
  enterRule(_localctx, 12, CgaParser::RuleStyleDecl);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(109);
    match(CgaParser::STYLE);
    setState(110);
    dynamic_cast<StyleDeclContext *>(_localctx)->name = match(CgaParser::ID);
    setState(113);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == CgaParser::EXTENDS) {
      setState(111);
      match(CgaParser::EXTENDS);
      setState(112);
      dynamic_cast<StyleDeclContext *>(_localctx)->base = match(CgaParser::ID);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- AnnotatedContext ------------------------------------------------------------------

CgaParser::AnnotatedContext::AnnotatedContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

CgaParser::AttrDeclContext* CgaParser::AnnotatedContext::attrDecl() {
  return getRuleContext<CgaParser::AttrDeclContext>(0);
}

CgaParser::ConstDeclContext* CgaParser::AnnotatedContext::constDecl() {
  return getRuleContext<CgaParser::ConstDeclContext>(0);
}

CgaParser::FunctionDeclContext* CgaParser::AnnotatedContext::functionDecl() {
  return getRuleContext<CgaParser::FunctionDeclContext>(0);
}

CgaParser::RuleDeclContext* CgaParser::AnnotatedContext::ruleDecl() {
  return getRuleContext<CgaParser::RuleDeclContext>(0);
}

std::vector<CgaParser::AnnotationContext *> CgaParser::AnnotatedContext::annotation() {
  return getRuleContexts<CgaParser::AnnotationContext>();
}

CgaParser::AnnotationContext* CgaParser::AnnotatedContext::annotation(size_t i) {
  return getRuleContext<CgaParser::AnnotationContext>(i);
}


size_t CgaParser::AnnotatedContext::getRuleIndex() const {
  return CgaParser::RuleAnnotated;
}

antlrcpp::Any CgaParser::AnnotatedContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitAnnotated(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::AnnotatedContext* CgaParser::annotated() {
  AnnotatedContext *_localctx = _tracker.createInstance<AnnotatedContext>(_ctx, getState());
  enterRule(_localctx, 14, CgaParser::RuleAnnotated);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(118);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while (_la == CgaParser::AT) {
      setState(115);
      annotation();
      setState(120);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(125);
    _errHandler->sync(this);
    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 12, _ctx)) {
    case 1: {
      setState(121);
      attrDecl();
      break;
    }

    case 2: {
      setState(122);
      constDecl();
      break;
    }

    case 3: {
      setState(123);
      functionDecl();
      break;
    }

    case 4: {
      setState(124);
      ruleDecl();
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

//----------------- AnnotationContext ------------------------------------------------------------------

CgaParser::AnnotationContext::AnnotationContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* CgaParser::AnnotationContext::AT() {
  return getToken(CgaParser::AT, 0);
}

tree::TerminalNode* CgaParser::AnnotationContext::ID() {
  return getToken(CgaParser::ID, 0);
}

tree::TerminalNode* CgaParser::AnnotationContext::LPAREN() {
  return getToken(CgaParser::LPAREN, 0);
}

tree::TerminalNode* CgaParser::AnnotationContext::RPAREN() {
  return getToken(CgaParser::RPAREN, 0);
}

std::vector<CgaParser::AnnotationArgContext *> CgaParser::AnnotationContext::annotationArg() {
  return getRuleContexts<CgaParser::AnnotationArgContext>();
}

CgaParser::AnnotationArgContext* CgaParser::AnnotationContext::annotationArg(size_t i) {
  return getRuleContext<CgaParser::AnnotationArgContext>(i);
}

std::vector<tree::TerminalNode *> CgaParser::AnnotationContext::COMMA() {
  return getTokens(CgaParser::COMMA);
}

tree::TerminalNode* CgaParser::AnnotationContext::COMMA(size_t i) {
  return getToken(CgaParser::COMMA, i);
}


size_t CgaParser::AnnotationContext::getRuleIndex() const {
  return CgaParser::RuleAnnotation;
}

antlrcpp::Any CgaParser::AnnotationContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitAnnotation(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::AnnotationContext* CgaParser::annotation() {
  AnnotationContext *_localctx = _tracker.createInstance<AnnotationContext>(_ctx, getState());
  enterRule(_localctx, 16, CgaParser::RuleAnnotation);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(127);
    match(CgaParser::AT);
    setState(128);
    dynamic_cast<AnnotationContext *>(_localctx)->name = match(CgaParser::ID);
    setState(141);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == CgaParser::LPAREN) {
      setState(129);
      match(CgaParser::LPAREN);
      setState(138);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if ((((_la & ~ 0x3fULL) == 0) &&
        ((1ULL << _la) & ((1ULL << CgaParser::TRUE)
        | (1ULL << CgaParser::FALSE)
        | (1ULL << CgaParser::PLUS)
        | (1ULL << CgaParser::MINUS)
        | (1ULL << CgaParser::BANG)
        | (1ULL << CgaParser::QUOTE)
        | (1ULL << CgaParser::TILDE)
        | (1ULL << CgaParser::LPAREN)
        | (1ULL << CgaParser::LBRACK)
        | (1ULL << CgaParser::FLOAT)
        | (1ULL << CgaParser::INT)
        | (1ULL << CgaParser::QID)
        | (1ULL << CgaParser::ID)
        | (1ULL << CgaParser::STRING))) != 0)) {
        setState(130);
        annotationArg();
        setState(135);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == CgaParser::COMMA) {
          setState(131);
          match(CgaParser::COMMA);
          setState(132);
          annotationArg();
          setState(137);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(140);
      match(CgaParser::RPAREN);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- AnnotationArgContext ------------------------------------------------------------------

CgaParser::AnnotationArgContext::AnnotationArgContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

CgaParser::ExprContext* CgaParser::AnnotationArgContext::expr() {
  return getRuleContext<CgaParser::ExprContext>(0);
}

tree::TerminalNode* CgaParser::AnnotationArgContext::ASSIGN() {
  return getToken(CgaParser::ASSIGN, 0);
}

tree::TerminalNode* CgaParser::AnnotationArgContext::ID() {
  return getToken(CgaParser::ID, 0);
}


size_t CgaParser::AnnotationArgContext::getRuleIndex() const {
  return CgaParser::RuleAnnotationArg;
}

antlrcpp::Any CgaParser::AnnotationArgContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitAnnotationArg(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::AnnotationArgContext* CgaParser::annotationArg() {
  AnnotationArgContext *_localctx = _tracker.createInstance<AnnotationArgContext>(_ctx, getState());
  enterRule(_localctx, 18, CgaParser::RuleAnnotationArg);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(145);
    _errHandler->sync(this);

    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 16, _ctx)) {
    case 1: {
      setState(143);
      dynamic_cast<AnnotationArgContext *>(_localctx)->key = match(CgaParser::ID);
      setState(144);
      match(CgaParser::ASSIGN);
      break;
    }

    }
    setState(147);
    expr(0);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- AttrDeclContext ------------------------------------------------------------------

CgaParser::AttrDeclContext::AttrDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* CgaParser::AttrDeclContext::ATTR() {
  return getToken(CgaParser::ATTR, 0);
}

tree::TerminalNode* CgaParser::AttrDeclContext::ASSIGN() {
  return getToken(CgaParser::ASSIGN, 0);
}

CgaParser::ValueContext* CgaParser::AttrDeclContext::value() {
  return getRuleContext<CgaParser::ValueContext>(0);
}

tree::TerminalNode* CgaParser::AttrDeclContext::ID() {
  return getToken(CgaParser::ID, 0);
}


size_t CgaParser::AttrDeclContext::getRuleIndex() const {
  return CgaParser::RuleAttrDecl;
}

antlrcpp::Any CgaParser::AttrDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitAttrDecl(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::AttrDeclContext* CgaParser::attrDecl() {
  AttrDeclContext *_localctx = _tracker.createInstance<AttrDeclContext>(_ctx, getState());
  enterRule(_localctx, 20, CgaParser::RuleAttrDecl);

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(149);
    match(CgaParser::ATTR);
    setState(150);
    dynamic_cast<AttrDeclContext *>(_localctx)->name = match(CgaParser::ID);
    setState(151);
    match(CgaParser::ASSIGN);
    setState(152);
    value();
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ConstDeclContext ------------------------------------------------------------------

CgaParser::ConstDeclContext::ConstDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* CgaParser::ConstDeclContext::CONST() {
  return getToken(CgaParser::CONST, 0);
}

tree::TerminalNode* CgaParser::ConstDeclContext::ASSIGN() {
  return getToken(CgaParser::ASSIGN, 0);
}

CgaParser::ValueContext* CgaParser::ConstDeclContext::value() {
  return getRuleContext<CgaParser::ValueContext>(0);
}

tree::TerminalNode* CgaParser::ConstDeclContext::ID() {
  return getToken(CgaParser::ID, 0);
}

tree::TerminalNode* CgaParser::ConstDeclContext::LPAREN() {
  return getToken(CgaParser::LPAREN, 0);
}

tree::TerminalNode* CgaParser::ConstDeclContext::RPAREN() {
  return getToken(CgaParser::RPAREN, 0);
}

CgaParser::ParamsContext* CgaParser::ConstDeclContext::params() {
  return getRuleContext<CgaParser::ParamsContext>(0);
}


size_t CgaParser::ConstDeclContext::getRuleIndex() const {
  return CgaParser::RuleConstDecl;
}

antlrcpp::Any CgaParser::ConstDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitConstDecl(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::ConstDeclContext* CgaParser::constDecl() {
  ConstDeclContext *_localctx = _tracker.createInstance<ConstDeclContext>(_ctx, getState());
  enterRule(_localctx, 22, CgaParser::RuleConstDecl);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(154);
    match(CgaParser::CONST);
    setState(155);
    dynamic_cast<ConstDeclContext *>(_localctx)->name = match(CgaParser::ID);
    setState(161);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == CgaParser::LPAREN) {
      setState(156);
      match(CgaParser::LPAREN);
      setState(158);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == CgaParser::ID) {
        setState(157);
        params();
      }
      setState(160);
      match(CgaParser::RPAREN);
    }
    setState(163);
    match(CgaParser::ASSIGN);
    setState(164);
    value();
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- FunctionDeclContext ------------------------------------------------------------------

CgaParser::FunctionDeclContext::FunctionDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* CgaParser::FunctionDeclContext::ASSIGN() {
  return getToken(CgaParser::ASSIGN, 0);
}

CgaParser::ValueContext* CgaParser::FunctionDeclContext::value() {
  return getRuleContext<CgaParser::ValueContext>(0);
}

tree::TerminalNode* CgaParser::FunctionDeclContext::ID() {
  return getToken(CgaParser::ID, 0);
}

tree::TerminalNode* CgaParser::FunctionDeclContext::QID() {
  return getToken(CgaParser::QID, 0);
}

tree::TerminalNode* CgaParser::FunctionDeclContext::LPAREN() {
  return getToken(CgaParser::LPAREN, 0);
}

tree::TerminalNode* CgaParser::FunctionDeclContext::RPAREN() {
  return getToken(CgaParser::RPAREN, 0);
}

CgaParser::ParamsContext* CgaParser::FunctionDeclContext::params() {
  return getRuleContext<CgaParser::ParamsContext>(0);
}


size_t CgaParser::FunctionDeclContext::getRuleIndex() const {
  return CgaParser::RuleFunctionDecl;
}

antlrcpp::Any CgaParser::FunctionDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitFunctionDecl(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::FunctionDeclContext* CgaParser::functionDecl() {
  FunctionDeclContext *_localctx = _tracker.createInstance<FunctionDeclContext>(_ctx, getState());
  enterRule(_localctx, 24, CgaParser::RuleFunctionDecl);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(166);
    dynamic_cast<FunctionDeclContext *>(_localctx)->name = _input->LT(1);
    _la = _input->LA(1);
    if (!(_la == CgaParser::QID

    || _la == CgaParser::ID)) {
      dynamic_cast<FunctionDeclContext *>(_localctx)->name = _errHandler->recoverInline(this);
    }
    else {
      _errHandler->reportMatch(this);
      consume();
    }
    setState(172);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == CgaParser::LPAREN) {
      setState(167);
      match(CgaParser::LPAREN);
      setState(169);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == CgaParser::ID) {
        setState(168);
        params();
      }
      setState(171);
      match(CgaParser::RPAREN);
    }
    setState(174);
    match(CgaParser::ASSIGN);
    setState(175);
    value();
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- RuleDeclContext ------------------------------------------------------------------

CgaParser::RuleDeclContext::RuleDeclContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* CgaParser::RuleDeclContext::ARROW() {
  return getToken(CgaParser::ARROW, 0);
}

CgaParser::RuleBodyContext* CgaParser::RuleDeclContext::ruleBody() {
  return getRuleContext<CgaParser::RuleBodyContext>(0);
}

tree::TerminalNode* CgaParser::RuleDeclContext::ID() {
  return getToken(CgaParser::ID, 0);
}

tree::TerminalNode* CgaParser::RuleDeclContext::LPAREN() {
  return getToken(CgaParser::LPAREN, 0);
}

tree::TerminalNode* CgaParser::RuleDeclContext::RPAREN() {
  return getToken(CgaParser::RPAREN, 0);
}

CgaParser::ParamsContext* CgaParser::RuleDeclContext::params() {
  return getRuleContext<CgaParser::ParamsContext>(0);
}


size_t CgaParser::RuleDeclContext::getRuleIndex() const {
  return CgaParser::RuleRuleDecl;
}

antlrcpp::Any CgaParser::RuleDeclContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitRuleDecl(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::RuleDeclContext* CgaParser::ruleDecl() {
  RuleDeclContext *_localctx = _tracker.createInstance<RuleDeclContext>(_ctx, getState());
  enterRule(_localctx, 26, CgaParser::RuleRuleDecl);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(177);
    dynamic_cast<RuleDeclContext *>(_localctx)->name = match(CgaParser::ID);
    setState(183);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == CgaParser::LPAREN) {
      setState(178);
      match(CgaParser::LPAREN);
      setState(180);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if (_la == CgaParser::ID) {
        setState(179);
        params();
      }
      setState(182);
      match(CgaParser::RPAREN);
    }
    setState(185);
    match(CgaParser::ARROW);
    setState(186);
    ruleBody();
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ParamsContext ------------------------------------------------------------------

CgaParser::ParamsContext::ParamsContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

std::vector<tree::TerminalNode *> CgaParser::ParamsContext::ID() {
  return getTokens(CgaParser::ID);
}

tree::TerminalNode* CgaParser::ParamsContext::ID(size_t i) {
  return getToken(CgaParser::ID, i);
}

std::vector<tree::TerminalNode *> CgaParser::ParamsContext::COMMA() {
  return getTokens(CgaParser::COMMA);
}

tree::TerminalNode* CgaParser::ParamsContext::COMMA(size_t i) {
  return getToken(CgaParser::COMMA, i);
}


size_t CgaParser::ParamsContext::getRuleIndex() const {
  return CgaParser::RuleParams;
}

antlrcpp::Any CgaParser::ParamsContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitParams(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::ParamsContext* CgaParser::params() {
  ParamsContext *_localctx = _tracker.createInstance<ParamsContext>(_ctx, getState());
  enterRule(_localctx, 28, CgaParser::RuleParams);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(188);
    match(CgaParser::ID);
    setState(193);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while (_la == CgaParser::COMMA) {
      setState(189);
      match(CgaParser::COMMA);
      setState(190);
      match(CgaParser::ID);
      setState(195);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- ValueContext ------------------------------------------------------------------

CgaParser::ValueContext::ValueContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}


size_t CgaParser::ValueContext::getRuleIndex() const {
  return CgaParser::RuleValue;
}

void CgaParser::ValueContext::copyFrom(ValueContext *ctx) {
  ParserRuleContext::copyFrom(ctx);
}

//----------------- StochasticValueContext ------------------------------------------------------------------

std::vector<tree::TerminalNode *> CgaParser::StochasticValueContext::PERCENT_LIT() {
  return getTokens(CgaParser::PERCENT_LIT);
}

tree::TerminalNode* CgaParser::StochasticValueContext::PERCENT_LIT(size_t i) {
  return getToken(CgaParser::PERCENT_LIT, i);
}

std::vector<tree::TerminalNode *> CgaParser::StochasticValueContext::COLON() {
  return getTokens(CgaParser::COLON);
}

tree::TerminalNode* CgaParser::StochasticValueContext::COLON(size_t i) {
  return getToken(CgaParser::COLON, i);
}

std::vector<CgaParser::ValueContext *> CgaParser::StochasticValueContext::value() {
  return getRuleContexts<CgaParser::ValueContext>();
}

CgaParser::ValueContext* CgaParser::StochasticValueContext::value(size_t i) {
  return getRuleContext<CgaParser::ValueContext>(i);
}

tree::TerminalNode* CgaParser::StochasticValueContext::ELSE() {
  return getToken(CgaParser::ELSE, 0);
}

CgaParser::StochasticValueContext::StochasticValueContext(ValueContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::StochasticValueContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitStochasticValue(this);
  else
    return visitor->visitChildren(this);
}
//----------------- PlainValueContext ------------------------------------------------------------------

CgaParser::ExprContext* CgaParser::PlainValueContext::expr() {
  return getRuleContext<CgaParser::ExprContext>(0);
}

CgaParser::PlainValueContext::PlainValueContext(ValueContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::PlainValueContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitPlainValue(this);
  else
    return visitor->visitChildren(this);
}
//----------------- CaseValueContext ------------------------------------------------------------------

tree::TerminalNode* CgaParser::CaseValueContext::ELSE() {
  return getToken(CgaParser::ELSE, 0);
}

std::vector<tree::TerminalNode *> CgaParser::CaseValueContext::COLON() {
  return getTokens(CgaParser::COLON);
}

tree::TerminalNode* CgaParser::CaseValueContext::COLON(size_t i) {
  return getToken(CgaParser::COLON, i);
}

std::vector<CgaParser::ValueContext *> CgaParser::CaseValueContext::value() {
  return getRuleContexts<CgaParser::ValueContext>();
}

CgaParser::ValueContext* CgaParser::CaseValueContext::value(size_t i) {
  return getRuleContext<CgaParser::ValueContext>(i);
}

std::vector<tree::TerminalNode *> CgaParser::CaseValueContext::CASE() {
  return getTokens(CgaParser::CASE);
}

tree::TerminalNode* CgaParser::CaseValueContext::CASE(size_t i) {
  return getToken(CgaParser::CASE, i);
}

std::vector<CgaParser::ExprContext *> CgaParser::CaseValueContext::expr() {
  return getRuleContexts<CgaParser::ExprContext>();
}

CgaParser::ExprContext* CgaParser::CaseValueContext::expr(size_t i) {
  return getRuleContext<CgaParser::ExprContext>(i);
}

CgaParser::CaseValueContext::CaseValueContext(ValueContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::CaseValueContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitCaseValue(this);
  else
    return visitor->visitChildren(this);
}
CgaParser::ValueContext* CgaParser::value() {
  ValueContext *_localctx = _tracker.createInstance<ValueContext>(_ctx, getState());
  enterRule(_localctx, 30, CgaParser::RuleValue);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    size_t alt;
    setState(222);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case CgaParser::CASE: {
        _localctx = dynamic_cast<ValueContext *>(_tracker.createInstance<CgaParser::CaseValueContext>(_localctx));
        enterOuterAlt(_localctx, 1);
        setState(201); 
        _errHandler->sync(this);
        _la = _input->LA(1);
        do {
          setState(196);
          match(CgaParser::CASE);
          setState(197);
          expr(0);
          setState(198);
          match(CgaParser::COLON);
          setState(199);
          value();
          setState(203); 
          _errHandler->sync(this);
          _la = _input->LA(1);
        } while (_la == CgaParser::CASE);
        setState(205);
        match(CgaParser::ELSE);
        setState(206);
        match(CgaParser::COLON);
        setState(207);
        value();
        break;
      }

      case CgaParser::PERCENT_LIT: {
        _localctx = dynamic_cast<ValueContext *>(_tracker.createInstance<CgaParser::StochasticValueContext>(_localctx));
        enterOuterAlt(_localctx, 2);
        setState(212); 
        _errHandler->sync(this);
        alt = 1;
        do {
          switch (alt) {
            case 1: {
                  setState(209);
                  match(CgaParser::PERCENT_LIT);
                  setState(210);
                  match(CgaParser::COLON);
                  setState(211);
                  value();
                  break;
                }

          default:
            throw NoViableAltException(this);
          }
          setState(214); 
          _errHandler->sync(this);
          alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 25, _ctx);
        } while (alt != 2 && alt != atn::ATN::INVALID_ALT_NUMBER);
        setState(219);
        _errHandler->sync(this);

        switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 26, _ctx)) {
        case 1: {
          setState(216);
          match(CgaParser::ELSE);
          setState(217);
          match(CgaParser::COLON);
          setState(218);
          value();
          break;
        }

        }
        break;
      }

      case CgaParser::TRUE:
      case CgaParser::FALSE:
      case CgaParser::PLUS:
      case CgaParser::MINUS:
      case CgaParser::BANG:
      case CgaParser::QUOTE:
      case CgaParser::TILDE:
      case CgaParser::LPAREN:
      case CgaParser::LBRACK:
      case CgaParser::FLOAT:
      case CgaParser::INT:
      case CgaParser::QID:
      case CgaParser::ID:
      case CgaParser::STRING: {
        _localctx = dynamic_cast<ValueContext *>(_tracker.createInstance<CgaParser::PlainValueContext>(_localctx));
        enterOuterAlt(_localctx, 3);
        setState(221);
        expr(0);
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

//----------------- RuleBodyContext ------------------------------------------------------------------

CgaParser::RuleBodyContext::RuleBodyContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}


size_t CgaParser::RuleBodyContext::getRuleIndex() const {
  return CgaParser::RuleRuleBody;
}

void CgaParser::RuleBodyContext::copyFrom(RuleBodyContext *ctx) {
  ParserRuleContext::copyFrom(ctx);
}

//----------------- OperationBodyContext ------------------------------------------------------------------

std::vector<CgaParser::OperationContext *> CgaParser::OperationBodyContext::operation() {
  return getRuleContexts<CgaParser::OperationContext>();
}

CgaParser::OperationContext* CgaParser::OperationBodyContext::operation(size_t i) {
  return getRuleContext<CgaParser::OperationContext>(i);
}

CgaParser::OperationBodyContext::OperationBodyContext(RuleBodyContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::OperationBodyContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitOperationBody(this);
  else
    return visitor->visitChildren(this);
}
//----------------- StochasticBodyContext ------------------------------------------------------------------

std::vector<tree::TerminalNode *> CgaParser::StochasticBodyContext::PERCENT_LIT() {
  return getTokens(CgaParser::PERCENT_LIT);
}

tree::TerminalNode* CgaParser::StochasticBodyContext::PERCENT_LIT(size_t i) {
  return getToken(CgaParser::PERCENT_LIT, i);
}

std::vector<tree::TerminalNode *> CgaParser::StochasticBodyContext::COLON() {
  return getTokens(CgaParser::COLON);
}

tree::TerminalNode* CgaParser::StochasticBodyContext::COLON(size_t i) {
  return getToken(CgaParser::COLON, i);
}

std::vector<CgaParser::RuleBodyContext *> CgaParser::StochasticBodyContext::ruleBody() {
  return getRuleContexts<CgaParser::RuleBodyContext>();
}

CgaParser::RuleBodyContext* CgaParser::StochasticBodyContext::ruleBody(size_t i) {
  return getRuleContext<CgaParser::RuleBodyContext>(i);
}

tree::TerminalNode* CgaParser::StochasticBodyContext::ELSE() {
  return getToken(CgaParser::ELSE, 0);
}

CgaParser::StochasticBodyContext::StochasticBodyContext(RuleBodyContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::StochasticBodyContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitStochasticBody(this);
  else
    return visitor->visitChildren(this);
}
//----------------- CaseBodyContext ------------------------------------------------------------------

tree::TerminalNode* CgaParser::CaseBodyContext::ELSE() {
  return getToken(CgaParser::ELSE, 0);
}

std::vector<tree::TerminalNode *> CgaParser::CaseBodyContext::COLON() {
  return getTokens(CgaParser::COLON);
}

tree::TerminalNode* CgaParser::CaseBodyContext::COLON(size_t i) {
  return getToken(CgaParser::COLON, i);
}

std::vector<CgaParser::RuleBodyContext *> CgaParser::CaseBodyContext::ruleBody() {
  return getRuleContexts<CgaParser::RuleBodyContext>();
}

CgaParser::RuleBodyContext* CgaParser::CaseBodyContext::ruleBody(size_t i) {
  return getRuleContext<CgaParser::RuleBodyContext>(i);
}

std::vector<tree::TerminalNode *> CgaParser::CaseBodyContext::CASE() {
  return getTokens(CgaParser::CASE);
}

tree::TerminalNode* CgaParser::CaseBodyContext::CASE(size_t i) {
  return getToken(CgaParser::CASE, i);
}

std::vector<CgaParser::ExprContext *> CgaParser::CaseBodyContext::expr() {
  return getRuleContexts<CgaParser::ExprContext>();
}

CgaParser::ExprContext* CgaParser::CaseBodyContext::expr(size_t i) {
  return getRuleContext<CgaParser::ExprContext>(i);
}

CgaParser::CaseBodyContext::CaseBodyContext(RuleBodyContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::CaseBodyContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitCaseBody(this);
  else
    return visitor->visitChildren(this);
}
CgaParser::RuleBodyContext* CgaParser::ruleBody() {
  RuleBodyContext *_localctx = _tracker.createInstance<RuleBodyContext>(_ctx, getState());
  enterRule(_localctx, 32, CgaParser::RuleRuleBody);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    size_t alt;
    setState(254);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case CgaParser::CASE: {
        _localctx = dynamic_cast<RuleBodyContext *>(_tracker.createInstance<CgaParser::CaseBodyContext>(_localctx));
        enterOuterAlt(_localctx, 1);
        setState(229); 
        _errHandler->sync(this);
        _la = _input->LA(1);
        do {
          setState(224);
          match(CgaParser::CASE);
          setState(225);
          expr(0);
          setState(226);
          match(CgaParser::COLON);
          setState(227);
          ruleBody();
          setState(231); 
          _errHandler->sync(this);
          _la = _input->LA(1);
        } while (_la == CgaParser::CASE);
        setState(233);
        match(CgaParser::ELSE);
        setState(234);
        match(CgaParser::COLON);
        setState(235);
        ruleBody();
        break;
      }

      case CgaParser::PERCENT_LIT: {
        _localctx = dynamic_cast<RuleBodyContext *>(_tracker.createInstance<CgaParser::StochasticBodyContext>(_localctx));
        enterOuterAlt(_localctx, 2);
        setState(240); 
        _errHandler->sync(this);
        alt = 1;
        do {
          switch (alt) {
            case 1: {
                  setState(237);
                  match(CgaParser::PERCENT_LIT);
                  setState(238);
                  match(CgaParser::COLON);
                  setState(239);
                  ruleBody();
                  break;
                }

          default:
            throw NoViableAltException(this);
          }
          setState(242); 
          _errHandler->sync(this);
          alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 29, _ctx);
        } while (alt != 2 && alt != atn::ATN::INVALID_ALT_NUMBER);
        setState(247);
        _errHandler->sync(this);

        switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 30, _ctx)) {
        case 1: {
          setState(244);
          match(CgaParser::ELSE);
          setState(245);
          match(CgaParser::COLON);
          setState(246);
          ruleBody();
          break;
        }

        }
        break;
      }

      case CgaParser::NIL:
      case CgaParser::DOT:
      case CgaParser::LBRACK:
      case CgaParser::QID:
      case CgaParser::LEAF:
      case CgaParser::ID: {
        _localctx = dynamic_cast<RuleBodyContext *>(_tracker.createInstance<CgaParser::OperationBodyContext>(_localctx));
        enterOuterAlt(_localctx, 3);
        setState(250); 
        _errHandler->sync(this);
        alt = 1;
        do {
          switch (alt) {
            case 1: {
                  setState(249);
                  operation();
                  break;
                }

          default:
            throw NoViableAltException(this);
          }
          setState(252); 
          _errHandler->sync(this);
          alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 31, _ctx);
        } while (alt != 2 && alt != atn::ATN::INVALID_ALT_NUMBER);
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

//----------------- OperationContext ------------------------------------------------------------------

CgaParser::OperationContext::OperationContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}


size_t CgaParser::OperationContext::getRuleIndex() const {
  return CgaParser::RuleOperation;
}

void CgaParser::OperationContext::copyFrom(OperationContext *ctx) {
  ParserRuleContext::copyFrom(ctx);
}

//----------------- PushPopOperationContext ------------------------------------------------------------------

tree::TerminalNode* CgaParser::PushPopOperationContext::LBRACK() {
  return getToken(CgaParser::LBRACK, 0);
}

tree::TerminalNode* CgaParser::PushPopOperationContext::RBRACK() {
  return getToken(CgaParser::RBRACK, 0);
}

std::vector<CgaParser::OperationContext *> CgaParser::PushPopOperationContext::operation() {
  return getRuleContexts<CgaParser::OperationContext>();
}

CgaParser::OperationContext* CgaParser::PushPopOperationContext::operation(size_t i) {
  return getRuleContext<CgaParser::OperationContext>(i);
}

CgaParser::PushPopOperationContext::PushPopOperationContext(OperationContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::PushPopOperationContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitPushPopOperation(this);
  else
    return visitor->visitChildren(this);
}
//----------------- CallOperationContext ------------------------------------------------------------------

tree::TerminalNode* CgaParser::CallOperationContext::LPAREN() {
  return getToken(CgaParser::LPAREN, 0);
}

tree::TerminalNode* CgaParser::CallOperationContext::RPAREN() {
  return getToken(CgaParser::RPAREN, 0);
}

tree::TerminalNode* CgaParser::CallOperationContext::ID() {
  return getToken(CgaParser::ID, 0);
}

tree::TerminalNode* CgaParser::CallOperationContext::QID() {
  return getToken(CgaParser::QID, 0);
}

std::vector<CgaParser::ExprContext *> CgaParser::CallOperationContext::expr() {
  return getRuleContexts<CgaParser::ExprContext>();
}

CgaParser::ExprContext* CgaParser::CallOperationContext::expr(size_t i) {
  return getRuleContext<CgaParser::ExprContext>(i);
}

CgaParser::SplitBodyContext* CgaParser::CallOperationContext::splitBody() {
  return getRuleContext<CgaParser::SplitBodyContext>(0);
}

CgaParser::OperationBlockContext* CgaParser::CallOperationContext::operationBlock() {
  return getRuleContext<CgaParser::OperationBlockContext>(0);
}

std::vector<tree::TerminalNode *> CgaParser::CallOperationContext::COMMA() {
  return getTokens(CgaParser::COMMA);
}

tree::TerminalNode* CgaParser::CallOperationContext::COMMA(size_t i) {
  return getToken(CgaParser::COMMA, i);
}

CgaParser::CallOperationContext::CallOperationContext(OperationContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::CallOperationContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitCallOperation(this);
  else
    return visitor->visitChildren(this);
}
//----------------- ShapeOperationContext ------------------------------------------------------------------

tree::TerminalNode* CgaParser::ShapeOperationContext::ID() {
  return getToken(CgaParser::ID, 0);
}

tree::TerminalNode* CgaParser::ShapeOperationContext::QID() {
  return getToken(CgaParser::QID, 0);
}

CgaParser::ShapeOperationContext::ShapeOperationContext(OperationContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::ShapeOperationContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitShapeOperation(this);
  else
    return visitor->visitChildren(this);
}
//----------------- DotOperationContext ------------------------------------------------------------------

tree::TerminalNode* CgaParser::DotOperationContext::DOT() {
  return getToken(CgaParser::DOT, 0);
}

CgaParser::DotOperationContext::DotOperationContext(OperationContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::DotOperationContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitDotOperation(this);
  else
    return visitor->visitChildren(this);
}
//----------------- NilOperationContext ------------------------------------------------------------------

tree::TerminalNode* CgaParser::NilOperationContext::NIL() {
  return getToken(CgaParser::NIL, 0);
}

CgaParser::NilOperationContext::NilOperationContext(OperationContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::NilOperationContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitNilOperation(this);
  else
    return visitor->visitChildren(this);
}
//----------------- LeafOperationContext ------------------------------------------------------------------

tree::TerminalNode* CgaParser::LeafOperationContext::LEAF() {
  return getToken(CgaParser::LEAF, 0);
}

CgaParser::LeafOperationContext::LeafOperationContext(OperationContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::LeafOperationContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitLeafOperation(this);
  else
    return visitor->visitChildren(this);
}
CgaParser::OperationContext* CgaParser::operation() {
  OperationContext *_localctx = _tracker.createInstance<OperationContext>(_ctx, getState());
  enterRule(_localctx, 34, CgaParser::RuleOperation);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(285);
    _errHandler->sync(this);
    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 37, _ctx)) {
    case 1: {
      _localctx = dynamic_cast<OperationContext *>(_tracker.createInstance<CgaParser::NilOperationContext>(_localctx));
      enterOuterAlt(_localctx, 1);
      setState(256);
      match(CgaParser::NIL);
      break;
    }

    case 2: {
      _localctx = dynamic_cast<OperationContext *>(_tracker.createInstance<CgaParser::CallOperationContext>(_localctx));
      enterOuterAlt(_localctx, 2);
      setState(257);
      dynamic_cast<CallOperationContext *>(_localctx)->name = _input->LT(1);
      _la = _input->LA(1);
      if (!(_la == CgaParser::QID

      || _la == CgaParser::ID)) {
        dynamic_cast<CallOperationContext *>(_localctx)->name = _errHandler->recoverInline(this);
      }
      else {
        _errHandler->reportMatch(this);
        consume();
      }
      setState(258);
      match(CgaParser::LPAREN);
      setState(267);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if ((((_la & ~ 0x3fULL) == 0) &&
        ((1ULL << _la) & ((1ULL << CgaParser::TRUE)
        | (1ULL << CgaParser::FALSE)
        | (1ULL << CgaParser::PLUS)
        | (1ULL << CgaParser::MINUS)
        | (1ULL << CgaParser::BANG)
        | (1ULL << CgaParser::QUOTE)
        | (1ULL << CgaParser::TILDE)
        | (1ULL << CgaParser::LPAREN)
        | (1ULL << CgaParser::LBRACK)
        | (1ULL << CgaParser::FLOAT)
        | (1ULL << CgaParser::INT)
        | (1ULL << CgaParser::QID)
        | (1ULL << CgaParser::ID)
        | (1ULL << CgaParser::STRING))) != 0)) {
        setState(259);
        expr(0);
        setState(264);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == CgaParser::COMMA) {
          setState(260);
          match(CgaParser::COMMA);
          setState(261);
          expr(0);
          setState(266);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(269);
      match(CgaParser::RPAREN);
      setState(272);
      _errHandler->sync(this);

      switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 35, _ctx)) {
      case 1: {
        setState(270);
        splitBody();
        break;
      }

      case 2: {
        setState(271);
        operationBlock();
        break;
      }

      }
      break;
    }

    case 3: {
      _localctx = dynamic_cast<OperationContext *>(_tracker.createInstance<CgaParser::LeafOperationContext>(_localctx));
      enterOuterAlt(_localctx, 3);
      setState(274);
      dynamic_cast<LeafOperationContext *>(_localctx)->leaf = match(CgaParser::LEAF);
      break;
    }

    case 4: {
      _localctx = dynamic_cast<OperationContext *>(_tracker.createInstance<CgaParser::ShapeOperationContext>(_localctx));
      enterOuterAlt(_localctx, 4);
      setState(275);
      dynamic_cast<ShapeOperationContext *>(_localctx)->name = _input->LT(1);
      _la = _input->LA(1);
      if (!(_la == CgaParser::QID

      || _la == CgaParser::ID)) {
        dynamic_cast<ShapeOperationContext *>(_localctx)->name = _errHandler->recoverInline(this);
      }
      else {
        _errHandler->reportMatch(this);
        consume();
      }
      break;
    }

    case 5: {
      _localctx = dynamic_cast<OperationContext *>(_tracker.createInstance<CgaParser::DotOperationContext>(_localctx));
      enterOuterAlt(_localctx, 5);
      setState(276);
      match(CgaParser::DOT);
      break;
    }

    case 6: {
      _localctx = dynamic_cast<OperationContext *>(_tracker.createInstance<CgaParser::PushPopOperationContext>(_localctx));
      enterOuterAlt(_localctx, 6);
      setState(277);
      match(CgaParser::LBRACK);
      setState(281);
      _errHandler->sync(this);
      _la = _input->LA(1);
      while ((((_la & ~ 0x3fULL) == 0) &&
        ((1ULL << _la) & ((1ULL << CgaParser::NIL)
        | (1ULL << CgaParser::DOT)
        | (1ULL << CgaParser::LBRACK)
        | (1ULL << CgaParser::QID)
        | (1ULL << CgaParser::LEAF)
        | (1ULL << CgaParser::ID))) != 0)) {
        setState(278);
        operation();
        setState(283);
        _errHandler->sync(this);
        _la = _input->LA(1);
      }
      setState(284);
      match(CgaParser::RBRACK);
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

//----------------- OperationBlockContext ------------------------------------------------------------------

CgaParser::OperationBlockContext::OperationBlockContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* CgaParser::OperationBlockContext::LBRACE() {
  return getToken(CgaParser::LBRACE, 0);
}

tree::TerminalNode* CgaParser::OperationBlockContext::RBRACE() {
  return getToken(CgaParser::RBRACE, 0);
}

std::vector<CgaParser::OperationContext *> CgaParser::OperationBlockContext::operation() {
  return getRuleContexts<CgaParser::OperationContext>();
}

CgaParser::OperationContext* CgaParser::OperationBlockContext::operation(size_t i) {
  return getRuleContext<CgaParser::OperationContext>(i);
}


size_t CgaParser::OperationBlockContext::getRuleIndex() const {
  return CgaParser::RuleOperationBlock;
}

antlrcpp::Any CgaParser::OperationBlockContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitOperationBlock(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::OperationBlockContext* CgaParser::operationBlock() {
  OperationBlockContext *_localctx = _tracker.createInstance<OperationBlockContext>(_ctx, getState());
  enterRule(_localctx, 36, CgaParser::RuleOperationBlock);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(287);
    match(CgaParser::LBRACE);
    setState(291);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while ((((_la & ~ 0x3fULL) == 0) &&
      ((1ULL << _la) & ((1ULL << CgaParser::NIL)
      | (1ULL << CgaParser::DOT)
      | (1ULL << CgaParser::LBRACK)
      | (1ULL << CgaParser::QID)
      | (1ULL << CgaParser::LEAF)
      | (1ULL << CgaParser::ID))) != 0)) {
      setState(288);
      operation();
      setState(293);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(294);
    match(CgaParser::RBRACE);
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- SplitBodyContext ------------------------------------------------------------------

CgaParser::SplitBodyContext::SplitBodyContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* CgaParser::SplitBodyContext::LBRACE() {
  return getToken(CgaParser::LBRACE, 0);
}

std::vector<CgaParser::SplitPartContext *> CgaParser::SplitBodyContext::splitPart() {
  return getRuleContexts<CgaParser::SplitPartContext>();
}

CgaParser::SplitPartContext* CgaParser::SplitBodyContext::splitPart(size_t i) {
  return getRuleContext<CgaParser::SplitPartContext>(i);
}

tree::TerminalNode* CgaParser::SplitBodyContext::RBRACE() {
  return getToken(CgaParser::RBRACE, 0);
}

std::vector<tree::TerminalNode *> CgaParser::SplitBodyContext::PIPE() {
  return getTokens(CgaParser::PIPE);
}

tree::TerminalNode* CgaParser::SplitBodyContext::PIPE(size_t i) {
  return getToken(CgaParser::PIPE, i);
}

tree::TerminalNode* CgaParser::SplitBodyContext::STAR() {
  return getToken(CgaParser::STAR, 0);
}


size_t CgaParser::SplitBodyContext::getRuleIndex() const {
  return CgaParser::RuleSplitBody;
}

antlrcpp::Any CgaParser::SplitBodyContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitSplitBody(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::SplitBodyContext* CgaParser::splitBody() {
  SplitBodyContext *_localctx = _tracker.createInstance<SplitBodyContext>(_ctx, getState());
  enterRule(_localctx, 38, CgaParser::RuleSplitBody);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(296);
    match(CgaParser::LBRACE);
    setState(297);
    splitPart();
    setState(302);
    _errHandler->sync(this);
    _la = _input->LA(1);
    while (_la == CgaParser::PIPE) {
      setState(298);
      match(CgaParser::PIPE);
      setState(299);
      splitPart();
      setState(304);
      _errHandler->sync(this);
      _la = _input->LA(1);
    }
    setState(305);
    match(CgaParser::RBRACE);
    setState(307);
    _errHandler->sync(this);

    _la = _input->LA(1);
    if (_la == CgaParser::STAR) {
      setState(306);
      dynamic_cast<SplitBodyContext *>(_localctx)->repeat = match(CgaParser::STAR);
    }
   
  }
  catch (RecognitionException &e) {
    _errHandler->reportError(this, e);
    _localctx->exception = std::current_exception();
    _errHandler->recover(this, _localctx->exception);
  }

  return _localctx;
}

//----------------- SplitPartContext ------------------------------------------------------------------

CgaParser::SplitPartContext::SplitPartContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}


size_t CgaParser::SplitPartContext::getRuleIndex() const {
  return CgaParser::RuleSplitPart;
}

void CgaParser::SplitPartContext::copyFrom(SplitPartContext *ctx) {
  ParserRuleContext::copyFrom(ctx);
}

//----------------- NestedPartContext ------------------------------------------------------------------

CgaParser::SplitBodyContext* CgaParser::NestedPartContext::splitBody() {
  return getRuleContext<CgaParser::SplitBodyContext>(0);
}

CgaParser::NestedPartContext::NestedPartContext(SplitPartContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::NestedPartContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitNestedPart(this);
  else
    return visitor->visitChildren(this);
}
//----------------- SizedPartContext ------------------------------------------------------------------

CgaParser::ExprContext* CgaParser::SizedPartContext::expr() {
  return getRuleContext<CgaParser::ExprContext>(0);
}

tree::TerminalNode* CgaParser::SizedPartContext::COLON() {
  return getToken(CgaParser::COLON, 0);
}

tree::TerminalNode* CgaParser::SizedPartContext::ASSIGN() {
  return getToken(CgaParser::ASSIGN, 0);
}

std::vector<CgaParser::OperationContext *> CgaParser::SizedPartContext::operation() {
  return getRuleContexts<CgaParser::OperationContext>();
}

CgaParser::OperationContext* CgaParser::SizedPartContext::operation(size_t i) {
  return getRuleContext<CgaParser::OperationContext>(i);
}

CgaParser::SizedPartContext::SizedPartContext(SplitPartContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::SizedPartContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitSizedPart(this);
  else
    return visitor->visitChildren(this);
}
CgaParser::SplitPartContext* CgaParser::splitPart() {
  SplitPartContext *_localctx = _tracker.createInstance<SplitPartContext>(_ctx, getState());
  enterRule(_localctx, 40, CgaParser::RuleSplitPart);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(318);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case CgaParser::TRUE:
      case CgaParser::FALSE:
      case CgaParser::PLUS:
      case CgaParser::MINUS:
      case CgaParser::BANG:
      case CgaParser::QUOTE:
      case CgaParser::TILDE:
      case CgaParser::LPAREN:
      case CgaParser::LBRACK:
      case CgaParser::FLOAT:
      case CgaParser::INT:
      case CgaParser::QID:
      case CgaParser::ID:
      case CgaParser::STRING: {
        _localctx = dynamic_cast<SplitPartContext *>(_tracker.createInstance<CgaParser::SizedPartContext>(_localctx));
        enterOuterAlt(_localctx, 1);
        setState(309);
        dynamic_cast<SizedPartContext *>(_localctx)->key = expr(0);
        setState(310);
        dynamic_cast<SizedPartContext *>(_localctx)->sep = _input->LT(1);
        _la = _input->LA(1);
        if (!(_la == CgaParser::ASSIGN

        || _la == CgaParser::COLON)) {
          dynamic_cast<SizedPartContext *>(_localctx)->sep = _errHandler->recoverInline(this);
        }
        else {
          _errHandler->reportMatch(this);
          consume();
        }
        setState(314);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while ((((_la & ~ 0x3fULL) == 0) &&
          ((1ULL << _la) & ((1ULL << CgaParser::NIL)
          | (1ULL << CgaParser::DOT)
          | (1ULL << CgaParser::LBRACK)
          | (1ULL << CgaParser::QID)
          | (1ULL << CgaParser::LEAF)
          | (1ULL << CgaParser::ID))) != 0)) {
          setState(311);
          operation();
          setState(316);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
        break;
      }

      case CgaParser::LBRACE: {
        _localctx = dynamic_cast<SplitPartContext *>(_tracker.createInstance<CgaParser::NestedPartContext>(_localctx));
        enterOuterAlt(_localctx, 2);
        setState(317);
        splitBody();
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

CgaParser::ExprContext::ExprContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}


size_t CgaParser::ExprContext::getRuleIndex() const {
  return CgaParser::RuleExpr;
}

void CgaParser::ExprContext::copyFrom(ExprContext *ctx) {
  ParserRuleContext::copyFrom(ctx);
}

//----------------- UnaryExprContext ------------------------------------------------------------------

CgaParser::ExprContext* CgaParser::UnaryExprContext::expr() {
  return getRuleContext<CgaParser::ExprContext>(0);
}

tree::TerminalNode* CgaParser::UnaryExprContext::MINUS() {
  return getToken(CgaParser::MINUS, 0);
}

tree::TerminalNode* CgaParser::UnaryExprContext::BANG() {
  return getToken(CgaParser::BANG, 0);
}

tree::TerminalNode* CgaParser::UnaryExprContext::PLUS() {
  return getToken(CgaParser::PLUS, 0);
}

CgaParser::UnaryExprContext::UnaryExprContext(ExprContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::UnaryExprContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitUnaryExpr(this);
  else
    return visitor->visitChildren(this);
}
//----------------- PrimaryExprContext ------------------------------------------------------------------

CgaParser::PrimaryContext* CgaParser::PrimaryExprContext::primary() {
  return getRuleContext<CgaParser::PrimaryContext>(0);
}

CgaParser::PrimaryExprContext::PrimaryExprContext(ExprContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::PrimaryExprContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitPrimaryExpr(this);
  else
    return visitor->visitChildren(this);
}
//----------------- BinaryExprContext ------------------------------------------------------------------

std::vector<CgaParser::ExprContext *> CgaParser::BinaryExprContext::expr() {
  return getRuleContexts<CgaParser::ExprContext>();
}

CgaParser::ExprContext* CgaParser::BinaryExprContext::expr(size_t i) {
  return getRuleContext<CgaParser::ExprContext>(i);
}

tree::TerminalNode* CgaParser::BinaryExprContext::STAR() {
  return getToken(CgaParser::STAR, 0);
}

tree::TerminalNode* CgaParser::BinaryExprContext::SLASH() {
  return getToken(CgaParser::SLASH, 0);
}

tree::TerminalNode* CgaParser::BinaryExprContext::PERCENT() {
  return getToken(CgaParser::PERCENT, 0);
}

tree::TerminalNode* CgaParser::BinaryExprContext::PLUS() {
  return getToken(CgaParser::PLUS, 0);
}

tree::TerminalNode* CgaParser::BinaryExprContext::MINUS() {
  return getToken(CgaParser::MINUS, 0);
}

tree::TerminalNode* CgaParser::BinaryExprContext::LT() {
  return getToken(CgaParser::LT, 0);
}

tree::TerminalNode* CgaParser::BinaryExprContext::LE() {
  return getToken(CgaParser::LE, 0);
}

tree::TerminalNode* CgaParser::BinaryExprContext::GT() {
  return getToken(CgaParser::GT, 0);
}

tree::TerminalNode* CgaParser::BinaryExprContext::GE() {
  return getToken(CgaParser::GE, 0);
}

tree::TerminalNode* CgaParser::BinaryExprContext::EQ() {
  return getToken(CgaParser::EQ, 0);
}

tree::TerminalNode* CgaParser::BinaryExprContext::NEQ() {
  return getToken(CgaParser::NEQ, 0);
}

tree::TerminalNode* CgaParser::BinaryExprContext::AND() {
  return getToken(CgaParser::AND, 0);
}

tree::TerminalNode* CgaParser::BinaryExprContext::OR() {
  return getToken(CgaParser::OR, 0);
}

CgaParser::BinaryExprContext::BinaryExprContext(ExprContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::BinaryExprContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitBinaryExpr(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::ExprContext* CgaParser::expr() {
   return expr(0);
}

CgaParser::ExprContext* CgaParser::expr(int precedence) {
  ParserRuleContext *parentContext = _ctx;
  size_t parentState = getState();
  CgaParser::ExprContext *_localctx = _tracker.createInstance<ExprContext>(_ctx, parentState);
  CgaParser::ExprContext *previousContext = _localctx;
  (void)previousContext; // Silence compiler, in case the context is not used by generated code.
  size_t startState = 42;
  enterRecursionRule(_localctx, 42, CgaParser::RuleExpr, precedence);

    size_t _la = 0;

  auto onExit = finally([=] {
    unrollRecursionContexts(parentContext);
  });
  try {
    size_t alt;
    enterOuterAlt(_localctx, 1);
    setState(324);
    _errHandler->sync(this);
    switch (_input->LA(1)) {
      case CgaParser::TRUE:
      case CgaParser::FALSE:
      case CgaParser::QUOTE:
      case CgaParser::TILDE:
      case CgaParser::LPAREN:
      case CgaParser::LBRACK:
      case CgaParser::FLOAT:
      case CgaParser::INT:
      case CgaParser::QID:
      case CgaParser::ID:
      case CgaParser::STRING: {
        _localctx = _tracker.createInstance<PrimaryExprContext>(_localctx);
        _ctx = _localctx;
        previousContext = _localctx;

        setState(321);
        primary();
        break;
      }

      case CgaParser::PLUS:
      case CgaParser::MINUS:
      case CgaParser::BANG: {
        _localctx = _tracker.createInstance<UnaryExprContext>(_localctx);
        _ctx = _localctx;
        previousContext = _localctx;
        setState(322);
        dynamic_cast<UnaryExprContext *>(_localctx)->op = _input->LT(1);
        _la = _input->LA(1);
        if (!((((_la & ~ 0x3fULL) == 0) &&
          ((1ULL << _la) & ((1ULL << CgaParser::PLUS)
          | (1ULL << CgaParser::MINUS)
          | (1ULL << CgaParser::BANG))) != 0))) {
          dynamic_cast<UnaryExprContext *>(_localctx)->op = _errHandler->recoverInline(this);
        }
        else {
          _errHandler->reportMatch(this);
          consume();
        }
        setState(323);
        expr(7);
        break;
      }

    default:
      throw NoViableAltException(this);
    }
    _ctx->stop = _input->LT(-1);
    setState(346);
    _errHandler->sync(this);
    alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 45, _ctx);
    while (alt != 2 && alt != atn::ATN::INVALID_ALT_NUMBER) {
      if (alt == 1) {
        if (!_parseListeners.empty())
          triggerExitRuleEvent();
        previousContext = _localctx;
        setState(344);
        _errHandler->sync(this);
        switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 44, _ctx)) {
        case 1: {
          auto newContext = _tracker.createInstance<BinaryExprContext>(_tracker.createInstance<ExprContext>(parentContext, parentState));
          _localctx = newContext;
          pushNewRecursionContext(newContext, startState, RuleExpr);
          setState(326);

          if (!(precpred(_ctx, 6))) throw FailedPredicateException(this, "precpred(_ctx, 6)");
          setState(327);
          dynamic_cast<BinaryExprContext *>(_localctx)->op = _input->LT(1);
          _la = _input->LA(1);
          if (!((((_la & ~ 0x3fULL) == 0) &&
            ((1ULL << _la) & ((1ULL << CgaParser::STAR)
            | (1ULL << CgaParser::SLASH)
            | (1ULL << CgaParser::PERCENT))) != 0))) {
            dynamic_cast<BinaryExprContext *>(_localctx)->op = _errHandler->recoverInline(this);
          }
          else {
            _errHandler->reportMatch(this);
            consume();
          }
          setState(328);
          expr(7);
          break;
        }

        case 2: {
          auto newContext = _tracker.createInstance<BinaryExprContext>(_tracker.createInstance<ExprContext>(parentContext, parentState));
          _localctx = newContext;
          pushNewRecursionContext(newContext, startState, RuleExpr);
          setState(329);

          if (!(precpred(_ctx, 5))) throw FailedPredicateException(this, "precpred(_ctx, 5)");
          setState(330);
          dynamic_cast<BinaryExprContext *>(_localctx)->op = _input->LT(1);
          _la = _input->LA(1);
          if (!(_la == CgaParser::PLUS

          || _la == CgaParser::MINUS)) {
            dynamic_cast<BinaryExprContext *>(_localctx)->op = _errHandler->recoverInline(this);
          }
          else {
            _errHandler->reportMatch(this);
            consume();
          }
          setState(331);
          expr(6);
          break;
        }

        case 3: {
          auto newContext = _tracker.createInstance<BinaryExprContext>(_tracker.createInstance<ExprContext>(parentContext, parentState));
          _localctx = newContext;
          pushNewRecursionContext(newContext, startState, RuleExpr);
          setState(332);

          if (!(precpred(_ctx, 4))) throw FailedPredicateException(this, "precpred(_ctx, 4)");
          setState(333);
          dynamic_cast<BinaryExprContext *>(_localctx)->op = _input->LT(1);
          _la = _input->LA(1);
          if (!((((_la & ~ 0x3fULL) == 0) &&
            ((1ULL << _la) & ((1ULL << CgaParser::LE)
            | (1ULL << CgaParser::GE)
            | (1ULL << CgaParser::LT)
            | (1ULL << CgaParser::GT))) != 0))) {
            dynamic_cast<BinaryExprContext *>(_localctx)->op = _errHandler->recoverInline(this);
          }
          else {
            _errHandler->reportMatch(this);
            consume();
          }
          setState(334);
          expr(5);
          break;
        }

        case 4: {
          auto newContext = _tracker.createInstance<BinaryExprContext>(_tracker.createInstance<ExprContext>(parentContext, parentState));
          _localctx = newContext;
          pushNewRecursionContext(newContext, startState, RuleExpr);
          setState(335);

          if (!(precpred(_ctx, 3))) throw FailedPredicateException(this, "precpred(_ctx, 3)");
          setState(336);
          dynamic_cast<BinaryExprContext *>(_localctx)->op = _input->LT(1);
          _la = _input->LA(1);
          if (!(_la == CgaParser::EQ

          || _la == CgaParser::NEQ)) {
            dynamic_cast<BinaryExprContext *>(_localctx)->op = _errHandler->recoverInline(this);
          }
          else {
            _errHandler->reportMatch(this);
            consume();
          }
          setState(337);
          expr(4);
          break;
        }

        case 5: {
          auto newContext = _tracker.createInstance<BinaryExprContext>(_tracker.createInstance<ExprContext>(parentContext, parentState));
          _localctx = newContext;
          pushNewRecursionContext(newContext, startState, RuleExpr);
          setState(338);

          if (!(precpred(_ctx, 2))) throw FailedPredicateException(this, "precpred(_ctx, 2)");
          setState(339);
          dynamic_cast<BinaryExprContext *>(_localctx)->op = match(CgaParser::AND);
          setState(340);
          expr(3);
          break;
        }

        case 6: {
          auto newContext = _tracker.createInstance<BinaryExprContext>(_tracker.createInstance<ExprContext>(parentContext, parentState));
          _localctx = newContext;
          pushNewRecursionContext(newContext, startState, RuleExpr);
          setState(341);

          if (!(precpred(_ctx, 1))) throw FailedPredicateException(this, "precpred(_ctx, 1)");
          setState(342);
          dynamic_cast<BinaryExprContext *>(_localctx)->op = match(CgaParser::OR);
          setState(343);
          expr(2);
          break;
        }

        } 
      }
      setState(348);
      _errHandler->sync(this);
      alt = getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 45, _ctx);
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

CgaParser::PrimaryContext::PrimaryContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}


size_t CgaParser::PrimaryContext::getRuleIndex() const {
  return CgaParser::RulePrimary;
}

void CgaParser::PrimaryContext::copyFrom(PrimaryContext *ctx) {
  ParserRuleContext::copyFrom(ctx);
}

//----------------- RelativePrimaryContext ------------------------------------------------------------------

tree::TerminalNode* CgaParser::RelativePrimaryContext::QUOTE() {
  return getToken(CgaParser::QUOTE, 0);
}

CgaParser::PrimaryContext* CgaParser::RelativePrimaryContext::primary() {
  return getRuleContext<CgaParser::PrimaryContext>(0);
}

CgaParser::RelativePrimaryContext::RelativePrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::RelativePrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitRelativePrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- ParenPrimaryContext ------------------------------------------------------------------

tree::TerminalNode* CgaParser::ParenPrimaryContext::LPAREN() {
  return getToken(CgaParser::LPAREN, 0);
}

CgaParser::ExprContext* CgaParser::ParenPrimaryContext::expr() {
  return getRuleContext<CgaParser::ExprContext>(0);
}

tree::TerminalNode* CgaParser::ParenPrimaryContext::RPAREN() {
  return getToken(CgaParser::RPAREN, 0);
}

CgaParser::ParenPrimaryContext::ParenPrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::ParenPrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitParenPrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- ArrayPrimaryContext ------------------------------------------------------------------

tree::TerminalNode* CgaParser::ArrayPrimaryContext::LBRACK() {
  return getToken(CgaParser::LBRACK, 0);
}

tree::TerminalNode* CgaParser::ArrayPrimaryContext::RBRACK() {
  return getToken(CgaParser::RBRACK, 0);
}

std::vector<CgaParser::ExprContext *> CgaParser::ArrayPrimaryContext::expr() {
  return getRuleContexts<CgaParser::ExprContext>();
}

CgaParser::ExprContext* CgaParser::ArrayPrimaryContext::expr(size_t i) {
  return getRuleContext<CgaParser::ExprContext>(i);
}

std::vector<tree::TerminalNode *> CgaParser::ArrayPrimaryContext::COMMA() {
  return getTokens(CgaParser::COMMA);
}

tree::TerminalNode* CgaParser::ArrayPrimaryContext::COMMA(size_t i) {
  return getToken(CgaParser::COMMA, i);
}

CgaParser::ArrayPrimaryContext::ArrayPrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::ArrayPrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitArrayPrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- StringPrimaryContext ------------------------------------------------------------------

tree::TerminalNode* CgaParser::StringPrimaryContext::STRING() {
  return getToken(CgaParser::STRING, 0);
}

CgaParser::StringPrimaryContext::StringPrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::StringPrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitStringPrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- CallPrimaryContext ------------------------------------------------------------------

tree::TerminalNode* CgaParser::CallPrimaryContext::LPAREN() {
  return getToken(CgaParser::LPAREN, 0);
}

tree::TerminalNode* CgaParser::CallPrimaryContext::RPAREN() {
  return getToken(CgaParser::RPAREN, 0);
}

tree::TerminalNode* CgaParser::CallPrimaryContext::ID() {
  return getToken(CgaParser::ID, 0);
}

tree::TerminalNode* CgaParser::CallPrimaryContext::QID() {
  return getToken(CgaParser::QID, 0);
}

std::vector<CgaParser::ExprContext *> CgaParser::CallPrimaryContext::expr() {
  return getRuleContexts<CgaParser::ExprContext>();
}

CgaParser::ExprContext* CgaParser::CallPrimaryContext::expr(size_t i) {
  return getRuleContext<CgaParser::ExprContext>(i);
}

std::vector<tree::TerminalNode *> CgaParser::CallPrimaryContext::COMMA() {
  return getTokens(CgaParser::COMMA);
}

tree::TerminalNode* CgaParser::CallPrimaryContext::COMMA(size_t i) {
  return getToken(CgaParser::COMMA, i);
}

CgaParser::CallPrimaryContext::CallPrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::CallPrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitCallPrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- BoolPrimaryContext ------------------------------------------------------------------

tree::TerminalNode* CgaParser::BoolPrimaryContext::TRUE() {
  return getToken(CgaParser::TRUE, 0);
}

tree::TerminalNode* CgaParser::BoolPrimaryContext::FALSE() {
  return getToken(CgaParser::FALSE, 0);
}

CgaParser::BoolPrimaryContext::BoolPrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::BoolPrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitBoolPrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- NumberPrimaryContext ------------------------------------------------------------------

CgaParser::NumberContext* CgaParser::NumberPrimaryContext::number() {
  return getRuleContext<CgaParser::NumberContext>(0);
}

CgaParser::NumberPrimaryContext::NumberPrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::NumberPrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitNumberPrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- NamePrimaryContext ------------------------------------------------------------------

tree::TerminalNode* CgaParser::NamePrimaryContext::ID() {
  return getToken(CgaParser::ID, 0);
}

tree::TerminalNode* CgaParser::NamePrimaryContext::QID() {
  return getToken(CgaParser::QID, 0);
}

CgaParser::NamePrimaryContext::NamePrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::NamePrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitNamePrimary(this);
  else
    return visitor->visitChildren(this);
}
//----------------- FloatingPrimaryContext ------------------------------------------------------------------

tree::TerminalNode* CgaParser::FloatingPrimaryContext::TILDE() {
  return getToken(CgaParser::TILDE, 0);
}

CgaParser::PrimaryContext* CgaParser::FloatingPrimaryContext::primary() {
  return getRuleContext<CgaParser::PrimaryContext>(0);
}

CgaParser::FloatingPrimaryContext::FloatingPrimaryContext(PrimaryContext *ctx) { copyFrom(ctx); }

antlrcpp::Any CgaParser::FloatingPrimaryContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitFloatingPrimary(this);
  else
    return visitor->visitChildren(this);
}
CgaParser::PrimaryContext* CgaParser::primary() {
  PrimaryContext *_localctx = _tracker.createInstance<PrimaryContext>(_ctx, getState());
  enterRule(_localctx, 44, CgaParser::RulePrimary);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    setState(386);
    _errHandler->sync(this);
    switch (getInterpreter<atn::ParserATNSimulator>()->adaptivePredict(_input, 50, _ctx)) {
    case 1: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<CgaParser::NumberPrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 1);
      setState(349);
      number();
      break;
    }

    case 2: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<CgaParser::StringPrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 2);
      setState(350);
      match(CgaParser::STRING);
      break;
    }

    case 3: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<CgaParser::BoolPrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 3);
      setState(351);
      dynamic_cast<BoolPrimaryContext *>(_localctx)->flag = _input->LT(1);
      _la = _input->LA(1);
      if (!(_la == CgaParser::TRUE

      || _la == CgaParser::FALSE)) {
        dynamic_cast<BoolPrimaryContext *>(_localctx)->flag = _errHandler->recoverInline(this);
      }
      else {
        _errHandler->reportMatch(this);
        consume();
      }
      break;
    }

    case 4: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<CgaParser::CallPrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 4);
      setState(352);
      dynamic_cast<CallPrimaryContext *>(_localctx)->name = _input->LT(1);
      _la = _input->LA(1);
      if (!(_la == CgaParser::QID

      || _la == CgaParser::ID)) {
        dynamic_cast<CallPrimaryContext *>(_localctx)->name = _errHandler->recoverInline(this);
      }
      else {
        _errHandler->reportMatch(this);
        consume();
      }
      setState(353);
      match(CgaParser::LPAREN);
      setState(362);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if ((((_la & ~ 0x3fULL) == 0) &&
        ((1ULL << _la) & ((1ULL << CgaParser::TRUE)
        | (1ULL << CgaParser::FALSE)
        | (1ULL << CgaParser::PLUS)
        | (1ULL << CgaParser::MINUS)
        | (1ULL << CgaParser::BANG)
        | (1ULL << CgaParser::QUOTE)
        | (1ULL << CgaParser::TILDE)
        | (1ULL << CgaParser::LPAREN)
        | (1ULL << CgaParser::LBRACK)
        | (1ULL << CgaParser::FLOAT)
        | (1ULL << CgaParser::INT)
        | (1ULL << CgaParser::QID)
        | (1ULL << CgaParser::ID)
        | (1ULL << CgaParser::STRING))) != 0)) {
        setState(354);
        expr(0);
        setState(359);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == CgaParser::COMMA) {
          setState(355);
          match(CgaParser::COMMA);
          setState(356);
          expr(0);
          setState(361);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(364);
      match(CgaParser::RPAREN);
      break;
    }

    case 5: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<CgaParser::NamePrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 5);
      setState(365);
      dynamic_cast<NamePrimaryContext *>(_localctx)->name = _input->LT(1);
      _la = _input->LA(1);
      if (!(_la == CgaParser::QID

      || _la == CgaParser::ID)) {
        dynamic_cast<NamePrimaryContext *>(_localctx)->name = _errHandler->recoverInline(this);
      }
      else {
        _errHandler->reportMatch(this);
        consume();
      }
      break;
    }

    case 6: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<CgaParser::ParenPrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 6);
      setState(366);
      match(CgaParser::LPAREN);
      setState(367);
      expr(0);
      setState(368);
      match(CgaParser::RPAREN);
      break;
    }

    case 7: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<CgaParser::ArrayPrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 7);
      setState(370);
      match(CgaParser::LBRACK);
      setState(379);
      _errHandler->sync(this);

      _la = _input->LA(1);
      if ((((_la & ~ 0x3fULL) == 0) &&
        ((1ULL << _la) & ((1ULL << CgaParser::TRUE)
        | (1ULL << CgaParser::FALSE)
        | (1ULL << CgaParser::PLUS)
        | (1ULL << CgaParser::MINUS)
        | (1ULL << CgaParser::BANG)
        | (1ULL << CgaParser::QUOTE)
        | (1ULL << CgaParser::TILDE)
        | (1ULL << CgaParser::LPAREN)
        | (1ULL << CgaParser::LBRACK)
        | (1ULL << CgaParser::FLOAT)
        | (1ULL << CgaParser::INT)
        | (1ULL << CgaParser::QID)
        | (1ULL << CgaParser::ID)
        | (1ULL << CgaParser::STRING))) != 0)) {
        setState(371);
        expr(0);
        setState(376);
        _errHandler->sync(this);
        _la = _input->LA(1);
        while (_la == CgaParser::COMMA) {
          setState(372);
          match(CgaParser::COMMA);
          setState(373);
          expr(0);
          setState(378);
          _errHandler->sync(this);
          _la = _input->LA(1);
        }
      }
      setState(381);
      match(CgaParser::RBRACK);
      break;
    }

    case 8: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<CgaParser::RelativePrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 8);
      setState(382);
      match(CgaParser::QUOTE);
      setState(383);
      primary();
      break;
    }

    case 9: {
      _localctx = dynamic_cast<PrimaryContext *>(_tracker.createInstance<CgaParser::FloatingPrimaryContext>(_localctx));
      enterOuterAlt(_localctx, 9);
      setState(384);
      match(CgaParser::TILDE);
      setState(385);
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

CgaParser::NumberContext::NumberContext(ParserRuleContext *parent, size_t invokingState)
  : ParserRuleContext(parent, invokingState) {
}

tree::TerminalNode* CgaParser::NumberContext::INT() {
  return getToken(CgaParser::INT, 0);
}

tree::TerminalNode* CgaParser::NumberContext::FLOAT() {
  return getToken(CgaParser::FLOAT, 0);
}


size_t CgaParser::NumberContext::getRuleIndex() const {
  return CgaParser::RuleNumber;
}

antlrcpp::Any CgaParser::NumberContext::accept(tree::ParseTreeVisitor *visitor) {
  if (auto parserVisitor = dynamic_cast<CgaVisitor*>(visitor))
    return parserVisitor->visitNumber(this);
  else
    return visitor->visitChildren(this);
}

CgaParser::NumberContext* CgaParser::number() {
  NumberContext *_localctx = _tracker.createInstance<NumberContext>(_ctx, getState());
  enterRule(_localctx, 46, CgaParser::RuleNumber);
  size_t _la = 0;

  auto onExit = finally([=] {
    exitRule();
  });
  try {
    enterOuterAlt(_localctx, 1);
    setState(388);
    _la = _input->LA(1);
    if (!(_la == CgaParser::FLOAT

    || _la == CgaParser::INT)) {
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

bool CgaParser::sempred(RuleContext *context, size_t ruleIndex, size_t predicateIndex) {
  switch (ruleIndex) {
    case 21: return exprSempred(dynamic_cast<ExprContext *>(context), predicateIndex);

  default:
    break;
  }
  return true;
}

bool CgaParser::exprSempred(ExprContext *_localctx, size_t predicateIndex) {
  switch (predicateIndex) {
    case 0: return precpred(_ctx, 6);
    case 1: return precpred(_ctx, 5);
    case 2: return precpred(_ctx, 4);
    case 3: return precpred(_ctx, 3);
    case 4: return precpred(_ctx, 2);
    case 5: return precpred(_ctx, 1);

  default:
    break;
  }
  return true;
}

// Static vars and initialization.
std::vector<dfa::DFA> CgaParser::_decisionToDFA;
atn::PredictionContextCache CgaParser::_sharedContextCache;

// We own the ATN which in turn owns the ATN states.
atn::ATN CgaParser::_atn;
std::vector<uint16_t> CgaParser::_serializedATN;

std::vector<std::string> CgaParser::_ruleNames = {
  "cgaFile", "declaration", "versionDecl", "dialectDecl", "importDecl", 
  "importArg", "styleDecl", "annotated", "annotation", "annotationArg", 
  "attrDecl", "constDecl", "functionDecl", "ruleDecl", "params", "value", 
  "ruleBody", "operation", "operationBlock", "splitBody", "splitPart", "expr", 
  "primary", "number"
};

std::vector<std::string> CgaParser::_literalNames = {
  "", "'version'", "'dialect'", "'import'", "'style'", "'extends'", "'attr'", 
  "'const'", "'case'", "'else'", "'NIL'", "'true'", "'false'", "'-->'", 
  "'@'", "'=='", "'!='", "'<='", "'>='", "'<'", "'>'", "'&&'", "'||'", "'='", 
  "'+'", "'-'", "'*'", "'/'", "'%'", "'!'", "'|'", "'''", "'~'", "':'", 
  "';'", "','", "'.'", "'('", "')'", "'['", "']'", "'{'", "'}'"
};

std::vector<std::string> CgaParser::_symbolicNames = {
  "", "VERSION", "DIALECT", "IMPORT", "STYLE", "EXTENDS", "ATTR", "CONST", 
  "CASE", "ELSE", "NIL", "TRUE", "FALSE", "ARROW", "AT", "EQ", "NEQ", "LE", 
  "GE", "LT", "GT", "AND", "OR", "ASSIGN", "PLUS", "MINUS", "STAR", "SLASH", 
  "PERCENT", "BANG", "PIPE", "QUOTE", "TILDE", "COLON", "SEMI", "COMMA", 
  "DOT", "LPAREN", "RPAREN", "LBRACK", "RBRACK", "LBRACE", "RBRACE", "PERCENT_LIT", 
  "FLOAT", "INT", "QID", "LEAF", "ID", "STRING", "UNTERMINATED_STRING", 
  "LINE_COMMENT", "HASH_COMMENT", "BLOCK_COMMENT", "UNTERMINATED_COMMENT", 
  "WS", "UNKNOWN_CHAR"
};

dfa::Vocabulary CgaParser::_vocabulary(_literalNames, _symbolicNames);

std::vector<std::string> CgaParser::_tokenNames;

CgaParser::Initializer::Initializer() {
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
    0x3a, 0x189, 0x4, 0x2, 0x9, 0x2, 0x4, 0x3, 0x9, 0x3, 0x4, 0x4, 0x9, 0x4, 
    0x4, 0x5, 0x9, 0x5, 0x4, 0x6, 0x9, 0x6, 0x4, 0x7, 0x9, 0x7, 0x4, 0x8, 
    0x9, 0x8, 0x4, 0x9, 0x9, 0x9, 0x4, 0xa, 0x9, 0xa, 0x4, 0xb, 0x9, 0xb, 
    0x4, 0xc, 0x9, 0xc, 0x4, 0xd, 0x9, 0xd, 0x4, 0xe, 0x9, 0xe, 0x4, 0xf, 
    0x9, 0xf, 0x4, 0x10, 0x9, 0x10, 0x4, 0x11, 0x9, 0x11, 0x4, 0x12, 0x9, 
    0x12, 0x4, 0x13, 0x9, 0x13, 0x4, 0x14, 0x9, 0x14, 0x4, 0x15, 0x9, 0x15, 
    0x4, 0x16, 0x9, 0x16, 0x4, 0x17, 0x9, 0x17, 0x4, 0x18, 0x9, 0x18, 0x4, 
    0x19, 0x9, 0x19, 0x3, 0x2, 0x7, 0x2, 0x34, 0xa, 0x2, 0xc, 0x2, 0xe, 0x2, 
    0x37, 0xb, 0x2, 0x3, 0x2, 0x3, 0x2, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 0x3, 
    0x3, 0x3, 0x3, 0x5, 0x3, 0x40, 0xa, 0x3, 0x3, 0x4, 0x3, 0x4, 0x3, 0x4, 
    0x3, 0x5, 0x3, 0x5, 0x3, 0x5, 0x5, 0x5, 0x48, 0xa, 0x5, 0x3, 0x6, 0x3, 
    0x6, 0x3, 0x6, 0x3, 0x6, 0x3, 0x6, 0x3, 0x6, 0x7, 0x6, 0x50, 0xa, 0x6, 
    0xc, 0x6, 0xe, 0x6, 0x53, 0xb, 0x6, 0x3, 0x6, 0x5, 0x6, 0x56, 0xa, 0x6, 
    0x3, 0x6, 0x5, 0x6, 0x59, 0xa, 0x6, 0x3, 0x6, 0x3, 0x6, 0x3, 0x6, 0x3, 
    0x6, 0x3, 0x6, 0x7, 0x6, 0x60, 0xa, 0x6, 0xc, 0x6, 0xe, 0x6, 0x63, 0xb, 
    0x6, 0x5, 0x6, 0x65, 0xa, 0x6, 0x3, 0x6, 0x5, 0x6, 0x68, 0xa, 0x6, 0x3, 
    0x7, 0x3, 0x7, 0x5, 0x7, 0x6c, 0xa, 0x7, 0x3, 0x7, 0x3, 0x7, 0x3, 0x8, 
    0x3, 0x8, 0x3, 0x8, 0x3, 0x8, 0x5, 0x8, 0x74, 0xa, 0x8, 0x3, 0x9, 0x7, 
    0x9, 0x77, 0xa, 0x9, 0xc, 0x9, 0xe, 0x9, 0x7a, 0xb, 0x9, 0x3, 0x9, 0x3, 
    0x9, 0x3, 0x9, 0x3, 0x9, 0x5, 0x9, 0x80, 0xa, 0x9, 0x3, 0xa, 0x3, 0xa, 
    0x3, 0xa, 0x3, 0xa, 0x3, 0xa, 0x3, 0xa, 0x7, 0xa, 0x88, 0xa, 0xa, 0xc, 
    0xa, 0xe, 0xa, 0x8b, 0xb, 0xa, 0x5, 0xa, 0x8d, 0xa, 0xa, 0x3, 0xa, 0x5, 
    0xa, 0x90, 0xa, 0xa, 0x3, 0xb, 0x3, 0xb, 0x5, 0xb, 0x94, 0xa, 0xb, 0x3, 
    0xb, 0x3, 0xb, 0x3, 0xc, 0x3, 0xc, 0x3, 0xc, 0x3, 0xc, 0x3, 0xc, 0x3, 
    0xd, 0x3, 0xd, 0x3, 0xd, 0x3, 0xd, 0x5, 0xd, 0xa1, 0xa, 0xd, 0x3, 0xd, 
    0x5, 0xd, 0xa4, 0xa, 0xd, 0x3, 0xd, 0x3, 0xd, 0x3, 0xd, 0x3, 0xe, 0x3, 
    0xe, 0x3, 0xe, 0x5, 0xe, 0xac, 0xa, 0xe, 0x3, 0xe, 0x5, 0xe, 0xaf, 0xa, 
    0xe, 0x3, 0xe, 0x3, 0xe, 0x3, 0xe, 0x3, 0xf, 0x3, 0xf, 0x3, 0xf, 0x5, 
    0xf, 0xb7, 0xa, 0xf, 0x3, 0xf, 0x5, 0xf, 0xba, 0xa, 0xf, 0x3, 0xf, 0x3, 
    0xf, 0x3, 0xf, 0x3, 0x10, 0x3, 0x10, 0x3, 0x10, 0x7, 0x10, 0xc2, 0xa, 
    0x10, 0xc, 0x10, 0xe, 0x10, 0xc5, 0xb, 0x10, 0x3, 0x11, 0x3, 0x11, 0x3, 
    0x11, 0x3, 0x11, 0x3, 0x11, 0x6, 0x11, 0xcc, 0xa, 0x11, 0xd, 0x11, 0xe, 
    0x11, 0xcd, 0x3, 0x11, 0x3, 0x11, 0x3, 0x11, 0x3, 0x11, 0x3, 0x11, 0x3, 
    0x11, 0x3, 0x11, 0x6, 0x11, 0xd7, 0xa, 0x11, 0xd, 0x11, 0xe, 0x11, 0xd8, 
    0x3, 0x11, 0x3, 0x11, 0x3, 0x11, 0x5, 0x11, 0xde, 0xa, 0x11, 0x3, 0x11, 
    0x5, 0x11, 0xe1, 0xa, 0x11, 0x3, 0x12, 0x3, 0x12, 0x3, 0x12, 0x3, 0x12, 
    0x3, 0x12, 0x6, 0x12, 0xe8, 0xa, 0x12, 0xd, 0x12, 0xe, 0x12, 0xe9, 0x3, 
    0x12, 0x3, 0x12, 0x3, 0x12, 0x3, 0x12, 0x3, 0x12, 0x3, 0x12, 0x3, 0x12, 
    0x6, 0x12, 0xf3, 0xa, 0x12, 0xd, 0x12, 0xe, 0x12, 0xf4, 0x3, 0x12, 0x3, 
    0x12, 0x3, 0x12, 0x5, 0x12, 0xfa, 0xa, 0x12, 0x3, 0x12, 0x6, 0x12, 0xfd, 
    0xa, 0x12, 0xd, 0x12, 0xe, 0x12, 0xfe, 0x5, 0x12, 0x101, 0xa, 0x12, 0x3, 
    0x13, 0x3, 0x13, 0x3, 0x13, 0x3, 0x13, 0x3, 0x13, 0x3, 0x13, 0x7, 0x13, 
    0x109, 0xa, 0x13, 0xc, 0x13, 0xe, 0x13, 0x10c, 0xb, 0x13, 0x5, 0x13, 
    0x10e, 0xa, 0x13, 0x3, 0x13, 0x3, 0x13, 0x3, 0x13, 0x5, 0x13, 0x113, 0xa, 
    0x13, 0x3, 0x13, 0x3, 0x13, 0x3, 0x13, 0x3, 0x13, 0x3, 0x13, 0x7, 0x13, 
    0x11a, 0xa, 0x13, 0xc, 0x13, 0xe, 0x13, 0x11d, 0xb, 0x13, 0x3, 0x13, 0x5, 
    0x13, 0x120, 0xa, 0x13, 0x3, 0x14, 0x3, 0x14, 0x7, 0x14, 0x124, 0xa, 
    0x14, 0xc, 0x14, 0xe, 0x14, 0x127, 0xb, 0x14, 0x3, 0x14, 0x3, 0x14, 0x3, 
    0x15, 0x3, 0x15, 0x3, 0x15, 0x3, 0x15, 0x7, 0x15, 0x12f, 0xa, 0x15, 0xc, 
    0x15, 0xe, 0x15, 0x132, 0xb, 0x15, 0x3, 0x15, 0x3, 0x15, 0x5, 0x15, 
    0x136, 0xa, 0x15, 0x3, 0x16, 0x3, 0x16, 0x3, 0x16, 0x7, 0x16, 0x13b, 0xa, 
    0x16, 0xc, 0x16, 0xe, 0x16, 0x13e, 0xb, 0x16, 0x3, 0x16, 0x5, 0x16, 
    0x141, 0xa, 0x16, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 0x5, 0x17, 
    0x147, 0xa, 0x17, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 
    0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 0x3, 
    0x17, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 0x3, 0x17, 
    0x7, 0x17, 0x15b, 0xa, 0x17, 0xc, 0x17, 0xe, 0x17, 0x15e, 0xb, 0x17, 0x3, 
    0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 
    0x3, 0x18, 0x7, 0x18, 0x168, 0xa, 0x18, 0xc, 0x18, 0xe, 0x18, 0x16b, 0xb, 
    0x18, 0x5, 0x18, 0x16d, 0xa, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 
    0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 
    0x7, 0x18, 0x179, 0xa, 0x18, 0xc, 0x18, 0xe, 0x18, 0x17c, 0xb, 0x18, 0x5, 
    0x18, 0x17e, 0xa, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 0x18, 0x3, 
    0x18, 0x5, 0x18, 0x185, 0xa, 0x18, 0x3, 0x19, 0x3, 0x19, 0x3, 0x19, 0x2, 
    0x3, 0x2c, 0x1a, 0x2, 0x4, 0x6, 0x8, 0xa, 0xc, 0xe, 0x10, 0x12, 0x14, 
    0x16, 0x18, 0x1a, 0x1c, 0x1e, 0x20, 0x22, 0x24, 0x26, 0x28, 0x2a, 0x2c, 
    0x2e, 0x30, 0x2, 0xb, 0x4, 0x2, 0x32, 0x32, 0x30, 0x30, 0x4, 0x2, 0x23, 
    0x23, 0x19, 0x19, 0x4, 0x2, 0x1f, 0x1f, 0x1a, 0x1b, 0x3, 0x2, 0x1c, 0x1e, 
    0x3, 0x2, 0x1a, 0x1b, 0x3, 0x2, 0x13, 0x16, 0x3, 0x2, 0x11, 0x12, 0x3, 
    0x2, 0xd, 0xe, 0x3, 0x2, 0x2e, 0x2f, 0x2, 0x1ba, 0x2, 0x35, 0x3, 0x2, 
    0x2, 0x2, 0x4, 0x3f, 0x3, 0x2, 0x2, 0x2, 0x6, 0x41, 0x3, 0x2, 0x2, 0x2, 
    0x8, 0x44, 0x3, 0x2, 0x2, 0x2, 0xa, 0x49, 0x3, 0x2, 0x2, 0x2, 0xc, 0x6b, 
    0x3, 0x2, 0x2, 0x2, 0xe, 0x6f, 0x3, 0x2, 0x2, 0x2, 0x10, 0x78, 0x3, 0x2, 
    0x2, 0x2, 0x12, 0x81, 0x3, 0x2, 0x2, 0x2, 0x14, 0x93, 0x3, 0x2, 0x2, 0x2, 
    0x16, 0x97, 0x3, 0x2, 0x2, 0x2, 0x18, 0x9c, 0x3, 0x2, 0x2, 0x2, 0x1a, 
    0xa8, 0x3, 0x2, 0x2, 0x2, 0x1c, 0xb3, 0x3, 0x2, 0x2, 0x2, 0x1e, 0xbe, 
    0x3, 0x2, 0x2, 0x2, 0x20, 0xe0, 0x3, 0x2, 0x2, 0x2, 0x22, 0x100, 0x3, 
    0x2, 0x2, 0x2, 0x24, 0x11f, 0x3, 0x2, 0x2, 0x2, 0x26, 0x121, 0x3, 0x2, 
    0x2, 0x2, 0x28, 0x12a, 0x3, 0x2, 0x2, 0x2, 0x2a, 0x140, 0x3, 0x2, 0x2, 
    0x2, 0x2c, 0x146, 0x3, 0x2, 0x2, 0x2, 0x2e, 0x184, 0x3, 0x2, 0x2, 0x2, 
    0x30, 0x186, 0x3, 0x2, 0x2, 0x2, 0x32, 0x34, 0x5, 0x4, 0x3, 0x2, 0x33, 
    0x32, 0x3, 0x2, 0x2, 0x2, 0x34, 0x37, 0x3, 0x2, 0x2, 0x2, 0x35, 0x33, 
    0x3, 0x2, 0x2, 0x2, 0x35, 0x36, 0x3, 0x2, 0x2, 0x2, 0x36, 0x38, 0x3, 0x2, 
    0x2, 0x2, 0x37, 0x35, 0x3, 0x2, 0x2, 0x2, 0x38, 0x39, 0x7, 0x2, 0x2, 0x3, 
    0x39, 0x3, 0x3, 0x2, 0x2, 0x2, 0x3a, 0x40, 0x5, 0x6, 0x4, 0x2, 0x3b, 
    0x40, 0x5, 0x8, 0x5, 0x2, 0x3c, 0x40, 0x5, 0xa, 0x6, 0x2, 0x3d, 0x40, 
    0x5, 0xe, 0x8, 0x2, 0x3e, 0x40, 0x5, 0x10, 0x9, 0x2, 0x3f, 0x3a, 0x3, 
    0x2, 0x2, 0x2, 0x3f, 0x3b, 0x3, 0x2, 0x2, 0x2, 0x3f, 0x3c, 0x3, 0x2, 0x2, 
    0x2, 0x3f, 0x3d, 0x3, 0x2, 0x2, 0x2, 0x3f, 0x3e, 0x3, 0x2, 0x2, 0x2, 
    0x40, 0x5, 0x3, 0x2, 0x2, 0x2, 0x41, 0x42, 0x7, 0x3, 0x2, 0x2, 0x42, 
    0x43, 0x7, 0x33, 0x2, 0x2, 0x43, 0x7, 0x3, 0x2, 0x2, 0x2, 0x44, 0x45, 
    0x7, 0x4, 0x2, 0x2, 0x45, 0x47, 0x7, 0x32, 0x2, 0x2, 0x46, 0x48, 0x7, 
    0x24, 0x2, 0x2, 0x47, 0x46, 0x3, 0x2, 0x2, 0x2, 0x47, 0x48, 0x3, 0x2, 
    0x2, 0x2, 0x48, 0x9, 0x3, 0x2, 0x2, 0x2, 0x49, 0x58, 0x7, 0x5, 0x2, 0x2, 
    0x4a, 0x55, 0x7, 0x32, 0x2, 0x2, 0x4b, 0x4c, 0x7, 0x27, 0x2, 0x2, 0x4c, 
    0x51, 0x7, 0x32, 0x2, 0x2, 0x4d, 0x4e, 0x7, 0x25, 0x2, 0x2, 0x4e, 0x50, 
    0x7, 0x32, 0x2, 0x2, 0x4f, 0x4d, 0x3, 0x2, 0x2, 0x2, 0x50, 0x53, 0x3, 
    0x2, 0x2, 0x2, 0x51, 0x4f, 0x3, 0x2, 0x2, 0x2, 0x51, 0x52, 0x3, 0x2, 0x2, 
    0x2, 0x52, 0x54, 0x3, 0x2, 0x2, 0x2, 0x53, 0x51, 0x3, 0x2, 0x2, 0x2, 
    0x54, 0x56, 0x7, 0x28, 0x2, 0x2, 0x55, 0x4b, 0x3, 0x2, 0x2, 0x2, 0x55, 
    0x56, 0x3, 0x2, 0x2, 0x2, 0x56, 0x57, 0x3, 0x2, 0x2, 0x2, 0x57, 0x59, 
    0x7, 0x23, 0x2, 0x2, 0x58, 0x4a, 0x3, 0x2, 0x2, 0x2, 0x58, 0x59, 0x3, 
    0x2, 0x2, 0x2, 0x59, 0x5a, 0x3, 0x2, 0x2, 0x2, 0x5a, 0x67, 0x7, 0x33, 
    0x2, 0x2, 0x5b, 0x64, 0x7, 0x27, 0x2, 0x2, 0x5c, 0x61, 0x5, 0xc, 0x7, 
    0x2, 0x5d, 0x5e, 0x7, 0x25, 0x2, 0x2, 0x5e, 0x60, 0x5, 0xc, 0x7, 0x2, 
    0x5f, 0x5d, 0x3, 0x2, 0x2, 0x2, 0x60, 0x63, 0x3, 0x2, 0x2, 0x2, 0x61, 
    0x5f, 0x3, 0x2, 0x2, 0x2, 0x61, 0x62, 0x3, 0x2, 0x2, 0x2, 0x62, 0x65, 
    0x3, 0x2, 0x2, 0x2, 0x63, 0x61, 0x3, 0x2, 0x2, 0x2, 0x64, 0x5c, 0x3, 0x2, 
    0x2, 0x2, 0x64, 0x65, 0x3, 0x2, 0x2, 0x2, 0x65, 0x66, 0x3, 0x2, 0x2, 0x2, 
    0x66, 0x68, 0x7, 0x28, 0x2, 0x2, 0x67, 0x5b, 0x3, 0x2, 0x2, 0x2, 0x67, 
    0x68, 0x3, 0x2, 0x2, 0x2, 0x68, 0xb, 0x3, 0x2, 0x2, 0x2, 0x69, 0x6a, 0x7, 
    0x32, 0x2, 0x2, 0x6a, 0x6c, 0x7, 0x19, 0x2, 0x2, 0x6b, 0x69, 0x3, 0x2, 
    0x2, 0x2, 0x6b, 0x6c, 0x3, 0x2, 0x2, 0x2, 0x6c, 0x6d, 0x3, 0x2, 0x2, 0x2, 
    0x6d, 0x6e, 0x5, 0x2c, 0x17, 0x2, 0x6e, 0xd, 0x3, 0x2, 0x2, 0x2, 0x6f, 
    0x70, 0x7, 0x6, 0x2, 0x2, 0x70, 0x73, 0x7, 0x32, 0x2, 0x2, 0x71, 0x72, 
    0x7, 0x7, 0x2, 0x2, 0x72, 0x74, 0x7, 0x32, 0x2, 0x2, 0x73, 0x71, 0x3, 
    0x2, 0x2, 0x2, 0x73, 0x74, 0x3, 0x2, 0x2, 0x2, 0x74, 0xf, 0x3, 0x2, 0x2, 
    0x2, 0x75, 0x77, 0x5, 0x12, 0xa, 0x2, 0x76, 0x75, 0x3, 0x2, 0x2, 0x2, 
    0x77, 0x7a, 0x3, 0x2, 0x2, 0x2, 0x78, 0x76, 0x3, 0x2, 0x2, 0x2, 0x78, 
    0x79, 0x3, 0x2, 0x2, 0x2, 0x79, 0x7f, 0x3, 0x2, 0x2, 0x2, 0x7a, 0x78, 
    0x3, 0x2, 0x2, 0x2, 0x7b, 0x80, 0x5, 0x16, 0xc, 0x2, 0x7c, 0x80, 0x5, 
    0x18, 0xd, 0x2, 0x7d, 0x80, 0x5, 0x1a, 0xe, 0x2, 0x7e, 0x80, 0x5, 0x1c, 
    0xf, 0x2, 0x7f, 0x7b, 0x3, 0x2, 0x2, 0x2, 0x7f, 0x7c, 0x3, 0x2, 0x2, 0x2, 
    0x7f, 0x7d, 0x3, 0x2, 0x2, 0x2, 0x7f, 0x7e, 0x3, 0x2, 0x2, 0x2, 0x80, 
    0x11, 0x3, 0x2, 0x2, 0x2, 0x81, 0x82, 0x7, 0x10, 0x2, 0x2, 0x82, 0x8f, 
    0x7, 0x32, 0x2, 0x2, 0x83, 0x8c, 0x7, 0x27, 0x2, 0x2, 0x84, 0x89, 0x5, 
    0x14, 0xb, 0x2, 0x85, 0x86, 0x7, 0x25, 0x2, 0x2, 0x86, 0x88, 0x5, 0x14, 
    0xb, 0x2, 0x87, 0x85, 0x3, 0x2, 0x2, 0x2, 0x88, 0x8b, 0x3, 0x2, 0x2, 0x2, 
    0x89, 0x87, 0x3, 0x2, 0x2, 0x2, 0x89, 0x8a, 0x3, 0x2, 0x2, 0x2, 0x8a, 
    0x8d, 0x3, 0x2, 0x2, 0x2, 0x8b, 0x89, 0x3, 0x2, 0x2, 0x2, 0x8c, 0x84, 
    0x3, 0x2, 0x2, 0x2, 0x8c, 0x8d, 0x3, 0x2, 0x2, 0x2, 0x8d, 0x8e, 0x3, 0x2, 
    0x2, 0x2, 0x8e, 0x90, 0x7, 0x28, 0x2, 0x2, 0x8f, 0x83, 0x3, 0x2, 0x2, 
    0x2, 0x8f, 0x90, 0x3, 0x2, 0x2, 0x2, 0x90, 0x13, 0x3, 0x2, 0x2, 0x2, 
    0x91, 0x92, 0x7, 0x32, 0x2, 0x2, 0x92, 0x94, 0x7, 0x19, 0x2, 0x2, 0x93, 
    0x91, 0x3, 0x2, 0x2, 0x2, 0x93, 0x94, 0x3, 0x2, 0x2, 0x2, 0x94, 0x95, 
    0x3, 0x2, 0x2, 0x2, 0x95, 0x96, 0x5, 0x2c, 0x17, 0x2, 0x96, 0x15, 0x3, 
    0x2, 0x2, 0x2, 0x97, 0x98, 0x7, 0x8, 0x2, 0x2, 0x98, 0x99, 0x7, 0x32, 
    0x2, 0x2, 0x99, 0x9a, 0x7, 0x19, 0x2, 0x2, 0x9a, 0x9b, 0x5, 0x20, 0x11, 
    0x2, 0x9b, 0x17, 0x3, 0x2, 0x2, 0x2, 0x9c, 0x9d, 0x7, 0x9, 0x2, 0x2, 
    0x9d, 0xa3, 0x7, 0x32, 0x2, 0x2, 0x9e, 0xa0, 0x7, 0x27, 0x2, 0x2, 0x9f, 
    0xa1, 0x5, 0x1e, 0x10, 0x2, 0xa0, 0x9f, 0x3, 0x2, 0x2, 0x2, 0xa0, 0xa1, 
    0x3, 0x2, 0x2, 0x2, 0xa1, 0xa2, 0x3, 0x2, 0x2, 0x2, 0xa2, 0xa4, 0x7, 
    0x28, 0x2, 0x2, 0xa3, 0x9e, 0x3, 0x2, 0x2, 0x2, 0xa3, 0xa4, 0x3, 0x2, 
    0x2, 0x2, 0xa4, 0xa5, 0x3, 0x2, 0x2, 0x2, 0xa5, 0xa6, 0x7, 0x19, 0x2, 
    0x2, 0xa6, 0xa7, 0x5, 0x20, 0x11, 0x2, 0xa7, 0x19, 0x3, 0x2, 0x2, 0x2, 
    0xa8, 0xae, 0x9, 0x2, 0x2, 0x2, 0xa9, 0xab, 0x7, 0x27, 0x2, 0x2, 0xaa, 
    0xac, 0x5, 0x1e, 0x10, 0x2, 0xab, 0xaa, 0x3, 0x2, 0x2, 0x2, 0xab, 0xac, 
    0x3, 0x2, 0x2, 0x2, 0xac, 0xad, 0x3, 0x2, 0x2, 0x2, 0xad, 0xaf, 0x7, 
    0x28, 0x2, 0x2, 0xae, 0xa9, 0x3, 0x2, 0x2, 0x2, 0xae, 0xaf, 0x3, 0x2, 
    0x2, 0x2, 0xaf, 0xb0, 0x3, 0x2, 0x2, 0x2, 0xb0, 0xb1, 0x7, 0x19, 0x2, 
    0x2, 0xb1, 0xb2, 0x5, 0x20, 0x11, 0x2, 0xb2, 0x1b, 0x3, 0x2, 0x2, 0x2, 
    0xb3, 0xb9, 0x7, 0x32, 0x2, 0x2, 0xb4, 0xb6, 0x7, 0x27, 0x2, 0x2, 0xb5, 
    0xb7, 0x5, 0x1e, 0x10, 0x2, 0xb6, 0xb5, 0x3, 0x2, 0x2, 0x2, 0xb6, 0xb7, 
    0x3, 0x2, 0x2, 0x2, 0xb7, 0xb8, 0x3, 0x2, 0x2, 0x2, 0xb8, 0xba, 0x7, 
    0x28, 0x2, 0x2, 0xb9, 0xb4, 0x3, 0x2, 0x2, 0x2, 0xb9, 0xba, 0x3, 0x2, 
    0x2, 0x2, 0xba, 0xbb, 0x3, 0x2, 0x2, 0x2, 0xbb, 0xbc, 0x7, 0xf, 0x2, 0x2, 
    0xbc, 0xbd, 0x5, 0x22, 0x12, 0x2, 0xbd, 0x1d, 0x3, 0x2, 0x2, 0x2, 0xbe, 
    0xc3, 0x7, 0x32, 0x2, 0x2, 0xbf, 0xc0, 0x7, 0x25, 0x2, 0x2, 0xc0, 0xc2, 
    0x7, 0x32, 0x2, 0x2, 0xc1, 0xbf, 0x3, 0x2, 0x2, 0x2, 0xc2, 0xc5, 0x3, 
    0x2, 0x2, 0x2, 0xc3, 0xc1, 0x3, 0x2, 0x2, 0x2, 0xc3, 0xc4, 0x3, 0x2, 0x2, 
    0x2, 0xc4, 0x1f, 0x3, 0x2, 0x2, 0x2, 0xc5, 0xc3, 0x3, 0x2, 0x2, 0x2, 
    0xc6, 0xc7, 0x7, 0xa, 0x2, 0x2, 0xc7, 0xc8, 0x5, 0x2c, 0x17, 0x2, 0xc8, 
    0xc9, 0x7, 0x23, 0x2, 0x2, 0xc9, 0xca, 0x5, 0x20, 0x11, 0x2, 0xca, 0xcc, 
    0x3, 0x2, 0x2, 0x2, 0xcb, 0xc6, 0x3, 0x2, 0x2, 0x2, 0xcc, 0xcd, 0x3, 0x2, 
    0x2, 0x2, 0xcd, 0xcb, 0x3, 0x2, 0x2, 0x2, 0xcd, 0xce, 0x3, 0x2, 0x2, 0x2, 
    0xce, 0xcf, 0x3, 0x2, 0x2, 0x2, 0xcf, 0xd0, 0x7, 0xb, 0x2, 0x2, 0xd0, 
    0xd1, 0x7, 0x23, 0x2, 0x2, 0xd1, 0xd2, 0x5, 0x20, 0x11, 0x2, 0xd2, 0xe1, 
    0x3, 0x2, 0x2, 0x2, 0xd3, 0xd4, 0x7, 0x2d, 0x2, 0x2, 0xd4, 0xd5, 0x7, 
    0x23, 0x2, 0x2, 0xd5, 0xd7, 0x5, 0x20, 0x11, 0x2, 0xd6, 0xd3, 0x3, 0x2, 
    0x2, 0x2, 0xd7, 0xd8, 0x3, 0x2, 0x2, 0x2, 0xd8, 0xd6, 0x3, 0x2, 0x2, 0x2, 
    0xd8, 0xd9, 0x3, 0x2, 0x2, 0x2, 0xd9, 0xdd, 0x3, 0x2, 0x2, 0x2, 0xda, 
    0xdb, 0x7, 0xb, 0x2, 0x2, 0xdb, 0xdc, 0x7, 0x23, 0x2, 0x2, 0xdc, 0xde, 
    0x5, 0x20, 0x11, 0x2, 0xdd, 0xda, 0x3, 0x2, 0x2, 0x2, 0xdd, 0xde, 0x3, 
    0x2, 0x2, 0x2, 0xde, 0xe1, 0x3, 0x2, 0x2, 0x2, 0xdf, 0xe1, 0x5, 0x2c, 
    0x17, 0x2, 0xe0, 0xcb, 0x3, 0x2, 0x2, 0x2, 0xe0, 0xd6, 0x3, 0x2, 0x2, 
    0x2, 0xe0, 0xdf, 0x3, 0x2, 0x2, 0x2, 0xe1, 0x21, 0x3, 0x2, 0x2, 0x2, 
    0xe2, 0xe3, 0x7, 0xa, 0x2, 0x2, 0xe3, 0xe4, 0x5, 0x2c, 0x17, 0x2, 0xe4, 
    0xe5, 0x7, 0x23, 0x2, 0x2, 0xe5, 0xe6, 0x5, 0x22, 0x12, 0x2, 0xe6, 0xe8, 
    0x3, 0x2, 0x2, 0x2, 0xe7, 0xe2, 0x3, 0x2, 0x2, 0x2, 0xe8, 0xe9, 0x3, 0x2, 
    0x2, 0x2, 0xe9, 0xe7, 0x3, 0x2, 0x2, 0x2, 0xe9, 0xea, 0x3, 0x2, 0x2, 0x2, 
    0xea, 0xeb, 0x3, 0x2, 0x2, 0x2, 0xeb, 0xec, 0x7, 0xb, 0x2, 0x2, 0xec, 
    0xed, 0x7, 0x23, 0x2, 0x2, 0xed, 0xee, 0x5, 0x22, 0x12, 0x2, 0xee, 0x101, 
    0x3, 0x2, 0x2, 0x2, 0xef, 0xf0, 0x7, 0x2d, 0x2, 0x2, 0xf0, 0xf1, 0x7, 
    0x23, 0x2, 0x2, 0xf1, 0xf3, 0x5, 0x22, 0x12, 0x2, 0xf2, 0xef, 0x3, 0x2, 
    0x2, 0x2, 0xf3, 0xf4, 0x3, 0x2, 0x2, 0x2, 0xf4, 0xf2, 0x3, 0x2, 0x2, 0x2, 
    0xf4, 0xf5, 0x3, 0x2, 0x2, 0x2, 0xf5, 0xf9, 0x3, 0x2, 0x2, 0x2, 0xf6, 
    0xf7, 0x7, 0xb, 0x2, 0x2, 0xf7, 0xf8, 0x7, 0x23, 0x2, 0x2, 0xf8, 0xfa, 
    0x5, 0x22, 0x12, 0x2, 0xf9, 0xf6, 0x3, 0x2, 0x2, 0x2, 0xf9, 0xfa, 0x3, 
    0x2, 0x2, 0x2, 0xfa, 0x101, 0x3, 0x2, 0x2, 0x2, 0xfb, 0xfd, 0x5, 0x24, 
    0x13, 0x2, 0xfc, 0xfb, 0x3, 0x2, 0x2, 0x2, 0xfd, 0xfe, 0x3, 0x2, 0x2, 
    0x2, 0xfe, 0xfc, 0x3, 0x2, 0x2, 0x2, 0xfe, 0xff, 0x3, 0x2, 0x2, 0x2, 
    0xff, 0x101, 0x3, 0x2, 0x2, 0x2, 0x100, 0xe7, 0x3, 0x2, 0x2, 0x2, 0x100, 
    0xf2, 0x3, 0x2, 0x2, 0x2, 0x100, 0xfc, 0x3, 0x2, 0x2, 0x2, 0x101, 0x23, 
    0x3, 0x2, 0x2, 0x2, 0x102, 0x120, 0x7, 0xc, 0x2, 0x2, 0x103, 0x104, 0x9, 
    0x2, 0x2, 0x2, 0x104, 0x10d, 0x7, 0x27, 0x2, 0x2, 0x105, 0x10a, 0x5, 
    0x2c, 0x17, 0x2, 0x106, 0x107, 0x7, 0x25, 0x2, 0x2, 0x107, 0x109, 0x5, 
    0x2c, 0x17, 0x2, 0x108, 0x106, 0x3, 0x2, 0x2, 0x2, 0x109, 0x10c, 0x3, 
    0x2, 0x2, 0x2, 0x10a, 0x108, 0x3, 0x2, 0x2, 0x2, 0x10a, 0x10b, 0x3, 0x2, 
    0x2, 0x2, 0x10b, 0x10e, 0x3, 0x2, 0x2, 0x2, 0x10c, 0x10a, 0x3, 0x2, 0x2, 
    0x2, 0x10d, 0x105, 0x3, 0x2, 0x2, 0x2, 0x10d, 0x10e, 0x3, 0x2, 0x2, 0x2, 
    0x10e, 0x10f, 0x3, 0x2, 0x2, 0x2, 0x10f, 0x112, 0x7, 0x28, 0x2, 0x2, 
    0x110, 0x113, 0x5, 0x28, 0x15, 0x2, 0x111, 0x113, 0x5, 0x26, 0x14, 0x2, 
    0x112, 0x110, 0x3, 0x2, 0x2, 0x2, 0x112, 0x111, 0x3, 0x2, 0x2, 0x2, 
    0x112, 0x113, 0x3, 0x2, 0x2, 0x2, 0x113, 0x120, 0x3, 0x2, 0x2, 0x2, 
    0x114, 0x120, 0x7, 0x31, 0x2, 0x2, 0x115, 0x120, 0x9, 0x2, 0x2, 0x2, 
    0x116, 0x120, 0x7, 0x26, 0x2, 0x2, 0x117, 0x11b, 0x7, 0x29, 0x2, 0x2, 
    0x118, 0x11a, 0x5, 0x24, 0x13, 0x2, 0x119, 0x118, 0x3, 0x2, 0x2, 0x2, 
    0x11a, 0x11d, 0x3, 0x2, 0x2, 0x2, 0x11b, 0x119, 0x3, 0x2, 0x2, 0x2, 
    0x11b, 0x11c, 0x3, 0x2, 0x2, 0x2, 0x11c, 0x11e, 0x3, 0x2, 0x2, 0x2, 
    0x11d, 0x11b, 0x3, 0x2, 0x2, 0x2, 0x11e, 0x120, 0x7, 0x2a, 0x2, 0x2, 
    0x11f, 0x102, 0x3, 0x2, 0x2, 0x2, 0x11f, 0x103, 0x3, 0x2, 0x2, 0x2, 
    0x11f, 0x114, 0x3, 0x2, 0x2, 0x2, 0x11f, 0x115, 0x3, 0x2, 0x2, 0x2, 
    0x11f, 0x116, 0x3, 0x2, 0x2, 0x2, 0x11f, 0x117, 0x3, 0x2, 0x2, 0x2, 
    0x120, 0x25, 0x3, 0x2, 0x2, 0x2, 0x121, 0x125, 0x7, 0x2b, 0x2, 0x2, 
    0x122, 0x124, 0x5, 0x24, 0x13, 0x2, 0x123, 0x122, 0x3, 0x2, 0x2, 0x2, 
    0x124, 0x127, 0x3, 0x2, 0x2, 0x2, 0x125, 0x123, 0x3, 0x2, 0x2, 0x2, 
    0x125, 0x126, 0x3, 0x2, 0x2, 0x2, 0x126, 0x128, 0x3, 0x2, 0x2, 0x2, 
    0x127, 0x125, 0x3, 0x2, 0x2, 0x2, 0x128, 0x129, 0x7, 0x2c, 0x2, 0x2, 
    0x129, 0x27, 0x3, 0x2, 0x2, 0x2, 0x12a, 0x12b, 0x7, 0x2b, 0x2, 0x2, 
    0x12b, 0x130, 0x5, 0x2a, 0x16, 0x2, 0x12c, 0x12d, 0x7, 0x20, 0x2, 0x2, 
    0x12d, 0x12f, 0x5, 0x2a, 0x16, 0x2, 0x12e, 0x12c, 0x3, 0x2, 0x2, 0x2, 
    0x12f, 0x132, 0x3, 0x2, 0x2, 0x2, 0x130, 0x12e, 0x3, 0x2, 0x2, 0x2, 
    0x130, 0x131, 0x3, 0x2, 0x2, 0x2, 0x131, 0x133, 0x3, 0x2, 0x2, 0x2, 
    0x132, 0x130, 0x3, 0x2, 0x2, 0x2, 0x133, 0x135, 0x7, 0x2c, 0x2, 0x2, 
    0x134, 0x136, 0x7, 0x1c, 0x2, 0x2, 0x135, 0x134, 0x3, 0x2, 0x2, 0x2, 
    0x135, 0x136, 0x3, 0x2, 0x2, 0x2, 0x136, 0x29, 0x3, 0x2, 0x2, 0x2, 0x137, 
    0x138, 0x5, 0x2c, 0x17, 0x2, 0x138, 0x13c, 0x9, 0x3, 0x2, 0x2, 0x139, 
    0x13b, 0x5, 0x24, 0x13, 0x2, 0x13a, 0x139, 0x3, 0x2, 0x2, 0x2, 0x13b, 
    0x13e, 0x3, 0x2, 0x2, 0x2, 0x13c, 0x13a, 0x3, 0x2, 0x2, 0x2, 0x13c, 
    0x13d, 0x3, 0x2, 0x2, 0x2, 0x13d, 0x141, 0x3, 0x2, 0x2, 0x2, 0x13e, 
    0x13c, 0x3, 0x2, 0x2, 0x2, 0x13f, 0x141, 0x5, 0x28, 0x15, 0x2, 0x140, 
    0x137, 0x3, 0x2, 0x2, 0x2, 0x140, 0x13f, 0x3, 0x2, 0x2, 0x2, 0x141, 0x2b, 
    0x3, 0x2, 0x2, 0x2, 0x142, 0x143, 0x8, 0x17, 0x1, 0x2, 0x143, 0x147, 0x5, 
    0x2e, 0x18, 0x2, 0x144, 0x145, 0x9, 0x4, 0x2, 0x2, 0x145, 0x147, 0x5, 
    0x2c, 0x17, 0x9, 0x146, 0x142, 0x3, 0x2, 0x2, 0x2, 0x146, 0x144, 0x3, 
    0x2, 0x2, 0x2, 0x147, 0x15c, 0x3, 0x2, 0x2, 0x2, 0x148, 0x149, 0xc, 0x8, 
    0x2, 0x2, 0x149, 0x14a, 0x9, 0x5, 0x2, 0x2, 0x14a, 0x15b, 0x5, 0x2c, 
    0x17, 0x9, 0x14b, 0x14c, 0xc, 0x7, 0x2, 0x2, 0x14c, 0x14d, 0x9, 0x6, 0x2, 
    0x2, 0x14d, 0x15b, 0x5, 0x2c, 0x17, 0x8, 0x14e, 0x14f, 0xc, 0x6, 0x2, 
    0x2, 0x14f, 0x150, 0x9, 0x7, 0x2, 0x2, 0x150, 0x15b, 0x5, 0x2c, 0x17, 
    0x7, 0x151, 0x152, 0xc, 0x5, 0x2, 0x2, 0x152, 0x153, 0x9, 0x8, 0x2, 0x2, 
    0x153, 0x15b, 0x5, 0x2c, 0x17, 0x6, 0x154, 0x155, 0xc, 0x4, 0x2, 0x2, 
    0x155, 0x156, 0x7, 0x17, 0x2, 0x2, 0x156, 0x15b, 0x5, 0x2c, 0x17, 0x5, 
    0x157, 0x158, 0xc, 0x3, 0x2, 0x2, 0x158, 0x159, 0x7, 0x18, 0x2, 0x2, 
    0x159, 0x15b, 0x5, 0x2c, 0x17, 0x4, 0x15a, 0x148, 0x3, 0x2, 0x2, 0x2, 
    0x15a, 0x14b, 0x3, 0x2, 0x2, 0x2, 0x15a, 0x14e, 0x3, 0x2, 0x2, 0x2, 
    0x15a, 0x151, 0x3, 0x2, 0x2, 0x2, 0x15a, 0x154, 0x3, 0x2, 0x2, 0x2, 
    0x15a, 0x157, 0x3, 0x2, 0x2, 0x2, 0x15b, 0x15e, 0x3, 0x2, 0x2, 0x2, 
    0x15c, 0x15a, 0x3, 0x2, 0x2, 0x2, 0x15c, 0x15d, 0x3, 0x2, 0x2, 0x2, 
    0x15d, 0x2d, 0x3, 0x2, 0x2, 0x2, 0x15e, 0x15c, 0x3, 0x2, 0x2, 0x2, 0x15f, 
    0x185, 0x5, 0x30, 0x19, 0x2, 0x160, 0x185, 0x7, 0x33, 0x2, 0x2, 0x161, 
    0x185, 0x9, 0x9, 0x2, 0x2, 0x162, 0x163, 0x9, 0x2, 0x2, 0x2, 0x163, 
    0x16c, 0x7, 0x27, 0x2, 0x2, 0x164, 0x169, 0x5, 0x2c, 0x17, 0x2, 0x165, 
    0x166, 0x7, 0x25, 0x2, 0x2, 0x166, 0x168, 0x5, 0x2c, 0x17, 0x2, 0x167, 
    0x165, 0x3, 0x2, 0x2, 0x2, 0x168, 0x16b, 0x3, 0x2, 0x2, 0x2, 0x169, 
    0x167, 0x3, 0x2, 0x2, 0x2, 0x169, 0x16a, 0x3, 0x2, 0x2, 0x2, 0x16a, 
    0x16d, 0x3, 0x2, 0x2, 0x2, 0x16b, 0x169, 0x3, 0x2, 0x2, 0x2, 0x16c, 
    0x164, 0x3, 0x2, 0x2, 0x2, 0x16c, 0x16d, 0x3, 0x2, 0x2, 0x2, 0x16d, 
    0x16e, 0x3, 0x2, 0x2, 0x2, 0x16e, 0x185, 0x7, 0x28, 0x2, 0x2, 0x16f, 
    0x185, 0x9, 0x2, 0x2, 0x2, 0x170, 0x171, 0x7, 0x27, 0x2, 0x2, 0x171, 
    0x172, 0x5, 0x2c, 0x17, 0x2, 0x172, 0x173, 0x7, 0x28, 0x2, 0x2, 0x173, 
    0x185, 0x3, 0x2, 0x2, 0x2, 0x174, 0x17d, 0x7, 0x29, 0x2, 0x2, 0x175, 
    0x17a, 0x5, 0x2c, 0x17, 0x2, 0x176, 0x177, 0x7, 0x25, 0x2, 0x2, 0x177, 
    0x179, 0x5, 0x2c, 0x17, 0x2, 0x178, 0x176, 0x3, 0x2, 0x2, 0x2, 0x179, 
    0x17c, 0x3, 0x2, 0x2, 0x2, 0x17a, 0x178, 0x3, 0x2, 0x2, 0x2, 0x17a, 
    0x17b, 0x3, 0x2, 0x2, 0x2, 0x17b, 0x17e, 0x3, 0x2, 0x2, 0x2, 0x17c, 
    0x17a, 0x3, 0x2, 0x2, 0x2, 0x17d, 0x175, 0x3, 0x2, 0x2, 0x2, 0x17d, 
    0x17e, 0x3, 0x2, 0x2, 0x2, 0x17e, 0x17f, 0x3, 0x2, 0x2, 0x2, 0x17f, 
    0x185, 0x7, 0x2a, 0x2, 0x2, 0x180, 0x181, 0x7, 0x21, 0x2, 0x2, 0x181, 
    0x185, 0x5, 0x2e, 0x18, 0x2, 0x182, 0x183, 0x7, 0x22, 0x2, 0x2, 0x183, 
    0x185, 0x5, 0x2e, 0x18, 0x2, 0x184, 0x15f, 0x3, 0x2, 0x2, 0x2, 0x184, 
    0x160, 0x3, 0x2, 0x2, 0x2, 0x184, 0x161, 0x3, 0x2, 0x2, 0x2, 0x184, 
    0x162, 0x3, 0x2, 0x2, 0x2, 0x184, 0x16f, 0x3, 0x2, 0x2, 0x2, 0x184, 
    0x170, 0x3, 0x2, 0x2, 0x2, 0x184, 0x174, 0x3, 0x2, 0x2, 0x2, 0x184, 
    0x180, 0x3, 0x2, 0x2, 0x2, 0x184, 0x182, 0x3, 0x2, 0x2, 0x2, 0x185, 0x2f, 
    0x3, 0x2, 0x2, 0x2, 0x186, 0x187, 0x9, 0xa, 0x2, 0x2, 0x187, 0x31, 0x3, 
    0x2, 0x2, 0x2, 0x35, 0x35, 0x3f, 0x47, 0x51, 0x55, 0x58, 0x61, 0x64, 
    0x67, 0x6b, 0x73, 0x78, 0x7f, 0x89, 0x8c, 0x8f, 0x93, 0xa0, 0xa3, 0xab, 
    0xae, 0xb6, 0xb9, 0xc3, 0xcd, 0xd8, 0xdd, 0xe0, 0xe9, 0xf4, 0xf9, 0xfe, 
    0x100, 0x10a, 0x10d, 0x112, 0x11b, 0x11f, 0x125, 0x130, 0x135, 0x13c, 
    0x140, 0x146, 0x15a, 0x15c, 0x169, 0x16c, 0x17a, 0x17d, 0x184, 
  };

  atn::ATNDeserializer deserializer;
  _atn = deserializer.deserialize(_serializedATN);

  size_t count = _atn.getNumberOfDecisions();
  _decisionToDFA.reserve(count);
  for (size_t i = 0; i < count; i++) { 
    _decisionToDFA.emplace_back(_atn.getDecisionState(i), i);
  }
}

// CgaParser::Initializer runs in the constructor, on first use (scripts/regen-grammar.sh).
