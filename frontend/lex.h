// Lexing: source text -> the token list the parser reads. Private to the front end.
//
// Besides running the ANTLR lexer this step
//  * reports lexical errors (E001: unknown characters, unterminated strings and
//    comments) and repairs what it can so parsing still sees sensible tokens;
//  * inserts an implicit ';' before a line that starts a new rule or declaration and at
//    the end of the file, which is what makes the ';' after a rule optional at the end
//    of a line (see grammar/Fgsg.g4).
#pragma once

#include "frontend/ast.h"
#include "frontend/diagnostics.h"

#include <memory>
#include <vector>

#include "antlr4-runtime.h"
#include "FgsgLexer.h"

namespace fgsg::frontend {

struct LexedSource {
  // The tokens point back at the input stream and lexer, so these live as long.
  std::unique_ptr<antlr4::ANTLRInputStream> input;
  std::unique_ptr<fgsg_grammar::FgsgLexer> lexer;
  std::vector<std::unique_ptr<antlr4::Token>> tokens;  // ends with EOF
  // lpfg's and L-Py's section headers (`decomposition:` ...), taken out of the tokens:
  // the line each section starts on, in order, and their `maximum depth:` values.
  std::vector<std::pair<size_t, RuleSection>> sectionStarts;
  int decompositionDepth = 1;
  int homomorphismDepth = 1;

  // The section of a statement that starts on `line`.
  RuleSection sectionAt(size_t line) const;
};

// Whether token `b` starts right where `a` ends, nothing between them (`#consider`, `?P(`).
inline bool writtenTogether(const antlr4::Token* a, const antlr4::Token* b) {
  return a->getStopIndex() + 1 == b->getStartIndex();
}

LexedSource lexSource(const SourceFile& file, Diagnostics& diags);  // the grammar's own text
// With `cache` (frontend/incremental_lex.h), only the region an edit changed since the
// cache's text is lexed again.
class IncrementalLexCache;
LexedSource lexText(const std::string& name, const std::string& text, Diagnostics& diags,
                    const std::vector<std::string>& importAliases = {}, IncrementalLexCache* cache = nullptr);

// An implicit ';' has no source text of its own; it sits on the last character of the
// token before it.
bool isImplicitSemicolon(const antlr4::Token* token);

// Source range of one token, in characters (1-based columns, end inclusive).
SourceRange tokenRange(const antlr4::Token* token);

}  // namespace fgsg::frontend
