
// Generated from grammar/Fgsg.g4 by ANTLR 4.7.2

#pragma once


#include "antlr4-runtime.h"


namespace fgsg_grammar {


class  FgsgLexer : public antlr4::Lexer {
public:
  enum {
    CONST = 1, ATTR = 2, SURFACE = 3, FIELD = 4, TEXTURE = 5, DERIVE = 6, 
    TURTLE = 7, COLLISION = 8, AXIOM = 9, PRIORITY = 10, TRUE = 11, FALSE = 12, 
    EPSILON = 13, ARROW = 14, ASSIGN = 15, EQ = 16, NEQ = 17, LE = 18, GE = 19, 
    LT = 20, GT = 21, AND = 22, OR = 23, PLUS = 24, MINUS = 25, STAR = 26, 
    SLASH = 27, PERCENT = 28, CARET = 29, BANG = 30, AMP = 31, PIPE = 32, 
    BACKSLASH = 33, DOLLAR = 34, TILDE = 35, QUESTION = 36, COLON = 37, 
    SEMI = 38, COMMA = 39, DOT = 40, LPAREN = 41, RPAREN = 42, LBRACK = 43, 
    RBRACK = 44, LBRACE = 45, RBRACE = 46, RELSIZE = 47, FLOAT = 48, INT = 49, 
    ID = 50, STRING = 51, UNTERMINATED_STRING = 52, LINE_COMMENT = 53, BLOCK_COMMENT = 54, 
    UNTERMINATED_COMMENT = 55, WS = 56, UNKNOWN_CHAR = 57
  };

  FgsgLexer(antlr4::CharStream *input);
  ~FgsgLexer();

  virtual std::string getGrammarFileName() const override;
  virtual const std::vector<std::string>& getRuleNames() const override;

  virtual const std::vector<std::string>& getChannelNames() const override;
  virtual const std::vector<std::string>& getModeNames() const override;
  virtual const std::vector<std::string>& getTokenNames() const override; // deprecated, use vocabulary instead
  virtual antlr4::dfa::Vocabulary& getVocabulary() const override;

  virtual const std::vector<uint16_t> getSerializedATN() const override;
  virtual const antlr4::atn::ATN& getATN() const override;

private:
  static std::vector<antlr4::dfa::DFA> _decisionToDFA;
  static antlr4::atn::PredictionContextCache _sharedContextCache;
  static std::vector<std::string> _ruleNames;
  static std::vector<std::string> _tokenNames;
  static std::vector<std::string> _channelNames;
  static std::vector<std::string> _modeNames;

  static std::vector<std::string> _literalNames;
  static std::vector<std::string> _symbolicNames;
  static antlr4::dfa::Vocabulary _vocabulary;
  static antlr4::atn::ATN _atn;
  static std::vector<uint16_t> _serializedATN;


  // Individual action functions triggered by action() above.

  // Individual semantic predicate functions triggered by sempred() above.

  struct Initializer {
    Initializer();
  };
  static Initializer _init;
};

}  // namespace fgsg_grammar
