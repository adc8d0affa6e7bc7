
// Generated from grammar/Fgsg.g4 by ANTLR 4.7.2

#pragma once


#include "antlr4-runtime.h"


namespace fgsg_grammar {


class  FgsgLexer : public antlr4::Lexer {
public:
  enum {
    CONST = 1, ATTR = 2, SURFACE = 3, FIELD = 4, TEXTURE = 5, DERIVE = 6, 
    TURTLE = 7, AXIOM = 8, PRIORITY = 9, TRUE = 10, FALSE = 11, EPSILON = 12, 
    ARROW = 13, ASSIGN = 14, EQ = 15, NEQ = 16, LE = 17, GE = 18, LT = 19, 
    GT = 20, AND = 21, OR = 22, PLUS = 23, MINUS = 24, STAR = 25, SLASH = 26, 
    PERCENT = 27, CARET = 28, BANG = 29, AMP = 30, PIPE = 31, BACKSLASH = 32, 
    DOLLAR = 33, TILDE = 34, QUESTION = 35, COLON = 36, SEMI = 37, COMMA = 38, 
    DOT = 39, LPAREN = 40, RPAREN = 41, LBRACK = 42, RBRACK = 43, LBRACE = 44, 
    RBRACE = 45, RELSIZE = 46, FLOAT = 47, INT = 48, ID = 49, STRING = 50, 
    UNTERMINATED_STRING = 51, LINE_COMMENT = 52, BLOCK_COMMENT = 53, UNTERMINATED_COMMENT = 54, 
    WS = 55, UNKNOWN_CHAR = 56
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
