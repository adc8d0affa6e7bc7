// Reading a REPL input into statements: the input's tokens split at each top-level ';',
// each statement's text sliced from the input as typed, and the key of what it defines
// (`rule:P` found by parsing the rule alone). Also what tells statements from a bare
// expression.
#include "cli/repl_statements.h"

#include "frontend/lex.h"
#include "frontend/parse.h"

#include <algorithm>
#include <charconv>
#include <string>

namespace fgsg::cli::repl {

using fgsg_grammar::FgsgLexer;
using frontend::SourceFile;
using frontend::SourceLoc;

namespace {

// Byte offset of 1-based character column `col` in a UTF-8 line.
size_t byteOffset(const std::string& line, int col) {
  size_t i = 0;
  for (int c = 1; c < col && i < line.size(); ++c) {
    ++i;
    while (i < line.size() && (static_cast<unsigned char>(line[i]) & 0xC0) == 0x80) ++i;
  }
  return i;
}

// The text from `begin` to `end` (inclusive, character columns).
std::string slice(const SourceFile& f, SourceLoc begin, SourceLoc end) {
  std::string out;
  for (int l = begin.line; l <= end.line && l <= static_cast<int>(f.lines.size()); ++l) {
    const std::string& line = f.lines[l - 1];
    const size_t from = l == begin.line ? byteOffset(line, begin.col) : 0;
    size_t to = line.size();
    if (l == end.line) {
      to = byteOffset(line, end.col + 1);
    }
    if (l != begin.line) out += '\n';
    if (from < to) out += line.substr(from, to - from);
  }
  return out;
}

struct Lexed {
  frontend::LexedSource lexed;
  std::vector<const antlr4::Token*> tokens;  // without EOF
};

Lexed lexQuietly(const SourceFile& f) {
  Lexed out;
  frontend::Diagnostics ignored(&f);
  out.lexed = frontend::lexSource(f, ignored);
  for (const auto& t : out.lexed.tokens)
    if (t->getType() != antlr4::Token::EOF) out.tokens.push_back(t.get());
  return out;
}

bool isDeclKeyword(size_t type) {
  switch (type) {
    case FgsgLexer::IMPORT: case FgsgLexer::CONST: case FgsgLexer::ATTR: case FgsgLexer::SURFACE:
    case FgsgLexer::FIELD: case FgsgLexer::TEXTURE: case FgsgLexer::TILESET: case FgsgLexer::DERIVE: case FgsgLexer::TURTLE:
    case FgsgLexer::COLLISION: case FgsgLexer::AXIOM: case FgsgLexer::PRIORITY:
      return true;
    default:
      return false;
  }
}

}  // namespace

bool Session::looksLikeStatements(const std::string& text) {
  const SourceFile f = SourceFile::make("<repl>", text);
  Lexed l = lexQuietly(f);
  if (l.tokens.empty()) return true;  // only comments: nothing to add
  if (isDeclKeyword(l.tokens[0]->getType())) return true;
  if (l.tokens.size() > 1 && l.tokens[0]->getType() == FgsgLexer::INT &&
      l.tokens[1]->getType() == FgsgLexer::COLON)
    return true;
  for (const auto* t : l.tokens)
    if (t->getType() == FgsgLexer::ARROW || t->getType() == FgsgLexer::ASSIGN) return true;
  return false;
}

std::vector<Statement> splitStatements(const std::shared_ptr<const SourceFile>& input, int& priority) {
  Lexed l = lexQuietly(*input);
  std::vector<Statement> added;
  size_t i = 0;
  while (i < l.tokens.size()) {
    const size_t start = i;
    const size_t type = l.tokens[start]->getType();
    if (type == FgsgLexer::SEMI) {
      ++i;
      continue;
    }
    if (type == FgsgLexer::PRIORITY) {  // priority [-] INT :
      size_t j = i + 1;
      bool negative = false;
      if (j < l.tokens.size() && l.tokens[j]->getType() == FgsgLexer::MINUS) negative = true, ++j;
      // A level that is not a small integer keeps the current one: compiling the
      // statement reports it (E002), so no exception may escape here.
      int level = 0;
      if (j < l.tokens.size()) {
        const std::string digits = l.tokens[j]->getText();
        auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), level);
        if (ec == std::errc() && end == digits.data() + digits.size()) priority = negative ? -level : level;
      }
      i = j + 2;
      continue;
    }
    int braces = 0;
    size_t end = i;
    // A field design's and a tileset's { } hold ';'.
    const bool block = type == FgsgLexer::FIELD || type == FgsgLexer::TILESET;
    for (; end < l.tokens.size(); ++end) {
      const size_t t = l.tokens[end]->getType();
      if (block && t == FgsgLexer::LBRACE) ++braces;
      if (block && t == FgsgLexer::RBRACE) braces = std::max(0, braces - 1);
      if (t == FgsgLexer::SEMI && braces == 0) break;
    }
    const size_t last = end - 1;  // the last token of the statement
    i = end + 1;
    Statement s;
    s.origin = input;
    const frontend::SourceRange first = frontend::tokenRange(l.tokens[start]);
    const frontend::SourceRange lastRange = frontend::tokenRange(l.tokens[last]);
    s.line = first.begin.line;
    s.col = first.begin.col;
    s.text = slice(*input, first.begin, lastRange.end);
    s.priority = priority;
    auto nameAfter = [&](const char* kind) {
      return std::string(kind) + (start + 1 < end ? l.tokens[start + 1]->getText() : "");
    };
    switch (type) {
      case FgsgLexer::IMPORT: s.key = "import:" + s.text; break;  // the same import again replaces nothing
      case FgsgLexer::CONST: case FgsgLexer::ATTR: s.key = nameAfter("value:"); break;
      case FgsgLexer::FIELD: s.key = nameAfter("field:"); break;
      case FgsgLexer::TEXTURE: s.key = nameAfter("texture:"); break;
      case FgsgLexer::TILESET: s.key = nameAfter("tileset:"); break;
      case FgsgLexer::SURFACE: s.key = "surface"; break;
      case FgsgLexer::DERIVE: s.key = "derive"; break;
      case FgsgLexer::TURTLE: s.key = "turtle"; break;
      case FgsgLexer::COLLISION: s.key = "collision"; break;
      case FgsgLexer::AXIOM: s.key = "axiom"; break;
      default: {
        // A rule: parse it alone to learn its predecessor (labels and contexts included).
        const SourceFile one = SourceFile::make(input->name, s.text);
        frontend::Program p;
        frontend::Diagnostics d(&one);
        frontend::parseProgram(one, p, d);
        s.key = "rule:" + (p.rules.empty() ? s.text : p.rules[0].predecessor.name);
      }
    }
    added.push_back(std::move(s));
  }
  return added;
}

bool hasStart(const std::vector<Statement>& list) {
  for (const Statement& s : list)
    if (s.key == "axiom" || s.key.rfind("rule:", 0) == 0) return true;
  return false;
}

}  // namespace fgsg::cli::repl
