#include "frontend/lsystem_not_yet.h"

#include "frontend/lex.h"

#include <string>

namespace fgsg::frontend {

using antlr4::Token;
using fgsg_grammar::FgsgLexer;

namespace {

// The index after the ')' closing the '(' at `open` (or the EOF's index).
size_t afterClosing(const std::vector<std::unique_ptr<Token>>& tokens, size_t open) {
  int depth = 0;
  for (size_t i = open; i < tokens.size(); ++i) {
    const size_t type = tokens[i]->getType();
    if (type == Token::EOF) return i;
    if (type == FgsgLexer::LPAREN) ++depth;
    if (type == FgsgLexer::RPAREN && --depth == 0) return i + 1;
  }
  return tokens.size();
}

}  // namespace

void dropLsystemSyntaxNotYetSupported(std::vector<std::unique_ptr<Token>>& tokens, Diagnostics& diags) {
  std::vector<std::unique_ptr<Token>> kept;
  kept.reserve(tokens.size());
  for (size_t i = 0; i < tokens.size();) {
    const Token* t = tokens[i].get();
    const Token* next = i + 1 < tokens.size() ? tokens[i + 1].get() : nullptr;
    const bool named = next && next->getType() == FgsgLexer::ID && writtenTogether(t, next);
    // ?P ?H ?U ?L are query modules (frontend/query_modules.h); ?E is not supported yet.
    if (named && t->getType() == FgsgLexer::QUESTION && next->getText() == "E" && i + 2 < tokens.size() &&
        tokens[i + 2]->getType() == FgsgLexer::LPAREN && writtenTogether(next, tokens[i + 2].get())) {
      const size_t end = afterClosing(tokens, i + 2);
      const SourceRange at{tokenRange(t).begin, tokenRange(tokens[end - 1].get()).end};
      diags.error("E048", at,
                  "the environmental query module '?E' (Mech and Prusinkiewicz 1996) is not supported yet "
                  "(docs/language.md, the turtle)");
      // A whole left context (`?E(x) < A -> ...`) goes with its '<', so the rule reads on.
      const bool aloneBefore = kept.empty() || kept.back()->getType() == FgsgLexer::SEMI ||
                               kept.back()->getLine() != t->getLine();
      i = aloneBefore && end < tokens.size() && tokens[end]->getType() == FgsgLexer::LT ? end + 1 : end;
      continue;
    }
    kept.push_back(std::move(tokens[i]));
    ++i;
  }
  tokens = std::move(kept);
}

}  // namespace fgsg::frontend
