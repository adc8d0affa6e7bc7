#include "frontend/lex.h"
#include "frontend/context_lists.h"
#include "frontend/incremental_lex.h"
#include "frontend/query_modules.h"

#include "FgsgParser.h"

#include <algorithm>
#include <cstdio>

namespace fgsg::frontend {

using fgsg_grammar::FgsgLexer;
using antlr4::Token;

namespace {

constexpr int kMaxLexicalErrors = 20;

size_t codePointCount(const std::string& s) {
  size_t n = 0;
  for (char c : s) n += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  return n;
}

// The runtime's UTF-8 decoder throws on malformed input; replace each byte that is not
// part of a valid sequence by U+FFFD, so columns still count one character per byte.
std::string validUtf8(const std::string& in) {
  std::string out;
  out.reserve(in.size());
  const auto* s = reinterpret_cast<const unsigned char*>(in.data());
  const size_t n = in.size();
  for (size_t i = 0; i < n;) {
    const unsigned char c = s[i];
    size_t len = 0;
    unsigned cp = 0;
    if (c < 0x80) len = 1, cp = c;
    else if ((c & 0xE0) == 0xC0) len = 2, cp = c & 0x1F;
    else if ((c & 0xF0) == 0xE0) len = 3, cp = c & 0x0F;
    else if ((c & 0xF8) == 0xF0) len = 4, cp = c & 0x07;
    bool ok = len > 0 && i + len <= n;
    for (size_t k = 1; ok && k < len; ++k) {
      ok = (s[i + k] & 0xC0) == 0x80;
      cp = (cp << 6) | (s[i + k] & 0x3F);
    }
    static const unsigned kMinForLength[] = {0, 0, 0x80, 0x800, 0x10000};
    ok = ok && cp >= kMinForLength[len] && cp <= 0x10FFFF && !(cp >= 0xD800 && cp <= 0xDFFF);
    if (ok) {
      out.append(in, i, len);
      i += len;
    } else {
      out += "\xEF\xBF\xBD";
      i += 1;
    }
  }
  return out;
}

std::string printable(const std::string& text) {
  std::string out;
  for (unsigned char c : text) {
    if (c < 0x20 || c == 0x7F) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

// The lexer ends in a catch-all rule, so this only fires if that ever changes.
class LexerErrorReporter : public antlr4::BaseErrorListener {
 public:
  explicit LexerErrorReporter(Diagnostics& diags) : diags_(diags) {}
  void syntaxError(antlr4::Recognizer*, Token*, size_t line, size_t col, const std::string& msg,
                   std::exception_ptr) override {
    SourceLoc at{static_cast<int>(line), static_cast<int>(col) + 1};
    diags_.error("E001", {at, at}, "unexpected input");
  }

 private:
  Diagnostics& diags_;
};

// ------------------------------------------------------------ implicit ';'

bool isStatementKeyword(size_t type) {
  switch (type) {
    case FgsgLexer::IMPORT: case FgsgLexer::CONST: case FgsgLexer::ATTR: case FgsgLexer::SURFACE:
    case FgsgLexer::FIELD: case FgsgLexer::TEXTURE: case FgsgLexer::TILESET: case FgsgLexer::DERIVE:
    case FgsgLexer::TURTLE: case FgsgLexer::IGNORE: case FgsgLexer::COLLISION: case FgsgLexer::AXIOM:
    case FgsgLexer::PRIORITY:
      return true;
    default:
      return false;
  }
}

bool isArrowToken(size_t type) { return type == FgsgLexer::ARROW || type == FgsgLexer::ASSIGN; }

// Tokens after which a statement cannot have ended: the next line continues it.
bool expectsContinuation(size_t type) {
  switch (type) {
    case FgsgLexer::SEMI: case FgsgLexer::COLON: case FgsgLexer::ARROW: case FgsgLexer::ASSIGN:
    case FgsgLexer::LPAREN: case FgsgLexer::LBRACK: case FgsgLexer::LBRACE:
    case FgsgLexer::COMMA: case FgsgLexer::QUESTION:  // not DOT: a polygon vertex `.` may end a line
    case FgsgLexer::LT: case FgsgLexer::GT: case FgsgLexer::LE: case FgsgLexer::GE:
    case FgsgLexer::EQ: case FgsgLexer::NEQ: case FgsgLexer::AND: case FgsgLexer::OR:
    case FgsgLexer::STAR: case FgsgLexer::TILDE:
      return true;
    default:
      return isStatementKeyword(type);
  }
}

class ImplicitSemicolons {
 public:
  explicit ImplicitSemicolons(const std::vector<std::unique_ptr<Token>>& tokens) : t_(tokens) {}

  // Indices before which an implicit ';' goes.
  std::vector<size_t> positions() const {
    std::vector<size_t> out;
    int depth = 0;
    bool inBlockStatement = false;  // a field design's or tileset's `{ ...; ...; }` holds ';'
    for (size_t i = 0; i < t_.size(); ++i) {
      const size_t type = t_[i]->getType();
      const bool startsStatement = type == Token::EOF || (firstOnLine(i) && (isStatementKeyword(type) ||
                                                                             startsRuleHead(i)));
      if (depth == 0 && i > 0 && startsStatement && !expectsContinuation(t_[i - 1]->getType())) {
        out.push_back(i);
        inBlockStatement = false;
      }
      switch (type) {
        case FgsgLexer::LPAREN: case FgsgLexer::LBRACK: case FgsgLexer::LBRACE:
          ++depth;
          break;
        case FgsgLexer::RPAREN: case FgsgLexer::RBRACK: case FgsgLexer::RBRACE:
          depth = std::max(depth - 1, 0);
          break;
        case FgsgLexer::FIELD: case FgsgLexer::TILESET:
          if (depth == 0) inBlockStatement = true;
          break;
        case FgsgLexer::SEMI:
          if (!(inBlockStatement && depth > 0)) depth = 0, inBlockStatement = false;
          break;
        default:
          break;
      }
    }
    return out;
  }

  // lpfg's `;`, the colour index's next colour (ABOP's '): a ';' in a rule's or the
  // axiom's successor with more of it after it on the same line, `A -> F ; F`. A ';'
  // that ends its line, or before a declaration or a rule head (`A -> B; B -> C;`), ends
  // the statement as always. Returns the indices of the ';'s that are colour steps.
  std::vector<size_t> colourSteps() const {
    std::vector<size_t> out;
    bool rule = startsRule(0);
    for (size_t i = 1; i < t_.size(); ++i) {
      const size_t ty = type(i);
      if (ty == FgsgLexer::SEMI) {
        const bool continues = type(i + 1) != Token::EOF && !firstOnLine(i + 1) && !isStatementKeyword(type(i + 1)) &&
                               !startsRuleHead(i + 1);
        if (rule && continues) {
          out.push_back(i);
          continue;
        }
        rule = startsRule(i + 1);
      } else if (firstOnLine(i) && !expectsContinuation(type(i - 1)) &&
                 (isStatementKeyword(ty) || startsRuleHead(i))) {
        rule = startsRule(i);  // a statement after an implicit ';'
      }
    }
    return out;
  }

  // lpfg's `,`, the colour index's previous colour: a ',' in a rule's or the axiom's
  // successor outside parentheses and braces, where ',' separates arguments and body parts
  // (`A -> F , F`; in a polygon's `{ }` it stays a separator). Returns their indices.
  std::vector<size_t> colourBacks() const {
    std::vector<size_t> out;
    bool rule = startsRule(0), successor = false;
    bool block = false;  // a field's or tileset's `{ ...; ...; }`, whose ';' end no statement
    int parens = 0, braces = 0;
    for (size_t i = 0; i < t_.size(); ++i) {
      const size_t ty = type(i);
      if (i > 0 && !(block && braces > 0) &&
          (type(i - 1) == FgsgLexer::SEMI || (firstOnLine(i) && !expectsContinuation(type(i - 1)) &&
                                              (isStatementKeyword(ty) || startsRuleHead(i))))) {
        rule = startsRule(i), successor = false, parens = braces = 0;  // the next statement
        block = ty == FgsgLexer::FIELD || ty == FgsgLexer::TILESET;
      }
      switch (ty) {
        case FgsgLexer::LPAREN: ++parens; break;
        case FgsgLexer::RPAREN: parens = std::max(parens - 1, 0); break;
        case FgsgLexer::LBRACE: ++braces; break;
        case FgsgLexer::RBRACE: braces = std::max(braces - 1, 0); break;
        case FgsgLexer::ARROW: case FgsgLexer::ASSIGN: case FgsgLexer::COLON:
          // A rule's successor follows its arrow; the axiom's, `axiom:`.
          if (rule && parens == 0 && (ty != FgsgLexer::COLON || type(i - 1) == FgsgLexer::AXIOM)) successor = true;
          break;
        case FgsgLexer::COMMA:
          if (successor && parens == 0 && braces == 0) out.push_back(i);
          break;
        default: break;
      }
    }
    return out;
  }

 private:
  size_t type(size_t i) const { return i < t_.size() ? t_[i]->getType() : Token::EOF; }

  bool startsRule(size_t i) const { return type(i) == FgsgLexer::AXIOM || startsRuleHead(i); }

  bool firstOnLine(size_t i) const { return i == 0 || t_[i]->getLine() > t_[i - 1]->getLine(); }

  // A module of a rule head: a name, or a turtle symbol that has rules (`+ -> -`).
  bool isModule(size_t ty) const {
    switch (ty) {
      case FgsgLexer::ID: case FgsgLexer::PLUS: case FgsgLexer::MINUS: case FgsgLexer::AMP:
      case FgsgLexer::CARET: case FgsgLexer::BACKSLASH: case FgsgLexer::SLASH: case FgsgLexer::PIPE:
      case FgsgLexer::BANG:
        return true;
      default:
        return false;
    }
  }

  // `label :`, `Pred(params) ~>`, `Pred >`, `Left Ctx <`, `Pred : guard ~>`.
  bool startsRuleHead(size_t i) const {
    if (type(i) == FgsgLexer::INT && type(i + 1) == FgsgLexer::COLON) return true;
    size_t j = i;
    int modules = 0;
    while (isModule(type(j))) {
      ++j;
      ++modules;
      if (type(j) == FgsgLexer::LPAREN && !skipParens(j)) return false;
    }
    if (modules == 0) return false;
    const size_t next = type(j);
    if (isArrowToken(next) || next == FgsgLexer::GT) return modules == 1;
    if (next == FgsgLexer::LT) return true;
    if (next == FgsgLexer::COLON) return modules == 1 && arrowEndsGuard(j + 1);
    return false;
  }

  // Moves `j` from '(' to just after its ')'; false if the statement ends first.
  bool skipParens(size_t& j) const {
    int depth = 0;
    for (; j < t_.size(); ++j) {
      const size_t ty = type(j);
      if (ty == FgsgLexer::SEMI || ty == Token::EOF) return false;
      if (ty == FgsgLexer::LPAREN) ++depth;
      if (ty == FgsgLexer::RPAREN && --depth == 0) {
        ++j;
        return true;
      }
    }
    return false;
  }

  // After `X :` - a label or a guard - an arrow must follow before the statement ends.
  // A line starting with a name or an arrow is a new rule or a Müller branch, not this.
  bool arrowEndsGuard(size_t k) const {
    for (; k < t_.size(); ++k) {
      const size_t ty = type(k);
      if (ty == FgsgLexer::SEMI || ty == Token::EOF) return false;
      if (firstOnLine(k) && (ty == FgsgLexer::ID || isArrowToken(ty))) return false;
      if (isArrowToken(ty)) return true;
    }
    return false;
  }

  const std::vector<std::unique_ptr<Token>>& t_;
};

// Shares the previous token's source: ANTLR's error recovery reads it when it conjures
// a missing token in front of this one.
std::unique_ptr<Token> implicitSemicolonAfter(Token& previous) {
  auto semi = std::make_unique<antlr4::CommonToken>(
      std::make_pair(previous.getTokenSource(), previous.getInputStream()), FgsgLexer::SEMI,
      Token::DEFAULT_CHANNEL, INVALID_INDEX, INVALID_INDEX);
  const SourceRange prev = tokenRange(&previous);
  semi->setText(";");
  semi->setLine(prev.end.line);
  semi->setCharPositionInLine(prev.end.col - 1);
  return semi;
}

// ------------------------------------------------------------ lexical errors

class LexicalErrors {
 public:
  explicit LexicalErrors(Diagnostics& diags) : diags_(diags) {}

  void report(const SourceRange& at, std::string message) {
    if (++count_ <= kMaxLexicalErrors) {
      diags_.error("E001", at, std::move(message));
    } else if (count_ == kMaxLexicalErrors + 1) {
      diags_.note(at, "too many lexical errors; the rest are not shown");
    }
  }

 private:
  Diagnostics& diags_;
  int count_ = 0;
};

std::string unknownCharactersMessage(const std::string& text) {
  std::string message = codePointCount(text) == 1 ? "unexpected character '" : "unexpected characters '";
  message += printable(text) + "'";
  if (text[0] == '#') message += " (comments are written // or /* */)";
  return message;
}

// Two tokens written together, with nothing between them.
bool adjacent(const Token* a, const Token* b) { return a->getStopIndex() + 1 == b->getStartIndex(); }

// Reports lexical error tokens and drops or repairs them.
std::vector<std::unique_ptr<Token>> checkLexicalErrors(std::vector<std::unique_ptr<Token>> raw,
                                                       LexicalErrors& errors) {
  std::vector<std::unique_ptr<Token>> out;
  out.reserve(raw.size());
  for (size_t i = 0; i < raw.size(); ++i) {
    Token* token = raw[i].get();
    switch (token->getType()) {
      case FgsgLexer::UNKNOWN_CHAR: {
        // lpfg's and L-Py's turtle modules `@Tp(x, y, z)`, `@Ts(e)`, `@O(r)` ...: '@' and
        // the name written after it are one turtle symbol (the parser's '$' token,
        // with its text "@Tp"); the front end knows which it supports (E048 the rest).
        if (token->getText() == "@" && i + 1 < raw.size() && raw[i + 1]->getType() == FgsgLexer::ID &&
            adjacent(token, raw[i + 1].get()) && raw[i + 1]->getLine() == token->getLine()) {
          auto* module = static_cast<antlr4::CommonToken*>(token);
          module->setType(FgsgLexer::DOLLAR);
          module->setText("@" + raw[i + 1]->getText());
          module->setStopIndex(raw[i + 1]->getStopIndex());
          out.push_back(std::move(raw[i]));
          ++i;
          break;
        }
        // Merge a run of adjacent unknown characters into one error.
        std::string text = token->getText();
        SourceRange range = tokenRange(token);
        while (i + 1 < raw.size() && raw[i + 1]->getType() == FgsgLexer::UNKNOWN_CHAR &&
               adjacent(raw[i].get(), raw[i + 1].get()) &&
               raw[i + 1]->getLine() == raw[i]->getLine()) {
          ++i;
          text += raw[i]->getText();
          range.end = tokenRange(raw[i].get()).end;
        }
        errors.report(range, unknownCharactersMessage(text));
        break;
      }
      case FgsgLexer::UNTERMINATED_STRING: {
        errors.report(tokenRange(token), "unterminated string (missing '\"' before the end of the line)");
        std::string text = token->getText();
        if (!text.empty() && text.back() == '\\') text.pop_back();
        auto* fixed = static_cast<antlr4::CommonToken*>(token);
        fixed->setType(FgsgLexer::STRING);
        fixed->setText(text + "\"");
        out.push_back(std::move(raw[i]));
        break;
      }
      case FgsgLexer::UNTERMINATED_COMMENT: {
        SourceLoc at{static_cast<int>(token->getLine()),
                     static_cast<int>(token->getCharPositionInLine()) + 1};
        errors.report({at, {at.line, at.col + 1}}, "unterminated comment (missing '*/')");
        break;
      }
      default:
        out.push_back(std::move(raw[i]));
    }
  }
  return out;
}

// A '.' is a member access only between two names, written together (`Scope.sx`,
// `F1.value1`); any other is an ABOP polygon vertex (`{ . f . }`, `[ + A { . ] . C . }`).
void markPolygonVertices(std::vector<std::unique_ptr<Token>>& tokens) {
  for (size_t i = 0; i < tokens.size(); ++i) {
    Token* dot = tokens[i].get();
    if (dot->getType() != FgsgLexer::DOT) continue;
    const bool member = i > 0 && i + 1 < tokens.size() && tokens[i - 1]->getType() == FgsgLexer::ID &&
                        tokens[i + 1]->getType() == FgsgLexer::ID && adjacent(tokens[i - 1].get(), dot) &&
                        adjacent(dot, tokens[i + 1].get());
    if (!member) static_cast<antlr4::CommonToken*>(dot)->setType(fgsg_grammar::FgsgParser::VERTEX);
  }
}

// `import "..." as facade;` makes `facade.Window` and `facade.floor_height` one name: the
// alias, '.' and a name written together become a single ID token (frontend/imports.cpp
// names the module's declarations so). Runs before the polygon '.'s are told apart.
void joinQualifiedNames(std::vector<std::unique_ptr<Token>>& tokens, std::vector<std::string> aliases) {
  for (size_t i = 0; i + 3 < tokens.size(); ++i)
    if (tokens[i]->getType() == FgsgLexer::IMPORT && tokens[i + 1]->getType() == FgsgLexer::STRING &&
        tokens[i + 2]->getType() == FgsgLexer::ID && tokens[i + 2]->getText() == "as" &&
        tokens[i + 3]->getType() == FgsgLexer::ID)
      aliases.push_back(tokens[i + 3]->getText());
  if (aliases.empty()) return;
  std::vector<std::unique_ptr<Token>> out;
  out.reserve(tokens.size());
  for (size_t i = 0; i < tokens.size(); ++i) {
    Token* t = tokens[i].get();
    if (t->getType() == FgsgLexer::ID && i + 2 < tokens.size() && tokens[i + 1]->getType() == FgsgLexer::DOT &&
        tokens[i + 2]->getType() == FgsgLexer::ID && adjacent(t, tokens[i + 1].get()) &&
        adjacent(tokens[i + 1].get(), tokens[i + 2].get()) &&
        std::find(aliases.begin(), aliases.end(), t->getText()) != aliases.end()) {
      auto* joined = static_cast<antlr4::CommonToken*>(t);
      joined->setText(t->getText() + "." + tokens[i + 2]->getText());
      joined->setStopIndex(tokens[i + 2]->getStopIndex());
      out.push_back(std::move(tokens[i]));
      i += 2;
      continue;
    }
    out.push_back(std::move(tokens[i]));
  }
  tokens = std::move(out);
}

// lpfg's and L-Py's section headers, each alone on its line: `production:`,
// `decomposition:`, `homomorphism:` (L-Py's `interpretation:`), and in the last two
// `maximum depth: N`. They leave the token list; `lexed` keeps the line each section
// starts on (the parser gives each rule its section) and the depths.
void lsystemSections(std::vector<std::unique_ptr<Token>>& tokens, Diagnostics& diags, LexedSource& lexed) {
  // Each token's line, taken first: the tokens before i have been moved into `out` when
  // token i is looked at (fuzz_imports: tokens[i - 1] was a null pointer there).
  std::vector<size_t> lines(tokens.size());
  for (size_t i = 0; i < tokens.size(); ++i) lines[i] = tokens[i]->getLine();
  const auto firstOnLine = [&](size_t i) { return i == 0 || lines[i] > lines[i - 1]; };
  const auto lastOnLine = [&](size_t i) {
    return i + 1 >= tokens.size() || tokens[i + 1]->getType() == Token::EOF ||
           tokens[i + 1]->getLine() > tokens[i]->getLine();
  };
  const auto is = [&](size_t i, size_t type, const char* text) {
    return i < tokens.size() && tokens[i]->getType() == type && (!text || tokens[i]->getText() == text);
  };
  RuleSection current = RuleSection::Production;
  std::vector<bool> drop(tokens.size(), false);  // decided first: the lambdas read the tokens
  for (size_t i = 0; i < tokens.size(); ++i) {
    if (!is(i, FgsgLexer::ID, nullptr) || !firstOnLine(i)) continue;
    const std::string word = tokens[i]->getText();
    const bool section = word == "production" || word == "homomorphism" || word == "interpretation" ||
                         word == "decomposition";
    if (section && is(i + 1, FgsgLexer::COLON, nullptr) && lastOnLine(i + 1)) {
      current = word == "production"      ? RuleSection::Production
                : word == "decomposition" ? RuleSection::Decomposition
                                          : RuleSection::Homomorphism;
      lexed.sectionStarts.emplace_back(lines[i], current);
      drop[i] = drop[i + 1] = true;
      ++i;
    } else if (word == "maximum" && is(i + 1, FgsgLexer::ID, "depth") && is(i + 2, FgsgLexer::COLON, nullptr)) {
      SourceRange at = tokenRange(tokens[i].get());
      at.end = tokenRange(tokens[i + 2].get()).end;
      // N, then at most a ';', alone on the line.
      const size_t n = i + 3;
      const bool wellFormed = is(n, FgsgLexer::INT, nullptr) && lines[n] == lines[i] &&
                              (lastOnLine(n) || (is(n + 1, FgsgLexer::SEMI, nullptr) && lastOnLine(n + 1)));
      long depth = 0;
      if (wellFormed) {
        const std::string digits = tokens[n]->getText();
        depth = digits.size() > 6 ? 1000000 : std::stol(digits);
      }
      if (current == RuleSection::Production)
        diags.error("E048", at, "'maximum depth:' belongs to a 'decomposition:' or 'homomorphism:' "
                                "('interpretation:') section: write it on the line after the section's header");
      else if (!wellFormed || depth < 1 || depth > 1000)
        diags.error("E002", at, "'maximum depth:' takes a whole number from 1 to 1000, alone on its line "
                                "(maximum depth: 3)");
      else
        (current == RuleSection::Decomposition ? lexed.decompositionDepth : lexed.homomorphismDepth) = int(depth);
      drop[i] = true;
      while (i + 1 < tokens.size() && tokens[i + 1]->getType() != Token::EOF && !firstOnLine(i + 1)) drop[++i] = true;
    }
  }
  std::vector<std::unique_ptr<Token>> out;
  out.reserve(tokens.size());
  for (size_t i = 0; i < tokens.size(); ++i)
    if (!drop[i]) out.push_back(std::move(tokens[i]));
  tokens = std::move(out);
}

// ABOP's and cpfg's `*` for "no context" and "no condition" in a production's head:
// `* < A > * : * -> B` is `A -> B`. Read so only where an expression cannot have a `*`
// (before '<', after '>' or ':' just before the arrow), so `a * b` stays a product.
void abopWildcards(std::vector<std::unique_ptr<Token>>& tokens) {
  const auto type = [&](size_t i) { return i < tokens.size() ? tokens[i]->getType() : size_t(Token::EOF); };
  const auto isArrow = [&](size_t i) { return type(i) == FgsgLexer::ARROW || type(i) == FgsgLexer::ASSIGN; };
  std::vector<bool> drop(tokens.size(), false);
  for (size_t i = 0; i < tokens.size(); ++i) {
    if (type(i) != FgsgLexer::STAR) continue;
    if (type(i + 1) == FgsgLexer::LT) {  // `* <`
      drop[i] = drop[i + 1] = true;
    } else if (i > 0 && type(i - 1) == FgsgLexer::GT && (isArrow(i + 1) || type(i + 1) == FgsgLexer::COLON)) {
      drop[i - 1] = drop[i] = true;  // `> * ->`, `> * : guard ->`
    } else if (i > 0 && type(i - 1) == FgsgLexer::COLON && isArrow(i + 1)) {
      drop[i - 1] = drop[i] = true;  // `: * ->`
    }
  }
  std::vector<std::unique_ptr<Token>> out;
  out.reserve(tokens.size());
  for (size_t i = 0; i < tokens.size(); ++i)
    if (!drop[i]) out.push_back(std::move(tokens[i]));
  tokens = std::move(out);
}

}  // namespace

RuleSection LexedSource::sectionAt(size_t line) const {
  RuleSection section = RuleSection::Production;
  for (const auto& [from, kind] : sectionStarts)
    if (from < line) section = kind;
  return section;
}

bool isImplicitSemicolon(const Token* token) {
  return token && token->getType() == FgsgLexer::SEMI && token->getStartIndex() == INVALID_INDEX;
}

SourceRange tokenRange(const Token* token) {
  SourceRange r;
  r.begin = {static_cast<int>(token->getLine()), static_cast<int>(token->getCharPositionInLine()) + 1};
  r.end = r.begin;
  if (token->getType() != Token::EOF && !isImplicitSemicolon(token)) {
    const size_t n = codePointCount(token->getText());
    if (n > 0) r.end.col = r.begin.col + static_cast<int>(n) - 1;
  }
  return r;
}

LexedSource lexSource(const SourceFile& file, Diagnostics& diags) {
  return lexText(file.name, file.mainText(), diags, file.importAliases);
}

LexedSource lexText(const std::string& name, const std::string& text, Diagnostics& diags,
                    const std::vector<std::string>& importAliases, IncrementalLexCache* cache) {
  LexedSource lexed;
  const std::string valid = validUtf8(text);
  auto input = std::make_unique<LookaheadTrackingStream>(valid);
  LookaheadTrackingStream& stream = *input;
  lexed.input = std::move(input);
  lexed.input->name = name;
  lexed.lexer = std::make_unique<FgsgLexer>(lexed.input.get());
  // Each token's text converted from the stream's UTF-32 once, when it is made, not at each
  // getText(): the steps below, tokenRange and the AST builder ask for it several times.
  static antlr4::CommonTokenFactory copyingText(true);
  lexed.lexer->setTokenFactory(&copyingText);
  lexed.lexer->removeErrorListeners();
  LexerErrorReporter reporter(diags);
  lexed.lexer->addErrorListener(&reporter);

  std::vector<std::unique_ptr<Token>> raw;
  if (cache) {
    const int errorsBefore = diags.errorCount();
    raw = cache->lex(*lexed.lexer, stream, valid);
    if (diags.errorCount() != errorsBefore) cache->clear();  // to be reported again next time
  } else {
    for (;;) {
      raw.push_back(lexed.lexer->nextToken());
      if (raw.back()->getType() == Token::EOF) break;
    }
  }
  lexed.lexer->removeErrorListeners();

  readContextListDeclarations(raw);  // before the `#` of `#consider` is a lexical error
  joinQueryModules(raw);
  LexicalErrors errors(diags);
  std::vector<std::unique_ptr<Token>> tokens = checkLexicalErrors(std::move(raw), errors);
  joinQualifiedNames(tokens, importAliases);
  lsystemSections(tokens, diags, lexed);
  abopWildcards(tokens);
  markPolygonVertices(tokens);
  for (size_t i : ImplicitSemicolons(tokens).colourSteps())
    static_cast<antlr4::CommonToken*>(tokens[i].get())->setType(fgsg_grammar::FgsgParser::COLORSTEP);
  for (size_t i : ImplicitSemicolons(tokens).colourBacks())  // the parser reads `,` as a colour step too; its text tells the two apart
    static_cast<antlr4::CommonToken*>(tokens[i].get())->setType(fgsg_grammar::FgsgParser::COLORSTEP);

  const std::vector<size_t> semicolons = ImplicitSemicolons(tokens).positions();
  lexed.tokens.reserve(tokens.size() + semicolons.size());
  size_t next = 0;
  for (size_t i = 0; i < tokens.size(); ++i) {
    if (next < semicolons.size() && semicolons[next] == i) {
      lexed.tokens.push_back(implicitSemicolonAfter(*lexed.tokens.back()));
      ++next;
    }
    lexed.tokens.push_back(std::move(tokens[i]));
  }
  return lexed;
}

}  // namespace fgsg::frontend
