#include "frontend/context_lists.h"

#include "frontend/lex.h"

#include "FgsgLexer.h"

namespace fgsg::frontend {

using antlr4::Token;
using fgsg_grammar::FgsgLexer;

namespace {

bool endsLine(const std::vector<std::unique_ptr<Token>>& tokens, size_t i) {
  return i + 1 >= tokens.size() || tokens[i + 1]->getType() == Token::EOF ||
         tokens[i + 1]->getLine() != tokens[i]->getLine();
}

// `ignore:` / `consider:` at `i` (the word, then its ':') is a declaration: the word first
// on its line, at least one module after the colon on that line, and no arrow up to the
// line's end or a ';'.
bool bareDeclaration(const std::vector<std::unique_ptr<Token>>& tokens, size_t i) {
  const bool firstOnLine = i == 0 || tokens[i - 1]->getLine() != tokens[i]->getLine();
  if (!firstOnLine || endsLine(tokens, i) || tokens[i + 1]->getType() != FgsgLexer::COLON) return false;
  size_t modules = 0;
  for (size_t k = i + 2; k < tokens.size() && tokens[k]->getLine() == tokens[i]->getLine(); ++k) {
    const size_t type = tokens[k]->getType();
    if (type == Token::EOF || type == FgsgLexer::SEMI) break;
    if (type == FgsgLexer::ARROW || type == FgsgLexer::ASSIGN) return false;
    ++modules;
  }
  return modules > 0;
}

}  // namespace

void readContextListDeclarations(std::vector<std::unique_ptr<Token>>& tokens) {
  // Decided first, on the whole list: bareDeclaration reads the tokens before i.
  std::vector<bool> joined(tokens.size(), false);  // the word `consider` joined to its '#'
  for (size_t i = 0; i < tokens.size(); ++i) {
    auto* t = static_cast<antlr4::CommonToken*>(tokens[i].get());
    const Token* next = i + 1 < tokens.size() ? tokens[i + 1].get() : nullptr;
    if (t->getType() == FgsgLexer::UNKNOWN_CHAR && t->getText() == "#" && next &&
        next->getType() == FgsgLexer::ID && next->getText() == "consider" && writtenTogether(t, next)) {
      t->setType(FgsgLexer::IGNORE);
      t->setText("#consider");
      t->setStopIndex(next->getStopIndex());
      joined[++i] = true;
    } else if (t->getType() == FgsgLexer::ID && (t->getText() == "consider" || t->getText() == "ignore") &&
               bareDeclaration(tokens, i)) {
      t->setType(FgsgLexer::IGNORE);
    }
  }
  std::vector<std::unique_ptr<Token>> out;
  out.reserve(tokens.size());
  for (size_t i = 0; i < tokens.size(); ++i)
    if (!joined[i]) out.push_back(std::move(tokens[i]));
  tokens = std::move(out);
}

}  // namespace fgsg::frontend
