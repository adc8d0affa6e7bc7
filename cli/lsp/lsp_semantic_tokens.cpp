// textDocument/semanticTokens: the document's tokens (the dialect's own ANTLR lexer, run on
// the editor's text) classified by what the analysis knows of each name: the grammar's
// rules, attrs, consts and fields (with the module alias of a qualified name), the rule
// parameters in scope, the shape symbols of successors, builtin commands, operations and
// functions, and queries (Scope.sx, scope.sx). Comments are what the lexers skip: the
// non-blank text between two tokens.
#include "cli/lsp/lsp_features.h"

#include "cli/lsp/lsp_text.h"
#include "frontend/builtins.h"
#include "frontend/cga/cga_parse.h"

#include "CgaLexer.h"
#include "FgsgLexer.h"
#include "antlr4-runtime.h"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

namespace fgsg::cli::lsp {
namespace {

using frontend::SourceLoc;
using frontend::SourceRange;
using fgsg_grammar::CgaLexer;
using fgsg_grammar::FgsgLexer;

// The legend's order: a token's type is its index here, its modifiers a bit set.
enum Type { kNamespace, kClass, kParameter, kVariable, kProperty, kFunction, kMethod, kKeyword, kComment, kString,
            kNumber, kDecorator };
const char* const kTypeNames[] = {"namespace", "class",   "parameter", "variable", "property", "function",
                                  "method",    "keyword", "comment",   "string",   "number",   "decorator"};
enum Modifier { kDeclaration = 1, kReadonly = 2, kDefaultLibrary = 4 };
const char* const kModifierNames[] = {"declaration", "readonly", "defaultLibrary"};

// One classified token, in code points: 0-based line and column.
struct Piece {
  int line, col, length, type, modifiers;
};

// A token as this file reads it: the lexer's type (of either dialect), its text and where
// it is (0-based code point index into the text, 1-based line, 0-based column).
struct Lexeme {
  size_t kind;
  std::string text;
  size_t start, stop;
  int line, col;
};

struct Dialect {
  bool cga;
  size_t id, qid, leaf, str, unterminatedStr, unterminatedComment, at, dot, lparen, colon, import;
  std::set<size_t> keywords, numbers;
};

Dialect fgsgDialect() {
  return {false, FgsgLexer::ID, size_t(-1), size_t(-1), FgsgLexer::STRING, FgsgLexer::UNTERMINATED_STRING,
          FgsgLexer::UNTERMINATED_COMMENT, size_t(-1), FgsgLexer::DOT, FgsgLexer::LPAREN, FgsgLexer::COLON,
          FgsgLexer::IMPORT,
          {FgsgLexer::IMPORT, FgsgLexer::CONST, FgsgLexer::ATTR, FgsgLexer::SURFACE, FgsgLexer::FIELD,
           FgsgLexer::TEXTURE, FgsgLexer::TILESET, FgsgLexer::DERIVE, FgsgLexer::TURTLE, FgsgLexer::IGNORE,
           FgsgLexer::COLLISION, FgsgLexer::AXIOM, FgsgLexer::PRIORITY, FgsgLexer::TRUE, FgsgLexer::FALSE,
           FgsgLexer::EPSILON},
          {FgsgLexer::INT, FgsgLexer::FLOAT, FgsgLexer::RELSIZE}};
}

Dialect cgaDialect() {
  return {true, CgaLexer::ID, CgaLexer::QID, CgaLexer::LEAF, CgaLexer::STRING, CgaLexer::UNTERMINATED_STRING,
          CgaLexer::UNTERMINATED_COMMENT, CgaLexer::AT, CgaLexer::DOT, CgaLexer::LPAREN, CgaLexer::COLON,
          CgaLexer::IMPORT,
          {CgaLexer::VERSION, CgaLexer::DIALECT, CgaLexer::IMPORT, CgaLexer::STYLE, CgaLexer::EXTENDS, CgaLexer::ATTR,
           CgaLexer::CONST, CgaLexer::CASE, CgaLexer::ELSE, CgaLexer::NIL, CgaLexer::TRUE, CgaLexer::FALSE},
          {CgaLexer::INT, CgaLexer::FLOAT, CgaLexer::PERCENT_LIT}};
}

template <class Lexer>
std::vector<Lexeme> lexAll(antlr4::ANTLRInputStream& input) {
  Lexer lexer(&input);
  lexer.removeErrorListeners();  // a lexical error is the diagnostics' to report
  std::vector<Lexeme> out;
  for (auto t = lexer.nextToken(); t->getType() != antlr4::Token::EOF; t = lexer.nextToken())
    out.push_back({t->getType(), t->getText(), t->getStartIndex(), t->getStopIndex(), static_cast<int>(t->getLine()),
                   static_cast<int>(t->getCharPositionInLine())});
  return out;
}

bool before(const SourceLoc& a, const SourceLoc& b) { return a.line != b.line ? a.line < b.line : a.col < b.col; }

// What the analysis knows of the document's own rules: their parameters (with where they
// are in scope: from the rule's head to the next statement) and the places successors write
// a shape symbol.
struct RuleFacts {
  struct Scope {
    SourceLoc begin, end;  // end exclusive
    std::vector<frontend::ParamDecl> params;
    bool contains(const SourceLoc& at) const { return !before(at, begin) && before(at, end); }
  };
  std::vector<Scope> scopes;
  std::set<std::pair<int, int>> symbols;  // (line, col) of a successor's shape symbol

  void addItems(const std::vector<frontend::Item>& items) {
    for (const auto& item : items) {
      if (item.kind == frontend::ItemKind::Call && !frontend::findCommand(item.name))
        symbols.insert({item.range.begin.line, item.range.begin.col});
      for (const auto& part : item.body) addItems(part.items);
      addItems(item.children);
    }
  }
};

RuleFacts ruleFacts(const Analysis& a) {
  RuleFacts facts;
  const int documentLines = a.documentLines();
  for (const auto& rule : a.program.rules) {
    if (rule.range.begin.line <= 0 || rule.range.begin.line > documentLines) continue;
    // The end is found once every statement's start is known (Classifier::scopeEnds): a .cga
    // rule's range is its name only.
    RuleFacts::Scope scope{rule.range.begin, rule.range.end, rule.predecessor.params};
    for (const auto* patterns : {&rule.leftContext, &rule.rightContext})
      for (const auto& p : *patterns) scope.params.insert(scope.params.end(), p.params.begin(), p.params.end());
    if (!scope.params.empty()) facts.scopes.push_back(std::move(scope));
    for (const auto& branch : rule.branches) facts.addItems(branch.successor.items);
  }
  for (const auto& axiom : a.program.axioms)
    if (axiom.range.begin.line > 0 && axiom.range.begin.line <= documentLines) facts.addItems(axiom.successor.items);
  return facts;
}

class Classifier {
 public:
  Classifier(const Analysis& a, const std::string& text, const Dialect& d) : d_(d), facts_(ruleFacts(a)) {
    input_.load(text);
    lexemes_ = d.cga ? lexAll<CgaLexer>(input_) : lexAll<FgsgLexer>(input_);
    const int documentLines = a.documentLines();
    for (const auto& def : a.definitions)
      if (!def.inDocument || def.nameRange.begin.line <= documentLines) definitions_.emplace(def.name, &def);
    scopeEnds(a);
  }

  std::vector<Piece> run() {
    for (size_t i = 0; i < lexemes_.size(); ++i) {
      commentsAfter(static_cast<long>(i) - 1, lexemes_[i].start);
      i = token(i);
    }
    commentsAfter(static_cast<long>(lexemes_.size()) - 1, input_.size());
    return std::move(pieces_);
  }

 private:
  void add(int line, int col, size_t length, int type, int modifiers = 0) {
    pieces_.push_back({line - 1, col, static_cast<int>(length), type, modifiers});
  }

  // Each rule's parameters are in scope up to the next statement: the next declaration,
  // rule or axiom the analysis has, or (in a .cga file, whose consts and functions it does
  // not keep) the next line that starts at its first column; in an fgsg file, at most to
  // the rule's end.
  void scopeEnds(const Analysis& a) {
    std::vector<SourceLoc> starts;
    for (const auto& r : a.program.rules) starts.push_back(r.range.begin);
    for (const auto& v : a.program.values) starts.push_back(v.range.begin);
    for (const auto& x : a.program.axioms) starts.push_back(x.range.begin);
    for (const auto& f : a.program.fields) starts.push_back(f.range.begin);
    for (const auto& i : a.program.imports) starts.push_back(i.range.begin);
    if (d_.cga)
      for (const auto& l : lexemes_)
        if (l.col == 0) starts.push_back({l.line, 1});
    std::sort(starts.begin(), starts.end(), before);
    for (auto& scope : facts_.scopes) {
      const auto next = std::upper_bound(starts.begin(), starts.end(), scope.begin, before);
      const SourceLoc end = next == starts.end() ? SourceLoc{INT32_MAX, 0} : *next;
      const SourceLoc ruleEnd{scope.end.line, scope.end.col + 1};
      scope.end = !d_.cga && before(scope.begin, ruleEnd) && before(ruleEnd, end) ? ruleEnd : end;
    }
  }

  // The comments between lexeme `prev` (none: -1) and the code point `to`.
  void commentsAfter(long prev, size_t to) {
    const size_t from = prev < 0 ? 0 : lexemes_[prev].stop + 1;
    if (from >= to) return;
    int line = 1, col = 0;  // where the gap starts: after the lexeme before it
    if (prev >= 0) {
      const Lexeme& p = lexemes_[prev];
      line = p.line, col = p.col;
      for (const char c : p.text)
        if (c == '\n') ++line, col = 0;
        else if ((static_cast<unsigned char>(c) & 0xC0) != 0x80) ++col;
    }
    comment(input_.getText(antlr4::misc::Interval(from, to - 1)), line, col);
  }

  // The non-blank runs of `text` (starting at `line`, `col`) as comments, one piece a line.
  void comment(const std::string& text, int line, int col) {
    int runCol = -1, runLength = 0;
    auto flush = [&] {
      if (runLength > 0) add(line, runCol, runLength, kComment);
      runCol = -1, runLength = 0;
    };
    for (const char c : text) {
      if ((static_cast<unsigned char>(c) & 0xC0) == 0x80) continue;  // inside a code point
      if (c == '\n') {
        flush();
        ++line, col = 0;
        continue;
      }
      const bool blank = c == ' ' || c == '\t' || c == '\r' || c == '\f';
      if (runCol < 0 && !blank) runCol = col;
      if (runCol >= 0 && !blank) runLength = col + 1 - runCol;  // blanks inside a comment belong to it
      ++col;
    }
    flush();
  }

  const Lexeme* at(size_t i) const { return i < lexemes_.size() ? &lexemes_[i] : nullptr; }
  bool adjacent(size_t i) const { return at(i + 1) && lexemes_[i].stop + 1 == lexemes_[i + 1].start; }

  // Classifies lexeme i (and those it joins with); the index of the last one it took.
  size_t token(size_t i) {
    const Lexeme& t = lexemes_[i];
    if (d_.keywords.count(t.kind)) {
      add(t.line, t.col, length(t), kKeyword);
      if (t.kind == d_.import) importAlias(i);
      return i;
    }
    if (d_.numbers.count(t.kind)) return add(t.line, t.col, length(t), kNumber), i;
    if (t.kind == d_.str || t.kind == d_.unterminatedStr) return add(t.line, t.col, length(t), kString), i;
    if (t.kind == d_.unterminatedComment) return comment(t.text, t.line, t.col), i;
    if (t.kind == d_.at && at(i + 1) && lexemes_[i + 1].kind == d_.id) {  // a .cga annotation: @StartRule
      add(t.line, t.col, 1 + length(lexemes_[i + 1]), kDecorator);
      return i + 1;
    }
    if (t.kind == d_.qid) return qualified(t.text, t.line, t.col), i;
    if (t.kind == d_.leaf) return name(t.text.substr(0, t.text.size() - 1), t.line, t.col, i), i;  // `Window.`
    if (t.kind != d_.id) return i;
    // fgsg's raw lexer reads `parts.Window` and `Scope.sx` as ID '.' ID, written together.
    size_t last = i;
    std::string joined = t.text;
    while (adjacent(last) && lexemes_[last + 1].kind == d_.dot && adjacent(last + 1) &&
           lexemes_[last + 2].kind == d_.id) {
      joined += "." + lexemes_[last + 2].text;
      last += 2;
    }
    if (last != i) return qualified(joined, t.line, t.col), last;
    name(t.text, t.line, t.col, i);
    return i;
  }

  // An import's alias: fgsg's `import "x" as alias`, CGA's `import alias : "x"`.
  void importAlias(size_t i) {
    const Lexeme* alias = nullptr;
    if (d_.cga) {
      if (at(i + 2) && lexemes_[i + 1].kind == d_.id && lexemes_[i + 2].kind == d_.colon) alias = &lexemes_[i + 1];
    } else if (at(i + 3) && lexemes_[i + 1].kind == d_.str && lexemes_[i + 2].kind == d_.id &&
               lexemes_[i + 2].text == "as" && lexemes_[i + 3].kind == d_.id) {
      add(lexemes_[i + 2].line, lexemes_[i + 2].col, 2, kKeyword);
      alias = &lexemes_[i + 3];
    }
    if (!alias) return;
    aliases_.insert(alias->text);
    add(alias->line, alias->col, length(*alias), kNamespace, kDeclaration);
    skip_.insert(alias->start);
  }

  // `alias.Name` (a module's declaration: the alias, then the name) or a query `object.member`.
  void qualified(const std::string& text, int line, int col) {
    const size_t dot = text.find('.');
    const std::string object = text.substr(0, dot);
    if (aliases_.count(object) || definitions_.count(text)) {
      add(line, col, codePoints(object), kNamespace);
      const int type = definitionType(text);
      if (type >= 0) add(line, col + static_cast<int>(codePoints(object)) + 1, codePoints(text) - dot - 1, type,
                         definitionModifiers(text));
      return;
    }
    add(line, col, codePoints(text), kMethod, kDefaultLibrary);
  }

  void name(const std::string& text, int line, int col, size_t i) {
    if (skip_.count(lexemes_[i].start)) return;
    const SourceLoc loc{line, col + 1};
    for (const auto& scope : facts_.scopes) {
      if (!scope.contains(loc)) continue;
      for (const auto& p : scope.params)
        if (p.name == text) {
          const bool declared = p.range.begin.line == loc.line && p.range.begin.col == loc.col;
          return add(line, col, codePoints(text), kParameter, declared ? kDeclaration : 0);
        }
    }
    if (const int type = definitionType(text); type >= 0) {
      int modifiers = definitionModifiers(text);
      for (auto [d, end] = definitions_.equal_range(text); d != end; ++d)
        if (d->second->inDocument && d->second->nameRange.begin.line == loc.line &&
            d->second->nameRange.begin.col == loc.col)
          modifiers |= kDeclaration;
      return add(line, col, codePoints(text), type, modifiers);
    }
    // A .cga annotation's key (`@Range(min=3)`) is no call of min().
    const bool call = at(i + 1) && lexemes_[i + 1].kind == d_.lparen;
    const bool builtin = d_.cga ? (frontend::isCityEngineOperationName(text) && call) ||
                                      (frontend::findFunction(text) && call)
                                : frontend::findCommand(text) || frontend::findFunction(text);
    if (builtin) return add(line, col, codePoints(text), kFunction, kDefaultLibrary);
    if (facts_.symbols.count({loc.line, loc.col})) return add(line, col, codePoints(text), kClass);
    // A .cga function the file declares (its calls are inlined, so the analysis does not list it).
    if (d_.cga && call) add(line, col, codePoints(text), kFunction);
  }

  int definitionType(const std::string& text) const {
    const auto d = definitions_.find(text);
    if (d == definitions_.end()) return -1;
    switch (d->second->kind) {
      case Definition::Kind::Rule: return kClass;
      case Definition::Kind::Attr: return kProperty;
      case Definition::Kind::Const: return kVariable;
      case Definition::Kind::Field: return kVariable;
    }
    return -1;
  }
  int definitionModifiers(const std::string& text) const {
    const auto d = definitions_.find(text);
    return d != definitions_.end() && d->second->kind == Definition::Kind::Const ? kReadonly : 0;
  }

  static size_t codePoints(const std::string& s) {
    size_t n = 0;
    for (const char c : s) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    return n;
  }
  static size_t length(const Lexeme& t) { return t.stop + 1 - t.start; }

  const Dialect& d_;
  RuleFacts facts_;
  antlr4::ANTLRInputStream input_;
  std::vector<Lexeme> lexemes_;
  std::multimap<std::string, const Definition*> definitions_;
  std::set<std::string> aliases_;
  std::set<size_t> skip_;  // lexemes already classified (an import's alias)
  std::vector<Piece> pieces_;
};

}  // namespace

Json semanticTokensLegend() {
  return Json{{"tokenTypes", Json(std::vector<std::string>(std::begin(kTypeNames), std::end(kTypeNames)))},
              {"tokenModifiers", Json(std::vector<std::string>(std::begin(kModifierNames), std::end(kModifierNames)))}};
}

Json semanticTokens(const Analysis& a, const std::string& text, const Json& range) {
  const bool cga = frontend::isCgaSource(a.path, text);
  const Dialect dialect = cga ? cgaDialect() : fgsgDialect();
  std::vector<Piece> pieces = Classifier(a, text, dialect).run();
  std::sort(pieces.begin(), pieces.end(),
            [](const Piece& x, const Piece& y) { return std::tie(x.line, x.col) < std::tie(y.line, y.col); });
  // Only the lines of `range` when one is asked (whole lines: a client asks for what it shows).
  int firstLine = 0, lastLine = INT32_MAX;
  if (range.is_object()) {
    firstLine = range.at("start").at("line").get<int>();
    lastLine = range.at("end").at("line").get<int>();
  }
  // LSP's encoding: five numbers a token, its line and start relative to the token before,
  // its columns and length in UTF-16 units.
  std::vector<int> data;
  int prevLine = 0, prevStart = 0;
  std::vector<std::string> lines;  // the text's lines, without their ends
  for (size_t start = 0; start <= text.size();) {
    const size_t eol = std::min(text.find('\n', start), text.size());
    lines.push_back(text.substr(start, eol - start));
    start = eol + 1;
  }
  for (const Piece& p : pieces) {
    if (p.line < firstLine || p.line > lastLine || p.length <= 0) continue;
    const std::string& lineText = p.line < static_cast<int>(lines.size()) ? lines[p.line] : lines.back();
    const int start = utf16Units(lineText, p.col);
    const int length = utf16Units(lineText, p.col + p.length) - start;
    data.insert(data.end(), {p.line - prevLine, p.line == prevLine ? start - prevStart : start, length, p.type, p.modifiers});
    prevLine = p.line, prevStart = start;
  }
  return Json{{"data", std::move(data)}};
}

}  // namespace fgsg::cli::lsp
