#include "frontend/syntax_errors.h"

#include "frontend/lex.h"

#include "FgsgParser.h"

namespace fgsg::frontend {

using antlr4::Parser;
using antlr4::Token;
using antlr4::misc::IntervalSet;
using fgsg_grammar::FgsgParser;

namespace {

constexpr size_t kMaxContextChars = 40;
constexpr size_t kMaxTokenChars = 24;

bool isContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// Keeps the last `maxChars` characters, cutting on a character boundary.
std::string lastChars(const std::string& s, size_t maxChars) {
  size_t chars = 0;
  for (size_t i = s.size(); i-- > 0;) {
    if (!isContinuationByte(s[i]) && ++chars == maxChars) return "..." + s.substr(i);
  }
  return s;
}

std::string firstChars(const std::string& s, size_t maxChars) {
  size_t chars = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    if (!isContinuationByte(s[i]) && chars++ == maxChars) return s.substr(0, i) + "...";
  }
  return s;
}

std::string collapseWhitespace(const std::string& s) {
  std::string out;
  bool space = false;
  for (char c : s) {
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f') {
      space = !out.empty();
    } else {
      if (space) out += ' ';
      space = false;
      out += c;
    }
  }
  return out;
}

std::string quoted(const std::string& s) {
  std::string out;
  out.reserve(s.size() + 2);
  out += '\'';
  out += s;
  out += '\'';
  return out;
}

std::string describeToken(const Token* t) {
  if (!t || t->getType() == Token::EOF) return "the end of the file";
  if (isImplicitSemicolon(t)) return "the end of the line";
  return quoted(firstChars(t->getText(), kMaxTokenChars));
}

const Token* statementStart(Parser* parser) {
  antlr4::ParserRuleContext* root = parser->getContext();
  if (!root) return nullptr;
  while (root->parent) root = static_cast<antlr4::ParserRuleContext*>(root->parent);
  return root->start;
}

// The statement's text before `at`, as the user wrote it: "A ~> B".
std::string textBefore(Parser* parser, const Token* first, const Token* at) {
  if (!at) return "";
  if (!first || at->getTokenIndex() == INVALID_INDEX || at->getTokenIndex() == 0) return "";
  const Token* last = parser->getTokenStream()->get(at->getTokenIndex() - 1);
  if (!last || isImplicitSemicolon(last) || isImplicitSemicolon(first) ||
      last->getTokenIndex() < first->getTokenIndex() || !first->getInputStream()) {
    return "";
  }
  const std::string text = first->getInputStream()->getText(
      antlr4::misc::Interval(first->getStartIndex(), last->getStopIndex()));
  return lastChars(collapseWhitespace(text), kMaxContextChars);
}

std::string afterText(Parser* parser, const Token* first, const Token* at) {
  const std::string before = textBefore(parser, first, at);
  return before.empty() ? std::string() : " after " + quoted(before);
}

std::string joinAlternatives(const std::vector<std::string>& parts) {
  std::string out;
  for (size_t i = 0; i < parts.size(); ++i) {
    if (i > 0) out += i + 1 == parts.size() ? " or " : ", ";
    out += parts[i];
  }
  return out;
}

// Words for a set of expected tokens: whole groups ("a successor", "an expression",
// "an operator") first, then single tokens; never ANTLR's raw set.
std::string describeExpected(IntervalSet set, const antlr4::dfa::Vocabulary& vocabulary) {
  using P = FgsgParser;
  std::vector<std::string> parts;
  auto group = [&](std::initializer_list<size_t> signature, std::initializer_list<size_t> members,
                   const char* words) {
    for (size_t t : signature) {
      if (!set.contains(t)) return;
    }
    for (size_t t : members) set.remove(t);
    parts.push_back(words);
  };
  if (set.size() > 1) set.remove(Token::EOF);

  group({P::CONST, P::PRIORITY, P::ID}, {P::CONST, P::ATTR, P::SURFACE, P::FIELD, P::TEXTURE,
        P::TILESET, P::DERIVE, P::TURTLE, P::COLLISION, P::AXIOM, P::PRIORITY, P::ID, P::INT, P::SEMI,
        P::IMPORT},
        "a rule or a declaration");
  // Where a successor may start, so may a Müller guard: "a successor" says enough.
  group({P::ID, P::LBRACK, P::PLUS}, {P::ID, P::LBRACK, P::PLUS, P::MINUS, P::AMP, P::AND, P::CARET,
        P::BACKSLASH, P::SLASH, P::BANG, P::DOLLAR, P::PERCENT, P::QUOTE, P::PIPE, P::OR, P::EPSILON,
        P::LPAREN, P::LBRACE, P::RBRACE, P::VERTEX, P::COLORSTEP, P::INT, P::FLOAT, P::RELSIZE, P::STRING, P::TRUE,
        P::FALSE, P::TILDE},
        "a successor");
  group({P::INT, P::STRING, P::ID, P::LPAREN}, {P::INT, P::FLOAT, P::RELSIZE, P::STRING, P::TRUE,
        P::FALSE, P::ID, P::LPAREN, P::MINUS, P::PLUS, P::BANG, P::TILDE}, "an expression");
  group({P::STAR, P::EQ, P::AND}, {P::STAR, P::SLASH, P::PERCENT, P::PLUS, P::MINUS, P::CARET,
        P::LT, P::GT, P::LE, P::GE, P::EQ, P::NEQ, P::AND, P::OR, P::QUESTION, P::DOT}, "an operator");
  group({P::ARROW}, {P::ARROW, P::ASSIGN}, "an arrow '~>'");
  group({P::INT, P::FLOAT}, {P::INT, P::FLOAT}, "a number");

  for (ssize_t t : set.toList()) {
    switch (t) {
      case P::ID: parts.push_back("a name"); break;
      case P::INT: parts.push_back("an integer"); break;
      case P::FLOAT: parts.push_back("a number"); break;
      case P::STRING: parts.push_back("a string"); break;
      case P::RELSIZE: parts.push_back("a relative size"); break;
      case P::EPSILON: parts.push_back("'\u03B5'"); break;
      case P::PRIORITY: parts.push_back("'priority'"); break;
      case P::ARROW: parts.push_back("'~>'"); break;
      case static_cast<ssize_t>(Token::EOF): parts.push_back("the end of the file"); break;
      default: {
        const std::string literal = vocabulary.getLiteralName(t);
        parts.push_back(literal.empty() ? vocabulary.getDisplayName(t) : literal);
      }
    }
  }
  constexpr size_t kMaxParts = 5;
  if (parts.size() > kMaxParts) {
    parts.resize(kMaxParts - 1);
    parts.push_back("...");
  }
  return joinAlternatives(parts);
}

// What the parser was reading when no alternative fit, for "expected X" in words.
std::string expectedForRule(size_t ruleIndex) {
  switch (ruleIndex) {
    case FgsgParser::RuleStatement: return "a rule or a declaration";
    case FgsgParser::RuleRuleBody:
    case FgsgParser::RuleBranch:
    case FgsgParser::RuleSuccessor: return "a successor";
    case FgsgParser::RuleItem:
    case FgsgParser::RuleSequenceItem:
    case FgsgParser::RuleBodyPart: return "a successor item";
    case FgsgParser::RuleRuleHead:
    case FgsgParser::RuleLeftContext:
    case FgsgParser::RuleRightContext:
    case FgsgParser::RuleContextModule:
    case FgsgParser::RuleModulePattern: return "a rule's predecessor";
    case FgsgParser::RuleExpr:
    case FgsgParser::RulePrimary:
    case FgsgParser::RuleCallArgs: return "an expression";
    case FgsgParser::RuleFieldSource: return "a field source (tensor(\"file\"), design tensor { ... } or curvature)";
    case FgsgParser::RuleDesignValue: return "a value";
    default: return "";
  }
}

// Where to point for an error found at `t`: the token itself, or just after the
// previous token when `t` is the end of the line or file (clang's "expected ';'" style).
SourceRange errorRange(Parser* parser, const Token* t) {
  if (t && t->getType() != Token::EOF && !isImplicitSemicolon(t)) return tokenRange(t);
  const size_t index = t ? t->getTokenIndex() : INVALID_INDEX;
  if (index != INVALID_INDEX && index > 0) {
    const Token* prev = parser->getTokenStream()->get(index - 1);
    if (isImplicitSemicolon(prev) && index > 1) prev = parser->getTokenStream()->get(index - 2);
    SourceRange r = tokenRange(prev);
    r.begin = {r.end.line, r.end.col + 1};
    r.end = r.begin;
    return r;
  }
  return t ? tokenRange(t) : SourceRange{};
}

// ABOP's digit modules (Fig. 1.31: `0 < 0 > 1 -> 1[+F1F1]`): fgsg's names start with a
// letter, so a whole number where a module would stand is what broke the statement — one
// that starts with it, or one in an axiom or a successor. Returns that number, or null.
// The number is the failing token or the one before it (`1 [` after an arrow), and not
// a probability or an argument (after ':', inside ( ) or { }).
const Token* digitModule(Parser* parser, const Token* first, const Token* at) {
  if (!first) return nullptr;
  if (first->getType() == FgsgParser::INT) return first;
  if (!at || at->getTokenIndex() == INVALID_INDEX || at->getTokenIndex() <= first->getTokenIndex()) return nullptr;
  antlr4::TokenStream* tokens = parser->getTokenStream();
  const Token* number = at->getType() == FgsgParser::INT ? at : tokens->get(at->getTokenIndex() - 1);
  if (number->getType() != FgsgParser::INT || number->getTokenIndex() <= first->getTokenIndex()) return nullptr;
  const size_t before = tokens->get(number->getTokenIndex() - 1)->getType();
  if (before == FgsgParser::COLON || before == FgsgParser::COMMA || before == FgsgParser::LPAREN) return nullptr;
  bool successor = first->getType() == FgsgParser::AXIOM;
  int depth = 0;  // inside ( ) or { } a number is an argument
  for (size_t i = first->getTokenIndex(); i < number->getTokenIndex(); ++i) {
    const size_t type = tokens->get(i)->getType();
    successor |= type == FgsgParser::ARROW;
    if (type == FgsgParser::LPAREN || type == FgsgParser::LBRACE) ++depth;
    if (type == FgsgParser::RPAREN || type == FgsgParser::RBRACE) --depth;
  }
  return successor && depth <= 0 ? number : nullptr;
}

}  // namespace

void SyntaxErrorStrategy::report(Parser* parser, Token* at, const std::string& message) {
  std::string code = "E002", text = message;
  SourceRange range = errorRange(parser, at);
  const Token* first = probeStatementStart_ ? probeStatementStart_ : statementStart(parser);
  if (const Token* digit = digitModule(parser, first, at)) {
    code = "E048";
    text = "the number '" + digit->getText() +
           "' cannot be a module: ABOP's digit module names (Fig. 1.31's 0 and 1) are not supported, fgsg's "
           "names start with a letter; write letters (a for 0, b for 1)";
    range = tokenRange(digit);
  }
  if (probeResult_) {
    if (probeResult_->message.empty()) *probeResult_ = {Severity::Error, code, text, range};
    return;
  }
  if (reportedInStatement_) return;
  reportedInStatement_ = true;
  diags_.error(code, range, text);
}

void SyntaxErrorStrategy::reset(Parser* parser) {
  DefaultErrorStrategy::reset(parser);
  reportedInStatement_ = false;
}

std::string SyntaxErrorStrategy::after(Parser* parser, const Token* at) const {
  return afterText(parser, probeStatementStart_ ? probeStatementStart_ : statementStart(parser), at);
}

bool SyntaxErrorStrategy::explainAsSuccessor(Parser* parser, const antlr4::NoViableAltException& e) {
  auto* tokens = dynamic_cast<antlr4::TokenStream*>(parser->getInputStream());
  if (probeResult_ || !tokens || !e.getStartToken() || !e.getOffendingToken()) return false;
  const size_t resumeAt = tokens->index();

  Diagnostic found;
  auto probeStrategy = std::make_shared<SyntaxErrorStrategy>(diags_);
  probeStrategy->probeResult_ = &found;
  probeStrategy->probeStatementStart_ = statementStart(parser);
  FgsgParser probe(tokens);
  probe.removeErrorListeners();
  probe.setErrorHandler(probeStrategy);
  tokens->seek(e.getStartToken()->getTokenIndex());
  try {
    probe.branch();
  } catch (const StatementAbandoned&) {
  }
  tokens->seek(resumeAt);

  // Only if reading a successor got at least as far as reading a guard did.
  const SourceRange failedAt = errorRange(parser, e.getOffendingToken());
  const bool asFar = found.range.begin.line > failedAt.begin.line ||
                     (found.range.begin.line == failedAt.begin.line && found.range.begin.col >= failedAt.begin.col);
  if (found.message.empty() || !asFar) return false;
  reportedInStatement_ = true;
  diags_.error(found.code, found.range, found.message);
  return true;
}

void SyntaxErrorStrategy::recover(Parser*, std::exception_ptr) { throw StatementAbandoned{}; }

// ALL(*) decisions look ahead many tokens; when every alternative dies further on, the
// decision's expected set says nothing about the failing token, so only name it then.
void SyntaxErrorStrategy::reportNoViableAlternative(Parser* parser, const antlr4::NoViableAltException& e) {
  if (dynamic_cast<FgsgParser::RuleBodyContext*>(e.getCtx()) && explainAsSuccessor(parser, e)) return;
  Token* at = e.getOffendingToken();
  std::string expected;
  if (e.getStartToken() == at) {
    if (auto* ctx = dynamic_cast<antlr4::RuleContext*>(e.getCtx())) expected = expectedForRule(ctx->getRuleIndex());
  }
  const std::string where = after(parser, at);
  if (expected.empty()) {
    report(parser, at, "unexpected " + describeToken(at) + where);
  } else {
    report(parser, at, "expected " + expected + where + ", found " + describeToken(at));
  }
}

void SyntaxErrorStrategy::reportInputMismatch(Parser* parser, const antlr4::InputMismatchException& e) {
  reportExpected(parser, e.getOffendingToken(), e.getExpectedTokens());
}

void SyntaxErrorStrategy::reportFailedPredicate(Parser* parser, const antlr4::FailedPredicateException& e) {
  Token* at = e.getOffendingToken();
  report(parser, at, "unexpected " + describeToken(at) + after(parser, at));
}

void SyntaxErrorStrategy::reportUnwantedToken(Parser* parser) {
  if (inErrorRecoveryMode(parser)) return;
  beginErrorCondition(parser);
  reportExpected(parser, parser->getCurrentToken(), getExpectedTokens(parser));
}

void SyntaxErrorStrategy::reportMissingToken(Parser* parser) {
  if (inErrorRecoveryMode(parser)) return;
  beginErrorCondition(parser);
  reportExpected(parser, parser->getCurrentToken(), getExpectedTokens(parser));
}

void SyntaxErrorStrategy::reportExpected(Parser* parser, Token* at, const IntervalSet& expected) {
  std::string what = describeExpected(expected, parser->getVocabulary());
  // At a rule's final ';' the successor loop has already been left behind, so the set
  // is just ';'; but more successor items would have fitted too.
  auto* rule = dynamic_cast<FgsgParser::GrammarRuleContext*>(parser->getContext());
  if (rule && expected.size() == 1 && expected.contains(static_cast<size_t>(FgsgParser::SEMI)) &&
      rule->ruleBody() && !rule->ruleBody()->branch().empty() &&
      !rule->ruleBody()->branch().back()->probability) {
    what = "';' or a successor";
  }
  // `collision centre(0.3);`: name the settings rather than "a name, '-', a number".
  if (dynamic_cast<FgsgParser::CollisionDeclContext*>(parser->getContext()))
    what = "a collision setting (all, mesh, centre R, geodesic R, distance D) or ';'";
  std::string hint;
  // `decay 2 * k;` in a field design: values are single words unless parenthesised.
  auto* ctx = parser->getContext();
  const bool inDesign = dynamic_cast<FgsgParser::FieldDesignItemContext*>(ctx) ||
                        dynamic_cast<FgsgParser::FieldDesignWordContext*>(ctx) ||
                        dynamic_cast<FgsgParser::DesignValueContext*>(ctx);
  if (inDesign && expected.contains(static_cast<size_t>(FgsgParser::SEMI)))
    what = "a keyword (at, decay, strength ...), a value or ';'";
  if (inDesign && at) {
    switch (at->getType()) {
      case FgsgParser::STAR: case FgsgParser::SLASH: case FgsgParser::PERCENT:
      case FgsgParser::CARET: case FgsgParser::PLUS: case FgsgParser::MINUS:
        hint = " (a design value is a number, a point, a const name or an expression in "
               "parentheses: `decay (2 * k)`)";
        break;
      default: break;
    }
  }
  // `I('cube')`: ' is ABOP's colour index; strings take double quotes.
  if (at && at->getType() == FgsgParser::QUOTE && expected.contains(static_cast<size_t>(FgsgParser::STRING)))
    hint = " (strings are written in double quotes: \"cube\")";
  report(parser, at, "expected " + what + after(parser, at) + ", found " + describeToken(at) + hint);
}

Token* SyntaxErrorStrategy::singleTokenDeletion(Parser* parser) {
  if (parser->getCurrentToken()->getType() == FgsgParser::SEMI) return nullptr;
  return DefaultErrorStrategy::singleTokenDeletion(parser);
}

void SyntaxErrorListener::syntaxError(antlr4::Recognizer*, Token* offendingSymbol, size_t line,
                                      size_t charPositionInLine, const std::string& msg, std::exception_ptr) {
  SourceRange at;
  if (offendingSymbol) {
    at = tokenRange(offendingSymbol);
  } else {
    at.begin = at.end = {static_cast<int>(line), static_cast<int>(charPositionInLine) + 1};
  }
  diags_.error("E002", at, "syntax error: " + msg);
}

}  // namespace fgsg::frontend
