// Incremental lexing (fgsg lsp, #50): the ANTLR lexer's raw tokens of a text are kept, and
// after an edit only the region around it is lexed again. The lexer has no modes and no
// predicates, so the tokens lexed from a position depend only on the text from there on:
//  * lexing restarts after the last token whose lexing (lookahead included, as the input
//    stream saw it) ended before the first changed character;
//  * it stops once a new token, past the changed text, starts where an old one started
//    (shifted by the edit) on a line after the edit: the rest are the old tokens shifted by
//    the edit's characters and lines. Block comments and strings spanning the edit are
//    lexed again whole, since the restart is before them.
// The result is the token list a full lex of the new text gives (tests/unit/frontend).
#pragma once

#include "antlr4-runtime.h"
#include "FgsgLexer.h"

#include <memory>
#include <string>
#include <vector>

namespace fgsg::frontend {

// An input stream that remembers the furthest character the lexer looked at.
class LookaheadTrackingStream : public antlr4::ANTLRInputStream {
 public:
  using antlr4::ANTLRInputStream::ANTLRInputStream;
  size_t LA(ssize_t i) override {
    if (i > 0) furthest = std::max(furthest, p + static_cast<size_t>(i) - 1);
    return antlr4::ANTLRInputStream::LA(i);
  }
  // Moves to character `index` (a restart point) without the line bookkeeping of seek().
  void jumpTo(size_t index) { p = index; }
  size_t furthest = 0;
};

// The raw tokens of the last text lexed, with how far each one's lexing looked.
class IncrementalLexCache {
 public:
  struct RawToken {
    size_t type, channel, start, stop, line, column;
    size_t lookedTo;  // the furthest character read while lexing it and every token before
    std::string text;
  };
  // How many tokens the last lex took over instead of lexing (tests, the bench).
  size_t reusedCount() const { return reused_; }
  size_t lexedCount() const { return lexed_; }

  // The raw tokens (up to and with EOF) of `input`'s text, `validText` in UTF-8, lexed by
  // `lexer`, which reads `input`; only the edited region when this cache holds an earlier
  // text. The cache then holds this text's tokens.
  std::vector<std::unique_ptr<antlr4::Token>> lex(fgsg_grammar::FgsgLexer& lexer, LookaheadTrackingStream& input,
                                                  const std::string& validText);
  // Forgets the tokens (a lexer error was reported: it must be reported again next time).
  void clear() {
    text_.clear();
    tokens_.clear();
    valid_ = false;
  }

 private:
  std::string text_;
  std::vector<RawToken> tokens_;
  bool valid_ = false;
  size_t reused_ = 0, lexed_ = 0;
};

}  // namespace fgsg::frontend
