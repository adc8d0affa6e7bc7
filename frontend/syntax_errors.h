// Syntax errors: turns ANTLR's recognition errors into E002 diagnostics worded for a
// grammar author ("expected ';' or a successor after 'A ~> B', found ')'") instead of
// ANTLR's token sets. Private to the front end.
#pragma once

#include "frontend/diagnostics.h"

#include "antlr4-runtime.h"

namespace fgsg::frontend {

// Thrown by SyntaxErrorStrategy::recover(): instead of ANTLR's token-by-token resync
// inside the statement (which cascades into follow-on errors), parse.cpp skips to the end
// of the statement and goes on with the next one.
struct StatementAbandoned {};

class SyntaxErrorStrategy : public antlr4::DefaultErrorStrategy {
 public:
  explicit SyntaxErrorStrategy(Diagnostics& diags) : diags_(diags) {}

  // Single-token insertion and deletion (recoverInline) still repair small slips such
  // as a missing ';' in place; anything else abandons the statement.
  void recover(antlr4::Parser* parser, std::exception_ptr e) override;
  // Called before each statement: leaves recovery mode and re-arms reporting.
  void reset(antlr4::Parser* parser) override;

 protected:
  void reportNoViableAlternative(antlr4::Parser* parser, const antlr4::NoViableAltException& e) override;
  void reportInputMismatch(antlr4::Parser* parser, const antlr4::InputMismatchException& e) override;
  void reportFailedPredicate(antlr4::Parser* parser, const antlr4::FailedPredicateException& e) override;
  void reportUnwantedToken(antlr4::Parser* parser) override;
  void reportMissingToken(antlr4::Parser* parser) override;
  // Never deletes a ';': that would run the statement into the next one.
  antlr4::Token* singleTokenDeletion(antlr4::Parser* parser) override;

 private:
  void report(antlr4::Parser* parser, antlr4::Token* at, const std::string& message);
  // For an error in the plain-or-guarded decision of a rule body: re-parse the first
  // part as a successor and report that parse's error, which names what was expected.
  // " after '<the statement so far>'", or "" at its first token.
  std::string after(antlr4::Parser* parser, const antlr4::Token* at) const;
  bool explainAsSuccessor(antlr4::Parser* parser, const antlr4::NoViableAltException& e);
  // "expected <set in words> after '<statement so far>', found <token>"
  void reportExpected(antlr4::Parser* parser, antlr4::Token* at, const antlr4::misc::IntervalSet& expected);

  Diagnostics& diags_;
  // One error per statement: after an in-place repair ANTLR would report every later
  // token the wrong repair disagrees with.
  bool reportedInStatement_ = false;
  // Set while probing for explainAsSuccessor: the first error goes here, not to diags_.
  Diagnostic* probeResult_ = nullptr;
  const antlr4::Token* probeStatementStart_ = nullptr;
};

// Receives whatever still reaches ANTLR's listener interface (nothing, as long as the
// strategy above words every error) and reports it as E002.
class SyntaxErrorListener : public antlr4::BaseErrorListener {
 public:
  explicit SyntaxErrorListener(Diagnostics& diags) : diags_(diags) {}
  void syntaxError(antlr4::Recognizer* recognizer, antlr4::Token* offendingSymbol, size_t line,
                   size_t charPositionInLine, const std::string& msg, std::exception_ptr e) override;

 private:
  Diagnostics& diags_;
};

}  // namespace fgsg::frontend
