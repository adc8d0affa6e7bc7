// Parsing drives ANTLR one statement at a time: lex (frontend/lex.cpp), then for each
// statement parse `statement`, build its AST (frontend/ast_builder.cpp), and on a syntax
// error skip to the statement's ';' so the next statement is read cleanly. Each statement
// is parsed in two stages (frontend/two_stage_parse.h): the errors come from the second.
#include "frontend/parse.h"

#include "frontend/ast_builder.h"
#include "frontend/cga/cga_parse.h"
#include "frontend/lex.h"
#include "frontend/statement_reuse.h"
#include "frontend/syntax_errors.h"
#include "frontend/two_stage_parse.h"

#include "FgsgParser.h"

#include <algorithm>

namespace fgsg::frontend {

using antlr4::Token;
using fgsg_grammar::FgsgParser;

namespace {

// After this many errors the rest of the file is most likely not .fgsg at all.
constexpr int kMaxErrors = 50;
// The parser recurses once per nesting level and per right-associative or prefix operator
// ('^', '?:', '~', unary '-'); at about 1 KiB of stack per level these bounds keep a
// statement within 2 MiB.
constexpr int kMaxNesting = 256;
constexpr int kMaxRecursiveOperators = 1024;

bool endsParsedOperand(size_t type) {
  switch (type) {
    case FgsgParser::ID: case FgsgParser::INT: case FgsgParser::FLOAT: case FgsgParser::RELSIZE:
    case FgsgParser::STRING: case FgsgParser::TRUE: case FgsgParser::FALSE:
    case FgsgParser::RPAREN: case FgsgParser::RBRACK: case FgsgParser::RBRACE:
      return true;
    default:
      return false;
  }
}

// A statement ends at its ';' (explicit or implicit), except inside a field design
// block, whose items end in ';' themselves.
class StatementScan {
 public:
  StatementScan(antlr4::CommonTokenStream& tokens, size_t start) : tokens_(tokens), start_(start) {}

  // Index just after the ';' ending the statement, the first at or after `from`; or the
  // index of EOF.
  size_t endAtOrAfter(size_t from) const {
    const bool field = type(start_) == FgsgParser::FIELD;
    int braces = 0;
    for (size_t i = start_;; ++i) {
      const size_t t = type(i);
      if (t == Token::EOF) return i;
      if (field && t == FgsgParser::LBRACE) ++braces;
      if (field && t == FgsgParser::RBRACE) braces = std::max(braces - 1, 0);
      if (t == FgsgParser::SEMI && braces == 0 && i >= from) return i + 1;
    }
  }

  // The first token that takes the statement deeper than the parser may recurse.
  const Token* tooDeep() const {
    const size_t end = endAtOrAfter(start_);
    int depth = 0;
    int recursive = 0;
    for (size_t i = start_; i < end; ++i) {
      switch (type(i)) {
        case FgsgParser::LPAREN: case FgsgParser::LBRACK: case FgsgParser::LBRACE:
          if (++depth > kMaxNesting) return tokens_.get(i);
          break;
        case FgsgParser::RPAREN: case FgsgParser::RBRACK: case FgsgParser::RBRACE:
          --depth;
          break;
        case FgsgParser::CARET: case FgsgParser::QUESTION: case FgsgParser::TILDE:
          if (++recursive > kMaxRecursiveOperators) return tokens_.get(i);
          break;
        case FgsgParser::BANG: case FgsgParser::MINUS: case FgsgParser::PLUS:
          // Only a prefix operator recurses; after an operand it is binary (or a turtle
          // symbol after an item), which the parser handles in a loop.
          if (i > start_ && !endsParsedOperand(type(i - 1)) && ++recursive > kMaxRecursiveOperators) {
            return tokens_.get(i);
          }
          break;
        default:
          break;
      }
    }
    return nullptr;
  }

 private:
  size_t type(size_t i) const { return i < tokens_.size() ? tokens_.get(i)->getType() : Token::EOF; }

  antlr4::CommonTokenStream& tokens_;
  size_t start_;
};

// Everything the parse and the AST of tokens [start, end) depend on, but for the lines the
// AST is moved by: each token's type, text, line from the first's, column and offsets from
// the first (tokens written together), the type of
// the token after (the parser's lookahead), the lpfg section and the priority in force.
std::string reusableStatementKey(antlr4::CommonTokenStream& tokens, size_t start, size_t end, RuleSection section,
                                 int priority) {
  std::string key = std::to_string(static_cast<int>(section)) + ' ' + std::to_string(priority);
  const size_t base = tokens.get(start)->getStartIndex(), firstLine = tokens.get(start)->getLine();
  auto number = [&](size_t n) {
    key += std::to_string(n);
    key += ',';
  };
  for (size_t i = start; i < end; ++i) {
    const Token* t = tokens.get(i);
    key += '\n';
    number(t->getType());
    number(t->getLine() - firstLine);
    number(t->getCharPositionInLine());
    number(t->getStartIndex() - base);
    number(t->getStopIndex() - base);
    key += t->getText();
  }
  key += '\n';
  number(end < tokens.size() ? tokens.get(end)->getType() : Token::EOF);
  return key;
}

size_t programStatementCount(const Program& p) {
  return p.imports.size() + p.values.size() + p.rules.size() + p.surfaces.size() + p.fields.size() +
         p.textures.size() + p.tilesets.size() + p.derives.size() + p.turtles.size() + p.ignores.size() +
         p.collisions.size() + p.axioms.size();
}

bool parseTextReusingStatements(const std::string& name, const std::string& text, Program& out, Diagnostics& diags,
                                const std::vector<std::string>& importAliases, StatementReuse* reuse);

}  // namespace

bool parseProgram(const SourceFile& file, Program& out, Diagnostics& diags) {
  if (isCgaSource(file.name, file.mainText())) return parseCgaText(file.name, file.mainText(), out, diags, file.startRule);
  if (!file.startRule.empty()) {
    // An fgsg grammar starts from its axiom, which may be any successor (or the seeds'):
    // it has no rule to name instead. Said before the parse, so the run does nothing else.
    diags.error("E803", SourceRange{{1, 1}, {1, 1}},
                "--start-rule " + file.startRule +
                    ": only a .cga grammar (CityEngine CGA) has a start rule to choose; this fgsg grammar "
                    "starts from its `axiom:` line");
    return false;
  }
  return parseText(file.name, file.mainText(), out, diags, file.importAliases);
}

bool parseProgramReusing(const SourceFile& file, Program& out, Diagnostics& diags, StatementReuse& reuse) {
  if (isCgaSource(file.name, file.mainText()) || !file.startRule.empty()) return parseProgram(file, out, diags);
  return parseTextReusingStatements(file.name, file.mainText(), out, diags, file.importAliases, &reuse);
}

bool parseText(const std::string& name, const std::string& text, Program& out, Diagnostics& diags,
               const std::vector<std::string>& importAliases) {
  // A module written in CityEngine's CGA (`import "facade.cga" as facade;`).
  if (isCgaSource(name, text)) return parseCgaText(name, text, out, diags);
  return parseTextReusingStatements(name, text, out, diags, importAliases, nullptr);
}

namespace {

bool parseTextReusingStatements(const std::string& name, const std::string& text, Program& out, Diagnostics& diags,
                                const std::vector<std::string>& importAliases, StatementReuse* reuse) {
  out.fileName = name;
  const int errorsBefore = diags.errorCount();

  LexedSource lexed = lexText(name, text, diags, importAliases, reuse ? &reuse->tokens() : nullptr);
  out.decompositionDepth = lexed.decompositionDepth;
  out.homomorphismDepth = lexed.homomorphismDepth;
  antlr4::ListTokenSource source(std::move(lexed.tokens));
  antlr4::CommonTokenStream tokens(&source);
  tokens.fill();

  FgsgParser firstStage(&tokens);
  makeFirstStage(firstStage);
  FgsgParser parser(&tokens);
  parser.removeErrorListeners();  // no console output: everything becomes a diagnostic
  SyntaxErrorListener listener(diags);
  parser.addErrorListener(&listener);
  auto strategy = std::make_shared<SyntaxErrorStrategy>(diags);
  parser.setErrorHandler(strategy);

  AstBuilder builder(out, diags);
  while (tokens.LA(1) != Token::EOF) {
    if (diags.errorCount() - errorsBefore >= kMaxErrors) {
      diags.note(tokenRange(tokens.LT(1)), "too many errors; stopped parsing here");
      break;
    }
    const size_t start = tokens.index();
    StatementScan scan(tokens, start);
    if (const Token* deep = scan.tooDeep()) {
      diags.error("E002", tokenRange(deep),
                  "statement nested too deeply (more than " + std::to_string(kMaxNesting) +
                      " brackets or " + std::to_string(kMaxRecursiveOperators) + " operators)");
      tokens.seek(scan.endAtOrAfter(start));
      continue;
    }
    const RuleSection section = lexed.sectionAt(tokens.LT(1)->getLine());
    builder.setSection(section);
    std::string key;
    size_t scannedEnd = 0;
    if (reuse) {
      scannedEnd = scan.endAtOrAfter(start);
      key = reusableStatementKey(tokens, start, scannedEnd, section, builder.priority());
      if (reuse->reuse(key, out, static_cast<int>(tokens.get(start)->getLine()))) {
        tokens.seek(scannedEnd);
        continue;
      }
    }
    // Each statement is parsed as a start rule: no invoking state, no recovery mode.
    firstStage.setState(antlr4::atn::ATNState::INVALID_STATE_NUMBER);
    firstStage.getErrorHandler()->reset(&firstStage);
    if (FgsgParser::StatementContext* statement = tryFirstStage([&] { return firstStage.statement(); })) {
      const size_t statementsBefore = programStatementCount(out), diagnosticsBefore = diags.all().size();
      const size_t rulesBefore = out.rules.size(), valuesBefore = out.values.size();
      builder.addStatement(statement);
      // Recorded only when it was one rule or value, parsed up to the scanned end, with no
      // diagnostic: anything else is parsed again next time.
      const bool one = programStatementCount(out) == statementsBefore + 1;
      const bool isRule = out.rules.size() == rulesBefore + 1, isValue = out.values.size() == valuesBefore + 1;
      if (reuse && one && (isRule || isValue) && tokens.index() == scannedEnd && diags.all().size() == diagnosticsBefore)
        reuse->record(key, isRule, out, static_cast<int>(tokens.get(start)->getLine()));
    } else {
      tokens.seek(start);
      parser.setState(antlr4::atn::ATNState::INVALID_STATE_NUMBER);
      strategy->reset(&parser);
      try {
        builder.addStatement(parser.statement());
      } catch (const StatementAbandoned&) {
        tokens.seek(scan.endAtOrAfter(tokens.index()));
      }
    }
    if (tokens.index() == start) tokens.consume();  // always make progress
  }
  if (diags.errorCount() != errorsBefore)
    if (const int line = cgaLookingLine(text))
      diags.note(SourceRange{{line, 1}, {line, 1}}, "this looks like CityEngine CGA: name the file .cga");
  return diags.errorCount() == errorsBefore;
}

}  // namespace

}  // namespace fgsg::frontend
