
// Generated from grammar/Fgsg.g4 by ANTLR 4.7.2

#pragma once


#include "antlr4-runtime.h"


namespace fgsg_grammar {


class  FgsgLexer : public antlr4::Lexer {
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
    UNKNOWN_CHAR = 61
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
