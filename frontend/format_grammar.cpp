#include "frontend/format_grammar.h"

#include "frontend/cga/cga_parse.h"
#include "frontend/lex.h"
#include "frontend/parse.h"

#include <algorithm>

namespace fgsg::frontend {

using antlr4::Token;
using fgsg_grammar::FgsgLexer;

namespace {

constexpr int kIndent = 2;

// Byte offset of the first byte that is not part of valid UTF-8, or npos.
size_t firstInvalidUtf8(const std::string& in) {
  const auto* s = reinterpret_cast<const unsigned char*>(in.data());
  for (size_t i = 0; i < in.size();) {
    const unsigned char c = s[i];
    size_t len = c < 0x80 ? 1 : (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 0;
    if (len == 0 || i + len > in.size()) return i;
    unsigned cp = len == 1 ? c : c & (0x7F >> len);
    for (size_t k = 1; k < len; ++k) {
      if ((s[i + k] & 0xC0) != 0x80) return i;
      cp = (cp << 6) | (s[i + k] & 0x3F);
    }
    static const unsigned kMinForLength[] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < kMinForLength[len] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return i;
    i += len;
  }
  return std::string::npos;
}

size_t codePoints(const std::string& s, size_t from = 0, size_t to = std::string::npos) {
  size_t n = 0;
  for (size_t i = from; i < std::min(to, s.size()); ++i) n += (static_cast<unsigned char>(s[i]) & 0xC0) != 0x80;
  return n;
}

SourceLoc locationOf(const std::string& text, size_t byte) {
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + byte, '\n'));
  const size_t lineStart = text.rfind('\n', byte == 0 ? 0 : byte - 1);
  const size_t from = lineStart == std::string::npos || byte == 0 ? 0 : lineStart + 1;
  return {line, 1 + static_cast<int>(codePoints(text, from, byte))};
}

// One thing the output writes again: a token or a comment, with what separated it from
// the one before in the input.
struct Atom {
  enum Kind { Code, LineComment, BlockComment } kind = Code;
  std::string text;
  size_t type = 0;        // Code: the lexer's token type
  size_t lexedType = 0;   // Code: its type once frontend/lex.cpp has read it (VERTEX, COLORSTEP)
  bool statementStart = false;  // Code: the first token of a statement
  int newlinesBefore = 0;
  bool spaceBefore = false;  // any whitespace between it and the atom before
  size_t column = 0;         // in the input, 0-based, in characters
  size_t byte = 0;           // where it starts in the input
};

bool isComment(const Atom& a) { return a.kind != Atom::Code; }

// The input's tokens and comments in order. Between two tokens the lexer skipped only
// whitespace and comments (grammar/Fgsg.g4), so the gaps are read here.
std::vector<Atom> readAtoms(const std::string& text) {
  std::vector<Atom> atoms;
  std::vector<size_t> byteOfCodePoint;  // ANTLR's indices count characters
  for (size_t i = 0; i < text.size(); ++i)
    if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) byteOfCodePoint.push_back(i);
  byteOfCodePoint.push_back(text.size());

  antlr4::ANTLRInputStream input(text);
  FgsgLexer lexer(&input);
  lexer.removeErrorListeners();
  size_t gapStart = 0;
  int newlines = 0;
  bool space = false;
  const auto columnAt = [&](size_t byte) {
    const size_t nl = byte == 0 ? std::string::npos : text.rfind('\n', byte - 1);
    return codePoints(text, nl == std::string::npos ? 0 : nl + 1, byte);
  };
  const auto push = [&](Atom a) {
    a.newlinesBefore = newlines;
    a.spaceBefore = space || newlines > 0;
    a.column = columnAt(a.byte);
    atoms.push_back(std::move(a));
    newlines = 0;
    space = false;
  };
  for (;;) {
    std::unique_ptr<Token> token = lexer.nextToken();
    const bool eof = token->getType() == Token::EOF;
    const size_t start = eof ? text.size() : byteOfCodePoint[token->getStartIndex()];
    for (size_t i = gapStart; i < start;) {
      if (text.compare(i, 2, "//") == 0 || text.compare(i, 2, "/*") == 0) {
        const bool line = text[i + 1] == '/';
        size_t end = line ? text.find_first_of("\r\n", i) : text.find("*/", i + 2);
        end = end == std::string::npos ? start : std::min(start, line ? end : end + 2);
        Atom a;
        a.kind = line ? Atom::LineComment : Atom::BlockComment;
        a.text = text.substr(i, end - i);
        if (line) a.text.erase(a.text.find_last_not_of(" \t\f") + 1);  // trailing blanks go
        a.byte = i;
        push(std::move(a));
        i = end;
      } else {
        newlines += text[i] == '\n';
        space = true;
        ++i;
      }
    }
    if (eof) break;
    gapStart = byteOfCodePoint[token->getStopIndex() + 1];
    Atom a;
    a.type = token->getType();
    a.lexedType = a.type;
    a.text = text.substr(start, gapStart - start);
    a.byte = start;
    push(std::move(a));
  }
  return atoms;
}

bool isOpener(size_t t) { return t == FgsgLexer::LPAREN || t == FgsgLexer::LBRACK || t == FgsgLexer::LBRACE; }
bool isCloser(size_t t) { return t == FgsgLexer::RPAREN || t == FgsgLexer::RBRACK || t == FgsgLexer::RBRACE; }

// What frontend/lex.cpp made of each token (by its start): its type, and whether it
// starts a statement: a ';' (written or implied by a line break) comes just before it, or
// `priority N:`, or it is an item of a field design's or tileset's `{ ...; ...; }`.
void markStatements(const std::string& name, const std::string& text, std::vector<Atom>& atoms) {
  SourceFile scratchFile = SourceFile::make(name, text);
  Diagnostics scratch(&scratchFile);
  LexedSource lexed = lexText(name, text, scratch);
  std::vector<size_t> byteOfCodePoint;
  for (size_t i = 0; i < text.size(); ++i)
    if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) byteOfCodePoint.push_back(i);
  struct Seen { size_t type; bool afterSemicolon; };
  std::vector<std::pair<size_t, Seen>> byByte;
  size_t statement = Token::EOF;  // the current statement's first token's type
  bool startNext = true;
  int depth = 0;
  for (size_t i = 0; i < lexed.tokens.size(); ++i) {
    const Token* t = lexed.tokens[i].get();
    const size_t type = t->getType();
    const bool block = statement == FgsgLexer::FIELD || statement == FgsgLexer::TILESET;
    const size_t before = i == 0 ? Token::EOF : lexed.tokens[i - 1]->getType();
    bool start = startNext;
    if (startNext) statement = type;
    else start = block && depth > 0 && (before == FgsgLexer::SEMI || (before == FgsgLexer::LBRACE && depth == 1));
    startNext = false;
    if (isOpener(type)) ++depth;
    if (isCloser(type)) depth = std::max(depth - 1, 0);
    if (depth == 0 && (type == FgsgLexer::SEMI || (type == FgsgLexer::COLON && statement == FgsgLexer::PRIORITY)))
      startNext = true;
    if (type == Token::EOF || isImplicitSemicolon(t)) continue;
    byByte.push_back({byteOfCodePoint[t->getStartIndex()], {type, start}});
  }
  size_t k = 0;
  for (Atom& a : atoms) {
    if (isComment(a)) continue;
    while (k < byByte.size() && byByte[k].first < a.byte) ++k;
    if (k < byByte.size() && byByte[k].first == a.byte) {
      a.lexedType = byByte[k].second.type;
      a.statementStart = byByte[k].second.afterSemicolon;
    } else {
      a.statementStart = true;  // left out of the statements: `production:`, `maximum depth: 2`
    }
  }
}


bool endsOperand(size_t t) {
  switch (t) {
    case FgsgLexer::ID: case FgsgLexer::INT: case FgsgLexer::FLOAT: case FgsgLexer::RELSIZE:
    case FgsgLexer::STRING: case FgsgLexer::TRUE: case FgsgLexer::FALSE: case FgsgLexer::RPAREN:
      return true;
    default:
      return false;
  }
}

bool isBinaryOperator(size_t t) {
  switch (t) {
    case FgsgLexer::STAR: case FgsgLexer::SLASH: case FgsgLexer::PERCENT: case FgsgLexer::PLUS:
    case FgsgLexer::MINUS: case FgsgLexer::EQ: case FgsgLexer::NEQ: case FgsgLexer::LE: case FgsgLexer::GE:
    case FgsgLexer::LT: case FgsgLexer::GT: case FgsgLexer::AND: case FgsgLexer::OR:
    case FgsgLexer::QUESTION: case FgsgLexer::COLON:
      return true;
    default:
      return false;
  }
}

// Where each code atom stands: its bracket depth, whether it is read as an expression
// (inside '( )', an attr's or const's value, a rule's guard or a branch's probability
// after its ':') and so whether an operator is binary.
struct Place {
  int depth = 0;           // brackets open before it
  bool parens = false;     // the innermost open bracket is '('
  bool expression = false;
  bool binary = false;     // an operator between two operands: spaces around
  bool unary = false;      // a prefix '-', '+' or '!': no space after
};

std::vector<Place> placeAtoms(const std::vector<Atom>& atoms) {
  std::vector<Place> places(atoms.size());
  std::vector<size_t> open;
  bool declaration = false, value = false;  // in a const or attr, after its '='
  bool rule = false, condition = false;      // in a rule, after a ':' (until an arrow or ';')
  size_t previous = Token::EOF;
  for (size_t i = 0; i < atoms.size(); ++i) {
    const Atom& a = atoms[i];
    Place& p = places[i];
    p.depth = static_cast<int>(open.size());
    if (isComment(a)) continue;
    if (a.statementStart && open.empty()) {
      declaration = a.type == FgsgLexer::CONST || a.type == FgsgLexer::ATTR;
      rule = a.type == FgsgLexer::ID || a.type == FgsgLexer::INT;  // a head or a label
      value = condition = false;
    }
    if (open.empty() && (a.type == FgsgLexer::ARROW || a.type == FgsgLexer::ASSIGN || a.type == FgsgLexer::SEMI))
      condition = false;
    p.parens = !open.empty() && open.back() == FgsgLexer::LPAREN;
    p.expression = p.parens || ((value || condition) && open.empty());
    p.binary = p.expression && isBinaryOperator(a.type) && endsOperand(previous);
    p.unary = p.expression && !endsOperand(previous) &&
              (a.type == FgsgLexer::MINUS || a.type == FgsgLexer::PLUS || a.type == FgsgLexer::BANG);
    if (declaration && open.empty() && a.type == FgsgLexer::ASSIGN) value = true;
    if (rule && open.empty() && a.type == FgsgLexer::COLON && !p.binary) condition = true;
    if (isOpener(a.type)) open.push_back(a.type);
    if (isCloser(a.type) && !open.empty()) open.pop_back();
    previous = a.type;
  }
  return places;
}

bool isArrow(size_t t) { return t == FgsgLexer::ARROW || t == FgsgLexer::ASSIGN; }

// The space between two tokens on one line.
const char* spaceBetween(const Atom& a, const Place& pa, const Atom& b, const Place& pb) {
  const bool aEnds = a.type == FgsgLexer::SEMI && a.lexedType == FgsgLexer::SEMI;  // not lpfg's colour step
  if (b.type == FgsgLexer::SEMI && b.lexedType == FgsgLexer::SEMI) return "";
  if (aEnds) return " ";
  if (b.type == FgsgLexer::COMMA && pb.parens) return "";
  if (a.type == FgsgLexer::COMMA && pa.parens) return " ";
  if (a.type == FgsgLexer::LPAREN || b.type == FgsgLexer::RPAREN) return "";
  if (isArrow(a.type) || isArrow(b.type)) return " ";
  if (pa.binary || pb.binary) return " ";
  if (pa.unary) return "";
  if (a.type == FgsgLexer::COLON) return " ";
  return b.spaceBefore ? " " : "";
}

std::string layOut(const std::vector<Atom>& atoms) {
  const std::vector<Place> places = placeAtoms(atoms);
  // The indentation a line gets when atom i begins it.
  const auto indentOf = [&](size_t i) {
    size_t code = i;
    while (code < atoms.size() && isComment(atoms[code])) ++code;
    int depth = places[i].depth;
    if (code == i && isCloser(atoms[i].type)) depth = std::max(depth - 1, 0);
    // A line that goes on with a statement is indented one step more than its brackets.
    const bool continues = code < atoms.size() && !atoms[code].statementStart;
    return kIndent * (depth + (continues ? 1 : 0));
  };
  std::string out;
  size_t lineStart = 0;
  for (size_t i = 0; i < atoms.size(); ++i) {
    const Atom& a = atoms[i];
    if (i == 0 || a.newlinesBefore > 0) {
      if (i > 0) out += a.newlinesBefore > 1 ? "\n\n" : "\n";
      lineStart = out.size();
      out.append(indentOf(i), ' ');
    } else if (isComment(a) && (i + 1 == atoms.size() || atoms[i + 1].newlinesBefore > 0)) {
      // A comment ending a line of code keeps its column (comments aligned in a column
      // stay so) where the code leaves room, else follows it after one space.
      const size_t width = codePoints(out, lineStart);
      out.append(a.column > width ? a.column - width : 1, ' ');
    } else if (isComment(a) || isComment(atoms[i - 1])) {
      if (a.spaceBefore) out += ' ';
    } else {
      out += spaceBetween(atoms[i - 1], places[i - 1], a, places[i]);
    }
    out += a.text;
  }
  if (!out.empty()) out += '\n';
  return out;
}

// The first token (by its start in `text`) where the two lexings differ, or npos.
size_t firstDifference(const std::string& name, const std::string& before, const std::string& after) {
  SourceFile fileBefore = SourceFile::make(name, before), fileAfter = SourceFile::make(name, after);
  Diagnostics d1(&fileBefore), d2(&fileAfter);
  LexedSource x = lexText(name, before, d1), y = lexText(name, after, d2);
  const std::vector<Atom> ax = readAtoms(before), ay = readAtoms(after);
  for (size_t i = 0; i < std::max(ax.size(), ay.size()); ++i)
    if (i >= ax.size() || i >= ay.size() || ax[i].kind != ay[i].kind || ax[i].text != ay[i].text)
      return i < ax.size() ? ax[i].byte : before.size();
  if (x.sectionStarts.size() != y.sectionStarts.size() || x.decompositionDepth != y.decompositionDepth ||
      x.homomorphismDepth != y.homomorphismDepth)
    return 0;
  std::vector<size_t> byteOfCodePoint;
  for (size_t i = 0; i < before.size(); ++i)
    if ((static_cast<unsigned char>(before[i]) & 0xC0) != 0x80) byteOfCodePoint.push_back(i);
  for (size_t i = 0; i < std::max(x.tokens.size(), y.tokens.size()); ++i) {
    const Token* a = i < x.tokens.size() ? x.tokens[i].get() : nullptr;
    const Token* b = i < y.tokens.size() ? y.tokens[i].get() : nullptr;
    if (a && b && a->getType() == b->getType() && a->getText() == b->getText()) continue;
    if (!a || a->getType() == Token::EOF || a->getStartIndex() == INVALID_INDEX) return before.size();
    return byteOfCodePoint[a->getStartIndex()];
  }
  return std::string::npos;
}

}  // namespace

bool formatGrammar(const SourceFile& file, std::string& out, Diagnostics& diags) {
  out.clear();
  const std::string text = file.mainText();
  if (isCgaSource(file.name, text)) {
    diags.error("E002", {{1, 1}, {1, 1}},
                "fgsg fmt formats .fgsg grammars; CityEngine CGA (.cga) is not supported yet");
    return false;
  }
  if (const size_t bad = firstInvalidUtf8(text); bad != std::string::npos) {
    const SourceLoc at = locationOf(text, bad);
    diags.error("E001", {at, at}, "not valid UTF-8 (the byte here); fgsg fmt leaves the file as it is");
    return false;
  }
  Program program;
  if (!parseText(file.name, text, program, diags)) return false;

  std::vector<Atom> atoms = readAtoms(text);
  markStatements(file.name, text, atoms);
  std::string formatted = layOut(atoms);
  if (const size_t at = firstDifference(file.name, text, formatted); at != std::string::npos) {
    const SourceLoc loc = locationOf(text, std::min(at, text.size()));
    diags.error("E999", {loc, loc},
                "internal error: formatting would change how this token is read; the file is left as it is "
                "(please report it)");
    return false;
  }
  out = std::move(formatted);
  return true;
}

}  // namespace fgsg::frontend
