
// Generated from grammar/Cga.g4 by ANTLR 4.7.2

#pragma once


#include "antlr4-runtime.h"


namespace fgsg_grammar {


class  CgaLexer : public antlr4::Lexer {
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

  CgaLexer(antlr4::CharStream *input);
  ~CgaLexer();

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
