
// Generated from grammar/Fgsg.g4 by ANTLR 4.7.2

#pragma once


#include "antlr4-runtime.h"


namespace fgsg_grammar {


class  FgsgLexer : public antlr4::Lexer {
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
    UNKNOWN_CHAR = 60
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
