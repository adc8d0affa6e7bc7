
// Generated from grammar/Fgsg.g4 by ANTLR 4.7.2

#pragma once


#include "antlr4-runtime.h"


namespace fgsg_grammar {


class  FgsgLexer : public antlr4::Lexer {
public:
  enum {
    CONST = 1, ATTR = 2, SURFACE = 3, FIELD = 4, TEXTURE = 5, TILESET = 6, 
    DERIVE = 7, TURTLE = 8, COLLISION = 9, AXIOM = 10, PRIORITY = 11, TRUE = 12, 
    FALSE = 13, EPSILON = 14, ARROW = 15, ASSIGN = 16, EQ = 17, NEQ = 18, 
    LE = 19, GE = 20, LT = 21, GT = 22, AND = 23, OR = 24, PLUS = 25, MINUS = 26, 
    STAR = 27, SLASH = 28, PERCENT = 29, CARET = 30, BANG = 31, AMP = 32, 
    PIPE = 33, BACKSLASH = 34, DOLLAR = 35, TILDE = 36, QUESTION = 37, COLON = 38, 
    SEMI = 39, COMMA = 40, DOT = 41, LPAREN = 42, RPAREN = 43, LBRACK = 44, 
    RBRACK = 45, LBRACE = 46, RBRACE = 47, RELSIZE = 48, FLOAT = 49, INT = 50, 
    ID = 51, STRING = 52, UNTERMINATED_STRING = 53, LINE_COMMENT = 54, BLOCK_COMMENT = 55, 
    UNTERMINATED_COMMENT = 56, WS = 57, UNKNOWN_CHAR = 58
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
